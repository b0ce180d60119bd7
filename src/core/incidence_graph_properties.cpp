// SPDX-License-Identifier: MIT
#include <cgogn/core/properties/incidence_graph_properties.h>
#include <cgogn/core/traversals/global.h>

#include "incidence_graph_records.h"

#include <algorithm>
#include <numeric>
#include <vector>

namespace cgogn
{

namespace
{

uint32 find_root(std::vector<uint32>& parent, uint32 x)
{
	while (parent[x] != x)
		x = parent[x] = parent[parent[x]];
	return x;
}

} // namespace

uint32 degree(const IncidenceGraph& ig, IncidenceGraph::Vertex v)
{
	uint32 n = 0;
	detail::IgRecords(ig).foreach_end(v.dart.index, [&](uint32) { ++n; });
	return n;
}

uint32 degree(const IncidenceGraph& ig, IncidenceGraph::Edge e)
{
	uint32 n = 0;
	detail::IgRecords(ig).foreach_use(e.dart.index, [&](Dart) { ++n; });
	return n;
}

uint32 codegree(const IncidenceGraph& ig, IncidenceGraph::Face f)
{
	uint32 n = 0;
	foreach_dart_of_orbit(ig, f, [&](Dart) { ++n; });
	return n;
}

bool is_manifold_edge(const IncidenceGraph& ig, IncidenceGraph::Edge e)
{
	return degree(ig, e) <= 2;
}

bool is_manifold_vertex(const IncidenceGraph& ig, IncidenceGraph::Vertex v)
{
	const detail::IgRecords r(ig);
	// the edges of v, joined by the faces at v (a face at v has two sides
	// there, one entering and one leaving): one fan when they are connected
	std::vector<uint32> edges;
	bool ok = r.foreach_end(v.dart.index, [&](uint32 end) {
		const uint32 d = degree(ig, IncidenceGraph::Edge(Dart(end >> 1)));
		edges.push_back(end >> 1);
		return d == 1 || d == 2;
	});
	if (!ok || edges.empty())
		return false;
	std::vector<uint32> parent(edges.size());
	std::iota(parent.begin(), parent.end(), 0u);
	auto slot = [&](uint32 e) { return uint32(std::find(edges.begin(), edges.end(), e) - edges.begin()); };
	uint32 groups = uint32(edges.size());
	for (std::size_t i = 0; i < edges.size(); ++i)
		r.foreach_use(edges[i], [&](Dart u) {
			if (r.target(u) != v.dart.index)
				return;
			const uint32 a = find_root(parent, uint32(i));
			const uint32 b = find_root(parent, slot(r.use_edge_end(r.next_in_face(u)) >> 1));
			if (a != b)
			{
				parent[a] = b;
				--groups;
			}
		});
	return groups == 1;
}

uint32 nb_connected_components(const IncidenceGraph& ig)
{
	const detail::IgRecords r(ig);
	const AttributeContainer& vertices = r.vertices();
	std::vector<uint32> parent(vertices.end_index());
	std::iota(parent.begin(), parent.end(), 0u);
	uint32 n = vertices.nb_lines();
	foreach_cell(ig, [&](IncidenceGraph::Edge e) {
		const uint32 a = find_root(parent, r.end_vertex(2 * e.dart.index));
		const uint32 b = find_root(parent, r.end_vertex(2 * e.dart.index + 1));
		if (a != b)
		{
			parent[a] = b;
			--n;
		}
	});
	return n;
}

int64 euler_characteristic(const IncidenceGraph& ig)
{
	return int64(nb_cells<IncidenceGraph::Vertex>(ig)) - int64(nb_cells<IncidenceGraph::Edge>(ig)) +
		   int64(nb_cells<IncidenceGraph::Face>(ig));
}

uint32 nb_non_manifold_edges(const IncidenceGraph& ig)
{
	uint32 n = 0;
	foreach_cell(ig, [&](IncidenceGraph::Edge e) { n += degree(ig, e) > 2; });
	return n;
}

uint32 nb_non_manifold_vertices(const IncidenceGraph& ig)
{
	uint32 n = 0;
	foreach_cell(ig, [&](IncidenceGraph::Vertex v) { n += !is_manifold_vertex(ig, v); });
	return n;
}

} // namespace cgogn
