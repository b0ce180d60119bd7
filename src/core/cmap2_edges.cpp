// SPDX-License-Identifier: MIT
// Edge operators of 2-maps: cut, collapse, flip.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/properties/properties.h>

#include "index_lines.h"

#include <algorithm>
#include <array>
#include <initializer_list>

namespace cgogn
{

namespace
{
constexpr Orbit V = Orbit::PHI21;
constexpr Orbit E = Orbit::PHI2;
constexpr Orbit F = Orbit::PHI1;
constexpr Orbit W = Orbit::PHI1_PHI2;

// Inserts a new dart after d in its face; it takes d's face, volume and boundary.
Dart insert_after(CMap2& m, Dart d, bool set_indices)
{
	const Dart nd = detail::add_dart(m);
	detail::set_phi1(m, nd, phi1(m, d));
	detail::set_phi1(m, d, nd);
	detail::set_boundary(m, nd, is_boundary(m, d));
	if (set_indices)
	{
		detail::copy_dart_index<F>(m, nd, d);
		detail::copy_dart_index<W>(m, nd, d);
	}
	return nd;
}

// True when vertices c and y are the same vertex or joined by an edge, from
// the topology alone: O(degree of c + degree of y) with a dart mark.
bool adjacent_or_same_by_topology(const CMap2& m, CMap2::Vertex c, CMap2::Vertex y)
{
	DartMarkerStore<CMap2> around_y(m);
	around_y.mark_orbit(y);
	if (around_y.is_marked(c.dart))
		return true;
	bool adjacent = false;
	// phi2(x) starts at the neighbour of c along x
	foreach_dart_of_orbit(m, c, [&](Dart x) { return !(adjacent = around_y.is_marked(phi2(m, x))); });
	return adjacent;
}

// The same in O(degree of c) when vertices are indexed: the lines of c's
// neighbours are compared with y's (reading an index is cheaper than marking
// y's darts: 1.7x faster on the sqrt(3) benchmark's flips). Darts left
// without a line (set_indices = false) send it to the topology; lines that
// are wrong (changed behind the library's back) are caught in debug builds.
bool adjacent_or_same(const CMap2& m, CMap2::Vertex c, CMap2::Vertex y)
{
	const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(V)];
	const uint32 iy = idx ? (*idx)[y.dart.index] : INVALID_INDEX;
	if (iy == INVALID_INDEX)
		return adjacent_or_same_by_topology(m, c, y);
	// a dart without a line (an operator called with set_indices = false):
	// the lines cannot tell, the topology does
	bool unindexed = false;
	const auto same_as_y = [&](Dart x) {
		const uint32 ix = (*idx)[x.index];
		unindexed = unindexed || ix == INVALID_INDEX;
		return ix == iy;
	};
	bool adjacent = same_as_y(c.dart);
	if (!adjacent)
		foreach_dart_of_orbit(m, c, [&](Dart x) { return !(adjacent = same_as_y(phi2(m, x))); });
	if (unindexed && !adjacent)
		return adjacent_or_same_by_topology(m, c, y);
	assert(adjacent == adjacent_or_same_by_topology(m, c, y) && "vertex indices out of date (see index_cells)");
	return adjacent;
}
} // namespace

CMap2::Vertex cut_edge(CMap2& m, CMap2::Edge e, bool set_indices)
{
	const Dart d = e.dart;
	const Dart d2 = phi2(m, d);
	const Dart n1 = insert_after(m, d, set_indices);  // new vertex -> end of d
	const Dart n2 = insert_after(m, d2, set_indices); // new vertex -> origin of d
	phi2_unsew(m, d);
	phi2_sew(m, d, n2);
	phi2_sew(m, d2, n1);
	if (set_indices)
	{
		detail::index_new_cell(m, CMap2::Vertex(n1));
		// the half {d, n2} keeps the edge's line, {n1, d2} gets a new one
		detail::copy_dart_index<E>(m, n2, d);
		detail::set_dart_index<E>(m, n1, INVALID_INDEX);
		detail::set_dart_index<E>(m, d2, INVALID_INDEX);
		detail::index_new_cell(m, CMap2::Edge(n1));
		detail::set_representative<E>(m, d);
		// rules: the new vertex between the ends, its corners between the
		// corners of the ends in their faces, the new half of the edge its copy
		if (detail::has_rules(m))
		{
			detail::inherit_midpoint<V>(m, n1, d, phi1(m, n1));
			detail::inherit<E>(m, n1, d);
			detail::inherit_midpoint<Orbit::DART>(m, n1, d, phi1(m, n1));
			detail::inherit_midpoint<Orbit::DART>(m, n2, d2, phi1(m, n2));
		}
	}
	return CMap2::Vertex(n1);
}

