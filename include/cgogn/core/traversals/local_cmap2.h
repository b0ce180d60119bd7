// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/detail/incidence_lookup.h>
#include <cgogn/core/traversals/global.h>

namespace cgogn
{

// Local traversals of 2-maps. Each calls f on the requested neighbours of a
// cell; f may return false to stop. Boundary faces are never reported. Costs
// are linear in the number of darts visited. Around a vertex the order is the
// cyclic order of the darts (phi1 o phi2); around a face, the phi1 order.
// The same functions serve the 2-D sub-cells (Vertex2, Edge2, Face2) of a 3-map.

/// Edges incident to vertex v, in cyclic order.
template <typename FUNC>
void foreach_incident_edge(const CMap2& m, CellParam<CMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Edge, void>(m, v, f))
		return;
	foreach_dart_of_orbit(m, v, [&](Dart d) { return call_and_continue(f, CMap2::Edge(d)); });
}

/// Faces incident to vertex v, in cyclic order (boundary faces skipped).
template <typename FUNC>
CGOGN_INLINE void foreach_incident_face(const CMap2& m, CellParam<CMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Face, void>(m, v, f))
		return;
	if (!has_boundary(m)) // a closed map: no boundary bit to read per dart
		detail::report_with_lines<CMap2::Face>(
			m, [&](const auto& report) { foreach_dart_of_orbit(m, v, report); }, f);
	else
		detail::report_with_lines<CMap2::Face>(
			m,
			[&](const auto& report) {
				foreach_dart_of_orbit(m, v, [&](Dart d) { return is_boundary(m, d) || report(d); });
			},
			f);
}

/// The connected component of vertex v.
template <typename FUNC>
void foreach_incident_volume(const CMap2&, CellParam<CMap2::Vertex> v, const FUNC& f)
{
	call_and_continue(f, CMap2::Volume(v.dart));
}

/// Vertices joined to v by an edge, in cyclic order.
template <typename FUNC>
CGOGN_INLINE void foreach_adjacent_vertex_through_edge(const CMap2& m, CellParam<CMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Vertex, CMap2::Edge>(m, v, f))
		return;
	const auto phi2_of = detail::state_of(m).phi2->view(); // see LineStorage::View
	detail::report_with_lines<CMap2::Vertex>(
		m,
		[&](const auto& report) {
			foreach_dart_of_orbit(m, v, [&](Dart d) { return report(Dart(phi2_of[d.index])); });
		},
		f);
}

/// Vertices sharing a face with v (v excluded), each once on a manifold mesh:
/// the edge neighbours in cyclic order, each followed by the other vertices of
/// the next incident face.
template <typename FUNC>
void foreach_adjacent_vertex_through_face(const CMap2& m, CellParam<CMap2::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Vertex, CMap2::Face>(m, v, f))
		return;
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		if (!call_and_continue(f, CMap2::Vertex(phi2(m, d))))
			return false;
		if (is_boundary(m, d))
			return true;
		for (Dart x = phi1(m, phi1(m, d)); phi1(m, x) != d; x = phi1(m, x))
			if (!call_and_continue(f, CMap2::Vertex(x)))
				return false;
		return true;
	});
}

/// The two vertices of edge e: the origin of e.dart first.
template <typename FUNC>
void foreach_incident_vertex(const CMap2& m, CellParam<CMap2::Edge> e, const FUNC& f)
{
	if (call_and_continue(f, CMap2::Vertex(e.dart)))
		call_and_continue(f, CMap2::Vertex(phi2(m, e.dart)));
}

/// The one or two faces incident to edge e (boundary faces skipped).
template <typename FUNC>
void foreach_incident_face(const CMap2& m, CellParam<CMap2::Edge> e, const FUNC& f)
{
	if (!is_boundary(m, e.dart) && !call_and_continue(f, CMap2::Face(e.dart)))
		return;
	const Dart d2 = phi2(m, e.dart);
	if (!is_boundary(m, d2))
		call_and_continue(f, CMap2::Face(d2));
}

/// The connected component of edge e.
template <typename FUNC>
void foreach_incident_volume(const CMap2&, CellParam<CMap2::Edge> e, const FUNC& f)
{
	call_and_continue(f, CMap2::Volume(e.dart));
}

/// Edges sharing a vertex with e (e excluded): around the origin of e.dart,
/// then around the other end.
template <typename FUNC>
void foreach_adjacent_edge_through_vertex(const CMap2& m, CellParam<CMap2::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Edge, CMap2::Vertex>(m, e, f))
		return;
	for (Dart start : {e.dart, phi2(m, e.dart)})
	{
		for (Dart it = phi1(m, phi2(m, start)); it != start; it = phi1(m, phi2(m, it)))
			if (!call_and_continue(f, CMap2::Edge(it)))
				return;
	}
}

