// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/core/traversals/global.h>

namespace cgogn
{

// Local traversals of incidence graphs. Each calls f on the requested
// neighbours of a cell; f may return false to stop. They count incidences:
// a neighbour reached through two shared cells is met twice (two faces
// sharing two edges, two faces meeting at two vertices). Around a vertex the
// order is its ring's, around an edge its radial ring's, along a face its
// cycle's. Faces are reported by one of their uses (compare them with
// same_cell). O(size of what is visited).

namespace detail
{
/// Calls f(end) on each edge end (2 x edge + side) around vertex v.
template <typename FUNC>
bool ig_foreach_end(const IncidenceGraph& ig, IncidenceGraph::Vertex v, const FUNC& f)
{
	const uint32 first = ig_first_end(ig, v.dart.index);
	if (first == NO_EDGE_END)
		return true;
	uint32 it = first;
	do
	{
		if (!call_and_continue(f, it))
			return false;
		it = ig_next_end(ig, it);
	} while (it != first);
	return true;
}
/// Calls f(use) on each use of edge e (around it).
template <typename FUNC>
bool ig_foreach_use(const IncidenceGraph& ig, IncidenceGraph::Edge e, const FUNC& f)
{
	const uint32 first = (*ig.links().edge_use)[e.dart.index];
	if (first == INVALID_INDEX)
		return true;
	Dart it(first);
	do
	{
		if (!call_and_continue(f, it))
			return false;
		it = next_use_around_edge(ig, it);
	} while (it.index != first);
	return true;
}
} // namespace detail

/// The edges of vertex v. O(degree of v).
template <typename FUNC>
void foreach_incident_edge(const IncidenceGraph& ig, IncidenceGraph::Vertex v, const FUNC& f)
{
	detail::ig_foreach_end(ig, v,
						   [&](uint32 end) { return call_and_continue(f, IncidenceGraph::Edge(Dart(end >> 1))); });
}

/// The vertices joined to v by an edge, once per edge. O(degree of v).
template <typename FUNC>
void foreach_adjacent_vertex_through_edge(const IncidenceGraph& ig, IncidenceGraph::Vertex v, const FUNC& f)
{
	detail::ig_foreach_end(ig, v, [&](uint32 end) {
		return call_and_continue(f, IncidenceGraph::Vertex(Dart(detail::ig_end_vertex(ig, end >> 1, 1u - (end & 1u)))));
	});
}

/// The faces around vertex v, each once (a face has one side entering v).
/// O(sum of the degrees of v's edges).
template <typename FUNC>
void foreach_incident_face(const IncidenceGraph& ig, IncidenceGraph::Vertex v, const FUNC& f)
{
	detail::ig_foreach_end(ig, v, [&](uint32 end) {
		return detail::ig_foreach_use(ig, IncidenceGraph::Edge(Dart(end >> 1)), [&](Dart u) {
			return use_target(ig, u) != v || call_and_continue(f, IncidenceGraph::Face(u));
		});
	});
}

/// The vertices sharing a face with v, other than v, once per face and
/// vertex (a neighbour across an edge is met once per face on that edge).
/// O(sum of the sizes of v's faces).
template <typename FUNC>
void foreach_adjacent_vertex_through_face(const IncidenceGraph& ig, IncidenceGraph::Vertex v, const FUNC& f)
{
	foreach_incident_face(ig, v, [&](IncidenceGraph::Face face) {
		return foreach_dart_of_orbit(ig, face, [&](Dart u) {
			const IncidenceGraph::Vertex w = use_origin(ig, u);
			return w == v || call_and_continue(f, w);
		});
	});
}

/// The two vertices of edge e: its first, then its second. O(1).
template <typename FUNC>
void foreach_incident_vertex(const IncidenceGraph& ig, IncidenceGraph::Edge e, const FUNC& f)
{
	if (call_and_continue(f, first_vertex(ig, e)))
		call_and_continue(f, second_vertex(ig, e));
}

/// The faces on edge e, around it. O(degree of e).
template <typename FUNC>
void foreach_incident_face(const IncidenceGraph& ig, IncidenceGraph::Edge e, const FUNC& f)
{
	detail::ig_foreach_use(ig, e, [&](Dart u) { return call_and_continue(f, IncidenceGraph::Face(u)); });
}

/// The other edges of e's two vertices: those of the first, then those of
/// the second. O(degrees of e's vertices).
template <typename FUNC>
void foreach_adjacent_edge_through_vertex(const IncidenceGraph& ig, IncidenceGraph::Edge e, const FUNC& f)
{
	auto others = [&](IncidenceGraph::Vertex v) {
		return detail::ig_foreach_end(ig, v, [&](uint32 end) {
			return (end >> 1) == e.dart.index || call_and_continue(f, IncidenceGraph::Edge(Dart(end >> 1)));
		});
	};
	if (others(first_vertex(ig, e)))
		others(second_vertex(ig, e));
}

/// The other edges of the faces on e, once per face. O(sum of the sizes of
/// e's faces).
template <typename FUNC>
void foreach_adjacent_edge_through_face(const IncidenceGraph& ig, IncidenceGraph::Edge e, const FUNC& f)
{
	detail::ig_foreach_use(ig, e, [&](Dart u) {
		for (Dart it = next_use_in_face(ig, u); it != u; it = next_use_in_face(ig, it))
			if (!call_and_continue(f, edge_of_use(ig, it)))
				return false;
		return true;
	});
}

/// The vertices of face f in its cycle order. O(size of f).
template <typename FUNC>
void foreach_incident_vertex(const IncidenceGraph& ig, IncidenceGraph::Face f, const FUNC& func)
{
	foreach_dart_of_orbit(ig, f, [&](Dart u) { return call_and_continue(func, use_origin(ig, u)); });
}

/// The edges of face f in its cycle order. O(size of f).
template <typename FUNC>
void foreach_incident_edge(const IncidenceGraph& ig, IncidenceGraph::Face f, const FUNC& func)
{
	foreach_dart_of_orbit(ig, f, [&](Dart u) { return call_and_continue(func, edge_of_use(ig, u)); });
}

/// The other faces on the edges of f, once per shared edge. O(sum of the
/// degrees of f's edges).
template <typename FUNC>
void foreach_adjacent_face_through_edge(const IncidenceGraph& ig, IncidenceGraph::Face f, const FUNC& func)
{
	foreach_dart_of_orbit(ig, f, [&](Dart u) {
		for (Dart it = next_use_around_edge(ig, u); it != u; it = next_use_around_edge(ig, it))
			if (!call_and_continue(func, IncidenceGraph::Face(it)))
				return false;
		return true;
	});
}

/// The other faces around the vertices of f, once per shared vertex.
/// O(sum over f's vertices of the degrees of their edges + face sizes).
template <typename FUNC>
void foreach_adjacent_face_through_vertex(const IncidenceGraph& ig, IncidenceGraph::Face f, const FUNC& func)
{
	foreach_dart_of_orbit(ig, f, [&](Dart u) {
		bool go = true;
		foreach_incident_face(ig, use_origin(ig, u), [&](IncidenceGraph::Face g) {
			if (same_cell(ig, g, f))
				return true;
			go = call_and_continue(func, g);
			return go;
		});
		return go;
	});
}

} // namespace cgogn
