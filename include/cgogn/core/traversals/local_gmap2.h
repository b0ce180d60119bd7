// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/detail/incidence_lookup.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/traversals/global.h>

namespace cgogn
{

// Local traversals of 2-G-maps, with the names and order of the CMap2 ones
// (local_cmap2.h), and like them reading an IncidenceCache of the relation
// when one is built. Each calls f on the requested neighbours of a cell; f may
// return false to stop. Boundary faces are never reported. A vertex's darts
// come in pairs (two per edge, two per face corner): the walks step by
// beta2 o beta1 around a vertex and by beta1 o beta0 around a face, meeting
// each incident cell once on a manifold surface. Costs are linear in the
// number of darts visited.

namespace detail
{

/// Calls f on x, g(x), g(g(x)), ... until back at d, with g = beta_b o beta_a:
/// one dart per corner around a vertex (a = 1, b = 2), one per edge around a
/// face (a = 0, b = 1), one per face around an edge of a 3-G-map (a = 2,
/// b = 3). Returns false when f stopped.
template <uint32 A, uint32 B, typename MAP, typename FUNC>
bool foreach_step_of(const MAP& m, Dart d, const FUNC& f)
{
	static_assert(std::derived_from<MAP, GMap2> && A <= MAP::dimension && B <= MAP::dimension);
	const auto b_of = detail::state_of(m).beta[B]->view(); // see LineStorage::View
	Dart x = d;
	if constexpr (A == 0)
	{
		do
		{
			if (!call_and_continue(f, x))
				return false;
			x = Dart(b_of[x.index ^ 1u]); // beta0 is the other dart of the pair
		} while (x != d);
	}
	else
	{
		const auto a_of = detail::state_of(m).beta[A]->view();
		do
		{
			if (!call_and_continue(f, x))
				return false;
			x = Dart(b_of[a_of[x.index]]);
		} while (x != d);
	}
	return true;
}

/// Calls f once per cell of type CELL among the darts of connected component
/// w, boundary cells skipped. O(size of the component).
template <typename CELL, typename FUNC>
void foreach_cell_of_component(const GMap2& m, Dart start, const FUNC& f)
{
	DartMarkerStore<GMap2> dm(m);
	foreach_dart_of_orbit(m, GMap2::Volume(start), [&](Dart d) {
		if (dm.is_marked(d))
			return true;
		dm.mark_orbit(CELL(d));
		return is_boundary_cell(m, CELL(d)) || call_and_continue(f, CELL(d));
	});
}

} // namespace detail

/// Edges incident to vertex v, in cyclic order. O(degree).
template <typename FUNC>
void foreach_incident_edge(const GMap2& m, CellParam<GMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Edge, void>(m, v, f))
		return;
	detail::foreach_step_of<1, 2>(m, v.dart, [&](Dart d) { return call_and_continue(f, GMap2::Edge(d)); });
}

/// Faces incident to vertex v, in cyclic order (boundary faces skipped). O(degree).
template <typename FUNC>
void foreach_incident_face(const GMap2& m, CellParam<GMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Face, void>(m, v, f))
		return;
	detail::foreach_step_of<1, 2>(m, v.dart,
								  [&](Dart d) { return is_boundary(m, d) || call_and_continue(f, GMap2::Face(d)); });
}

/// The connected component of vertex v. O(1).
template <typename FUNC>
void foreach_incident_volume(const GMap2&, CellParam<GMap2::Vertex> v, const FUNC& f)
{
	call_and_continue(f, GMap2::Volume(v.dart));
}

/// Vertices joined to v by an edge, in cyclic order. O(degree).
template <typename FUNC>
void foreach_adjacent_vertex_through_edge(const GMap2& m, CellParam<GMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Vertex, GMap2::Edge>(m, v, f))
		return;
	detail::foreach_step_of<1, 2>(m, v.dart, [&](Dart d) { return call_and_continue(f, GMap2::Vertex(beta0(m, d))); });
}

/// Vertices sharing a face with v (v excluded), each once on a manifold
/// mesh: the edge neighbours in cyclic order, each followed by the other
/// vertices of the next incident face. O(sum of the degrees of its faces).
template <typename FUNC>
void foreach_adjacent_vertex_through_face(const GMap2& m, CellParam<GMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Vertex, GMap2::Face>(m, v, f))
		return;
	detail::foreach_step_of<1, 2>(m, v.dart, [&](Dart d) {
		// d's edge leads to the first neighbour; d's face holds the others,
		// up to the vertex before v on the way back
		const Dart n = beta0(m, d);
		if (!call_and_continue(f, GMap2::Vertex(n)))
			return false;
		if (is_boundary(m, d))
			return true;
		for (Dart x = beta<1, 0>(m, n); beta<1, 0>(m, x) != beta1(m, d); x = beta<1, 0>(m, x))
			if (!call_and_continue(f, GMap2::Vertex(x)))
				return false;
		return true;
	});
}

/// The two vertices of edge e: that of e.dart first. O(1).
template <typename FUNC>
void foreach_incident_vertex(const GMap2& m, CellParam<GMap2::Edge> e, const FUNC& f)
{
	if (call_and_continue(f, GMap2::Vertex(e.dart)))
		call_and_continue(f, GMap2::Vertex(beta0(m, e.dart)));
}

