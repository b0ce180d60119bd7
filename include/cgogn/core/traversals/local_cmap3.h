// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/traversals/local_cell_set.h>
#include <cgogn/core/traversals/local_cmap2.h>

#include <algorithm>
#include <array>
#include <vector>

namespace cgogn
{

// Local traversals of 3-maps. f may return false to stop. Boundary volumes
// are never reported. Around an edge and around a face the order is defined
// (the cyclic order of the volumes around the edge, phi1 order along the
// face); around a vertex and in a volume no order can be assumed (they are
// flooded with pooled marks: allocation-free once warm). Adjacencies report
// each cell once and never the starting cell.

namespace detail
{

// Calls f once per cell of type CELL incident to vertex v, with `inner` the
// orbit of the intersection of v with such a cell (used to mark it as seen).
template <typename CELL, Orbit INNER, typename FUNC>
void foreach_cell_around_vertex3(const CMap3& m, CMap3::Vertex v, const FUNC& f)
{
	DartMarkerStore<CMap3> seen(m);
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		if (seen.is_marked(d))
			return true;
		if constexpr (INNER == Orbit::DART)
			seen.mark(d);
		else if constexpr (INNER == Orbit::PHI21)
			seen.mark_orbit(Cell<Orbit::PHI21>(d));
		else if constexpr (INNER == Orbit::PHI1_PHI3) // vertex of a face: d and phi3 o phi1
		{
			seen.mark(d);
			seen.mark(phi1(m, phi3(m, d)));
		}
		else // PHI2_PHI3: darts of an edge leaving v: cycle of phi3 o phi2
		{
			Dart it = d;
			do
			{
				seen.mark(it);
				it = phi2(m, phi3(m, it));
			} while (it != d);
		}
		return is_boundary_cell(m, CELL(d)) || call_and_continue(f, CELL(d));
	});
}

// The vertices adjacent to v through an edge are the vertices at phi1 of the
// darts of v (each dart leaves v); in a 3-G-map, at beta0 of its darts (the
// other end of the dart's edge), the relation held where a 3-map holds phi1,
// so the same code serves both. On a map with indexed vertices they are
// told apart by their line, with a mark on the vertex container (a bit per
// vertex, which stays in cache) instead of marking the darts of every edge
// around v (a cycle of ~10 darts per edge in a tet mesh): one flood of the
// vertex instead of a flood plus a walk around each edge. The neighbours are
// collected first and reported after, so that a vertex without a line (made
// with set_indices = false) can still fall back to the dart walk: returns
// false then, having reported nothing.
/// The same with the vertex lines given: `line_of` (per dart) and the
/// container of the vertices, for a map whose vertex lines are held
/// elsewhere (a multiresolution 3-map at its finest level).
template <typename MAP, typename LINES, typename FUNC>
bool foreach_adjacent_vertex_by_line(const MAP& m, typename MAP::Vertex v, AttributeContainer& vertices,
									 const LINES& line_of, const FUNC& f)
{
	static_assert(std::is_same_v<MAP, CMap3> || std::is_same_v<MAP, GMap3>);
	using Neighbour = LocatedCell<MAP::Vertex::ORBIT>;
	// up to 64 neighbours on the stack (a tet mesh vertex has ~14), more on the heap
	std::array<Neighbour, 64> few;
	std::vector<Neighbour> many;
	uint32 n = 0;
	bool all_lines = true;
	{
		// clears the bits it set and gives the mark back, also on bad_alloc
		struct Seen
		{
			AttributeContainer& vertices;
			const std::array<Neighbour, 64>& few;
			const std::vector<Neighbour>& many;
			const uint32& n;
			ReservedMark mark{vertices};
			~Seen()
			{
				for (uint32 i = 0; i < std::min<uint32>(n, uint32(few.size())); ++i)
					mark->reset(few[i].line);
				for (const Neighbour& w : many)
					mark->reset(w.line);
			}
		} guard{vertices, few, many, n};
		MarkAttribute& seen = *guard.mark;
		// the dart at the other end of d's edge: phi1(d) in a 3-map, beta0(d)
		// (the other dart of d's pair) in a 3-G-map
		const auto phi1_of = detail::state_of(m).phi1->view();
		const auto other_end = [phi1_of](uint32 d) -> uint32 {
			if constexpr (is_gmap_v<MAP>)
			{
				(void)phi1_of; // captured for the 3-map branch
				return d ^ 1u;
			}
			else
				return phi1_of[d];
		};
		auto collect = [&](Dart d) {
			const Dart e(other_end(d.index));
			const uint32 w = line_of[e.index];
			if (w == INVALID_INDEX)
			{
				all_lines = false;
				return false;
			}
			if (seen.test(w))
				return true;
			if (n < few.size())
				few[n] = Neighbour(e, w);
			else
				many.emplace_back(e, w);
			++n;
			seen.set(w); // last: a set bit is always recorded (bad_alloc)
			return true;
		};
		// told by the walk which dart comes later (foreach_dart_of_vertex3),
		// loads the vertex line of its other end, read above, ahead of time
		struct Collect
		{
			const decltype(collect)& f;
			decltype(line_of) lines;
			decltype(other_end) end_of;
			CGOGN_INLINE bool operator()(Dart d) const
			{
				return f(d);
			}
			CGOGN_INLINE void prefetch_line(uint32 d) const
			{
				CGOGN_PREFETCH(&lines[end_of(d)]);
			}
		};
		foreach_dart_of_orbit(m, v, Collect{collect, line_of, other_end});
	}
	if (!all_lines)
		return false;
	const uint32 on_stack = std::min<uint32>(n, uint32(few.size()));
	for (uint32 i = 0; i < on_stack; ++i)
		if (!call_and_continue(f, few[i]))
			return true;
	for (const Neighbour& w : many)
		if (!call_and_continue(f, w))
			return true;
	return true;
}
/// foreach_adjacent_vertex_by_line with the map's own vertex lines.
template <typename MAP, typename FUNC>
bool foreach_adjacent_vertex_by_line(const MAP& m, typename MAP::Vertex v, const FUNC& f)
{
	return foreach_adjacent_vertex_by_line(m, v, *detail::state_of(m).cells[orbit_index(MAP::Vertex::ORBIT)],
										   detail::state_of(m).cell_index[orbit_index(MAP::Vertex::ORBIT)]->view(), f);
}

} // namespace detail

