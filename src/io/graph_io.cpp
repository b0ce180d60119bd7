// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/operators/graph.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/graph.h>

#include "file_io.h"
#include "formats.h"
#include "graph_data.h"
#include "text_reader.h"
#include "text_writer.h"

#include <algorithm>
#include <map>
#include <string_view>
#include <vector>

namespace cgogn::io
{

namespace
{

// The header `# D:3 NV:12 NE:11` (the colons read as blanks, keys in any order).
struct CgHeader
{
	uint32 dimension = 0, nb_vertices = 0, nb_edges = 0;
};

CgHeader read_cg_header(detail::TextReader& in)
{
	in.skip_space();
	std::string line(in.rest_of_line());
	std::replace(line.begin(), line.end(), ':', ' ');
	detail::TextReader header(line, in.path(), '\0', in.line());
	if (header.token() != "#")
		in.fail("expected the header '# D:3 NV:<vertices> NE:<edges>'");
	CgHeader h;
	bool seen[3] = {false, false, false};
	for (std::string_view key = header.token(); !key.empty(); key = header.token())
	{
		const int k = key == "D" ? 0 : key == "NV" ? 1 : key == "NE" ? 2 : -1;
		if (k < 0)
			header.fail("unknown header key '" + detail::TextReader::printable(key) + "' (expected D, NV and NE)");
		if (seen[k])
			header.fail("header key '" + std::string(key) + "' given twice");
		uint32& v = k == 0 ? h.dimension : k == 1 ? h.nb_vertices : h.nb_edges;
		v = header.read_uint(k == 0 ? "dimension" : k == 1 ? "number of vertices" : "number of edges");
		seen[k] = true;
	}
	if (!seen[0] || !seen[1] || !seen[2])
		in.fail("the header must give D, NV and NE ('# D:3 NV:<vertices> NE:<edges>')");
	if (h.dimension != 2 && h.dimension != 3)
		in.fail("dimension D:" + std::to_string(h.dimension) + " not supported (2 or 3)");
	in.next_line();
	return h;
}

detail::GraphData read_cg(std::string_view text, const std::string& path, bool with_radius, uint32 base)
{
	detail::TextReader in(text, path, '\0');
	const CgHeader h = read_cg_header(in);
	// "v 0 0\n" and "e 0 1\n": at least 6 bytes a line
	in.check_count(uint64(h.nb_vertices) + h.nb_edges, 6, "vertices and edges");
	detail::GraphData d;
	d.positions.reserve(h.nb_vertices);
	d.edges.reserve(h.nb_edges);
	// the next line that is not blank or a comment, and its first token
	auto next_record = [&]() -> std::string_view {
		while (true)
		{
			in.skip_space();
			std::string_view t = in.token_in_line();
			if (t.empty() || t[0] != '#')
				return t;
			in.next_line();
		}
	};
	for (uint32 i = 0; i < h.nb_vertices; ++i)
	{
		const std::string_view t = next_record();
		if (t != "v")
			in.fail("expected vertex " + std::to_string(i) + " of " + std::to_string(h.nb_vertices) + " ('v x y" +
					(h.dimension == 3 ? " z" : "") + (with_radius ? " r" : "") + "'), found '" +
					detail::TextReader::printable(t) + "'");
		Vec3 p = Vec3::Zero();
		for (uint32 k = 0; k < h.dimension; ++k)
			p[k] = in.to_double(in.token_in_line(), "a coordinate");
		d.positions.push_back(p);
		if (with_radius)
			d.radii.push_back(in.to_double(in.token_in_line(), "a radius"));
		in.next_line(); // further tokens are not ours
	}
	for (uint32 i = 0; i < h.nb_edges; ++i)
	{
		const std::string_view t = next_record();
		if (t != "e")
			in.fail("expected edge " + std::to_string(i) + " of " + std::to_string(h.nb_edges) + " ('e a b'), found '" +
					detail::TextReader::printable(t) + "'");
		uint32 ends[2];
		for (uint32& v : ends)
		{
			const int64 x = in.to_int(in.token_in_line(), "a vertex index");
			if (x < int64(base) || x - int64(base) >= int64(h.nb_vertices))
				in.fail("vertex index " + std::to_string(x) + " out of range (the file has " +
						std::to_string(h.nb_vertices) + " vertices, indexed from " + std::to_string(base) + ")");
			v = uint32(x - base);
		}
		// a comment may end the line
		if (const std::string_view rest = in.token_in_line(); !rest.empty() && rest[0] != '#')
			in.fail("unexpected '" + detail::TextReader::printable(rest) + "' after an edge");
		d.edges.emplace_back(ends[0], ends[1]);
		in.next_line();
	}
	if (!next_record().empty() || !in.at_end())
		in.fail("more lines than the header's NV:" + std::to_string(h.nb_vertices) +
				" NE:" + std::to_string(h.nb_edges));
	return d;
}

detail::GraphData read_skel(std::string_view text, const std::string& path)
{
	detail::TextReader in(text, path, '\0');
	in.next_line(); // a free header line
	const uint32 n = in.read_uint("the number of vertices");
	in.check_count(n, 12, "vertices");
	detail::GraphData d;
	d.positions.assign(n, Vec3::Zero());
	d.radii.assign(n, 0.0);
	std::vector<uint8> seen(n, 0);
	// how many times each end lists the other: {a, b} with a <= b
	std::map<std::pair<uint32, uint32>, std::pair<uint32, uint32>> listed;
	for (uint32 i = 0; i < n; ++i)
	{
		const uint32 id = in.read_uint("a vertex id");
		if (id >= n)
			in.fail("vertex id " + std::to_string(id) + " out of range (the file has " + std::to_string(n) +
					" vertices, ids from 0)");
		if (seen[id]++)
			in.fail("vertex id " + std::to_string(id) + " given twice");
		for (uint32 k = 0; k < 3; ++k)
			d.positions[id][k] = in.read_double("a coordinate");
		d.radii[id] = in.read_double("a radius");
		const uint32 k = in.read_uint("the number of neighbours");
		in.check_count(k, 2, "neighbours");
		for (uint32 j = 0; j < k; ++j)
		{
			const uint32 other = in.read_uint("a neighbour id");
			if (other >= n)
				in.fail("neighbour id " + std::to_string(other) + " out of range (the file has " + std::to_string(n) +
						" vertices)");
			auto& counts = listed[{std::min(id, other), std::max(id, other)}];
			(id <= other ? counts.first : counts.second)++;
		}
	}
	if (!in.at_end())
		in.fail("more data after the " + std::to_string(n) + " vertices");
	for (const auto& [ends, counts] : listed)
	{
		// an edge is listed by both its ends; a self-loop twice by its vertex
		uint32 times = std::max(counts.first, counts.second);
		if (ends.first == ends.second)
		{
			d.nb_one_sided_edges += counts.first % 2;
			times = (counts.first + 1) / 2;
		}
		else
			d.nb_one_sided_edges += std::max(counts.first, counts.second) - std::min(counts.first, counts.second);
		for (uint32 t = 0; t < times; ++t)
			d.edges.emplace_back(ends.first, ends.second);
	}
	return d;
}

// An OBJ polyline index: 1-based, or negative (relative to the last vertex
// defined so far); `v/vt` keeps the vertex.
uint32 obj_index(detail::TextReader& in, std::string_view t, uint32 nb_vertices)
{
	const std::size_t slash = t.find('/');
	const int64 i = in.to_int(t.substr(0, slash), "a vertex index");
	const int64 k = i < 0 ? int64(nb_vertices) + i : i - 1;
	if (i == 0 || k < 0 || k >= int64(nb_vertices))
		in.fail("vertex index " + std::to_string(i) + " out of range (" + std::to_string(nb_vertices) +
				" vertices defined so far)");
	return uint32(k);
}

detail::GraphData read_obj_lines(std::string_view text, const std::string& path)
{
	detail::TextReader in(text, path, '#');
	detail::GraphData d;
	std::vector<uint32> polyline;
	while (!in.at_end())
	{
		const std::string_view t = in.token_in_line();
		if (t == "v")
		{
			Vec3 p;
			for (uint32 k = 0; k < 3; ++k)
				p[k] = in.to_double(in.token_in_line(), "a coordinate");
			d.positions.push_back(p);
		}
		else if (t == "l")
		{
			polyline.clear();
			for (std::string_view x = in.token_in_line(); !x.empty(); x = in.token_in_line())
				polyline.push_back(obj_index(in, x, uint32(d.positions.size())));
			if (polyline.size() < 2)
				in.fail("a line ('l') needs at least 2 vertices");
			for (std::size_t i = 0; i + 1 < polyline.size(); ++i)
				d.edges.emplace_back(polyline[i], polyline[i + 1]);
		}
		else if (t == "f")
			++d.nb_faces_ignored;
		else if (t != "vt" && t != "vn" && t != "vp" && t != "o" && t != "g" && t != "s" && t != "usemtl" &&
				 t != "mtllib")
			in.fail("unknown OBJ statement '" + detail::TextReader::printable(t) + "'");
		in.next_line();
	}
	return d;
}

// The line and polyline cells of a VTK file (legacy or XML), read by the
// volume readers into MeshData::segments.
detail::GraphData read_vtk_lines(std::string_view text, const std::string& path, bool xml)
{
	const detail::MeshData m = xml ? detail::read_vtu(text, path) : detail::read_vtk(text, path);
	detail::GraphData d;
	d.positions.reserve(m.nb_vertices());
	for (uint32 i = 0; i < m.nb_vertices(); ++i)
		d.positions.emplace_back(m.positions[3 * i], m.positions[3 * i + 1], m.positions[3 * i + 2]);
	d.edges = m.segments;
	if (const detail::Column* r = m.find_vertex_column("radius"); r != nullptr && r->dim == 1)
		d.radii = r->values;
	d.nb_cells_ignored = m.nb_cells();
	return d;
}

} // namespace

namespace detail
{

GraphData read_graph(std::string_view text, const std::string& path, GraphFormat format, uint32 index_base)
{
	switch (format)
	{
	case GraphFormat::Cg:
		return read_cg(text, path, false, index_base);
	case GraphFormat::Cgr:
		return read_cg(text, path, true, index_base);
	case GraphFormat::Obj:
		return read_obj_lines(text, path);
	case GraphFormat::Vtk:
	case GraphFormat::Vtu:
		return read_vtk_lines(text, path, format == GraphFormat::Vtu);
	default:
		return read_skel(text, path);
	}
}

} // namespace detail

namespace
{

template <typename T>
void check_vertex_attribute(const Graph& g, const std::string& name, const std::string& path)
{
	auto a = container_of<Orbit::ALPHA1>(g).find(name);
	if (a != nullptr && a->type() != std::type_index(typeid(T)))
		throw Error(path, "the graph already has a vertex attribute '" + name +
							  "' of another type: cannot load the file's '" + name + "' into it");
}

} // namespace

namespace detail
{

GraphLoadReport build_graph(Graph& g, const GraphData& d, const std::string& path)
{
	check_vertex_attribute<Vec3>(g, "position", path);
	if (!d.radii.empty())
		check_vertex_attribute<double>(g, "radius", path);

	auto position = get_attribute<Vec3, Graph::Vertex>(g, "position");
	if (!position)
		position = add_attribute<Vec3, Graph::Vertex>(g, "position");
	std::shared_ptr<CellAttribute<double, Orbit::ALPHA1>> radius;
	if (!d.radii.empty())
	{
		radius = get_attribute<double, Graph::Vertex>(g, "radius");
		if (!radius)
			radius = add_attribute<double, Graph::Vertex>(g, "radius");
	}
	// edges get lines in the file's order, and save_graph writes them back so
	index_cells<Graph::Edge>(g);
	std::vector<Graph::Vertex> vertices;
	vertices.reserve(d.positions.size());
	for (std::size_t i = 0; i < d.positions.size(); ++i)
	{
		const Graph::Vertex v = add_vertex(g);
		value<Vec3>(g, position, v) = d.positions[i];
		if (radius)
			value<double>(g, radius, v) = d.radii[i];
		vertices.push_back(v);
	}
	for (const auto& [a, b] : d.edges)
		connect_vertices(g, vertices[a], vertices[b]);

	GraphLoadReport r;
	r.nb_vertices_read = uint32(d.positions.size());
	r.nb_edges_read = uint32(d.edges.size());
	r.radius = !d.radii.empty();
	r.nb_one_sided_edges = d.nb_one_sided_edges;
	r.nb_faces_ignored = d.nb_faces_ignored;
	r.nb_cells_ignored = d.nb_cells_ignored;
	return r;
}

} // namespace detail

GraphLoadReport load_graph(Graph& g, const std::string& path, const GraphLoadOptions& options)
{
	const std::string ext = detail::lower_extension(path);
	if (ext != "cg" && ext != "cgr" && ext != "skel" && ext != "obj" && ext != "vtk" && ext != "vtu")
		throw Error(path, "unknown graph format '." + ext + "' (.cg, .cgr, .skel, .obj, .vtk and .vtu are read)");
	if (options.index_base > 1)
		throw Error(path, "index_base must be 0 or 1");
	const std::string text = detail::read_file(path);
	const detail::GraphFormat format = ext == "cg"     ? detail::GraphFormat::Cg
									   : ext == "cgr"  ? detail::GraphFormat::Cgr
									   : ext == "skel" ? detail::GraphFormat::Skel
									   : ext == "vtk"  ? detail::GraphFormat::Vtk
									   : ext == "vtu"  ? detail::GraphFormat::Vtu
													   : detail::GraphFormat::Obj;
	return detail::build_graph(g, detail::read_graph(text, path, format, options.index_base), path);
}

void save_graph(const Graph& g, const std::string& path)
{
	const std::string ext = detail::lower_extension(path);
	if (ext != "cg" && ext != "cgr" && ext != "obj" && ext != "vtk" && ext != "vtu")
		throw Error(path, "cannot write graph format '." + ext + "' (.cg, .cgr, .obj, .vtk and .vtu are written)");
	const bool obj = ext == "obj";
	const auto position = get_attribute<Vec3, Graph::Vertex>(g, "position");
	if (!position)
		throw Error(path, "the graph has no Vec3 vertex attribute 'position'");
	std::shared_ptr<CellAttribute<double, Orbit::ALPHA1>> radius;
	if (ext == "cgr")
	{
		radius = get_attribute<double, Graph::Vertex>(g, "radius");
		if (!radius)
			throw Error(path, "a .cgr file needs the double vertex attribute 'radius'");
	}
	// vertices numbered in the order of their lines (the graph is indexed:
	// it has a vertex attribute), every vertex with one
	foreach_dart(g, [&](Dart d) {
		if (index_of(g, Graph::Vertex(d)) == INVALID_INDEX)
			throw Error(path, "a vertex has no index (made with set_indices = false: call index_cells)");
	});
	const AttributeContainer& lines = container_of<Orbit::ALPHA1>(g);
	std::vector<uint32> number(lines.end_index(), INVALID_INDEX);
	if (ext == "vtk" || ext == "vtu")
	{
		// points and one line cell per edge, radii as point data
		detail::MeshData m;
		if (!radius)
			radius = get_attribute<double, Graph::Vertex>(g, "radius");
		detail::Column radii{"radius", 1, {}};
		foreach_cell(g, [&](Graph::Vertex v) {
			number[index_of(g, v)] = m.nb_vertices();
			const Vec3& p = value<Vec3>(g, position, v);
			m.positions.insert(m.positions.end(), {p[0], p[1], p[2]});
			if (radius)
				radii.values.push_back(value<double>(g, radius, v));
		});
		if (radius)
			m.vertex_columns.push_back(std::move(radii));
		foreach_cell(g, [&](Graph::Edge e) {
			m.segments.emplace_back(number[index_of(g, Graph::Vertex(e.dart))],
									number[index_of(g, Graph::Vertex(alpha0(g, e.dart)))]);
		});
		detail::write_file(path, ext == "vtk" ? detail::write_vtk(m, false) : detail::write_vtu(m, false));
		return;
	}
	std::string s = obj ? std::string("# a graph: its vertices, and one line (l) per edge\n")
						: "# D:3 NV:" + std::to_string(nb_cells<Graph::Vertex>(g)) +
							  " NE:" + std::to_string(nb_cells<Graph::Edge>(g)) + "\n";
	// OBJ indices start at 1
	const uint32 first = obj ? 1 : 0;
	uint32 n = 0;
	foreach_cell(g, [&](Graph::Vertex v) {
		number[index_of(g, v)] = first + n++;
		const Vec3& p = value<Vec3>(g, position, v);
		s += 'v';
		for (uint32 k = 0; k < 3; ++k)
		{
			s += ' ';
			detail::append_double(s, p[k]);
		}
		if (radius)
		{
			s += ' ';
			detail::append_double(s, value<double>(g, radius, v));
		}
		s += '\n';
	});
	auto number_of = [&](Dart d) { return number[index_of(g, Graph::Vertex(d))]; };
	foreach_cell(g, [&](Graph::Edge e) {
		s += obj ? "l " : "e ";
		detail::append_uint(s, number_of(e.dart));
		s += ' ';
		detail::append_uint(s, number_of(alpha0(g, e.dart)));
		s += '\n';
	});
	detail::write_file(path, s);
}

} // namespace cgogn::io
