// SPDX-License-Identifier: MIT
// The hexahedral refinement of the finest map of a multiresolution 3-map.
#include "mrmap3_refine.h"

#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/traversals/local_cmap3.h>

#include <array>
#include <stdexcept>
#include <utility>

namespace cgogn::detail
{

void MRVolumeRefinement::set_edge_id(Dart d, uint8 id)
{
	foreach_dart_of_orbit(map_, CMap3::Edge(d), [&](Dart x) { (*s_.edge_id)[x.index] = id; });
}

Dart MRVolumeRefinement::cut_edge(Dart d)
{
	std::vector<Dart> ring;
	foreach_dart_of_orbit(map_, CMap3::Edge(d), [&](Dart x) { ring.push_back(x); });
	cgogn::cut_edge(map_, CMap3::Edge(d), false);
	for (Dart x : ring)
	{
		const Dart n = phi1(map_, x);
		(*s_.edge_id)[n.index] = edge_id(x);
		(*s_.face_id)[n.index] = face_id(x);
		created_.push_back(n);
	}
	return phi1(map_, d);
}

Dart MRVolumeRefinement::cut_face(Dart d, Dart e, uint8 id)
{
	const Dart y = cgogn::cut_face(map_, d, e, false).dart;
	foreach_dart_of_orbit(map_, CMap3::Edge(y), [&](Dart x) {
		(*s_.edge_id)[x.index] = id;
		(*s_.face_id)[x.index] = face_id(d);
		created_.push_back(x);
	});
	return y;
}

namespace
{
/// The smallest edge id different from a: a new inner edge of a face
/// differs from the edge whose midpoint it leaves, so that phi1 at a
/// coarser level, turning around the midpoint, does not take it.
uint8 inner_edge_id(uint8 a)
{
	return a == 0 ? 1 : 0;
}
} // namespace

void MRVolumeRefinement::quadrangulate(Dart f)
{
	std::vector<Dart> c; // the darts leaving the midpoints, in phi1 order
	Dart it = f;
	do
	{
		c.push_back(phi1(map_, it));
		it = phi1(map_, phi1(map_, it));
	} while (it != f);
	const auto inner_id = [&](Dart mid) { return inner_edge_id(edge_id(mid)); };
	const Dart y = cut_face(c[0], c[2], inner_id(c[0])); // midpoint 0 -> midpoint 2
	cut_edge(y);
	const Dart to_second = phi1(map_, y); // centre -> midpoint 2
	set_edge_id(to_second, inner_id(c[2]));
	// the centre's dart in the part holding midpoint 1
	cut_face(phi2(map_, y), c[1], inner_id(c[1]));
	Dart from_centre = to_second;
	for (std::size_t i = 3; i < c.size(); ++i)
		from_centre = cut_face(from_centre, c[i], inner_id(c[i]));
}

void MRVolumeRefinement::triangulate(Dart f)
{
	// c[i]: the dart leaving the midpoint of the i-th edge, toward its end
	const std::array<Dart, 3> c{phi1(map_, f), phi1(map_, phi1(map_, phi1(map_, f))), phi_1(map_, f)};
	const auto joining = [&](Dart a, Dart b) {
		uint8 id = 0;
		while (id == edge_id(a) || id == edge_id(b))
			++id;
		return id;
	};
	// the corner of the first, second and third edge's origin, in turn; the
	// last cut leaves the middle triangle
	const Dart y = cut_face(c[2], c[0], joining(c[2], c[0])); // midpoint 2 -> midpoint 0
	cut_face(c[0], c[1], joining(c[0], c[1]));
	cut_face(c[1], y, joining(c[1], c[2]));
}

/// Goes straight on across a vertex of 4 edges on the surface of d's finest
/// volume: the dart leaving the end of d opposite to d.
Dart MRVolumeRefinement::straight(Dart d) const
{
	return phi1(map_, phi2(map_, phi1(map_, d)));
}

Dart MRVolumeRefinement::cut_volume_along(const std::vector<Dart>& path)
{
	if (!can_cut_volume(map_, path))
		throw std::logic_error("volume refinement: an inner path of a volume is not closed");
	std::array<bool, 256> used{};
	for (Dart p : path)
		foreach_dart_of_orbit(map_, CMap3::Edge(p), [&](Dart x) { used[face_id(x)] = true; });
	uint8 id = 0;
	while (used[id])
		++id;
	const Dart f = cgogn::cut_volume(map_, path, false).dart;
	for (Dart p : path)
		for (Dart x : {phi2(map_, p), phi3(map_, phi2(map_, p))})
		{
			(*s_.face_id)[x.index] = id;
			(*s_.edge_id)[x.index] = edge_id(p);
			created_.push_back(x);
		}
	return f;
}

/// Cuts the volume of `start` along the closed path of k darts that goes
/// straight on from it (see cut_volume_along).
Dart MRVolumeRefinement::cut_volume_straight(Dart start, uint32 k)
{
	std::vector<Dart> path{start};
	while (path.size() < k)
		path.push_back(straight(path.back()));
	if (straight(path.back()) != start)
		throw std::logic_error("hexahedral refinement: a hexahedron's inner path is not closed");
	return cut_volume_along(path);
}

void MRVolumeRefinement::split_hexahedron(const std::array<Dart, 4>& h)
{
	const Dart a = h[0], a2 = h[1], t = h[2], t2 = h[3];
	// the middle section, parallel to B and T, through the midpoints of the
	// 4 edges joining them: an octagon, cut into 4 quads around the
	// volume's centre
	const Dart o = cut_volume_straight(phi1(map_, phi1(map_, phi2(map_, a))), 8);
	const Dart y = cut_face(o, phi1(map_, phi1(map_, phi1(map_, phi1(map_, o)))), 0);
	cut_edge(y);
	const Dart from_centre = phi1(map_, y);
	cut_face(from_centre, phi1(map_, phi1(map_, phi1(map_, from_centre))), 0);
	const Dart other = phi2(map_, y);
	cut_face(other, phi1(map_, phi1(map_, phi1(map_, other))), 0);
	// each half: a section through the centres of B (or T) and of the
	// volume, cut in 2 along them, then a section across it in each quarter
	for (const auto& [b, b2] : {std::pair{a, a2}, std::pair{t, t2}})
	{
		const Dart s = cut_volume_straight(phi2(map_, phi1(map_, b)), 6);
		// s: midpoint of b's edge -> centre of B; on the section: centre of
		// B at phi1(s), the volume's centre 3 darts further
		const Dart from_face_centre = phi1(map_, s);
		cut_face(from_face_centre, phi1(map_, phi1(map_, phi1(map_, from_face_centre))), 0);
		cut_volume_straight(phi1(map_, phi1(map_, b)), 4);
		cut_volume_straight(phi1(map_, phi1(map_, b2)), 4);
	}
}

void MRVolumeRefinement::label_created(uint32 l)
{
	for (Dart d : created_)
		(*s_.level)[d.index] = uint8(l);
	s_.darts_per_level[l] += uint32(created_.size());
}

std::array<Dart, 4> mr_hexahedron_corners(const MRState3& s, uint32 l, Dart a)
{
	const auto p1 = [&](Dart d) { return mr_phi1(s, l, d); };
	const Dart t = mr_phi2(s, l, p1(p1(mr_phi2(s, l, a))));
	return {a, p1(p1(a)), t, p1(p1(t))};
}

} // namespace cgogn::detail
