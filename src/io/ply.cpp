// SPDX-License-Identifier: MIT
// PLY: ascii, binary little and big endian, any property layout. Vertex
// properties x, y, z are the position; face list `vertex_indices` (or
// `vertex_index`) the polygons. Other scalar properties of vertices and faces
// become columns: nx ny nz -> `normal`, red green blue -> `color`, u v (or s t,
// texture_u texture_v) -> `tex_coord`, name_x name_y [name_z] -> Vec2/Vec3
// `name`, anything else -> a scalar column of its name. A face list
// `texcoord` (MeshLab's u v per corner) -> the corner column `tex_coord`.
// Other elements and list properties are read and reported as not loaded.
#include "byte_reader.h"
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace cgogn::io::detail
{

namespace
{

enum class PType : uint8
{
	Int8,
	UInt8,
	Int16,
	UInt16,
	Int32,
	UInt32,
	Float32,
	Float64
};

// Each PLY scalar type: its names, its size in a binary file and the type
// of the column a scalar property of it gives (floats: Float64). By PType.
struct PlyType
{
	PType type;
	std::string_view name, alias;
	uint32 size;
	ValueType column;
};
constexpr PlyType PLY_TYPES[] = {{PType::Int8, "char", "int8", 1, ValueType::Int8},
								 {PType::UInt8, "uchar", "uint8", 1, ValueType::UInt8},
								 {PType::Int16, "short", "int16", 2, ValueType::Int16},
								 {PType::UInt16, "ushort", "uint16", 2, ValueType::UInt16},
								 {PType::Int32, "int", "int32", 4, ValueType::Int32},
								 {PType::UInt32, "uint", "uint32", 4, ValueType::UInt32},
								 {PType::Float32, "float", "float32", 4, ValueType::Float64},
								 {PType::Float64, "double", "float64", 8, ValueType::Float64}};

const PlyType& ply_type(PType t)
{
	return PLY_TYPES[uint32(t)];
}

std::optional<PType> parse_type(std::string_view t)
{
	for (const PlyType& p : PLY_TYPES)
		if (t == p.name || t == p.alias)
			return p.type;
	return std::nullopt;
}

uint32 type_size(PType t)
{
	return ply_type(t).size;
}

bool is_integer(PType t)
{
	return t != PType::Float32 && t != PType::Float64;
}

struct Property
{
	std::string name;
	PType type = PType::Float32;
	bool is_list = false;
	PType count_type = PType::UInt8;
	// where a scalar goes: -1 nowhere, -2 position (a list: the face's
	// vertices), -3 (a face list) the per-corner texture coordinates, else a
	// column
	int column = -1;
	uint32 component = 0;
	uint64 header_line = 0;
};

struct Element
{
	std::string name;
	uint64 count = 0;
	std::vector<Property> props;
	uint64 header_line = 0;
};

double read_binary(ByteReader& b, PType t)
{
	switch (t)
	{
	case PType::Int8:
		return b.read<int8>();
	case PType::UInt8:
		return b.read<uint8>();
	case PType::Int16:
		return b.read<int16_t>();
	case PType::UInt16:
		return b.read<uint16>();
	case PType::Int32:
		return b.read<int32>();
	case PType::UInt32:
		return b.read<uint32>();
	case PType::Float32:
		return b.read<float>();
	case PType::Float64:
		return b.read<double>();
	}
	return 0.0;
}

// The column type of a scalar property of type t.
ValueType value_type(PType t)
{
	return ply_type(t).column;
}

// Groups the scalar properties of an element into columns (see the file
// comment). A scalar property whose column name is taken by a group (`normal`
// beside nx ny nz, `foo` beside foo_x foo_y) or reserved (data_name_conflict)
// is an error at its header line: it would collide with that attribute.
void assign_columns(Element& e, std::vector<Column>& cols, bool is_vertex, const std::string& path)
{
	auto find = [&](std::string_view n) -> Property* {
		for (auto& p : e.props)
			if (!p.is_list && p.column == -1 && p.name == n)
				return &p;
		return nullptr;
	};
	auto group = [&](const std::string& col, std::initializer_list<std::string_view> names) {
		std::vector<Property*> ps;
		for (auto n : names)
		{
			Property* p = find(n);
			if (!p)
				return;
			ps.push_back(p);
		}
		for (const auto& c : cols)
			if (c.name == col)
				return; // a group of this name exists: these properties stay scalars
		if (std::string why = data_name_conflict({}, col, is_vertex); !why.empty())
			throw Error(path, Error::Where::Line, ps[0]->header_line,
						"property '" + ps[0]->name + "' of element '" + e.name + "': " + why);
		cols.push_back(Column{col, uint32(ps.size()), {}});
		for (uint32 k = 0; k < ps.size(); ++k)
		{
			ps[k]->column = int(cols.size() - 1);
			ps[k]->component = k;
		}
	};
	if (is_vertex)
	{
		static constexpr std::string_view xyz[3] = {"x", "y", "z"};
		for (uint32 k = 0; k < 3; ++k)
			if (Property* p = find(xyz[k]))
			{
				p->column = -2;
				p->component = k;
			}
	}
	group("normal", {"nx", "ny", "nz"});
	group("color", {"red", "green", "blue"});
	group("tex_coord", {"u", "v"});
	group("tex_coord", {"s", "t"});
	group("tex_coord", {"texture_u", "texture_v"});
	for (auto& p : e.props)
	{
		if (p.is_list || p.column != -1 || p.name.size() < 3 || p.name.substr(p.name.size() - 2) != "_x")
			continue;
		const std::string base = p.name.substr(0, p.name.size() - 2);
		if (find(base + "_z"))
			group(base, {base + "_x", base + "_y", base + "_z"});
		else
			group(base, {base + "_x", base + "_y"});
	}
	std::vector<std::string> names;
	for (const auto& c : cols)
		names.push_back(c.name);
	for (auto& p : e.props)
	{
		if (p.is_list || p.column != -1)
			continue;
		if (std::string why = data_name_conflict(names, p.name, is_vertex); !why.empty())
			throw Error(path, Error::Where::Line, p.header_line,
						"property '" + p.name + "' of element '" + e.name + "': " + why);
		names.push_back(p.name);
		cols.push_back(Column{p.name, 1, {}, value_type(p.type)});
		p.column = int(cols.size() - 1);
	}
}

} // namespace

MeshData read_ply(std::string_view data, const std::string& path)
{
	// ---- header
	const std::size_t end_header = data.find("end_header");
	if (data.substr(0, 3) != "ply")
		throw Error(path, Error::Where::Line, 1, "not a PLY file: it does not start with 'ply'");
	if (end_header == std::string_view::npos)
		throw Error(path, "PLY header without 'end_header'");
	std::size_t body = end_header + 10;
	if (body < data.size() && data[body] == '\r')
		++body;
	if (body < data.size() && data[body] == '\n')
		++body;
	TextReader h(data.substr(0, end_header), path, '\0');
	h.next_line();
	int format = -1; // 0 ascii, 1 little endian, 2 big endian
	std::vector<Element> elements;
	while (!h.at_end())
	{
		std::string_view k = h.token_in_line();
		if (k == "format")
		{
			std::string_view f = h.token_in_line();
			if (f == "ascii")
				format = 0;
			else if (f == "binary_little_endian")
				format = 1;
			else if (f == "binary_big_endian")
				format = 2;
			else
				h.fail("unknown PLY format '" + TextReader::printable(f) + "'");
			h.rest_of_line();
		}
		else if (k == "comment" || k == "obj_info")
			h.rest_of_line();
		else if (k == "element")
		{
			Element e;
			e.name = std::string(h.token_in_line());
			for (const auto& f : elements)
				if (f.name == e.name && (e.name == "vertex" || e.name == "face"))
					h.fail("element '" + TextReader::printable(e.name) + "' declared twice");
			const int64 c = h.to_int(h.token_in_line(), "an element count");
			if (c < 0)
				h.fail("negative element count");
			e.count = uint64(c);
			e.header_line = h.line();
			elements.push_back(std::move(e));
		}
		else if (k == "property")
		{
			if (elements.empty())
				h.fail("property before any element");
			Property p;
			std::string_view t = h.token_in_line();
			if (t == "list")
			{
				p.is_list = true;
				std::string_view ct = h.token_in_line();
				auto c = parse_type(ct);
				if (!c || !is_integer(*c))
					h.fail("bad list count type '" + TextReader::printable(ct) + "'");
				p.count_type = *c;
				t = h.token_in_line();
			}
			auto ty = parse_type(t);
			if (!ty)
				h.fail("unknown property type '" + TextReader::printable(t) + "'");
			p.type = *ty;
			p.name = std::string(h.token_in_line());
			if (p.name.empty())
				h.fail("property without a name");
			for (const auto& q : elements.back().props)
				if (q.name == p.name)
					h.fail("element '" + TextReader::printable(elements.back().name) + "' has two properties named '" +
						   TextReader::printable(p.name) + "'");
			p.header_line = h.line();
			elements.back().props.push_back(std::move(p));
		}
		else if (k.empty())
		{
		}
		else
			h.fail("unknown PLY header keyword '" + TextReader::printable(k) + "'");
		if (!h.at_eol())
			h.fail("unexpected '" + TextReader::printable(h.token_in_line()) + "' in the header");
	}
	if (format < 0)
		throw Error(path, "PLY header without a 'format' line");

	MeshData d;
	uint64 nv = 0;
	bool have_vertex = false;
	for (auto& e : elements)
	{
		if (e.name == "vertex")
		{
			have_vertex = true;
			nv = e.count;
			assign_columns(e, d.vertex_columns, true, path);
			int found = 0;
			for (const auto& p : e.props)
				found += p.column == -2;
			if (found != 3)
				throw Error(path, Error::Where::Line, e.header_line, "the vertex element lacks x, y or z");
		}
		else if (e.name == "face")
		{
			assign_columns(e, d.cell_columns, false, path);
			bool found = false;
			for (auto& p : e.props)
				if (p.is_list && (p.name == "vertex_indices" || p.name == "vertex_index") && !found)
				{
					p.column = -2;
					found = true;
				}
			if (!found)
				throw Error(path, Error::Where::Line, e.header_line, "the face element has no vertex_indices list");
			for (auto& p : e.props)
				if (p.is_list && p.name == "texcoord" && !is_integer(p.type))
					p.column = -3; // MeshLab's per-corner u v pairs
		}
		else
			d.dropped.push_back("PLY element '" + e.name + "' (" + std::to_string(e.count) +
								"): vertices and faces are loaded");
		if (e.name == "vertex" || e.name == "face")
			for (const auto& p : e.props)
				if (p.is_list && p.column == -1)
					d.dropped.push_back("PLY list property '" + p.name + "' of the " + e.name + " element");
	}
	if (!have_vertex)
		throw Error(path, "PLY file without a vertex element");

	// ---- body
	std::vector<double> texcoords;       // the faces' texcoord lists, one after the other
	std::vector<uint32> texcoord_counts; // and their lengths
	auto face_index = [&](auto& reader, double v) {
		if (!(v >= 0.0) || v >= double(nv) || v != std::floor(v))
			reader.fail("vertex index " + std::to_string(int64(v)) + " out of range (the file has " +
						std::to_string(nv) + " vertices)");
		d.cell_vertices.push_back(uint32(v));
	};
	auto prepare = [&](Element& e, auto& reader, uint64 min_bytes) {
		reader.check_count(e.count, std::max<uint64>(min_bytes, 1), (e.name + " elements").c_str());
		std::vector<Column>* cols = e.name == "vertex" ? &d.vertex_columns
									: e.name == "face" ? &d.cell_columns
													   : nullptr;
		if (cols)
			for (auto& c : *cols)
				c.values.reserve(e.count * c.dim);
		if (e.name == "vertex")
			d.positions.resize(3 * e.count);
		if (e.name == "face")
			d.cell_sizes.reserve(e.count);
		return cols;
	};
	if (format == 0)
	{
		// line numbers continue the header's
		TextReader r(data.substr(body), path, '\0',
					 1 + uint64(std::count(data.begin(), data.begin() + std::ptrdiff_t(body), '\n')));
		for (auto& e : elements)
		{
			std::vector<Column>* cols = prepare(e, r, 2 * std::max<std::size_t>(e.props.size(), 1));
			const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
			for (uint64 i = 0; i < e.count; ++i)
			{
				for (const auto& p : e.props)
				{
					if (p.is_list)
					{
						const int64 n = r.read_int("a list count");
						if (n < 0 || uint64(n) > r.remaining() / 2)
							r.fail("bad list count " + std::to_string(n));
						if (is_face && p.column == -2)
						{
							d.cell_sizes.push_back(uint32(n));
							for (int64 j = 0; j < n; ++j)
								face_index(r, double(r.read_int("a vertex index")));
						}
						else if (is_face && p.column == -3)
						{
							texcoord_counts.push_back(uint32(n));
							for (int64 j = 0; j < n; ++j)
								texcoords.push_back(r.read_double("a texture coordinate"));
						}
						else
							for (int64 j = 0; j < n; ++j)
								r.read_double("a list value");
						continue;
					}
					const double v =
						is_integer(p.type) ? double(r.read_int("an integer value")) : r.read_double("a property value");
					if (p.column == -2 && is_vertex)
						d.positions[3 * i + p.component] = v;
					else if (p.column >= 0 && cols)
						(*cols)[std::size_t(p.column)].values.push_back(v);
				}
			}
		}
		if (!r.at_end())
			r.fail("unexpected content after the declared elements");
	}
	else
	{
		ByteReader b(data, body, path, format == 2);
		for (auto& e : elements)
		{
			uint64 min_bytes = 0;
			for (const auto& p : e.props)
				min_bytes += p.is_list ? type_size(p.count_type) : type_size(p.type);
			std::vector<Column>* cols = prepare(e, b, min_bytes);
			const bool is_vertex = e.name == "vertex", is_face = e.name == "face";
			for (uint64 i = 0; i < e.count; ++i)
			{
				for (const auto& p : e.props)
				{
					if (p.is_list)
					{
						const double n = read_binary(b, p.count_type);
						if (n < 0 || n > double(b.remaining() / type_size(p.type)))
							b.fail("bad list count " + std::to_string(int64(n)));
						const uint32 k = uint32(n);
						if (is_face && p.column == -2)
						{
							d.cell_sizes.push_back(k);
							for (uint32 j = 0; j < k; ++j)
								face_index(b, read_binary(b, p.type));
						}
						else if (is_face && p.column == -3)
						{
							texcoord_counts.push_back(k);
							for (uint32 j = 0; j < k; ++j)
							{
								texcoords.push_back(read_binary(b, p.type));
								if (!std::isfinite(texcoords.back()))
									b.fail("a texture coordinate is not finite");
							}
						}
						else
							b.skip(std::size_t(k) * type_size(p.type));
						continue;
					}
					const double v = read_binary(b, p.type);
					if (!std::isfinite(v))
						b.fail("property '" + p.name + "' is not finite: NaN and infinite values are rejected");
					if (p.column == -2 && is_vertex)
						d.positions[3 * i + p.component] = v;
					else if (p.column >= 0 && cols)
						(*cols)[std::size_t(p.column)].values.push_back(v);
				}
			}
		}
		if (b.remaining() != 0)
			b.fail("unexpected " + std::to_string(b.remaining()) + " bytes after the declared elements");
	}
	if (!texcoord_counts.empty())
	{
		for (uint32 f = 0; f < d.nb_cells(); ++f)
			if (texcoord_counts[f] != 2 * d.cell_sizes[f])
				throw Error(path, "face " + std::to_string(f) + " has " + std::to_string(texcoord_counts[f]) +
									  " texcoord values for " + std::to_string(d.cell_sizes[f]) +
									  " corners (2 per corner)");
		d.corner_columns.push_back(Column{"tex_coord", 2, std::move(texcoords)});
	}
	return d;
}

namespace
{

bool byte_valued(const Column& c)
{
	return std::all_of(c.values.begin(), c.values.end(),
					   [](double v) { return v >= 0.0 && v <= 255.0 && v == std::floor(v); });
}

// Header lines and per-element writers for a list of columns: each value
// is written as a byte (colours of 0 to 255), as a double, or as the integer
// type of its column.
struct ColumnLayout
{
	const Column* col;
	bool as_byte;
	std::optional<PType> integer; // the PLY integer type of an integer column
};

// The PLY type that writes the integer column c exactly: its own, or for
// 64-bit values (PLY has no 64-bit integers) int or uint when they fit;
// nullopt (written as double, exactly: see Column) when none does.
std::optional<PType> ply_integer_type(const Column& c)
{
	if (!is_integer_type(c.type))
		return std::nullopt;
	for (const PlyType& p : PLY_TYPES)
		if (p.column == c.type)
			return p.type;
	const auto [lo, hi] = std::minmax_element(c.values.begin(), c.values.end());
	const bool empty = lo == c.values.end();
	if (c.type == ValueType::Int64 && (empty || (*lo >= -2147483648.0 && *hi <= 2147483647.0)))
		return PType::Int32;
	if (c.type == ValueType::UInt64 && (empty || *hi <= 4294967295.0))
		return PType::UInt32;
	return std::nullopt;
}

// A property name of an element and what it writes, to refuse a second use.
struct PropertyOwner
{
	std::string property;
	std::string owner;
};

// `owners` holds the element's properties written before the columns (x y z,
// vertex_indices); a column whose property name is taken throws io::Error, as
// the file would not read back.
std::vector<ColumnLayout> layout(const std::vector<Column>& cols, std::string& header, const char* element,
								 std::vector<PropertyOwner> owners, const std::string& path)
{
	std::vector<ColumnLayout> out;
	for (const auto& c : cols)
	{
		if (c.dim < 1 || c.dim > 3)
			continue;
		const bool as_byte = c.name == "color" && c.dim == 3 && byte_valued(c);
		const std::optional<PType> integer = c.dim == 1 ? ply_integer_type(c) : std::nullopt;
		const std::string_view type = as_byte ? "uchar" : integer ? ply_type(*integer).name : "double";
		auto prop = [&](const std::string& n) {
			for (const auto& o : owners)
				if (o.property == n)
					throw Error(path, std::string("cannot write the ") + element + " attribute '" + c.name +
										  "' as the PLY property '" + n + "': " + o.owner + " uses that name");
			owners.push_back({n, "the " + std::string(element) + " attribute '" + c.name + "'"});
			header += "property ";
			header += type;
			header += ' ';
			header += n;
			header += '\n';
		};
		if (c.name == "normal" && c.dim == 3)
			for (auto n : {"nx", "ny", "nz"})
				prop(n);
		else if (c.name == "color" && c.dim == 3)
			for (auto n : {"red", "green", "blue"})
				prop(n);
		else if (c.name == "tex_coord" && c.dim == 2)
			for (auto n : {"u", "v"})
				prop(n);
		else if (c.dim == 1)
			prop(c.name);
		else
			for (uint32 k = 0; k < c.dim; ++k)
				prop(c.name + (k == 0 ? "_x" : k == 1 ? "_y" : "_z"));
		out.push_back({&c, as_byte, integer});
	}
	return out;
}

void put_columns(std::string& s, const std::vector<ColumnLayout>& cols, std::size_t i, bool binary)
{
	for (const auto& l : cols)
		for (uint32 k = 0; k < l.col->dim; ++k)
		{
			const double v = l.col->values[i * l.col->dim + k];
			if (l.integer && binary)
				visit_value_type(value_type(*l.integer), [&]<typename T>() { append_raw(s, T(v)); });
			else if (l.integer)
			{
				s += ' ';
				append_int(s, int64(v));
			}
			else if (binary)
			{
				if (l.as_byte)
					s.push_back(char(uint8(v)));
				else
					append_raw(s, v);
			}
			else
			{
				s += ' ';
				append_double(s, v);
			}
		}
}

} // namespace

std::string write_ply(const MeshData& d, bool binary, const std::string& path)
{
	std::string s = "ply\nformat ";
	s += binary ? "binary_little_endian 1.0\n" : "ascii 1.0\n";
	s += "comment written by cgogn\nelement vertex ";
	append_uint(s, d.nb_vertices());
	s += "\nproperty double x\nproperty double y\nproperty double z\n";
	auto vcols = layout(d.vertex_columns, s, "vertex",
						{{"x", "the position"}, {"y", "the position"}, {"z", "the position"}}, path);
	uint32 max_degree = 0;
	for (uint32 n : d.cell_sizes)
		max_degree = std::max(max_degree, n);
	const bool byte_count = max_degree < 256;
	s += "element face ";
	append_uint(s, d.nb_cells());
	s += byte_count ? "\nproperty list uchar int vertex_indices\n" : "\nproperty list int int vertex_indices\n";
	// per-corner texture coordinates: MeshLab's face list `texcoord`
	const Column* texcoord = nullptr;
	for (const Column& c : d.corner_columns)
		if (c.name == "tex_coord" && c.dim == 2)
			texcoord = &c;
	const bool texcoord_byte_count = 2 * max_degree < 256;
	if (texcoord)
		s += texcoord_byte_count ? "property list uchar double texcoord\n" : "property list int double texcoord\n";
	auto fcols =
		layout(d.cell_columns, s, "face",
			   {{"vertex_indices", "the face's vertex list"}, {"texcoord", "the corners' texture coordinates"}}, path);
	s += "end_header\n";
	s.reserve(s.size() + std::size_t(d.nb_vertices()) * (binary ? 24 : 40) + d.cell_vertices.size() * 8);
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
	{
		for (uint32 k = 0; k < 3; ++k)
		{
			const double x = d.positions[3 * std::size_t(v) + k];
			if (binary)
				append_raw(s, x);
			else
			{
				if (k > 0)
					s += ' ';
				append_double(s, x);
			}
		}
		put_columns(s, vcols, v, binary);
		if (!binary)
			s += '\n';
	}
	std::size_t k = 0;
	for (uint32 f = 0; f < d.nb_cells(); ++f)
	{
		const uint32 n = d.cell_sizes[f];
		if (binary)
		{
			if (byte_count)
				s.push_back(char(uint8(n)));
			else
				append_raw(s, int32(n));
			for (uint32 i = 0; i < n; ++i)
				append_raw(s, int32(d.cell_vertices[k++]));
		}
		else
		{
			append_uint(s, n);
			for (uint32 i = 0; i < n; ++i)
			{
				s += ' ';
				append_uint(s, d.cell_vertices[k++]);
			}
		}
		if (texcoord)
		{
			const double* uv = texcoord->values.data() + 2 * (k - n);
			if (binary)
			{
				if (texcoord_byte_count)
					s.push_back(char(uint8(2 * n)));
				else
					append_raw(s, int32(2 * n));
				for (uint32 i = 0; i < 2 * n; ++i)
					append_raw(s, uv[i]);
			}
			else
			{
				s += ' ';
				append_uint(s, 2 * n);
				for (uint32 i = 0; i < 2 * n; ++i)
				{
					s += ' ';
					append_double(s, uv[i]);
				}
			}
		}
		put_columns(s, fcols, f, binary);
		if (!binary)
			s += '\n';
	}
	return s;
}

} // namespace cgogn::io::detail
