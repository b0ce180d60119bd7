// SPDX-License-Identifier: MIT
// The 1-to-8 refinements of a tetrahedron and of a hexahedron in a local
// numbering of their points, shared by the serial and the distributed
// volume subdivisions so that both cut a cell the same way.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <array>

namespace cgogn::modeling
{

/// A point of a cell's refinement: the centre of an old cell of dimension
/// `dim` (0: a corner, 1: an edge's midpoint, 2: a face's centroid, 3: the
/// volume's centroid), given by one of its darts.
struct RefinementPoint
{
	uint32 dim; ///< The dimension of the old cell the point is the centre of.
	Dart dart;  ///< A dart of that cell.
};

/// The 10 points of the red refinement of tetrahedron w: its corners 0..3 in
/// VTK order (0, 1, 2 counterclockwise seen from 3), then the midpoints of the edges
/// 01, 02, 03, 12, 13, 23. Precondition: w is a tetrahedron. O(1).
std::array<RefinementPoint, 10> tet_refinement_points(const CMap3& m, CMap3::Volume w);

/// The three diagonals of a tetrahedron's inner octahedron, as pairs of
/// points of tet_refinement_points.
inline constexpr std::array<std::array<uint32, 2>, 3> tet_octahedron_diagonals = {{{4, 9}, {5, 8}, {6, 7}}};

/// The diagonal (0..2) along which to cut the inner octahedron of a
/// tetrahedron whose 10 refinement points are at `points`: the shortest;
/// among diagonals of the same length, the one whose ends, each pair sorted
/// by (x, y, z), come first in that order. So the cut depends on the
/// geometry only, not on the dart a tetrahedron is stored from. O(1).
uint32 tet_cut_diagonal(const std::array<Vec3, 10>& points);

/// The 8 children of a tetrahedron when its octahedron is cut along diagonal
/// k (0..2): the 4 corner tetrahedra then the 4 around the diagonal, each by
/// 4 points of tet_refinement_points in VTK order (positively oriented). O(1).
const std::array<std::array<uint32, 4>, 8>& tet_children(uint32 diagonal);

/// The 27 points of the refinement of hexahedron w on a 3 x 3 x 3 grid,
/// point x + 3 y + 9 z: the corners at coordinates 0 and 2, the edge
/// midpoints, face centroids and the volume centroid between them.
/// Precondition: w is a hexahedron. O(1).
std::array<RefinementPoint, 27> hex_refinement_points(const CMap3& m, CMap3::Volume w);

/// The 8 children of a hexahedron, each by 8 points of hex_refinement_points
/// in VTK order (bottom quad, then the quad above it), oriented as the
/// parent. O(1).
const std::array<std::array<uint32, 8>, 8>& hex_children();

} // namespace cgogn::modeling
