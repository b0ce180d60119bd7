// SPDX-License-Identifier: MIT
// The 1-skeleton of a map as a graph, with its vertex and edge attributes.
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/operators/graph.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap3.h>

#include "attribute_copy.h"

#include <vector>

namespace cgogn
{

namespace
{

// Copies the attributes of the cells of orbit FROM in m into the graph's
// container of orbit TO, line i of m going to line_of[i] (INVALID_INDEX:
// no cell).
template <Orbit FROM, Orbit TO, typename MAP>
void copy_cell_attributes(const MAP& m, Graph& g, const std::vector<uint32>& line_of)
{
	if (!is_indexed<Cell<FROM>>(m))
		return;
	detail::copy_attributes(container_of<FROM>(m), container_of<TO>(g), [&](uint32 i, const auto& put) {
		if (line_of[i] != INVALID_INDEX)
			put(line_of[i]);
	});
}

template <typename MAP>
Graph skeleton_of(const MAP& m)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Edge = typename mesh_traits<MAP>::Edge;
	Graph g;
	index_cells<Graph::Vertex>(g);
	index_cells<Graph::Edge>(g);
	// the graph vertex of each dart of m
	std::vector<Graph::Vertex> vertex_of(container_of<Orbit::DART>(m).end_index());
	std::vector<uint32> vertex_line(container_of<Vertex::ORBIT>(m).end_index(), INVALID_INDEX);
	const bool vertices_indexed = is_indexed<Vertex>(m);
	foreach_cell(m, [&](Vertex v) {
		const Graph::Vertex w = add_vertex(g);
		foreach_dart_of_orbit(m, v, [&](Dart d) { vertex_of[d.index] = w; });
		if (vertices_indexed)
			vertex_line[index_of(m, v)] = index_of(g, w);
	});
	std::vector<uint32> edge_line(container_of<Edge::ORBIT>(m).end_index(), INVALID_INDEX);
	const bool edges_indexed = is_indexed<Edge>(m);
	foreach_cell(m, [&](Edge e) {
		Graph::Vertex ends[2];
		uint32 n = 0;
		foreach_incident_vertex(m, e, [&](Vertex v) {
			if (n < 2)
				ends[n++] = vertex_of[v.dart.index];
		});
		const Graph::Edge x = connect_vertices(g, ends[0], n == 2 ? ends[1] : ends[0]);
		if (edges_indexed)
			edge_line[index_of(m, e)] = index_of(g, x);
	});
	copy_cell_attributes<Vertex::ORBIT, Orbit::ALPHA1>(m, g, vertex_line);
	copy_cell_attributes<Edge::ORBIT, Orbit::ALPHA0>(m, g, edge_line);
	return g;
}

} // namespace

Graph to_graph(const CMap2& m)
{
	return skeleton_of(m);
}

Graph to_graph(const GMap2& m)
{
	return skeleton_of(m);
}

Graph to_graph(const CMap3& m)
{
	return skeleton_of(m);
}

Graph to_graph(const GMap3& m)
{
	return skeleton_of(m);
}

} // namespace cgogn