/// The one or two faces incident to edge e (boundary faces skipped). O(1).
template <typename FUNC>
void foreach_incident_face(const GMap2& m, CellParam<GMap2::Edge> e, const FUNC& f)
{
	if (!is_boundary(m, e.dart) && !call_and_continue(f, GMap2::Face(e.dart)))
		return;
	const Dart d2 = beta2(m, e.dart);
	if (!is_boundary(m, d2))
		call_and_continue(f, GMap2::Face(d2));
}

/// The connected component of edge e. O(1).
template <typename FUNC>
void foreach_incident_volume(const GMap2&, CellParam<GMap2::Edge> e, const FUNC& f)
{
	call_and_continue(f, GMap2::Volume(e.dart));
}

/// Edges sharing a vertex with e (e excluded): around the vertex of e.dart,
/// then around the other end. O(degree of both ends).
template <typename FUNC>
void foreach_adjacent_edge_through_vertex(const GMap2& m, CellParam<GMap2::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Edge, GMap2::Vertex>(m, e, f))
		return;
	for (Dart start : {e.dart, beta0(m, e.dart)})
		if (!detail::foreach_step_of<1, 2>(m, start,
										   [&](Dart d) { return d == start || call_and_continue(f, GMap2::Edge(d)); }))
			return;
}

/// Edges sharing a (non-boundary) face with e, e excluded. O(degree of its
/// faces).
template <typename FUNC>
void foreach_adjacent_edge_through_face(const GMap2& m, CellParam<GMap2::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Edge, GMap2::Face>(m, e, f))
		return;
	for (Dart start : {e.dart, beta2(m, e.dart)})
	{
		if (is_boundary(m, start))
			continue;
		if (!detail::foreach_step_of<0, 1>(m, start,
										   [&](Dart d) { return d == start || call_and_continue(f, GMap2::Edge(d)); }))
			return;
	}
}

/// Vertices of face f, in the order of its darts from f.dart. O(codegree).
template <typename FUNC>
void foreach_incident_vertex(const GMap2& m, CellParam<GMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<GMap2::Vertex, void>(m, f, fn))
		return;
	detail::foreach_step_of<0, 1>(m, f.dart, [&](Dart d) { return call_and_continue(fn, GMap2::Vertex(d)); });
}

/// Edges of face f, in the same order. O(codegree).
template <typename FUNC>
void foreach_incident_edge(const GMap2& m, CellParam<GMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<GMap2::Edge, void>(m, f, fn))
		return;
	detail::foreach_step_of<0, 1>(m, f.dart, [&](Dart d) { return call_and_continue(fn, GMap2::Edge(d)); });
}

/// The connected component of face f. O(1).
template <typename FUNC>
void foreach_incident_volume(const GMap2&, CellParam<GMap2::Face> f, const FUNC& fn)
{
	call_and_continue(fn, GMap2::Volume(f.dart));
}

/// Faces across the edges of f (boundary faces skipped), in the same order.
/// O(codegree).
template <typename FUNC>
void foreach_adjacent_face_through_edge(const GMap2& m, CellParam<GMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<GMap2::Face, GMap2::Edge>(m, f, fn))
		return;
	detail::foreach_step_of<0, 1>(m, f.dart, [&](Dart d) {
		const Dart d2 = beta2(m, d);
		return is_boundary(m, d2) || call_and_continue(fn, GMap2::Face(d2));
	});
}

/// Faces sharing at least a vertex with f (f excluded), each once on a
/// manifold mesh: around each vertex of f in turn. O(sum of the degrees of
/// its vertices).
template <typename FUNC>
void foreach_adjacent_face_through_vertex(const GMap2& m, CellParam<GMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<GMap2::Face, GMap2::Vertex>(m, f, fn))
		return;
	detail::foreach_step_of<0, 1>(m, f.dart, [&](Dart d) {
		// around d's vertex, from the face across d's edge to the face before
		// the one across the corner's other edge (reported by the previous vertex)
		const Dart stop = beta1(m, d); // f's own corner at this vertex, by its other dart
		for (Dart it = beta2(m, d); it != stop;)
		{
			const Dart next = beta<1, 2>(m, it);
			if (next == stop)
				break;
			if (!is_boundary(m, it) && !call_and_continue(fn, GMap2::Face(it)))
				return false;
			it = next;
		}
		return true;
	});
}

/// Vertices of connected component w (no defined order). O(size of w).
template <typename FUNC>
void foreach_incident_vertex(const GMap2& m, CellParam<GMap2::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Vertex, void>(m, w, f))
		return;
	detail::foreach_cell_of_component<GMap2::Vertex>(m, w.dart, f);
}
/// Edges of connected component w (no defined order). O(size of w).
template <typename FUNC>
void foreach_incident_edge(const GMap2& m, CellParam<GMap2::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Edge, void>(m, w, f))
		return;
	detail::foreach_cell_of_component<GMap2::Edge>(m, w.dart, f);
}
/// Faces of connected component w, boundary faces skipped (no defined
/// order). O(size of w).
template <typename FUNC>
void foreach_incident_face(const GMap2& m, CellParam<GMap2::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap2::Face, void>(m, w, f))
		return;
	detail::foreach_cell_of_component<GMap2::Face>(m, w.dart, f);
}

} // namespace cgogn
