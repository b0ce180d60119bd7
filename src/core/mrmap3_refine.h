// SPDX-License-Identifier: MIT
// The cuts of the volume refinements of the finest map of a multiresolution
// 3-map, one piece at a time: hexahedral (add_level and subdivide_volume)
// and tetrahedral-octahedral (add_level, see mrmap3_tetra_octa.h).
#pragma once

#include <cgogn/core/map/mrmap3.h>

#include <array>
#include <vector>

namespace cgogn::detail
{

/// The cuts of the volume refinements, on the finest map of s with its
/// operators (without indices). Every new dart gets the edge and face ids
/// of the rules of MRState3 and is recorded (created()); its level is left
/// to the caller (label_created).
class MRVolumeRefinement
{
public:
	explicit MRVolumeRefinement(MRState3& s) : s_(s), map_(s.map)
	{
	}

	/// Cuts d's finest edge at its middle; the new halves keep the ids of
	/// the darts they follow. Returns the dart leaving the new vertex along
	/// d's direction. O(degree of the edge).
	Dart cut_edge(Dart d);

	/// Joins the midpoints of the cut edges of finest face f (f: a dart
	/// leaving a corner; corners and midpoints alternate) to a new centre:
	/// k quads. O(k).
	void quadrangulate(Dart f);

	/// Joins the midpoints of the cut edges of finest triangle f (f: a dart
	/// leaving a corner; corners and midpoints alternate) by 3 inner edges:
	/// 4 triangles. An inner edge takes the smallest edge id different from
	/// the ids of the two edges whose midpoints it joins. O(1).
	void triangulate(Dart f);

	/// Cuts the face of d and e by a new edge from origin(d) to origin(e), of
	/// the face's face id and edge id `id`. Returns its dart from origin(d),
	/// in the part of the face that holds e. O(degree of the face).
	Dart cut_face(Dart d, Dart e, uint8 id);

	/// Cuts the finest volume of `path` along the closed path (see
	/// can_cut_volume); the new face takes the smallest face id not used
	/// around the path's edges, its darts the edge ids of the path's.
	/// Returns the new face's dart on the path side, from the end of path[0]
	/// to its origin. Throws std::logic_error when the path is not closed.
	/// O(size of the path x degree of its edges).
	Dart cut_volume_along(const std::vector<Dart>& path);

	/// Cuts a hexahedron whose edges are cut and faces quadrangulated (and
	/// nothing finer on its surface) into 8: h holds a corner dart a of a
	/// face B, the corner dart two corners on in B, a corner dart t of the
	/// face opposite to B and the corner dart two corners on from t.
	/// Throws std::logic_error when an inner path does not close. O(1).
	void split_hexahedron(const std::array<Dart, 4>& h);

	/// The finest map being refined.
	CMap3& map()
	{
		return map_;
	}

	/// The darts created so far.
	const std::vector<Dart>& created() const
	{
		return created_;
	}

	/// Gives the created darts level l and counts them in
	/// darts_per_level[l] (which must exist). O(darts created).
	void label_created(uint32 l);

private:
	uint8 edge_id(Dart d) const
	{
		return (*s_.edge_id)[d.index];
	}
	uint8 face_id(Dart d) const
	{
		return (*s_.face_id)[d.index];
	}
	void set_edge_id(Dart d, uint8 id);
	Dart straight(Dart d) const;
	Dart cut_volume_straight(Dart start, uint32 k);

	MRState3& s_;
	CMap3& map_;
	std::vector<Dart> created_;
};

/// The corner darts split_hexahedron needs for the hexahedron of dart a,
/// read at level l (a: a dart of level <= l of the hexahedron). O(cost of a
/// few level steps).
std::array<Dart, 4> mr_hexahedron_corners(const MRState3& s, uint32 l, Dart a);

} // namespace cgogn::detail