// ---- incidences of a vertex

/// Edges incident to vertex v.
template <typename FUNC>
void foreach_incident_edge(const CMap3& m, CellParam<CMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Edge, void>(m, v, f))
		return;
	detail::foreach_cell_around_vertex3<CMap3::Edge, Orbit::PHI2_PHI3>(m, v, f);
}
/// Faces incident to vertex v.
template <typename FUNC>
void foreach_incident_face(const CMap3& m, CellParam<CMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Face, void>(m, v, f))
		return;
	detail::foreach_cell_around_vertex3<CMap3::Face, Orbit::PHI1_PHI3>(m, v, f);
}
/// Volumes incident to vertex v (boundary volumes skipped).
template <typename FUNC>
void foreach_incident_volume(const CMap3& m, CellParam<CMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Volume, void>(m, v, f))
		return;
	detail::foreach_cell_around_vertex3<CMap3::Volume, Orbit::PHI21>(m, v, f);
}

// ---- incidences of an edge

/// The two vertices of edge e: the origin of e.dart first.
template <typename FUNC>
void foreach_incident_vertex(const CMap3& m, CellParam<CMap3::Edge> e, const FUNC& f)
{
	if (call_and_continue(f, CMap3::Vertex(e.dart)))
		call_and_continue(f, CMap3::Vertex(phi1(m, e.dart)));
}
/// Faces around edge e, in cyclic order.
template <typename FUNC>
void foreach_incident_face(const CMap3& m, CellParam<CMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Face, void>(m, e, f))
		return;
	Dart it = e.dart;
	do
	{
		if (!call_and_continue(f, CMap3::Face(it)))
			return;
		it = phi3(m, phi2(m, it));
	} while (it != e.dart);
}
/// Volumes around edge e, in cyclic order (boundary volumes skipped).
template <typename FUNC>
void foreach_incident_volume(const CMap3& m, CellParam<CMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Volume, void>(m, e, f))
		return;
	Dart it = e.dart;
	do
	{
		if (!is_boundary(m, it) && !call_and_continue(f, CMap3::Volume(it)))
			return;
		it = phi3(m, phi2(m, it));
	} while (it != e.dart);
}

// ---- incidences of a face

/// Vertices of face f in phi1 order.
template <typename FUNC>
void foreach_incident_vertex(const CMap3& m, CellParam<CMap3::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<CMap3::Vertex, void>(m, f, fn))
		return;
	foreach_dart_of_orbit(m, CMap3::Face2(f.dart), [&](Dart d) { return call_and_continue(fn, CMap3::Vertex(d)); });
}
/// Edges of face f in phi1 order.
template <typename FUNC>
void foreach_incident_edge(const CMap3& m, CellParam<CMap3::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<CMap3::Edge, void>(m, f, fn))
		return;
	foreach_dart_of_orbit(m, CMap3::Face2(f.dart), [&](Dart d) { return call_and_continue(fn, CMap3::Edge(d)); });
}
/// The one or two volumes of face f (boundary volumes skipped).
template <typename FUNC>
void foreach_incident_volume(const CMap3& m, CellParam<CMap3::Face> f, const FUNC& fn)
{
	if (!is_boundary(m, f.dart) && !call_and_continue(fn, CMap3::Volume(f.dart)))
		return;
	const Dart d3 = phi3(m, f.dart);
	if (!is_boundary(m, d3))
		call_and_continue(fn, CMap3::Volume(d3));
}

