// SPDX-License-Identifier: MIT
// Edge operators of 2-G-maps: collapse and flip.
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/operators/gmap2.h>
#include <cgogn/core/properties/gmap_properties.h>

#include "gmap_darts.h"
#include "index_lines.h"
#include "reindex.h"

#include <algorithm>
#include <cassert>

namespace cgogn
{

namespace
{
constexpr Orbit V = Orbit::BETA1_BETA2;
constexpr Orbit F = Orbit::BETA0_BETA1;

bool same_vertex(const GMap2& m, Dart a, Dart b)
{
	return same_orbit(m, GMap2::Vertex(a), GMap2::Vertex(b));
}

// True when the two vertices are the same or joined by an edge: O(degree of
// both) with a dart mark (beta0 of a dart of a vertex is a dart of the
// neighbour along its edge).
bool adjacent_or_same(const GMap2& m, GMap2::Vertex a, GMap2::Vertex b)
{
	DartMarkerStore<GMap2> around_b(m);
	around_b.mark_orbit(b);
	if (around_b.is_marked(a.dart))
		return true;
	bool adjacent = false;
	foreach_dart_of_orbit(m, a, [&](Dart x) { return !(adjacent = around_b.is_marked(beta0(m, x))); });
	return adjacent;
}

// A vertex of degree >= 3: walking around it from d by beta2 o beta1 takes
// at least 3 steps to come back.
bool degree_at_least_3(const GMap2& m, Dart d)
{
	const Dart x = beta<1, 2>(m, d);
	return x != d && beta<1, 2>(m, x) != d;
}

bool on_boundary_edge(const GMap2& m, Dart x)
{
	return is_boundary(m, x) || is_boundary(m, beta2(m, x));
}
} // namespace

bool can_collapse_edge(const GMap2& m, GMap2::Edge e)
{
	const Dart d = e.dart, d0 = beta0(m, d), d2 = beta2(m, d);
	if (same_orbit(m, GMap2::Face(d), GMap2::Face(d2)))
		return false;
	if (same_vertex(m, d, d0))
		return false; // a loop: nothing to contract
	const uint32 deg1 = codegree(m, GMap2::Face(d)), deg2 = codegree(m, GMap2::Face(d2));
	if (deg1 < 3 || deg2 < 3)
		return false;
	// vertices opposite to e in its triangles (the outside counts as a vertex):
	// two edges away from d in its face
	const Dart opp1 = deg1 == 3 ? beta<1, 0>(m, d) : Dart();
	const Dart opp2 = deg2 == 3 ? beta<1, 0>(m, d2) : Dart();
	if (opp1.is_valid() && opp2.is_valid() && same_vertex(m, opp1, opp2))
		return false; // two triangles (or a triangle and a triangular hole) on the same three vertices
	const bool a_boundary = is_incident_to_boundary(m, GMap2::Vertex(d));
	const bool b_boundary = is_incident_to_boundary(m, GMap2::Vertex(d0));
	if (a_boundary && b_boundary && !is_boundary(m, d) && !is_boundary(m, d2))
		return false; // would pinch two boundary parts together
	if (a_boundary && b_boundary)
	{
		// a vertex joined to both ends by boundary edges (other than e) would
		// get an edge with the boundary on both sides
		DartMarkerStore<GMap2> ends_from_a(m);
		foreach_dart_of_orbit(m, GMap2::Vertex(d), [&](Dart x) {
			if (x != d && x != d2 && on_boundary_edge(m, x))
				ends_from_a.mark_orbit(GMap2::Vertex(beta0(m, x)));
		});
		bool shared = false;
		foreach_dart_of_orbit(m, GMap2::Vertex(d0), [&](Dart y) {
			shared = !same_orbit(m, GMap2::Edge(y), e) && on_boundary_edge(m, y) && ends_from_a.is_marked(beta0(m, y));
			return !shared;
		});
		if (shared)
			return false;
	}
	// the link condition: every neighbour of both ends is opposite to e in a
	// (non-boundary) triangle
	DartMarkerStore<GMap2> around_a(m);
	foreach_dart_of_orbit(m, GMap2::Vertex(d), [&](Dart x) { around_a.mark_orbit(GMap2::Vertex(beta0(m, x))); });
	bool ok = true;
	foreach_dart_of_orbit(m, GMap2::Vertex(d0), [&](Dart y) {
		const Dart w = beta0(m, y); // a dart of a neighbour of b
		if (same_orbit(m, GMap2::Edge(y), e) || !around_a.is_marked(w))
			return true;
		ok = (opp1.is_valid() && !is_boundary(m, d) && same_vertex(m, w, opp1)) ||
			 (opp2.is_valid() && !is_boundary(m, d2) && same_vertex(m, w, opp2));
		return ok;
	});
	return ok;
}

namespace
{
// After a collapse, face (p, beta0(p), q, beta0(q)) with beta1(p) == q may
// have 2 edges: then it is removed and its two edges become one (the darts
// outside it are glued by beta2). Returns true when it was removed; its four
// darts are appended to `removed`.
bool remove_if_two_gon(GMap2& m, Dart p, Dart q, std::vector<Dart>& removed)
{
	const Dart p0 = beta0(m, p), q0 = beta0(m, q);
	if (beta1(m, p0) != q0)
		return false;
	const Dart p2 = beta2(m, p), q2 = beta2(m, q), p02 = beta2(m, p0), q02 = beta2(m, q0);
	detail::link_beta<2>(m, p2, q2);
	detail::link_beta<2>(m, p02, q02);
	removed.insert(removed.end(), {p, p0, q, q0});
	return true;
}
} // namespace

GMap2::Vertex collapse_edge(GMap2& m, GMap2::Edge e, bool set_indices)
{
	assert(can_collapse_edge(m, e));
	const std::array<Dart, 4> edge = detail::edge_darts(m, e.dart); // d (a), d0 (b), d2 (a), d20 (b)
	// the other darts of the corners of e: at a (p, r) and b (q, s), in d's face (p, q) and the other (r, s)
	const Dart p = beta1(m, edge[0]), q = beta1(m, edge[1]), r = beta1(m, edge[2]), s = beta1(m, edge[3]);
	// b's darts first: the surviving vertex, and the merged edges, keep b's lines
	std::vector<Dart> region{q, s, beta2(m, q), beta2(m, s), p, r, beta2(m, p), beta2(m, r)};
	// the opposite vertices of the triangles, also by darts outside them
	for (Dart x : {p, q, r, s})
		region.insert(region.end(), {beta0(m, x), beta<0, 2>(m, x)});
	detail::RegionReindexer<GMap2> reindex;
	if (set_indices)
	{
		reindex.record(m, region);
		reindex.record(m, {edge.begin(), edge.end()});
	}
	detail::link_beta<1>(m, p, q);
	detail::link_beta<1>(m, r, s);
	std::vector<Dart> removed(edge.begin(), edge.end());
	remove_if_two_gon(m, p, q, removed);
	remove_if_two_gon(m, r, s, removed);
	std::erase_if(region, [&](Dart x) { return std::find(removed.begin(), removed.end(), x) != removed.end(); });
	detail::remove_dart_pairs(m, removed);
	assert(!region.empty());
	if (set_indices)
		reindex.apply(m, region);
	return GMap2::Vertex(region.front());
}

bool can_flip_edge(const GMap2& m, GMap2::Edge e)
{
	const Dart d = e.dart, d2 = beta2(m, d);
	if (is_boundary(m, d) || is_boundary(m, d2) || same_orbit(m, GMap2::Face(d), GMap2::Face(d2)))
		return false;
	if (codegree(m, GMap2::Face(d)) < 3 || codegree(m, GMap2::Face(d2)) < 3)
		return false;
	if (!degree_at_least_3(m, d) || !degree_at_least_3(m, beta0(m, d)))
		return false;
	// the new ends: the vertex after beta0(d) in d's face, the one after d in d2's
	const Dart c = beta<0, 1, 0>(m, d), dd = beta<1, 0>(m, d2);
	return !adjacent_or_same(m, GMap2::Vertex(c), GMap2::Vertex(dd));
}

void flip_edge(GMap2& m, GMap2::Edge e, bool set_indices)
{
	assert(can_flip_edge(m, e));
	// d at a, d0 at b, in face f1 = (a, b, c, ...); d2 at a, d20 at b, in f2 = (b, a, dd, ...)
	const auto [d, d0, d2, d20] = detail::edge_darts(m, e.dart);
	const Dart p = beta1(m, d);   // a, in f1, towards the vertex before a
	const Dart q = beta1(m, d0);  // b, on edge (b, c), which moves to f2
	const Dart q0 = beta0(m, q);  // c, on edge (b, c)
	const Dart u = beta1(m, q0);  // c, in f1, on the next edge
	const Dart r = beta1(m, d2);  // a, on edge (a, dd), which moves to f1
	const Dart r0 = beta0(m, r);  // dd, on edge (a, dd)
	const Dart w = beta1(m, r0);  // dd, in f2, on the next edge
	const Dart s = beta1(m, d20); // b, in f2
	// f1 = (..., a, dd, c, ...): d at dd, d0 at c; f2 = (..., dd, c, b, ...): d2 at dd, d20 at c
	detail::link_beta<1>(m, p, r);
	detail::link_beta<1>(m, r0, d);
	detail::link_beta<1>(m, d0, u);
	detail::link_beta<1>(m, w, d2);
	detail::link_beta<1>(m, d20, q0);
	detail::link_beta<1>(m, q, s);
	if (!set_indices)
		return;
	// faces: the edges (a, dd) and (b, c) changed faces
	for (Dart x : {r, r0})
		detail::copy_dart_index<F>(m, x, d);
	for (Dart x : {q, q0})
		detail::copy_dart_index<F>(m, x, d2);
	detail::set_representative<F>(m, d);
	detail::set_representative<F>(m, d2);
	// vertices: the four darts of e changed vertices; a and b keep p and q
	detail::set_representative<V>(m, p);
	detail::set_representative<V>(m, q);
	for (Dart x : {d, d2})
		detail::copy_dart_index<V>(m, x, r0);
	for (Dart x : {d0, d20})
		detail::copy_dart_index<V>(m, x, q0);
}

bool can_flip_back_edge(const GMap2& m, GMap2::Edge e)
{
	return can_flip_edge(m, GMap2::Edge(beta0(m, e.dart)));
}

void flip_back_edge(GMap2& m, GMap2::Edge e, bool set_indices)
{
	flip_edge(m, GMap2::Edge(beta0(m, e.dart)), set_indices);
}

} // namespace cgogn
