// SPDX-License-Identifier: MIT
// General operators of 3-maps: creation, closing, sewing, removal, cuts and merges.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/properties/properties.h>

#include "cmap3_build.h"
#include "reindex.h"

#include <algorithm>
#include <numeric>

namespace cgogn
{

namespace
{
CMap3::Volume add_volume(CMap3& m, const detail::FaceList& faces, uint32 nb_vertices, bool set_indices)
{
	std::vector<uint32> labels(nb_vertices), dart_labels;
	std::iota(labels.begin(), labels.end(), 0u);
	std::vector<Dart> darts = detail::add_volume_topology(m, faces, labels, dart_labels);
	std::vector<Dart> created;
	detail::close_phi3_holes(m, darts, created);
	if (set_indices)
	{
		darts.insert(darts.end(), created.begin(), created.end());
		detail::RegionReindexer<CMap3>().apply(m, darts);
	}
	return CMap3::Volume(darts.front());
}

std::vector<Dart> face_darts(const CMap3& m, Dart d)
{
	std::vector<Dart> v;
	foreach_dart_of_orbit(m, CMap3::Face2(d), [&](Dart x) { v.push_back(x); });
	return v;
}

bool contains(const std::vector<Dart>& v, Dart d)
{
	return std::find(v.begin(), v.end(), d) != v.end();
}
} // namespace

CMap3::Volume add_tetra(CMap3& m, bool set_indices)
{
	return add_volume(m, *detail::cell_faces(4), 4, set_indices);
}
CMap3::Volume add_pyramid(CMap3& m, uint32 n, bool set_indices)
{
	assert(n >= 3);
	return add_volume(m, detail::pyramid_faces(n), n + 1, set_indices);
}
CMap3::Volume add_prism(CMap3& m, uint32 n, bool set_indices)
{
	assert(n >= 3);
	return add_volume(m, detail::prism_faces(n), 2 * n, set_indices);
}
CMap3::Volume add_hexa(CMap3& m, bool set_indices)
{
	return add_prism(m, 4, set_indices);
}

uint32 close(CMap3& m, bool set_indices)
{
	std::vector<Dart> all, created;
	foreach_dart(m, [&](Dart d) { all.push_back(d); });
	detail::close_phi3_holes(m, all, created);
	uint32 n = 0;
	{
		DartMarkerStore<CMap3> seen(m);
		for (Dart b : created)
			if (!seen.is_marked(b))
			{
				seen.mark_orbit(CMap3::Volume(b));
				++n;
			}
	}
	if (set_indices)
		detail::RegionReindexer<CMap3>().apply(m, created);
	return n;
}

CMap3::Volume close_hole(CMap3& m, Dart d, bool set_indices)
{
	assert(phi3(m, d) == d);
	// the free faces reachable from d across edges
	std::vector<Dart> hole;
	DartMarkerStore<CMap3> seen(m);
	std::vector<Dart> pending{d};
	while (!pending.empty())
	{
		const Dart x = pending.back();
		pending.pop_back();
		if (seen.is_marked(x))
			continue;
		for (Dart y : face_darts(m, x))
		{
			seen.mark(y);
			hole.push_back(y);
			Dart it = phi2(m, y); // turn around the edge of y to the next free face
			while (phi3(m, it) != it)
				it = phi2(m, phi3(m, it));
			if (!seen.is_marked(it))
				pending.push_back(it);
		}
	}
	detail::RegionReindexer<CMap3> reindexer;
	if (set_indices)
		reindexer.record(m, hole); // the hole's component: the new boundary joins it
	std::vector<Dart> created;
	detail::close_phi3_holes(m, hole, created);
	if (set_indices)
		reindexer.apply(m, created);
	return CMap3::Volume(created.front());
}

void unsew_volumes(CMap3& m, CMap3::Face f, bool set_indices)
{
	assert(!is_boundary(m, f.dart) && !is_boundary(m, phi3(m, f.dart)));
	std::vector<Dart> side = face_darts(m, f.dart);
	for (Dart x : face_darts(m, phi3(m, f.dart)))
		side.push_back(x);
	detail::RegionReindexer<CMap3> reindexer;
	reindexer.components_may_split();
	if (set_indices)
		reindexer.record(m, side);
	std::vector<std::pair<Dart, Dart>> cut;
	for (std::size_t i = 0; i < side.size() / 2; ++i)
	{
		cut.emplace_back(side[i], phi3(m, side[i]));
		phi3_unsew(m, side[i]);
	}
	std::vector<Dart> created, repaired;
	detail::close_phi3_holes(m, side, created, cut, &repaired);
	if (set_indices)
	{
		side.insert(side.end(), created.begin(), created.end());
		side.insert(side.end(), repaired.begin(), repaired.end());
		reindexer.apply(m, side);
	}
}

bool can_sew_volumes(const CMap3& m, CMap3::Face f1, CMap3::Face f2)
{
	const Dart d1 = f1.dart, d2 = f2.dart;
	if (is_boundary(m, d1) || is_boundary(m, d2) || !is_boundary(m, phi3(m, d1)) || !is_boundary(m, phi3(m, d2)))
		return false;
	if (same_orbit(m, CMap3::Face2(d1), CMap3::Face2(d2)))
		return false;
	return codegree(static_cast<const CMap1&>(m), CMap1::Face(d1)) ==
		   codegree(static_cast<const CMap1&>(m), CMap1::Face(d2));
}

void sew_volumes(CMap3& m, CMap3::Face f1, CMap3::Face f2, bool set_indices)
{
	assert(can_sew_volumes(m, f1, f2));
	std::vector<Dart> x = face_darts(m, f1.dart), y;
	for (Dart it = f2.dart; y.size() < x.size(); it = phi_1(m, it))
		y.push_back(it);
	std::vector<Dart> b1, b2;
	for (std::size_t i = 0; i < x.size(); ++i)
	{
		b1.push_back(phi3(m, x[i]));
		b2.push_back(phi3(m, y[i]));
	}
	detail::RegionReindexer<CMap3> reindexer;
	// the boundary faces that vanish may have been the only link between two
	// parts (fans of a pinched edge joined through the boundary)
	reindexer.components_may_split();
	std::vector<Dart> touched = x;
	touched.insert(touched.end(), y.begin(), y.end());
	touched.insert(touched.end(), b1.begin(), b1.end());
	touched.insert(touched.end(), b2.begin(), b2.end());
	if (set_indices)
		reindexer.record(m, touched);
	// The boundary faces in between vanish. A boundary dart n beside them
	// meets the dart its edge leads to across them: from phi2(n), go to the
	// matching dart of the other face (b1[i] <-> b2[i]) and take its phi2,
	// again while that is one of the vanishing darts (a boundary face folded
	// onto itself or onto the other one along an edge).
	std::vector<Dart> region = x;
	region.insert(region.end(), y.begin(), y.end());
	const auto vanishing = [&](Dart d) { return contains(b1, d) || contains(b2, d); };
	const auto matching = [&](Dart b) {
		const auto i1 = std::find(b1.begin(), b1.end(), b);
		return i1 != b1.end() ? b2[std::size_t(i1 - b1.begin())]
							  : b1[std::size_t(std::find(b2.begin(), b2.end(), b) - b2.begin())];
	};
	std::vector<std::pair<Dart, Dart>> meet;
	for (const std::vector<Dart>* face : {&b1, &b2})
		for (Dart b : *face)
		{
			const Dart n = phi2(m, b);
			if (vanishing(n))
				continue;
			Dart t = b;
			do
				t = phi2(m, matching(t));
			while (vanishing(t));
			meet.emplace_back(n, t);
		}
	for (const auto& [n, t] : meet)
	{
		detail::set_phi2(m, n, t);
		region.push_back(n);
	}
	for (std::size_t i = 0; i < x.size(); ++i)
	{
		detail::remove_dart(m, b1[i]);
		detail::remove_dart(m, b2[i]);
		detail::set_phi3(m, x[i], y[i]);
		detail::set_phi3(m, y[i], x[i]);
	}
	if (set_indices)
		reindexer.apply(m, region);
}

void remove_volume(CMap3& m, CMap3::Volume w, bool set_indices)
{
	assert(!is_boundary(m, w.dart));
	std::vector<Dart> darts;
	foreach_dart_of_orbit(m, w, [&](Dart d) { darts.push_back(d); });
	detail::RegionReindexer<CMap3> reindexer;
	reindexer.components_may_split();
	if (set_indices)
	{
		std::vector<Dart> touched = darts;
		for (Dart d : darts)
			touched.push_back(phi3(m, d));
		reindexer.record(m, touched);
	}
	for (Dart d : darts)
		detail::set_boundary(m, d, true);
	// faces between w and a boundary volume vanish, one after the other
	std::vector<Dart> removed, region;
	for (Dart d : darts)
	{
		if (contains(removed, d) || !is_boundary(m, phi3(m, d)))
			continue;
		std::vector<Dart> xs = face_darts(m, d), ys;
		for (Dart x : xs)
			ys.push_back(phi3(m, x));
		// the dart met across the vanishing face from z: the face can be glued
		// to itself along an edge (folded), the walk then goes on through it
		const auto across = [&](Dart z) {
			for (std::size_t k = 0; k <= 2 * xs.size(); ++k)
			{
				if (const auto ix = std::find(xs.begin(), xs.end(), z); ix != xs.end())
					z = phi2(m, ys[std::size_t(ix - xs.begin())]);
				else if (const auto iy = std::find(ys.begin(), ys.end(), z); iy != ys.end())
					z = phi2(m, xs[std::size_t(iy - ys.begin())]);
				else
					return z;
			}
			return Dart(); // the face and its folds are the whole surface there
		};
		for (std::size_t i = 0; i < xs.size(); ++i)
		{
			const Dart nx = across(phi2(m, xs[i])), ny = across(phi2(m, ys[i]));
			if (!nx.is_valid() || !ny.is_valid())
				continue;
			detail::set_phi2(m, nx, ny);
			detail::set_phi2(m, ny, nx);
			region.push_back(nx);
			region.push_back(ny);
		}
		removed.insert(removed.end(), xs.begin(), xs.end());
		removed.insert(removed.end(), ys.begin(), ys.end());
	}
	for (Dart d : darts)
		if (!contains(removed, d))
			region.insert(region.end(), {d, phi3(m, d)}); // phi3(d): the neighbour's cells
	std::erase_if(region, [&](Dart d) { return contains(removed, d); });
	for (Dart d : removed)
		detail::remove_dart(m, d);
	if (set_indices)
		reindexer.apply(m, region);
}

CMap3::Vertex cut_edge(CMap3& m, CMap3::Edge e, bool set_indices)
{
	std::vector<Dart> ring;
	foreach_dart_of_orbit(m, e, [&](Dart d) { ring.push_back(d); });
	detail::RegionReindexer<CMap3> reindexer;
	if (set_indices)
		reindexer.record(m, ring);
	std::vector<Dart> p2(ring.size()), p3(ring.size()), added(ring.size());
	auto position = [&](Dart d) { return std::size_t(std::find(ring.begin(), ring.end(), d) - ring.begin()); };
	for (std::size_t i = 0; i < ring.size(); ++i)
	{
		p2[i] = phi2(m, ring[i]);
		p3[i] = phi3(m, ring[i]);
		const Dart n = detail::add_dart(m);
		detail::set_phi1(m, n, phi1(m, ring[i]));
		detail::set_phi1(m, ring[i], n);
		detail::set_boundary(m, n, is_boundary(m, ring[i]));
		added[i] = n;
	}
	// x: a -> v keeps x's neighbours' new halves: phi_k(x) = n(phi_k(x)), phi_k(n(x)) = phi_k(x)
	for (std::size_t i = 0; i < ring.size(); ++i)
	{
		detail::set_phi2(m, ring[i], added[position(p2[i])]);
		detail::set_phi2(m, added[i], p2[i]);
		detail::set_phi3(m, ring[i], added[position(p3[i])]);
		detail::set_phi3(m, added[i], p3[i]);
	}
	if (set_indices)
	{
		std::vector<Dart> region = ring;
		region.insert(region.end(), added.begin(), added.end());
		reindexer.apply(m, region);
		// rules: the new vertex between the ends, each of its corners between
		// the corners of the ends (the reindexing gave the new half of the
		// edge the edge's values)
		if (detail::has_rules(m))
		{
			detail::inherit_midpoint<CMap3::Vertex::ORBIT>(m, added[0], ring[0], phi1(m, added[0]));
			if (container_of<Orbit::DART>(m).has_rules())
				for (std::size_t i = 0; i < ring.size(); ++i)
					detail::inherit_midpoint<Orbit::DART>(m, added[i], ring[i], phi1(m, added[i]));
		}
	}
	return CMap3::Vertex(added[0]);
}

bool can_cut_face(const CMap3& m, Dart d, Dart e)
{
	return d != e && phi1(m, d) != e && phi1(m, e) != d && same_orbit(m, CMap3::Face2(d), CMap3::Face2(e));
}

CMap3::Edge cut_face(CMap3& m, Dart d, Dart e, bool set_indices)
{
	assert(can_cut_face(m, d, e));
	const Dart dB = phi1(m, phi3(m, d)), eB = phi1(m, phi3(m, e)); // same origins, other side
	detail::RegionReindexer<CMap3> reindexer;
	std::vector<Dart> region = face_darts(m, d);
	for (Dart x : face_darts(m, dB))
		region.push_back(x);
	if (set_indices)
		reindexer.record(m, region);
	auto cut = [&](Dart a, Dart b) {
		// x: origin(b) -> origin(a) before a, y: origin(a) -> origin(b) before b
		const Dart pa = phi_1(m, a), pb = phi_1(m, b);
		const Dart x = detail::add_dart(m), y = detail::add_dart(m);
		detail::set_phi1(m, pb, x);
		detail::set_phi1(m, x, a);
		detail::set_phi1(m, pa, y);
		detail::set_phi1(m, y, b);
		phi2_sew(m, x, y);
		detail::set_boundary(m, x, is_boundary(m, a));
		detail::set_boundary(m, y, is_boundary(m, a));
		return std::make_pair(x, y);
	};
	auto [x, y] = cut(d, e);
	auto [xB, yB] = cut(dB, eB);
	phi3_sew(m, x, yB);
	phi3_sew(m, y, xB);
	if (set_indices)
	{
		region.insert(region.end(), {x, y, xB, yB});
		reindexer.apply(m, region);
		// rules: each new corner a part of the corner it cut (the reindexing
		// gave the new part of the face the face's values; the new edge has
		// no parent edge)
		if (detail::has_rules(m))
		{
			detail::inherit<Orbit::DART>(m, x, e);
			detail::inherit<Orbit::DART>(m, y, d);
			detail::inherit<Orbit::DART>(m, xB, eB);
			detail::inherit<Orbit::DART>(m, yB, dB);
		}
	}
	return CMap3::Edge(y);
}

bool can_cut_volume(const CMap3& m, const std::vector<Dart>& path)
{
	const std::size_t k = path.size();
	if (k < 3 || is_boundary(m, path[0]))
		return false;
	// each dart leaves the vertex of the volume where the previous one arrived
	// (so every dart is in the volume of path[0]), and no vertex but the first
	// is reached twice: each vertex of the volume is walked once
	DartMarkerStore<CMap3> met(m);
	met.mark_orbit(CMap3::Vertex2(path[0]));
	for (std::size_t i = 0; i < k; ++i)
	{
		const Dart next = path[(i + 1) % k];
		const bool closing = i + 1 == k;
		if (!closing && met.is_marked(next))
			return false;
		bool follows = false;
		foreach_dart_of_orbit(m, CMap3::Vertex2(phi1(m, path[i])), [&](Dart x) {
			if (!closing)
				met.mark(x);
			follows = follows || x == next;
		});
		if (!follows)
			return false;
	}
	return true;
}

CMap3::Face cut_volume(CMap3& m, const std::vector<Dart>& path, bool set_indices)
{
	const std::size_t k = path.size();
	assert(can_cut_volume(m, path));
	std::vector<Dart> q(k), f(k), g(k);
	for (std::size_t i = 0; i < k; ++i)
		q[i] = phi2(m, path[i]);
	detail::RegionReindexer<CMap3> reindexer;
	std::vector<Dart> region = path;
	region.insert(region.end(), q.begin(), q.end());
	if (set_indices)
		reindexer.record(m, region);
	for (std::size_t i = 0; i < k; ++i)
	{
		f[i] = detail::add_dart(m);
		g[i] = detail::add_dart(m);
	}
	for (std::size_t i = 0; i < k; ++i)
	{
		detail::set_phi1(m, f[i], f[(i + k - 1) % k]); // f_i: a_i+1 -> a_i
		detail::set_phi1(m, g[i], g[(i + 1) % k]);     // g_i: a_i -> a_i+1
		detail::set_phi2(m, path[i], f[i]);
		detail::set_phi2(m, f[i], path[i]);
		detail::set_phi2(m, q[i], g[i]);
		detail::set_phi2(m, g[i], q[i]);
		detail::set_phi3(m, f[i], g[i]);
		detail::set_phi3(m, g[i], f[i]);
	}
	if (set_indices)
	{
		region.insert(region.end(), f.begin(), f.end());
		region.insert(region.end(), g.begin(), g.end());
		// the reindexing gives the new part of the volume the volume's
		// values; the new face has no parent face
		reindexer.apply(m, region);
	}
	return CMap3::Face(f[0]);
}

bool can_merge_incident_volumes(const CMap3& m, CMap3::Face f)
{
	const Dart d = f.dart, d3 = phi3(m, d);
	if (is_boundary(m, d) || is_boundary(m, d3) || same_orbit(m, CMap3::Volume(d), CMap3::Volume(d3)))
		return false;
	// a face glued to itself along an edge (phi2 inside the face) would leave
	// that edge without faces: its darts vanish with the face
	const auto folded = [&](Dart x) {
		bool fold = false;
		foreach_dart_of_orbit(m, CMap3::Face2(x), [&](Dart y) {
			return !(fold = same_orbit(m, CMap3::Face2(phi2(m, y)), CMap3::Face2(x)));
		});
		return fold;
	};
	return !folded(d) && !folded(d3);
}

CMap3::Volume merge_incident_volumes(CMap3& m, CMap3::Face f, bool set_indices)
{
	assert(can_merge_incident_volumes(m, f));
	std::vector<Dart> xs = face_darts(m, f.dart), ys;
	for (Dart x : xs)
		ys.push_back(phi3(m, x));
	detail::RegionReindexer<CMap3> reindexer;
	std::vector<Dart> region;
	for (std::size_t i = 0; i < xs.size(); ++i)
		region.insert(region.end(), {phi2(m, xs[i]), phi2(m, ys[i])});
	if (set_indices)
	{
		std::vector<Dart> touched = region;
		touched.insert(touched.end(), xs.begin(), xs.end());
		touched.insert(touched.end(), ys.begin(), ys.end());
		reindexer.record(m, touched);
	}
	for (std::size_t i = 0; i < xs.size(); ++i)
	{
		const Dart nx = region[2 * i], ny = region[2 * i + 1];
		detail::set_phi2(m, nx, ny);
		detail::set_phi2(m, ny, nx);
	}
	for (std::size_t i = 0; i < xs.size(); ++i)
	{
		detail::remove_dart(m, xs[i]);
		detail::remove_dart(m, ys[i]);
	}
	if (set_indices)
		reindexer.apply(m, region);
	return CMap3::Volume(region[0]);
}

bool can_merge_incident_faces(const CMap3& m, CMap3::Edge e)
{
	if (degree(m, e) != 2)
		return false;
	const Dart d = e.dart, d2 = phi2(m, d);
	return !same_orbit(m, CMap3::Face2(d), CMap3::Face2(d2)) &&
		   codegree(static_cast<const CMap1&>(m), CMap1::Face(d)) >= 3 &&
		   codegree(static_cast<const CMap1&>(m), CMap1::Face(d2)) >= 3;
}

CMap3::Face merge_incident_faces(CMap3& m, CMap3::Edge e, bool set_indices)
{
	assert(can_merge_incident_faces(m, e));
	std::vector<Dart> ring;
	foreach_dart_of_orbit(m, e, [&](Dart d) { ring.push_back(d); });
	detail::RegionReindexer<CMap3> reindexer;
	if (set_indices)
		reindexer.record(m, ring);
	std::vector<Dart> region;
	// ring holds pairs (x, phi2(x)), one per volume around the edge
	for (std::size_t i = 0; i < ring.size(); i += 2)
	{
		const Dart x = ring[i], x2 = ring[i + 1];
		const Dart px = phi_1(m, x), px2 = phi_1(m, x2);
		const Dart nx = phi1(m, x), nx2 = phi1(m, x2);
		detail::set_phi1(m, px, nx2);
		detail::set_phi1(m, px2, nx);
		region.insert(region.end(), {nx, nx2});
	}
	for (Dart d : ring)
		detail::remove_dart(m, d);
	if (set_indices)
		reindexer.apply(m, region);
	return CMap3::Face(region[0]);
}

} // namespace cgogn