bool can_collapse_edge(const CMap2& m, CMap2::Edge e)
{
	const Dart d = e.dart;
	const Dart d2 = phi2(m, d);
	if (same_orbit(m, CMap2::Face(d), CMap2::Face(d2)))
		return false;
	if (same_orbit(m, CMap2::Vertex(d), CMap2::Vertex(d2)))
		return false; // a loop: nothing to contract
	const uint32 deg1 = codegree(m, CMap2::Face(d)), deg2 = codegree(m, CMap2::Face(d2));
	if (deg1 < 3 || deg2 < 3)
		return false;
	// vertices opposite to e in its triangles (the outside counts as a vertex)
	const Dart opp1 = deg1 == 3 ? phi_1(m, d) : Dart();
	const Dart opp2 = deg2 == 3 ? phi_1(m, d2) : Dart();
	if (opp1.is_valid() && opp2.is_valid() && same_orbit(m, CMap2::Vertex(opp1), CMap2::Vertex(opp2)))
		return false; // two triangles (or a triangle and a triangular hole) on the same three vertices
	const bool a_boundary = is_incident_to_boundary(m, CMap2::Vertex(d));
	const bool b_boundary = is_incident_to_boundary(m, CMap2::Vertex(d2));
	if (a_boundary && b_boundary && !is_boundary(m, d) && !is_boundary(m, d2))
		return false; // would pinch two boundary parts together
	if (a_boundary && b_boundary)
	{
		// the edge part of the link condition, with the outside as a vertex: a
		// vertex c joined to a and to b by boundary edges puts the edge
		// (c, outside) in the links of both ends, never in the link of e (a
		// set of vertices): the collapse would glue two boundary edges into an
		// edge with the boundary on both sides
		const auto on_boundary = [&](Dart x) { return is_boundary(m, x) || is_boundary(m, phi2(m, x)); };
		DartMarkerStore<CMap2> ends_from_a(m);
		foreach_dart_of_orbit(m, CMap2::Vertex(d), [&](Dart x) {
			if (x != d && on_boundary(x))
				ends_from_a.mark_orbit(CMap2::Vertex(phi2(m, x)));
		});
		bool shared = false;
		foreach_dart_of_orbit(m, CMap2::Vertex(d2), [&](Dart y) {
			shared = y != d2 && on_boundary(y) && ends_from_a.is_marked(phi2(m, y));
			return !shared;
		});
		if (shared)
			return false;
	}
	// neighbours of a, marked; every neighbour of b among them must be opposite
	DartMarkerStore<CMap2> around_a(m);
	foreach_dart_of_orbit(m, CMap2::Vertex(d), [&](Dart x) { around_a.mark_orbit(CMap2::Vertex(phi2(m, x))); });
	bool ok = true;
	foreach_dart_of_orbit(m, CMap2::Vertex(d2), [&](Dart y) {
		const Dart w = phi2(m, y); // a dart of a neighbour of b
		if (w == d || !around_a.is_marked(w))
			return true;
		const bool opposite =
			(opp1.is_valid() && !is_boundary(m, d) && same_orbit(m, CMap2::Vertex(w), CMap2::Vertex(opp1))) ||
			(opp2.is_valid() && !is_boundary(m, d2) && same_orbit(m, CMap2::Vertex(w), CMap2::Vertex(opp2)));
		ok = opposite;
		return ok;
	});
	return ok;
}