// ---- incidences of a volume

namespace detail
{
/// When the volume of d is a tetrahedron (four distinct triangles glued
/// pairwise), writes its corners' darts in `corners` (d, phi1 d, phi_1 d and
/// the apex phi_1 phi2 d) and returns true; false otherwise. O(1): 12 phi1 and
/// 6 phi2 reads, no marks, so tet meshes skip the flooding of the general case.
inline bool tetra_corners(const CMap3& m, Dart d, std::array<Dart, 4>& corners)
{
	auto triangle = [&](Dart x, std::array<Dart, 3>& t) {
		t = {x, phi1(m, x), phi1(m, phi1(m, x))};
		return phi1(m, t[2]) == x;
	};
	auto in = [](Dart x, const std::array<Dart, 3>& t) { return x == t[0] || x == t[1] || x == t[2]; };
	// f0 = (d: A -> B, B -> C, C -> A); f1, f2, f3 across its edges, whose
	// other edges must meet two by two at the apex D
	std::array<Dart, 3> f0, f1, f2, f3;
	if (!triangle(d, f0) || !triangle(phi2(m, f0[0]), f1) || !triangle(phi2(m, f0[1]), f2) ||
		!triangle(phi2(m, f0[2]), f3))
		return false;
	if (phi2(m, f1[1]) != f3[2] || phi2(m, f1[2]) != f2[1] || phi2(m, f2[2]) != f3[1])
		return false;
	// a volume of fewer darts glued to itself could pass the tests above
	if (in(f1[0], f0) || in(f2[0], f0) || in(f2[0], f1) || in(f3[0], f0) || in(f3[0], f1) || in(f3[0], f2))
		return false;
	corners = {f0[0], f0[1], f0[2], f1[2]};
	return true;
}
} // namespace detail

/// Vertices of volume w. A tetrahedron's four corners are read directly
/// (detail::tetra_corners); other volumes are flooded with marks.
template <typename FUNC>
void foreach_incident_vertex(const CMap3& m, CellParam<CMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Vertex, void>(m, w, f))
		return;
	if (std::array<Dart, 4> c; detail::tetra_corners(m, w.dart, c))
	{
		for (Dart d : c)
			if (!call_and_continue(f, CMap3::Vertex(d)))
				return;
		return;
	}
	detail::foreach_cell_of_volume<CMap3::Vertex>(m, w.dart, f);
}
/// Edges of volume w.
template <typename FUNC>
void foreach_incident_edge(const CMap3& m, CellParam<CMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Edge, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume<CMap3::Edge>(m, w.dart, f);
}
/// Faces of volume w.
template <typename FUNC>
void foreach_incident_face(const CMap3& m, CellParam<CMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Face, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume<CMap3::Face>(m, w.dart, f);
}

/// Generic form of the incidences above, for a CMap3 or a GMap3: calls f on
/// each cell of type TARGET incident to c. The cost of the incidence called.
template <typename TARGET, typename MAP, typename CELL, typename FUNC>
requires(MAP::dimension == 3) void foreach_incident_cell3(const MAP& m, CELL c, const FUNC& f)
{
	using T = mesh_traits<MAP>;
	if constexpr (std::is_same_v<TARGET, typename T::Vertex>)
		foreach_incident_vertex(m, c, [&](typename T::Vertex x) { return call_and_continue(f, x); });
	else if constexpr (std::is_same_v<TARGET, typename T::Edge>)
		foreach_incident_edge(m, c, [&](typename T::Edge x) { return call_and_continue(f, x); });
	else if constexpr (std::is_same_v<TARGET, typename T::Face>)
		foreach_incident_face(m, c, [&](typename T::Face x) { return call_and_continue(f, x); });
	else
	{
		static_assert(std::is_same_v<TARGET, typename T::Volume>);
		foreach_incident_volume(m, c, [&](typename T::Volume x) { return call_and_continue(f, x); });
	}
}

// ---- adjacencies: X adjacent to x through a common Y, each once, x excluded

