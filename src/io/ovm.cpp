// SPDX-License-Identifier: MIT
// OpenVolumeMesh's ascii files (.ovm): vertices, edges (vertex pairs), faces
// (cycles of half-edges: half-edge 2e goes along edge e, 2e + 1 against it),
// polyhedra (lists of half-faces: half-face 2f has face f's orientation,
// 2f + 1 the reverse; their normals point into the cell), then properties
// ("vprop double \"name\"" and one value per vertex, and so for edges,
// half-edges, faces, half-faces, cells and the mesh).
#include <cgogn/io/error.h>

#include "formats.h"
#include "map_transfer.h"
#include "text_reader.h"
#include "text_writer.h"

#include <algorithm>
#include <array>
#include <map>
#include <string_view>

namespace cgogn::io::detail
{

namespace
{

std::string lower(std::string_view s)
{
	std::string r(s);
	std::transform(r.begin(), r.end(), r.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	return r;
}

// The number of values per element of an .ovm property type (scalars 1,
// vec2*/vec3*/vec4* 2/3/4); 0 for the types whose values the reader cannot
// count (strings, vectors, maps).
uint32 components_of(const std::string& type)
{
	static const char* scalars[] = {"int",           "unsigned int", "short",         "unsigned short", "long",
									"unsigned long", "char",         "unsigned char", "bool",           "float",
									"double",        "uint",         "uchar",         "ushort",         "ulong"};
	for (const char* t : scalars)
		if (type == t)
			return 1;
	if (type.size() >= 5 && type.rfind("vec", 0) == 0 && type[3] >= '2' && type[3] <= '4')
	{
		const std::string rest = type.substr(4);
		if (rest == "d" || rest == "f" || rest == "i" || rest == "ui" || rest == "c" || rest == "uc")
			return uint32(type[3] - '0');
	}
	return 0;
}

// The .ovm integer type names and their column types; each type's first
// name is the one written.
constexpr std::pair<std::string_view, ValueType> INTEGER_TYPES[] = {
	{"char", ValueType::Int8},           {"uchar", ValueType::UInt8},
	{"short", ValueType::Int16},         {"ushort", ValueType::UInt16},
	{"int", ValueType::Int32},           {"uint", ValueType::UInt32},
	{"long", ValueType::Int64},          {"ulong", ValueType::UInt64},
	{"unsigned char", ValueType::UInt8}, {"unsigned short", ValueType::UInt16},
	{"unsigned int", ValueType::UInt32}, {"unsigned long", ValueType::UInt64}};

// The column type of an .ovm scalar type: its integer type, Float64 for
// float, double and bool.
ValueType ovm_value_type(const std::string& type)
{
	for (const auto& [name, t] : INTEGER_TYPES)
		if (type == name)
			return t;
	return ValueType::Float64;
}

// The .ovm name of a column type.
std::string_view ovm_type_name(ValueType t)
{
	for (const auto& [name, v] : INTEGER_TYPES)
		if (v == t)
			return name;
	return "double";
}

// Whether b is the cycle a, starting anywhere (same direction). O(size).
bool same_cycle(const std::vector<uint32>& a, const std::vector<uint32>& b)
{
	const auto start = std::find(b.begin(), b.end(), a[0]);
	if (a.size() != b.size() || start == b.end())
		return false;
	const std::size_t p = std::size_t(start - b.begin());
	for (std::size_t i = 0; i < a.size(); ++i)
		if (b[(p + i) % b.size()] != a[i])
			return false;
	return true;
}

} // namespace

MeshData read_ovm(std::string_view text, const std::string& path)
{
	TextReader r(text, path, '#');
	MeshData d;
	std::string_view t = r.token();
	if (lower(t) == "ovm")
	{
		const std::string kind = lower(r.token_in_line());
		if (kind == "binary")
			r.fail("binary .ovm files are not read (write them as ascii with OpenVolumeMesh)");
		if (kind != "ascii")
			r.fail("expected ASCII after OVM, found '" + TextReader::printable(kind) + "'");
		t = r.token();
	}
	auto section = [&](std::string_view found, const char* name) {
		if (lower(found) != lower(name))
			r.fail(std::string("expected the section ") + name + ", found '" + TextReader::printable(found) + "'");
	};

	section(t, "Vertices");
	const uint32 nv = r.read_uint("the number of vertices");
	r.check_count(nv, 6, "vertices");
	d.positions.reserve(std::size_t(nv) * 3);
	for (uint32 i = 0; i < 3 * nv; ++i)
		d.positions.push_back(r.read_double("a vertex coordinate"));

	section(r.token(), "Edges");
	const uint32 ne = r.read_uint("the number of edges");
	r.check_count(ne, 4, "edges");
	std::vector<std::array<uint32, 2>> edges(ne);
	for (auto& e : edges)
		for (uint32& v : e)
		{
			v = r.read_uint("a vertex index");
			if (v >= nv)
				r.fail("vertex index " + std::to_string(v) + " out of range (the file has " + std::to_string(nv) +
					   " vertices)");
		}

	section(r.token(), "Faces");
	const uint32 nf = r.read_uint("the number of faces");
	r.check_count(nf, 4, "faces");
	std::vector<uint32> face_first(nf + 1, 0), face_vertices;
	for (uint32 f = 0; f < nf; ++f)
	{
		const uint32 k = r.read_uint("the number of half-edges of a face");
		r.check_count(k, 2, "half-edges");
		uint32 previous_end = INVALID_INDEX, first_start = INVALID_INDEX;
		for (uint32 i = 0; i < k; ++i)
		{
			const uint32 h = r.read_uint("a half-edge index");
			if (h / 2 >= ne)
				r.fail("half-edge index " + std::to_string(h) + " out of range (the file has " + std::to_string(ne) +
					   " edges)");
			const uint32 from = edges[h / 2][h % 2], to = edges[h / 2][1 - h % 2];
			if (previous_end != INVALID_INDEX && from != previous_end)
				r.fail("face " + std::to_string(f) + ": half-edge " + std::to_string(h) +
					   " does not start where the previous one ends");
			if (i == 0)
				first_start = from;
			previous_end = to;
			face_vertices.push_back(from);
		}
		if (k > 0 && previous_end != first_start)
			r.fail("face " + std::to_string(f) + ": its half-edges do not close a cycle");
		face_first[f + 1] = uint32(face_vertices.size());
	}

	section(r.token(), "Polyhedra");
	const uint32 nc = r.read_uint("the number of polyhedra");
	r.check_count(nc, 2, "polyhedra");
	std::vector<uint8> face_used(nf, 0);
	std::vector<uint32> sizes, ids;
	for (uint32 c = 0; c < nc; ++c)
	{
		const uint32 k = r.read_uint("the number of half-faces of a polyhedron");
		if (k == 0)
			r.fail("polyhedron " + std::to_string(c) + " has no half-face");
		r.check_count(k, 2, "half-faces");
		sizes.clear();
		ids.clear();
		for (uint32 i = 0; i < k; ++i)
		{
			const uint32 h = r.read_uint("a half-face index");
			const uint32 f = h / 2;
			if (f >= nf)
				r.fail("half-face index " + std::to_string(h) + " out of range (the file has " + std::to_string(nf) +
					   " faces)");
			face_used[f] = 1;
			sizes.push_back(face_first[f + 1] - face_first[f]);
			// the half-face's normal points into the cell: outward is the other side
			const auto b = face_vertices.begin() + face_first[f], e = face_vertices.begin() + face_first[f + 1];
			if (h % 2 == 1)
				ids.insert(ids.end(), b, e);
			else
				ids.insert(ids.end(), std::make_reverse_iterator(e), std::make_reverse_iterator(b));
		}
		d.add_polyhedron(k, sizes, ids);
	}
	d.finish_polyhedra();
	if (const auto unused = std::count(face_used.begin(), face_used.end(), 0); unused > 0)
		d.dropped.push_back(std::to_string(unused) + " face(s) in no polyhedron: a volume map holds faces of cells");

	// properties: vertex and cell ones of scalar or 2-3 component types
	// become columns; the others are reported
	std::vector<std::string> vertex_names, cell_names;
	while (!r.at_end())
	{
		const std::string entity = lower(r.token());
		std::string type = lower(r.token_in_line());
		const std::string_view rest = r.rest_of_line();
		if (type == "unsigned" || type == "long") // two-word types: "unsigned int", "unsigned long"...
		{
			const std::size_t space = rest.find_first_not_of(" \t");
			const std::size_t word_end = rest.find_first_of(" \t\"", space);
			if (space != std::string_view::npos && rest[space] != '"')
				type += " " + lower(rest.substr(space, word_end - space));
		}
		const std::size_t q0 = rest.find('"'), q1 = rest.rfind('"');
		if (q0 == std::string_view::npos || q1 == q0)
			r.fail("a property header without its name in quotes");
		const std::string name(rest.substr(q0 + 1, q1 - q0 - 1));
		uint64 count = 0;
		if (entity == "vprop")
			count = nv;
		else if (entity == "eprop")
			count = ne;
		else if (entity == "heprop")
			count = 2 * uint64(ne);
		else if (entity == "fprop")
			count = nf;
		else if (entity == "hfprop")
			count = 2 * uint64(nf);
		else if (entity == "cprop")
			count = nc;
		else if (entity == "mprop")
			count = 1;
		else
			r.fail("unknown property kind '" + TextReader::printable(entity) + "'");
		const uint32 dim = components_of(type);
		if (dim == 0)
		{
			d.dropped.push_back(entity + " '" + name + "' of type " + type +
								" and the properties after it: values of that type are not read");
			break;
		}
		r.check_count(count * dim, 2, "property values");
		std::vector<double> values(count * dim);
		const ValueType value_type = dim == 1 ? ovm_value_type(type) : ValueType::Float64;
		for (double& v : values)
			v = is_integer_type(value_type) ? double(r.read_int("an integer property value"))
											: r.read_double("a property value");
		if ((entity == "vprop" || entity == "cprop") && dim <= 3)
		{
			std::vector<std::string>& names = entity == "vprop" ? vertex_names : cell_names;
			if (std::string why = data_name_conflict(names, name, entity == "vprop"); !why.empty())
				r.fail(why);
			names.push_back(name);
			(entity == "vprop" ? d.vertex_columns : d.cell_columns)
				.push_back(Column{name, dim, std::move(values), value_type});
		}
		else
			d.dropped.push_back(entity + " '" + name + "' of type " + type +
								": a volume map takes vertex and cell properties of up to 3 components");
	}
	return d;
}

std::string write_ovm(const MeshData& d)
{
	const PolyhedronSoup cells = cells_as_polyhedra(d);
	std::string s = "OVM ASCII\nVertices\n";
	append_uint(s, d.nb_vertices());
	s += '\n';
	for (std::size_t i = 0; i < d.positions.size(); ++i)
	{
		append_double(s, d.positions[i]);
		s += i % 3 == 2 ? '\n' : ' ';
	}
	// edges and faces numbered in the order the cells first use them
	std::map<std::pair<uint32, uint32>, uint32> edge_of;
	std::vector<std::pair<uint32, uint32>> edges;
	std::map<std::vector<uint32>, uint32> face_of; // a face's cycle from its smallest vertex, both ways
	std::vector<std::vector<uint32>> faces;        // as first listed (outward of the first cell using it)
	std::vector<uint32> half_faces;                // of each cell, in order
	std::size_t first = 0;
	for (uint32 nf : cells.cell_nb_faces)
		for (uint32 f = 0; f < nf; ++f)
		{
			const uint32 n = cells.face_sizes[half_faces.size()];
			std::vector<uint32> fv(cells.face_vertices.begin() + std::ptrdiff_t(first),
								   cells.face_vertices.begin() + std::ptrdiff_t(first + n));
			first += n;
			std::vector<uint32> key = fv;
			std::rotate(key.begin(), std::min_element(key.begin(), key.end()), key.end());
			if (key.size() > 2 && key[1] > key.back())
				std::reverse(key.begin() + 1, key.end());
			auto [it, inserted] = face_of.try_emplace(key, uint32(faces.size()));
			if (inserted)
			{
				faces.push_back(fv);
				for (uint32 i = 0; i < n; ++i)
				{
					const uint32 a = fv[i], b = fv[(i + 1) % n];
					if (edge_of.try_emplace({std::min(a, b), std::max(a, b)}, uint32(edges.size())).second)
						edges.emplace_back(std::min(a, b), std::max(a, b));
				}
			}
			// the face as this cell sees it from outside: its inward half-face
			// is the stored face's when the cell lists it the stored way round
			const bool same = same_cycle(fv, faces[it->second]);
			half_faces.push_back(2 * it->second + (same ? 1 : 0));
		}
	s += "Edges\n";
	append_uint(s, edges.size());
	s += '\n';
	for (const auto& [a, b] : edges)
	{
		append_uint(s, a);
		s += ' ';
		append_uint(s, b);
		s += '\n';
	}
	s += "Faces\n";
	append_uint(s, faces.size());
	s += '\n';
	for (const auto& fv : faces)
	{
		append_uint(s, fv.size());
		for (std::size_t i = 0; i < fv.size(); ++i)
		{
			const uint32 a = fv[i], b = fv[(i + 1) % fv.size()];
			s += ' ';
			append_uint(s, 2 * edge_of.at({std::min(a, b), std::max(a, b)}) + (a < b ? 0 : 1));
		}
		s += '\n';
	}
	s += "Polyhedra\n";
	append_uint(s, cells.cell_nb_faces.size());
	s += '\n';
	std::size_t h = 0;
	for (uint32 nf : cells.cell_nb_faces)
	{
		append_uint(s, nf);
		for (uint32 f = 0; f < nf; ++f)
		{
			s += ' ';
			append_uint(s, half_faces[h++]);
		}
		s += '\n';
	}
	auto properties = [&](const char* entity, const std::vector<Column>& columns) {
		for (const auto& c : columns)
		{
			if (c.dim < 1 || c.dim > 3 || c.name.find('"') != std::string::npos)
				continue;
			const bool integer = c.dim == 1 && is_integer_type(c.type);
			s += entity;
			s += ' ';
			s += integer ? ovm_type_name(c.type) : c.dim == 1 ? "double" : c.dim == 2 ? "vec2d" : "vec3d";
			s += " \"";
			s += c.name;
			s += "\"\n";
			for (std::size_t i = 0; i < c.values.size(); ++i)
			{
				if (integer)
					append_int(s, int64(c.values[i]));
				else
					append_double(s, c.values[i]);
				s += (i + 1) % c.dim == 0 ? '\n' : ' ';
			}
		}
	};
	properties("vprop", d.vertex_columns);
	properties("cprop", d.cell_columns);
	return s;
}

} // namespace cgogn::io::detail