namespace
{
// When `from`, about to be removed, represents its cell of orbit O, `to` (a
// dart of the same cell) does instead.
template <Orbit O>
void hand_over_representative(CMap2& m, Dart from, Dart to)
{
	const uint32 line = detail::index_or_invalid<O>(m, from);
	if (line != INVALID_INDEX)
	{
		uint32& key = detail::state_of(m).cells[orbit_index(O)]->key()[line];
		if (key == from.index)
			key = to.index;
	}
}

// Dart s takes the place of dart t in t's face (t is about to be removed):
// same neighbours in the cycle, same boundary mark, same face and volume lines.
void take_place_in_face(CMap2& m, Dart s, Dart t, bool set_indices)
{
	const Dart next = phi1(m, t);
	const Dart prev = phi_1(m, t);
	detail::set_phi1(m, s, next == t ? s : next);
	detail::set_phi1(m, prev == t ? s : prev, s);
	detail::set_boundary(m, s, is_boundary(m, t));
	if (set_indices)
	{
		detail::copy_dart_index<F>(m, s, t);
		detail::copy_dart_index<W>(m, s, t);
		detail::set_representative<F>(m, s);
		detail::set_representative<W>(m, s);
	}
}

// Removes the face {p, n} reduced to two edges after a collapse. Its two edges
// {p, pp} and {n, nn} (pp = phi2(p), nn = phi2(n)) become one: the one whose
// lower dart is lower survives whole (both darts, its line), its 2-gon dart
// taking the place of the outer dart of the other edge. So a collapse that
// undoes a split gives back the darts the split found (they are older, hence
// lower, than the ones it added) instead of scattering new ones among them.
// The face that receives the dart takes the lower of its line and the 2-gon's
// (the other is released). The darts the caller still holds (`held`) that
// this removes are replaced by the dart that takes their place (same face
// position, same origin).
void remove_two_gon(CMap2& m, Dart p, std::initializer_list<Dart*> held, bool set_indices)
{
	const Dart n = phi1(m, p);
	const Dart pp = phi2(m, p), nn = phi2(m, n);
	const bool keep_n = std::min(n.index, nn.index) < std::min(p.index, pp.index);
	const Dart s = keep_n ? n : p;    // 2-gon dart of the surviving edge
	const Dart s2 = keep_n ? nn : pp; // its phi2, stays in place
	const Dart t = keep_n ? pp : nn;  // outer dart of the other edge: s takes its place
	const Dart r = keep_n ? p : n;    // 2-gon dart of the other edge (t == phi2(r))
	const uint32 two_gon_line = detail::index_or_invalid<F>(m, s);
	const uint32 gone_edge_line = detail::index_or_invalid<E>(m, r);
	take_place_in_face(m, s, t, set_indices);
	if (set_indices)
	{
		detail::release_index<E>(m, gone_edge_line);
		detail::set_representative<E>(m, s);
		// r and s2 start at the same vertex (as do t and s); s2 is a dart of a
		// neighbouring face, often far in memory: read the (smaller) vertex keys instead
		hand_over_representative<V>(m, r, s2);
		hand_over_representative<V>(m, t, s);
		const uint32 face_line = detail::index_or_invalid<F>(m, s);
		if (two_gon_line != INVALID_INDEX && face_line != INVALID_INDEX && two_gon_line < face_line)
		{
			detail::write_index(m, CMap2::Face(s), two_gon_line);
			detail::release_index<F>(m, face_line);
		}
		else
			detail::release_index<F>(m, two_gon_line);
	}
	detail::remove_dart(m, r);
	detail::remove_dart(m, t);
	for (Dart* h : held)
		if (*h == r)
			*h = s2; // r is a 2-gon dart: no face position to keep, s2 leaves the same vertex
		else if (*h == t)
			*h = s;
}
} // namespace

