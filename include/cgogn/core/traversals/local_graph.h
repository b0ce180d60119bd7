// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>

namespace cgogn
{

// Local traversals of graphs. Each calls f on the requested neighbours of a
// cell; f may return false to stop. They count incidences: a self-loop is
// met once per half-edge, so twice around its vertex, as degree counts it.
// Around a vertex the order is alpha1's. O(degree) or O(1).

/// Edges incident to vertex v, once per half-edge at v (a self-loop twice);
/// none for an isolated vertex. O(degree of v).
template <typename FUNC>
void foreach_incident_edge(const Graph& g, Graph::Vertex v, const FUNC& f)
{
	foreach_dart_of_orbit(g, v, [&](Dart d) { return is_isolated(g, d) || call_and_continue(f, Graph::Edge(d)); });
}

/// The two ends of edge e: the vertex of e.dart, then the other one (the same
/// vertex twice for a self-loop). O(1).
template <typename FUNC>
void foreach_incident_vertex(const Graph& g, Graph::Edge e, const FUNC& f)
{
	if (call_and_continue(f, Graph::Vertex(e.dart)))
		call_and_continue(f, Graph::Vertex(alpha0(g, e.dart)));
}

/// The vertices at the other end of each edge of v, once per half-edge at v
/// (v itself twice for a self-loop, a neighbour joined by two edges twice).
/// O(degree of v).
template <typename FUNC>
void foreach_adjacent_vertex_through_edge(const Graph& g, Graph::Vertex v, const FUNC& f)
{
	foreach_dart_of_orbit(g, v, [&](Dart d) {
		const Dart e = alpha0(g, d);
		return e == d || call_and_continue(f, Graph::Vertex(e));
	});
}

/// The edges sharing a vertex with e (e excluded), once per incidence: those
/// around the vertex of e.dart, then those around the other end. O(degree of
/// both ends).
template <typename FUNC>
void foreach_adjacent_edge_through_vertex(const Graph& g, Graph::Edge e, const FUNC& f)
{
	const Dart b = alpha0(g, e.dart);
	for (const Dart end : {e.dart, b})
	{
		bool go_on = true;
		foreach_dart_of_orbit(g, Graph::Vertex(end), [&](Dart d) {
			if (d == e.dart || d == b)
				return true;
			go_on = call_and_continue(f, Graph::Edge(d));
			return go_on;
		});
		if (!go_on)
			return;
	}
}

} // namespace cgogn