/// Edges sharing a (non-boundary) face with e, e excluded.
template <typename FUNC>
void foreach_adjacent_edge_through_face(const CMap2& m, CellParam<CMap2::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Edge, CMap2::Face>(m, e, f))
		return;
	for (Dart start : {e.dart, phi2(m, e.dart)})
	{
		if (is_boundary(m, start))
			continue;
		for (Dart it = phi1(m, start); it != start; it = phi1(m, it))
			if (!call_and_continue(f, CMap2::Edge(it)))
				return;
	}
}

/// Vertices of face f in phi1 order.
template <typename FUNC>
CGOGN_INLINE void foreach_incident_vertex(const CMap2& m, CellParam<CMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<CMap2::Vertex, void>(m, f, fn))
		return;
	detail::report_with_lines<CMap2::Vertex>(
		m, [&](const auto& report) { foreach_dart_of_orbit(m, f, report); }, fn);
}

/// Edges of face f in phi1 order.
template <typename FUNC>
void foreach_incident_edge(const CMap2& m, CellParam<CMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<CMap2::Edge, void>(m, f, fn))
		return;
	foreach_dart_of_orbit(m, f, [&](Dart d) { return call_and_continue(fn, CMap2::Edge(d)); });
}

/// The connected component of face f.
template <typename FUNC>
void foreach_incident_volume(const CMap2&, CellParam<CMap2::Face> f, const FUNC& fn)
{
	call_and_continue(fn, CMap2::Volume(f.dart));
}

/// Faces across the edges of f (boundary faces skipped), in phi1 order.
template <typename FUNC>
void foreach_adjacent_face_through_edge(const CMap2& m, CellParam<CMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<CMap2::Face, CMap2::Edge>(m, f, fn))
		return;
	foreach_dart_of_orbit(m, f, [&](Dart d) {
		const Dart d2 = phi2(m, d);
		return is_boundary(m, d2) || call_and_continue(fn, CMap2::Face(d2));
	});
}

/// Faces sharing at least a vertex with f (f excluded), each once on a
/// manifold mesh: around each vertex of f in turn.
template <typename FUNC>
void foreach_adjacent_face_through_vertex(const CMap2& m, CellParam<CMap2::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<CMap2::Face, CMap2::Vertex>(m, f, fn))
		return;
	foreach_dart_of_orbit(m, f, [&](Dart d) {
		// faces around the origin of d, from the one across d to the one before
		// the face across phi_1(d) (that one is reported by the previous vertex)
		for (Dart it = phi1(m, phi2(m, d)); it != d;)
		{
			const Dart next = phi1(m, phi2(m, it));
			if (next == d)
				break;
			if (!is_boundary(m, it) && !call_and_continue(fn, CMap2::Face(it)))
				return false;
			it = next;
		}
		return true;
	});
}

namespace detail
{
/// Calls f once per cell of type CELL found on the darts of a volume (a
/// connected component of a 2-map, a volume of a 3-map), boundary cells skipped.
template <typename CELL, typename MAP, typename FUNC>
void foreach_cell_of_volume(const MAP& m, Dart start, const FUNC& f)
{
	DartMarkerStore<MAP> dm(m);
	foreach_dart_of_orbit(m, Cell<Orbit::PHI1_PHI2>(start), [&](Dart d) {
		if (dm.is_marked(d))
			return true;
		if constexpr (CELL::ORBIT == Orbit::PHI21 || CELL::ORBIT == Orbit::PHI21_PHI31)
			dm.mark_orbit(Cell<Orbit::PHI21>(d)); // the vertex inside this volume
		else if constexpr (CELL::ORBIT == Orbit::PHI2 || CELL::ORBIT == Orbit::PHI2_PHI3)
			dm.mark_orbit(Cell<Orbit::PHI2>(d));
		else
			dm.mark_orbit(Cell<Orbit::PHI1>(d));
		return is_boundary_cell(m, CELL(d)) || call_and_continue(f, CELL(d));
	});
}
} // namespace detail

/// Vertices of connected component w (no defined order).
template <typename FUNC>
void foreach_incident_vertex(const CMap2& m, CellParam<CMap2::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Vertex, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume<CMap2::Vertex>(m, w.dart, f);
}
/// Edges of connected component w (no defined order).
template <typename FUNC>
void foreach_incident_edge(const CMap2& m, CellParam<CMap2::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Edge, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume<CMap2::Edge>(m, w.dart, f);
}
/// Faces of connected component w, boundary faces skipped (no defined order).
template <typename FUNC>
void foreach_incident_face(const CMap2& m, CellParam<CMap2::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap2::Face, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume<CMap2::Face>(m, w.dart, f);
}

} // namespace cgogn