CMap2::Vertex collapse_edge(CMap2& m, CMap2::Edge e, bool set_indices)
{
	assert(can_collapse_edge(m, e));
	const Dart d = e.dart;      // a -> b, a disappears
	const Dart d2 = phi2(m, d); // b -> a
	const uint32 a_line = detail::index_or_invalid<V>(m, d);
	const uint32 b_line = detail::index_or_invalid<V>(m, d2);
	// the darts leaving a: only they need b's line afterwards (b's darts are
	// often far apart in memory: rewriting them all cost more than the rest
	// of the collapse); a vertex too large for the buffer is rewritten whole
	std::array<Dart, 32> a_darts;
	uint32 nb_a_darts = 0;
	const bool relabel_a_only = set_indices && a_line != INVALID_INDEX && b_line != INVALID_INDEX &&
								foreach_dart_of_orbit(m, CMap2::Vertex(d), [&](Dart x) {
									if (nb_a_darts == a_darts.size())
										return false;
									a_darts[nb_a_darts++] = x;
									return true;
								});
	const Dart p1 = phi_1(m, d), n1 = phi1(m, d);
	const Dart p2 = phi_1(m, d2), n2 = phi1(m, d2);
	// 1. take the edge out of both faces
	detail::set_phi1(m, p1, n1);
	detail::set_phi1(m, p2, n2);
	if (set_indices)
	{
		detail::release_index<E>(m, detail::index_or_invalid<E>(m, d));
		detail::set_representative<F>(m, n1);
		detail::set_representative<F>(m, n2);
		detail::set_representative<W>(m, n1);
	}
	detail::remove_dart(m, d);
	detail::remove_dart(m, d2);
	// the surviving vertex: n1 starts at b (and so does n2 now)
	Dart keep = n1;
	// 2. remove the faces reduced to 2 edges: their two edges become one
	// (the first removal may replace p2: when the first triangle shares an
	// edge with the second face, of degree >= 4 then)
	Dart second = p2;
	if (phi1(m, phi1(m, p1)) == p1)
		remove_two_gon(m, p1, {&keep, &second}, set_indices);
	if (phi1(m, phi1(m, second)) == second)
		remove_two_gon(m, second, {&keep}, set_indices);
	if (relabel_a_only)
	{
		// a's surviving darts: still live, not reused (a collapse allocates nothing)
		for (uint32 i = 0; i < nb_a_darts; ++i)
			if (is_dart_valid(m, a_darts[i]))
				detail::set_dart_index<V>(m, a_darts[i], b_line);
		detail::set_representative<V>(m, keep);
		detail::release_index<V>(m, a_line);
	}
	else if (set_indices && detail::state_of(m).cell_index[orbit_index(V)] != nullptr)
		detail::merge_cell_indices(m, CMap2::Vertex(keep), b_line, a_line);
	return CMap2::Vertex(keep);
}

namespace
{
// The conditions shared by both directions of a flip: both sides are distinct
// non-boundary faces of at least 3 edges and both end vertices have degree >= 3.
bool flip_sides_allowed(const CMap2& m, Dart d, Dart d2)
{
	if (is_boundary(m, d) || is_boundary(m, d2))
		return false;
	// faces of at least 3 edges (phi1(phi1(x)) == x for 1 or 2 edges), distinct
	const Dart d1 = phi1(m, d), e1 = phi1(m, d2);
	if (phi1(m, d1) == d || phi1(m, e1) == d2 || same_orbit(m, CMap2::Face(d), CMap2::Face(d2)))
		return false;
	// end vertices of degree >= 3: the vertex of d is (d, e1, phi<2, 1>(e1), ...)
	return !(e1 == d || phi<2, 1>(m, e1) == d || d1 == d2 || phi<2, 1>(m, d1) == d2);
}
} // namespace

bool can_flip_edge(const CMap2& m, CMap2::Edge e)
{
	const Dart d = e.dart;
	const Dart d2 = phi2(m, d);
	if (!flip_sides_allowed(m, d, d2))
		return false;
	// the new edge joins the end of phi1(d2) and the end of phi1(d): they must
	// be distinct and not adjacent already (the one walk around a vertex that
	// Surface_mesh's is_flip_topologically_allowed also makes)
	return !adjacent_or_same(m, CMap2::Vertex(phi<1, 1>(m, d)), CMap2::Vertex(phi<1, 1>(m, d2)));
}

