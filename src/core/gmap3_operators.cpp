// SPDX-License-Identifier: MIT
// Operators of 3-G-maps: cut and merge edges, faces and volumes; sew and
// unsew volumes.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/operators/gmap3.h>
#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/properties/properties.h>

#include "gmap3_close.h"
#include "gmap_darts.h"
#include "reindex.h"

#include <algorithm>
#include <cassert>

namespace cgogn
{

namespace
{
bool contains(const std::vector<Dart>& v, Dart d)
{
	return std::find(v.begin(), v.end(), d) != v.end();
}

// A face side of at least 3 edges: turning by beta0 o beta1 takes 3 steps or
// more to come back.
bool at_least_3_edges(const GMap3& m, Dart d)
{
	const Dart x = beta<0, 1>(m, d);
	return x != d && beta<0, 1>(m, x) != d;
}
} // namespace

GMap3::Vertex cut_edge(GMap3& m, GMap3::Edge e, bool set_indices)
{
	std::vector<Dart> region = detail::orbit_darts(m, e);
	detail::RegionReindexer<GMap3> reindex;
	const bool rules = set_indices && detail::has_rules(m);
	// a dart at the far end that the cut does not move (it moves beta0 of
	// e.dart to the new vertex)
	const Dart far_end = rules ? beta1(m, beta0(m, e.dart)) : Dart();
	if (set_indices)
		reindex.record(m, region);
	const std::vector<Dart> added = detail::insert_vertex_in_edge(m, e.dart);
	region.insert(region.end(), added.begin(), added.end());
	if (set_indices)
		reindex.apply(m, region);
	// rules, as in a 2-G-map: the new vertex between the ends, the new half
	// of the edge (new darts only) a copy of the edge
	if (rules)
	{
		detail::inherit_midpoint<GMap3::Vertex::ORBIT>(m, added[0], e.dart, far_end);
		detail::inherit<GMap3::Edge::ORBIT>(m, added[0], e.dart);
	}
	return GMap3::Vertex(added[0]);
}

bool can_cut_face(const GMap3& m, Dart d, Dart e)
{
	return detail::corners_can_be_joined(m, d, e);
}

GMap3::Edge cut_face(GMap3& m, Dart d, Dart e, bool set_indices)
{
	assert(can_cut_face(m, d, e));
	const Dart d3 = beta3(m, d), e3 = beta3(m, e);
	std::vector<Dart> region{d, beta1(m, d), e, beta1(m, e), d3, beta1(m, d3), e3, beta1(m, e3)};
	detail::RegionReindexer<GMap3> reindex;
	if (set_indices)
		reindex.record(m, region);
	// the same cut on both sides: beta3 maps the walk of one side onto the
	// other's, so the new darts correspond one to one
	const detail::FaceSideCut a = detail::split_face_side(m, d, e);
	const detail::FaceSideCut b = detail::split_face_side(m, d3, e3);
	beta_sew<3>(m, a.p, b.p);
	beta_sew<3>(m, a.p0, b.p0);
	beta_sew<3>(m, a.q, b.q);
	beta_sew<3>(m, a.q0, b.q0);
	region.insert(region.end(), {a.p, a.p0, a.q, a.q0, b.p, b.p0, b.q, b.q0});
	if (set_indices)
		reindex.apply(m, region);
	return GMap3::Edge(a.p);
}

bool can_merge_incident_faces(const GMap3& m, GMap3::Edge e)
{
	const Dart d = e.dart, d2 = beta2(m, d);
	// around the edge: the face of d, the face of d2 in d's volume, that face
	// again across beta3, and back to d's face on the other side
	if (beta<2, 3, 2>(m, d) != beta3(m, d))
		return false;
	if (same_orbit(m, GMap3::Face(d), GMap3::Face(d2)))
		return false;
	return at_least_3_edges(m, d) && at_least_3_edges(m, d2);
}

GMap3::Face merge_incident_faces(GMap3& m, GMap3::Edge e, bool set_indices)
{
	assert(can_merge_incident_faces(m, e));
	const std::vector<Dart> edge = detail::orbit_darts(m, e);
	// each dart x of the edge: its corner neighbour beta1(x) in one face meets
	// beta1(beta2(x)) in the other
	std::vector<Dart> kept;
	for (Dart x : edge)
		kept.push_back(beta1(m, x));
	std::vector<Dart> region = kept;
	region.insert(region.end(), edge.begin(), edge.end());
	detail::RegionReindexer<GMap3> reindex;
	if (set_indices)
		reindex.record(m, region);
	std::vector<std::pair<Dart, Dart>> links;
	for (Dart x : edge)
		links.emplace_back(beta1(m, x), beta1(m, beta2(m, x)));
	for (const auto& [a, b] : links)
		detail::set_beta<1>(m, a, b);
	detail::remove_dart_pairs(m, edge);
	if (set_indices)
		reindex.apply(m, kept); // kept[0] = beta1(e.dart), in the face of e.dart
	return GMap3::Face(kept.front());
}

namespace
{
// The darts of the vertex of d in its volume met at odd steps of the walk
// beta1, beta2, beta1, ... from d (those reached by a beta1 step), until the
// walk comes back: the darts on d's side of any chain through the vertex.
bool met_after_beta1_step(const GMap3& m, Dart from, Dart target)
{
	Dart x = from;
	do
	{
		x = beta1(m, x);
		if (x == target)
			return true;
		x = beta2(m, x);
	} while (x != from);
	return false;
}
} // namespace

bool can_cut_volume(const GMap3& m, const std::vector<Dart>& path)
{
	const std::size_t n = path.size();
	if (n < 3 || is_boundary(m, path[0]))
		return false;
	// each dart is met from the end of the previous one around their vertex
	// in the volume: the chain stays in one volume
	for (std::size_t i = 0; i < n; ++i)
		if (!met_after_beta1_step(m, beta0(m, path[i]), path[(i + 1) % n]))
			return false;
	DartMarkerStore<GMap3> seen(m);
	for (Dart d : path)
	{
		if (seen.is_marked(d))
			return false; // a vertex met twice
		seen.mark_orbit(GMap3::Vertex2(d));
	}
	return true;
}

GMap3::Face cut_volume(GMap3& m, const std::vector<Dart>& path, bool set_indices)
{
	assert(can_cut_volume(m, path));
	const std::size_t n = path.size();
	// path dart p_i and its end beta0(p_i), with their neighbours across the
	// edge (beta2), which go to the other part
	std::vector<Dart> ps, others;
	for (Dart p : path)
		for (Dart x : {p, beta0(m, p)})
		{
			ps.push_back(x);
			others.push_back(beta2(m, x));
		}
	std::vector<Dart> region = ps;
	region.insert(region.end(), others.begin(), others.end());
	detail::RegionReindexer<GMap3> reindex;
	if (set_indices)
		reindex.record(m, region);
	// the new face: a[k] glued to ps[k] (the path's side), b[k] to others[k]
	std::vector<Dart> a(2 * n), b(2 * n);
	for (std::size_t k = 0; k < 2 * n; k += 2)
	{
		a[k] = detail::add_dart_pair(m);
		b[k] = detail::add_dart_pair(m);
		a[k + 1] = beta0(m, a[k]);
		b[k + 1] = beta0(m, b[k]);
	}
	for (std::size_t k = 0; k < 2 * n; ++k)
	{
		detail::link_beta<2>(m, ps[k], a[k]);
		detail::link_beta<2>(m, others[k], b[k]);
		beta_sew<3>(m, a[k], b[k]);
	}
	for (std::size_t i = 0; i < n; ++i)
	{
		const std::size_t k = 2 * i, next = (2 * i + 2) % (2 * n);
		beta_sew<1>(m, a[k + 1], a[next]); // at the vertex where p_i ends and p_i+1 starts
		beta_sew<1>(m, b[k + 1], b[next]);
	}
	region.insert(region.end(), a.begin(), a.end());
	region.insert(region.end(), b.begin(), b.end());
	if (set_indices)
		reindex.apply(m, region);
	return GMap3::Face(a[0]);
}

bool can_merge_incident_volumes(const GMap3& m, GMap3::Face f)
{
	const Dart d = f.dart, d3 = beta3(m, d);
	if (is_boundary(m, d) || is_boundary(m, d3))
		return false;
	if (same_orbit(m, GMap3::Volume(d), GMap3::Volume(d3)))
		return false;
	DartMarkerStore<GMap3> face(m);
	face.mark_orbit(f);
	bool glued_to_itself = false;
	foreach_dart_of_orbit(m, f, [&](Dart x) { return !(glued_to_itself = face.is_marked(beta2(m, x))); });
	if (glued_to_itself)
		return false;
	// the faces that would meet across each edge of f: distinct, or the merge
	// would fold one onto itself (walked from one dart per edge and side)
	bool folds = false;
	foreach_dart_of_orbit(m, GMap3::Face2(d), [&](Dart x) {
		if (x.index % 2 == 1)
			return true;
		const Dart z = beta<3, 2>(m, x);
		foreach_dart_of_orbit(m, GMap3::Face(beta2(m, x)), [&](Dart y) { return !(folds = y == z); });
		return !folds;
	});
	return !folds;
}

GMap3::Volume merge_incident_volumes(GMap3& m, GMap3::Face f, bool set_indices)
{
	assert(can_merge_incident_volumes(m, f));
	const std::vector<Dart> face = detail::orbit_darts(m, f);
	// each dart x of the face: its neighbour beta2(x) in one volume meets
	// beta2(beta3(x)) in the other
	std::vector<Dart> kept;
	for (Dart x : face)
		kept.push_back(beta2(m, x));
	std::vector<Dart> region = kept;
	region.insert(region.end(), face.begin(), face.end());
	detail::RegionReindexer<GMap3> reindex;
	if (set_indices)
		reindex.record(m, region);
	std::vector<std::pair<Dart, Dart>> links;
	for (Dart x : face)
		links.emplace_back(beta2(m, x), beta<3, 2>(m, x));
	for (const auto& [a, b] : links)
		detail::set_beta<2>(m, a, b);
	detail::remove_dart_pairs(m, face);
	if (set_indices)
		reindex.apply(m, kept); // kept[0] = beta2(f.dart), in the volume of f.dart
	return GMap3::Volume(kept.front());
}

bool can_sew_volumes(const GMap3& m, GMap3::Face f1, GMap3::Face f2)
{
	const Dart d1 = f1.dart, d2 = f2.dart;
	if (is_boundary(m, d1) || is_boundary(m, d2) || !is_boundary(m, beta3(m, d1)) || !is_boundary(m, beta3(m, d2)))
		return false;
	if (same_orbit(m, GMap3::Face(d1), GMap3::Face(d2)))
		return false;
	return codegree(m, GMap3::Face(d1)) == codegree(m, GMap3::Face(d2));
}

void sew_volumes(GMap3& m, GMap3::Face f1, GMap3::Face f2, bool set_indices)
{
	assert(can_sew_volumes(m, f1, f2));
	// the two face sides walked in step from f1.dart and f2.dart
	std::vector<Dart> x, y;
	Dart i = f1.dart, j = f2.dart;
	do
	{
		x.insert(x.end(), {i, beta0(m, i)});
		y.insert(y.end(), {j, beta0(m, j)});
		i = beta<0, 1>(m, i);
		j = beta<0, 1>(m, j);
	} while (i != f1.dart);
	std::vector<Dart> b1, b2;
	for (std::size_t k = 0; k < x.size(); ++k)
	{
		b1.push_back(beta3(m, x[k]));
		b2.push_back(beta3(m, y[k]));
	}
	detail::RegionReindexer<GMap3> reindex;
	// the vanishing boundary faces may have been the only link between two
	// parts (fans of a pinched edge joined through the boundary)
	reindex.components_may_split();
	std::vector<Dart> region = x;
	region.insert(region.end(), y.begin(), y.end());
	if (set_indices)
	{
		std::vector<Dart> touched = region;
		touched.insert(touched.end(), b1.begin(), b1.end());
		touched.insert(touched.end(), b2.begin(), b2.end());
		reindex.record(m, touched);
	}
	// A boundary dart nb beside the vanishing faces meets the dart its edge
	// leads to across them: from beta2(nb), go to the matching dart of the
	// other face (b1[k] <-> b2[k]) and take its beta2, again while that is a
	// vanishing dart (a boundary face folded onto itself or onto the other).
	const auto vanishing = [&](Dart d) { return contains(b1, d) || contains(b2, d); };
	const auto matching = [&](Dart b) {
		const auto k1 = std::find(b1.begin(), b1.end(), b);
		return k1 != b1.end() ? b2[std::size_t(k1 - b1.begin())]
							  : b1[std::size_t(std::find(b2.begin(), b2.end(), b) - b2.begin())];
	};
	std::vector<std::pair<Dart, Dart>> meet;
	for (const std::vector<Dart>* face : {&b1, &b2})
		for (Dart b : *face)
		{
			const Dart nb = beta2(m, b);
			if (vanishing(nb))
				continue;
			Dart t = b;
			do
				t = beta2(m, matching(t));
			while (vanishing(t));
			meet.emplace_back(nb, t);
		}
	for (const auto& [nb, t] : meet)
	{
		detail::set_beta<2>(m, nb, t);
		region.push_back(nb);
	}
	detail::remove_dart_pairs(m, b1);
	detail::remove_dart_pairs(m, b2);
	for (std::size_t k = 0; k < x.size(); ++k)
		detail::link_beta<3>(m, x[k], y[k]);
	if (set_indices)
		reindex.apply(m, region);
}

void unsew_volumes(GMap3& m, GMap3::Face f, bool set_indices)
{
	assert(can_unsew_volumes(m, f));
	std::vector<Dart> side = detail::orbit_darts(m, GMap3::Face2(f.dart));
	const std::size_t half = side.size();
	for (std::size_t k = 0; k < half; ++k)
		side.push_back(beta3(m, side[k]));
	// the cells around: those of the face's darts (the boundary darts beside
	// it, relinked by the closing, are in the same vertices and edges)
	std::vector<Dart> region = side;
	detail::RegionReindexer<GMap3> reindex;
	reindex.components_may_split();
	if (set_indices)
		reindex.record(m, region);
	for (std::size_t k = 0; k < half; ++k)
		beta_unsew<3>(m, side[k]);
	std::vector<Dart> made;
	detail::close_beta3_holes(m, side, made);
	region.insert(region.end(), made.begin(), made.end());
	if (set_indices)
		reindex.apply(m, region);
}

bool can_unsew_volumes(const GMap3& m, GMap3::Face f)
{
	return !is_boundary(m, f.dart) && !is_boundary(m, beta3(m, f.dart));
}

} // namespace cgogn
