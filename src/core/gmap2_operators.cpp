// SPDX-License-Identifier: MIT
// Operators of 2-G-maps: cut an edge, cut a face, merge the faces of an edge.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/operators/gmap2.h>

#include "gmap_darts.h"
#include "reindex.h"

#include <cassert>

namespace cgogn
{

GMap2::Vertex cut_edge(GMap2& m, GMap2::Edge e, bool set_indices)
{
	const std::array<Dart, 4> old = detail::edge_darts(m, e.dart);
	std::vector<Dart> region(old.begin(), old.end());
	detail::RegionReindexer<GMap2> reindex;
	const bool rules = set_indices && detail::has_rules(m);
	// a dart at the far end that the cut does not move: old[1], the beta0
	// of e.dart, moves to the new vertex
	const Dart far_end = rules ? beta1(m, old[1]) : Dart();
	if (set_indices)
		reindex.record(m, region);
	const std::vector<Dart> added = detail::insert_vertex_in_edge(m, e.dart);
	region.insert(region.end(), added.begin(), added.end());
	if (set_indices)
	{
		reindex.apply(m, region);
		// rules: the new vertex between the ends; the new half of the edge,
		// made of new darts only (the reindexing cannot tell it is a part of
		// the edge), a copy of the half that kept the edge's darts
		if (rules)
		{
			detail::inherit_midpoint<GMap2::Vertex::ORBIT>(m, added[0], old[0], far_end);
			detail::inherit<GMap2::Edge::ORBIT>(m, added[0], old[0]);
		}
	}
	return GMap2::Vertex(added[0]);
}

bool detail::corners_can_be_joined(const GMap2& m, Dart d, Dart e)
{
	bool same_face = false;
	foreach_dart_of_orbit(m, GMap2::Face(d), [&](Dart x) { return !(same_face = x == e); });
	if (!same_face)
		return false;
	const Dart e1 = beta1(m, e);
	if (e == d || e1 == d)
		return false; // the same corner
	// joined by an edge of the face: e or beta1(e) is beta0 of d's corner
	for (Dart x : {d, beta1(m, d)})
		if (beta0(m, x) == e || beta0(m, x) == e1)
			return false;
	return true;
}

detail::FaceSideCut detail::split_face_side(GMap2& m, Dart d, Dart e)
{
	const Dart d1 = beta1(m, d), e1 = beta1(m, e);
	// f: the dart of e's corner met first walking from d away from d1 (beta0
	// first); the part d ... f is d's
	Dart f = Dart();
	for (Dart x = d;;)
	{
		x = beta0(m, x);
		if (x == e || x == e1)
		{
			f = x;
			break;
		}
		x = beta1(m, x);
	}
	const Dart g = f == e ? e1 : e;
	const Dart p = new_dart_pair_like(m, d), q = new_dart_pair_like(m, d);
	const FaceSideCut c{p, beta0(m, p), q, beta0(m, q)};
	beta_unsew<1>(m, d);
	beta_unsew<1>(m, e);
	beta_sew<1>(m, d, c.p);
	beta_sew<1>(m, f, c.p0);
	beta_sew<1>(m, d1, c.q);
	beta_sew<1>(m, g, c.q0);
	beta_sew<2>(m, c.p, c.q);
	beta_sew<2>(m, c.p0, c.q0);
	return c;
}

bool can_cut_face(const GMap2& m, GMap2::Vertex v1, GMap2::Vertex v2)
{
	return !is_boundary(m, v1.dart) && !is_boundary(m, v2.dart) && detail::corners_can_be_joined(m, v1.dart, v2.dart);
}

GMap2::Edge cut_face(GMap2& m, GMap2::Vertex v1, GMap2::Vertex v2, bool set_indices)
{
	assert(can_cut_face(m, v1, v2));
	const Dart d = v1.dart, e = v2.dart;
	std::vector<Dart> region{d, beta1(m, d), e, beta1(m, e)};
	detail::RegionReindexer<GMap2> reindex;
	if (set_indices)
		reindex.record(m, region);
	const detail::FaceSideCut c = detail::split_face_side(m, d, e);
	region.insert(region.end(), {c.p, c.p0, c.q, c.q0});
	if (set_indices)
		reindex.apply(m, region);
	return GMap2::Edge(c.p);
}

bool can_merge_incident_faces(const GMap2& m, GMap2::Edge e)
{
	const Dart d = e.dart, d2 = beta2(m, d);
	if (is_boundary(m, d) || is_boundary(m, d2))
		return false;
	return !same_orbit(m, GMap2::Face(d), GMap2::Face(d2));
}

GMap2::Face merge_incident_faces(GMap2& m, GMap2::Edge e, bool set_indices)
{
	assert(can_merge_incident_faces(m, e));
	const std::array<Dart, 4> edge = detail::edge_darts(m, e.dart);
	// the corners around the edge: at d's end a = beta1(d) in d's face and
	// b = beta1(beta2(d)) in the other; at the other end, the same from beta0(d)
	const Dart a = beta1(m, edge[0]), b = beta1(m, edge[2]);
	const Dart a0 = beta1(m, edge[1]), b0 = beta1(m, edge[3]);
	std::vector<Dart> region(edge.begin(), edge.end());
	region.insert(region.end(), {a, b, a0, b0});
	detail::RegionReindexer<GMap2> reindex;
	if (set_indices)
		reindex.record(m, region);
	for (Dart x : edge)
		beta_unsew<1>(m, x);
	beta_sew<1>(m, a, b);
	beta_sew<1>(m, a0, b0);
	detail::remove_dart_pair(m, edge[0]);
	detail::remove_dart_pair(m, edge[2]);
	const std::vector<Dart> kept{a, b, a0, b0};
	if (set_indices)
		reindex.apply(m, kept);
	return GMap2::Face(a);
}

} // namespace cgogn