bool can_flip_back_edge(const CMap2& m, CMap2::Edge e)
{
	const Dart d = e.dart;
	const Dart d2 = phi2(m, d);
	if (!flip_sides_allowed(m, d, d2))
		return false;
	// the new edge joins the origins of phi_1(d) and phi_1(d2), which differ
	// from the forward flip's ends unless both faces are triangles
	return !adjacent_or_same(m, CMap2::Vertex(phi_1(m, d)), CMap2::Vertex(phi_1(m, d2)));
}

namespace
{
// Indices after a flip: two darts changed faces, d and d2 changed origins.
void fix_after_flip(CMap2& m, Dart d, Dart d2, Dart moved_to_f2, Dart moved_to_f1, Dart origin_of_d, Dart origin_of_d2,
					Dart rep_old_origin_d, Dart rep_old_origin_d2)
{
	// faces: the dart that moved takes the index of its new face
	detail::copy_dart_index<F>(m, moved_to_f2, d2);
	detail::copy_dart_index<F>(m, moved_to_f1, d);
	detail::set_representative<F>(m, d);
	detail::set_representative<F>(m, d2);
	// vertices: d and d2 have new origins; their old vertices need another representative
	detail::set_representative<V>(m, rep_old_origin_d);
	detail::set_representative<V>(m, rep_old_origin_d2);
	detail::copy_dart_index<V>(m, d, origin_of_d);
	detail::copy_dart_index<V>(m, d2, origin_of_d2);
	// corners: d and d2 take the corner of the dart that started at their
	// new origin in the face they joined
	if (detail::has_rules(m))
	{
		detail::inherit<Orbit::DART>(m, d, origin_of_d);
		detail::inherit<Orbit::DART>(m, d2, origin_of_d2);
	}
}
} // namespace

void flip_edge(CMap2& m, CMap2::Edge e, bool set_indices)
{
	assert(can_flip_edge(m, e));
	const Dart d = e.dart, d2 = phi2(m, d);
	const Dart d1 = phi1(m, d), d11 = phi1(m, d1), dp = phi_1(m, d);
	const Dart e1 = phi1(m, d2), e11 = phi1(m, e1), ep = phi_1(m, d2);
	// face of d: (d, d1, d11, ..., dp) -> (d, d11, ..., dp, e1)
	// face of d2: (d2, e1, e11, ..., ep) -> (d2, e11, ..., ep, d1)
	detail::set_phi1(m, d, d11);
	detail::set_phi1(m, dp, e1);
	detail::set_phi1(m, e1, d);
	detail::set_phi1(m, d2, e11);
	detail::set_phi1(m, ep, d1);
	detail::set_phi1(m, d1, d2);
	if (set_indices)
		fix_after_flip(m, d, d2, d1, e1, e11, d11, e1, d1);
}

void flip_back_edge(CMap2& m, CMap2::Edge e, bool set_indices)
{
	assert(can_flip_back_edge(m, e));
	const Dart d = e.dart, d2 = phi2(m, d);
	const Dart d1 = phi1(m, d), dp = phi_1(m, d), dpp = phi_1(m, dp);
	const Dart e1 = phi1(m, d2), ep = phi_1(m, d2), epp = phi_1(m, ep);
	// face of d: (d, d1, ..., dpp, dp) -> (d, ep, d1, ..., dpp)
	// face of d2: (d2, e1, ..., epp, ep) -> (d2, dp, e1, ..., epp)
	detail::set_phi1(m, dpp, d);
	detail::set_phi1(m, d, ep);
	detail::set_phi1(m, ep, d1);
	detail::set_phi1(m, epp, d2);
	detail::set_phi1(m, d2, dp);
	detail::set_phi1(m, dp, e1);
	if (set_indices)
		// d now starts where dp starts, d2 where ep starts
		fix_after_flip(m, d, d2, dp, ep, dp, ep, e1, d1);
}

} // namespace cgogn
