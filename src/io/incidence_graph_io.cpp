// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/operators/incidence_graph.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_incidence_graph.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/incidence_graph.h>

#include "file_io.h"
#include "incidence_graph_data.h"
#include "text_reader.h"
#include "text_writer.h"

#include <algorithm>
#include <vector>

namespace cgogn::io
{

namespace detail
{

IgData read_ig(std::string_view text, const std::string& path)
{
	detail::TextReader in(text, path, '#');
	in.skip_blank();
	if (in.token() != "IG")
		in.fail("expected the header 'IG <vertices> <edges> <faces>'");
	const uint32 nv = in.read_uint("the number of vertices");
	const uint32 ne = in.read_uint("the number of edges");
	const uint32 nf = in.read_uint("the number of faces");
	// "v 0 0 0\n", "e 0 1\n", "f 3 0 1 2\n": at least 6 bytes a line
	in.check_count(uint64(nv) + ne + nf, 6, "vertices, edges and faces");
	IgData d;
	d.positions.reserve(nv);
	d.edges.reserve(ne);
	d.face_sizes.reserve(nf);
	auto expect = [&](std::string_view tag, uint32 i, uint32 n, const char* what) {
		const std::string_view t = in.token();
		if (t != tag)
			in.fail("expected " + std::string(what) + " " + std::to_string(i) + " of " + std::to_string(n) + " ('" +
					std::string(tag) + " ...'), found '" + detail::TextReader::printable(t) + "'");
	};
	auto index = [&](uint32 bound, const char* what) {
		const int64 x = in.to_int(in.token_in_line(), what);
		if (x < 0 || x >= int64(bound))
			in.fail(std::string(what) + " " + std::to_string(x) + " out of range (the file has " +
					std::to_string(bound) + ")");
		return uint32(x);
	};
	for (uint32 i = 0; i < nv; ++i)
	{
		expect("v", i, nv, "vertex");
		Vec3 p;
		for (uint32 k = 0; k < 3; ++k)
			p[k] = in.to_double(in.token_in_line(), "a coordinate");
		d.positions.push_back(p);
		in.next_line();
	}
	for (uint32 i = 0; i < ne; ++i)
	{
		expect("e", i, ne, "edge");
		const uint32 a = index(nv, "vertex index"), b = index(nv, "vertex index");
		if (a == b)
			in.fail("edge " + std::to_string(i) + " joins vertex " + std::to_string(a) + " to itself");
		d.edges.push_back({a, b});
		in.next_line();
	}
	std::vector<uint32> vertices;
	for (uint32 i = 0; i < nf; ++i)
	{
		expect("f", i, nf, "face");
		const uint32 k = in.to_uint(in.token_in_line(), "the number of edges of a face");
		if (k < 3)
			in.fail("face " + std::to_string(i) + " has " + std::to_string(k) + " edges (at least 3)");
		in.check_count(k, 2, "face edges");
		const std::size_t first = d.face_edges.size();
		for (uint32 j = 0; j < k; ++j)
			d.face_edges.push_back(index(ne, "edge index"));
		// a simple cycle in the order given: e_1 toward the vertex it shares with e_2
		const auto& e0 = d.edges[d.face_edges[first]];
		const auto& e1 = d.edges[d.face_edges[first + 1]];
		const bool backward = e0[0] == e1[0] || e0[0] == e1[1];
		uint32 at = backward ? e0[0] : e0[1];
		vertices.assign(1, backward ? e0[1] : e0[0]);
		for (uint32 j = 1; j < k; ++j)
		{
			const auto& e = d.edges[d.face_edges[first + j]];
			if (e[0] != at && e[1] != at)
				in.fail("face " + std::to_string(i) + ": edge " + std::to_string(d.face_edges[first + j]) +
						" does not continue the cycle (the edges must be listed in cycle order)");
			vertices.push_back(at);
			at = e[0] == at ? e[1] : e[0];
		}
		if (at != vertices[0])
			in.fail("face " + std::to_string(i) + ": its edges do not close a cycle");
		std::sort(vertices.begin(), vertices.end());
		if (std::adjacent_find(vertices.begin(), vertices.end()) != vertices.end())
			in.fail("face " + std::to_string(i) + ": its cycle meets a vertex twice (not a simple cycle)");
		d.face_sizes.push_back(k);
		if (!in.at_eol())
			in.fail("unexpected '" + detail::TextReader::printable(in.token_in_line()) + "' after face " +
					std::to_string(i));
		in.next_line();
	}
	in.skip_blank();
	if (!in.at_end())
		in.fail("more lines than the header's " + std::to_string(nv) + " vertices, " + std::to_string(ne) +
				" edges and " + std::to_string(nf) + " faces");
	return d;
}

IncidenceGraphLoadReport build_incidence_graph(IncidenceGraph& ig, const IgData& d, const std::string& path)
{
	auto pos = get_attribute<Vec3, IncidenceGraph::Vertex>(ig, "position");
	if (!pos && container_of<Orbit::IG_VERTEX>(ig).find("position") != nullptr)
		throw Error(path, "the incidence graph has a vertex attribute 'position' of another type");
	if (uint64(d.positions.size()) + container_of<Orbit::IG_VERTEX>(ig).end_index() >= INVALID_INDEX - 1 ||
		uint64(d.edges.size()) + container_of<Orbit::IG_EDGE>(ig).end_index() >= INVALID_INDEX ||
		uint64(d.face_edges.size()) + container_of<Orbit::DART>(ig).end_index() >= INVALID_INDEX)
		throw Error(path, "the complex is too large for 32-bit indices");
	if (!pos)
		pos = add_attribute<Vec3, IncidenceGraph::Vertex>(ig, "position");
	std::vector<IncidenceGraph::Vertex> vertex;
	vertex.reserve(d.positions.size());
	for (const Vec3& p : d.positions)
	{
		vertex.push_back(add_vertex(ig));
		value<Vec3>(ig, pos, vertex.back()) = p;
	}
	std::vector<IncidenceGraph::Edge> edge;
	edge.reserve(d.edges.size());
	for (const auto& [a, b] : d.edges)
		edge.push_back(add_edge(ig, vertex[a], vertex[b]));
	std::vector<IncidenceGraph::Edge> sides;
	std::size_t k = 0;
	for (uint32 n : d.face_sizes)
	{
		sides.clear();
		for (uint32 j = 0; j < n; ++j)
			sides.push_back(edge[d.face_edges[k + j]]);
		k += n;
		add_face(ig, sides); // checked by read_ig: cannot throw
	}
	return {uint32(d.positions.size()), uint32(d.edges.size()), uint32(d.face_sizes.size())};
}

} // namespace detail

IncidenceGraphLoadReport load_incidence_graph(IncidenceGraph& ig, const std::string& path)
{
	return detail::build_incidence_graph(ig, detail::read_ig(detail::read_file(path), path), path);
}

void save_incidence_graph(const IncidenceGraph& ig, const std::string& path)
{
	auto pos = get_attribute<Vec3, IncidenceGraph::Vertex>(ig, "position");
	if (!pos)
		throw Error(path, "the incidence graph has no Vec3 vertex attribute 'position' to write");
	std::vector<uint32> vertex_id(container_of<Orbit::IG_VERTEX>(ig).end_index(), INVALID_INDEX);
	std::vector<uint32> edge_id(container_of<Orbit::IG_EDGE>(ig).end_index(), INVALID_INDEX);
	std::string out = "IG ";
	detail::append_uint(out, nb_cells<IncidenceGraph::Vertex>(ig));
	out += ' ';
	detail::append_uint(out, nb_cells<IncidenceGraph::Edge>(ig));
	out += ' ';
	detail::append_uint(out, nb_cells<IncidenceGraph::Face>(ig));
	out += '\n';
	uint32 n = 0;
	foreach_cell(ig, [&](IncidenceGraph::Vertex v) {
		vertex_id[v.dart.index] = n++;
		const Vec3& p = value<Vec3>(ig, pos, v);
		out += "v ";
		for (uint32 k = 0; k < 3; ++k)
		{
			detail::append_double(out, p[k]);
			out += k < 2 ? ' ' : '\n';
		}
	});
	n = 0;
	foreach_cell(ig, [&](IncidenceGraph::Edge e) {
		edge_id[e.dart.index] = n++;
		out += "e ";
		detail::append_uint(out, vertex_id[first_vertex(ig, e).dart.index]);
		out += ' ';
		detail::append_uint(out, vertex_id[second_vertex(ig, e).dart.index]);
		out += '\n';
	});
	foreach_cell(ig, [&](IncidenceGraph::Face f) {
		out += "f ";
		uint32 k = 0;
		foreach_incident_edge(ig, f, [&](IncidenceGraph::Edge) { ++k; });
		detail::append_uint(out, k);
		foreach_incident_edge(ig, f, [&](IncidenceGraph::Edge e) {
			out += ' ';
			detail::append_uint(out, edge_id[e.dart.index]);
		});
		out += '\n';
	});
	detail::write_file(path, out);
}

} // namespace cgogn::io