namespace detail
{
/// The X cells incident to the Y cells incident to x, each once, x excluded,
/// on a CMap3 or a GMap3: a pooled set of the X cells met (bits in X's
/// container when X is indexed, marks on their darts otherwise).
/// O(sum of the sizes of the cells met).
template <typename X, typename Y, typename MAP, typename FUNC>
void foreach_adjacent3(const MAP& m, X x, const FUNC& f)
{
	LocalCellSet<MAP, X> seen(m);
	seen.insert(x);
	bool go_on = true;
	auto visit_y = [&](Y y) {
		foreach_incident_cell3<X>(m, y, [&](X x2) {
			if (seen.insert(x2))
				go_on = call_and_continue(f, x2);
			return go_on;
		});
		return go_on;
	};
	foreach_incident_cell3<Y>(m, x, visit_y);
}
} // namespace detail

template <typename FUNC>
void foreach_adjacent_vertex_through_edge(const CMap3& m, CellParam<CMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Vertex, CMap3::Edge>(m, v, f))
		return;
	if (is_indexed<CMap3::Vertex>(m) && detail::foreach_adjacent_vertex_by_line(m, v, f))
		return;
	// two edges may join v to the same vertex (and a loop edge to v itself):
	// each neighbour is reported once, v never. Darts are marked, not lines:
	// this walk also serves vertices left without a line by an operator.
	DartMarkerStore<CMap3> seen(m);
	seen.mark_orbit(v);
	foreach_incident_edge(m, v, [&](CMap3::Edge e) {
		// e.dart leaves v (see foreach_cell_around_vertex3): its phi1 starts at the other end
		const CMap3::Vertex w(phi1(m, e.dart));
		if (seen.is_marked(w.dart))
			return true;
		seen.mark_orbit(w);
		return call_and_continue(f, w);
	});
}
template <typename FUNC>
void foreach_adjacent_vertex_through_face(const CMap3& m, CellParam<CMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Vertex, CMap3::Face>(m, v, f))
		return;
	detail::foreach_adjacent3<CMap3::Vertex, CMap3::Face>(m, v, f);
}
template <typename FUNC>
void foreach_adjacent_vertex_through_volume(const CMap3& m, CellParam<CMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Vertex, CMap3::Volume>(m, v, f))
		return;
	detail::foreach_adjacent3<CMap3::Vertex, CMap3::Volume>(m, v, f);
}
template <typename FUNC>
void foreach_adjacent_edge_through_vertex(const CMap3& m, CellParam<CMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Edge, CMap3::Vertex>(m, e, f))
		return;
	detail::foreach_adjacent3<CMap3::Edge, CMap3::Vertex>(m, e, f);
}
template <typename FUNC>
void foreach_adjacent_edge_through_face(const CMap3& m, CellParam<CMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Edge, CMap3::Face>(m, e, f))
		return;
	detail::foreach_adjacent3<CMap3::Edge, CMap3::Face>(m, e, f);
}
template <typename FUNC>
void foreach_adjacent_edge_through_volume(const CMap3& m, CellParam<CMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Edge, CMap3::Volume>(m, e, f))
		return;
	detail::foreach_adjacent3<CMap3::Edge, CMap3::Volume>(m, e, f);
}
template <typename FUNC>
void foreach_adjacent_face_through_vertex(const CMap3& m, CellParam<CMap3::Face> fc, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Face, CMap3::Vertex>(m, fc, f))
		return;
	detail::foreach_adjacent3<CMap3::Face, CMap3::Vertex>(m, fc, f);
}
template <typename FUNC>
void foreach_adjacent_face_through_edge(const CMap3& m, CellParam<CMap3::Face> fc, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Face, CMap3::Edge>(m, fc, f))
		return;
	detail::foreach_adjacent3<CMap3::Face, CMap3::Edge>(m, fc, f);
}
template <typename FUNC>
void foreach_adjacent_face_through_volume(const CMap3& m, CellParam<CMap3::Face> fc, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Face, CMap3::Volume>(m, fc, f))
		return;
	detail::foreach_adjacent3<CMap3::Face, CMap3::Volume>(m, fc, f);
}
template <typename FUNC>
void foreach_adjacent_volume_through_vertex(const CMap3& m, CellParam<CMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Volume, CMap3::Vertex>(m, w, f))
		return;
	detail::foreach_adjacent3<CMap3::Volume, CMap3::Vertex>(m, w, f);
}
template <typename FUNC>
void foreach_adjacent_volume_through_edge(const CMap3& m, CellParam<CMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Volume, CMap3::Edge>(m, w, f))
		return;
	detail::foreach_adjacent3<CMap3::Volume, CMap3::Edge>(m, w, f);
}
template <typename FUNC>
void foreach_adjacent_volume_through_face(const CMap3& m, CellParam<CMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<CMap3::Volume, CMap3::Face>(m, w, f))
		return;
	detail::foreach_adjacent3<CMap3::Volume, CMap3::Face>(m, w, f);
}

} // namespace cgogn
