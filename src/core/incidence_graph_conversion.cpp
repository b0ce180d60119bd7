// SPDX-License-Identifier: MIT
// Incidence graphs to and from 2-maps, and their 1-skeleton as a graph.
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/operators/graph.h>
#include <cgogn/core/operators/incidence_graph.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/utils/error.h>

#include "attribute_copy.h"
#include "incidence_graph_records.h"

#include <algorithm>
#include <vector>

namespace cgogn
{

namespace
{

// Copies the attributes of orbit FROM of `from` into the container of orbit
// TO of `to`, line i going to line_of[i] (INVALID_INDEX: nowhere).
template <Orbit FROM, Orbit TO>
void copy_lines(const CMapBase& from, CMapBase& to, const std::vector<uint32>& line_of)
{
	detail::copy_attributes(container_of<FROM>(from), container_of<TO>(to), [&](uint32 i, const auto& put) {
		if (i < line_of.size() && line_of[i] != INVALID_INDEX)
			put(line_of[i]);
	});
}

// True when the container holds an attribute of the user's (not the key, not a "__" one).
bool has_user_attributes(const AttributeContainer& c)
{
	for (const auto& a : c.attributes())
		if (a.get() != &c.key() && a->name().rfind("__", 0) != 0)
			return true;
	return false;
}

} // namespace

IncidenceGraph to_incidence_graph(const CMap2& m)
{
	using V = CMap2::Vertex;
	using E = CMap2::Edge;
	using F = CMap2::Face;
	IncidenceGraph ig;
	const detail::IgRecords r(ig);
	std::vector<uint32> vertex_of(container_of<Orbit::DART>(m).end_index(), INVALID_INDEX);
	std::vector<uint32> vertex_line(container_of<V::ORBIT>(m).end_index(), INVALID_INDEX);
	foreach_cell(m, [&](V v) {
		const uint32 w = add_vertex(ig).dart.index;
		foreach_dart_of_orbit(m, v, [&](Dart d) { vertex_of[d.index] = w; });
		if (is_indexed<V>(m))
			vertex_line[index_of(m, v)] = w;
	});
	// the side (edge end) of each dart of m
	std::vector<uint32> side_of(vertex_of.size(), INVALID_INDEX);
	std::vector<uint32> edge_line(container_of<E::ORBIT>(m).end_index(), INVALID_INDEX);
	foreach_cell(m, [&](E e) {
		const Dart d = e.dart, d2 = phi2(m, d);
		if (vertex_of[d.index] == vertex_of[d2.index])
			throw TopologyError("to_incidence_graph: an edge has the same vertex at both ends");
		const uint32 x = add_edge(ig, IncidenceGraph::Vertex(Dart(vertex_of[d.index])),
								  IncidenceGraph::Vertex(Dart(vertex_of[d2.index])))
							 .dart.index;
		side_of[d.index] = 2 * x;
		side_of[d2.index] = 2 * x + 1;
		if (is_indexed<E>(m))
			edge_line[index_of(m, e)] = x;
	});
	const bool faces_indexed = is_indexed<F>(m);
	if (faces_indexed)
		index_cells<IncidenceGraph::Face>(ig);
	std::vector<uint32> face_line(faces_indexed ? container_of<F::ORBIT>(m).end_index() : 0, INVALID_INDEX);
	std::vector<uint32> sides, met;
	foreach_cell(m, [&](F f) {
		sides.clear();
		met.clear();
		foreach_dart_of_orbit(m, f, [&](Dart d) {
			sides.push_back(side_of[d.index]);
			met.push_back(vertex_of[d.index]);
		});
		std::sort(met.begin(), met.end());
		if (sides.size() < 3 || std::adjacent_find(met.begin(), met.end()) != met.end())
			throw TopologyError("to_incidence_graph: a face meets a vertex twice or has fewer than 3 edges");
		const Dart u = detail::ig_build_face(ig, sides);
		if (faces_indexed)
			face_line[index_of(m, f)] = index_of(ig, IncidenceGraph::Face(u));
	});
	copy_lines<V::ORBIT, Orbit::IG_VERTEX>(m, ig, vertex_line);
	copy_lines<E::ORBIT, Orbit::IG_EDGE>(m, ig, edge_line);
	if (faces_indexed)
		copy_lines<F::ORBIT, Orbit::PHI1>(m, ig, face_line);
	return ig;
}

CMap2 to_cmap2(const IncidenceGraph& ig, BuildReport* report)
{
	const detail::IgRecords r(ig);
	// soup vertex i: the i-th live vertex line
	std::vector<uint32> soup_id(r.vertices().end_index(), INVALID_INDEX);
	std::vector<uint32> line_of_id;
	foreach_cell(ig, [&](IncidenceGraph::Vertex v) {
		soup_id[v.dart.index] = uint32(line_of_id.size());
		line_of_id.push_back(v.dart.index);
	});
	std::vector<uint32> sizes, ids;
	std::vector<uint32> face_lines; // the ig face line of each soup face
	const bool faces_indexed = is_indexed<IncidenceGraph::Face>(ig);
	foreach_cell(ig, [&](IncidenceGraph::Face f) {
		uint32 n = 0;
		foreach_dart_of_orbit(ig, f, [&](Dart u) {
			ids.push_back(soup_id[r.origin(u)]);
			++n;
		});
		sizes.push_back(n);
		if (faces_indexed)
			face_lines.push_back(index_of(ig, f));
	});
	CMap2 m;
	const bool faces_wanted = faces_indexed && has_user_attributes(container_of<Orbit::PHI1>(ig));
	if (faces_wanted)
		index_cells<CMap2::Face>(m);
	BuildReport built = build_surface(m, uint32(line_of_id.size()), sizes, ids);
	// vertices: soup vertex i is line offset + i; split copies take its values
	std::vector<std::vector<uint32>> lines_of_vertex(r.vertices().end_index());
	std::vector<uint32> ig_vertex_of_line(container_of<Orbit::PHI21>(m).end_index(), INVALID_INDEX);
	for (uint32 i = 0; i < line_of_id.size(); ++i)
		if (container_of<Orbit::PHI21>(m).is_live(built.vertex_offset + i))
		{
			lines_of_vertex[line_of_id[i]].push_back(built.vertex_offset + i);
			ig_vertex_of_line[built.vertex_offset + i] = line_of_id[i];
		}
	for (const auto& [line, id] : built.split_vertices)
	{
		lines_of_vertex[line_of_id[id]].push_back(line);
		if (line >= ig_vertex_of_line.size())
			ig_vertex_of_line.resize(line + 1, INVALID_INDEX);
		ig_vertex_of_line[line] = line_of_id[id];
	}
	detail::copy_attributes(container_of<Orbit::IG_VERTEX>(ig), container_of<Orbit::PHI21>(m),
							[&](uint32 i, const auto& put) {
								for (uint32 line : lines_of_vertex[i])
									put(line);
							});
	// edges: the ig edge joining the ends of each edge of m
	if (has_user_attributes(container_of<Orbit::IG_EDGE>(ig)))
	{
		index_cells<CMap2::Edge>(m);
		std::vector<std::vector<uint32>> lines_of_edge(r.edges().end_index());
		foreach_cell(m, [&](CMap2::Edge e) {
			const uint32 a = ig_vertex_of_line[index_of(m, CMap2::Vertex(e.dart))];
			const uint32 b = ig_vertex_of_line[index_of(m, CMap2::Vertex(phi1(m, e.dart)))];
			const IncidenceGraph::Edge x =
				find_edge(ig, IncidenceGraph::Vertex(Dart(a)), IncidenceGraph::Vertex(Dart(b)));
			if (x.is_valid())
				lines_of_edge[x.dart.index].push_back(index_of(m, e));
		});
		detail::copy_attributes(container_of<Orbit::IG_EDGE>(ig), container_of<Orbit::PHI2>(m),
								[&](uint32 i, const auto& put) {
									for (uint32 line : lines_of_edge[i])
										put(line);
								});
	}
	// faces: built in the soup's order, each as consecutive darts from its
	// first vertex (every face of an incidence graph is buildable)
	if (faces_wanted)
	{
		std::vector<uint32> face_to(container_of<Orbit::PHI1>(ig).end_index(), INVALID_INDEX);
		uint32 first = 0;
		for (std::size_t k = 0; k < sizes.size(); ++k)
		{
			face_to[face_lines[k]] = index_of(m, CMap2::Face(Dart(first)));
			first += sizes[k];
		}
		copy_lines<Orbit::PHI1, Orbit::PHI1>(ig, m, face_to);
	}
	if (report)
		*report = std::move(built);
	return m;
}

Graph to_graph(const IncidenceGraph& ig)
{
	Graph g;
	index_cells<Graph::Vertex>(g);
	index_cells<Graph::Edge>(g);
	const detail::IgRecords r(ig);
	std::vector<Graph::Vertex> vertex_of(r.vertices().end_index());
	std::vector<uint32> vertex_line(r.vertices().end_index(), INVALID_INDEX);
	foreach_cell(ig, [&](IncidenceGraph::Vertex v) {
		vertex_of[v.dart.index] = add_vertex(g);
		vertex_line[v.dart.index] = index_of(g, vertex_of[v.dart.index]);
	});
	std::vector<uint32> edge_line(r.edges().end_index(), INVALID_INDEX);
	foreach_cell(ig, [&](IncidenceGraph::Edge e) {
		const Graph::Edge x = connect_vertices(g, vertex_of[r.end_vertex(2 * e.dart.index)],
											   vertex_of[r.end_vertex(2 * e.dart.index + 1)]);
		edge_line[e.dart.index] = index_of(g, x);
	});
	copy_lines<Orbit::IG_VERTEX, Orbit::ALPHA1>(ig, g, vertex_line);
	copy_lines<Orbit::IG_EDGE, Orbit::ALPHA0>(ig, g, edge_line);
	return g;
}

} // namespace cgogn
