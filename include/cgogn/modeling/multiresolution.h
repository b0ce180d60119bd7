// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mrmap2_attributes.h>
#include <cgogn/geometry/types/vector_traits.h>

namespace cgogn::modeling
{

/// The subdivision rules that predict a level from the one below (the
/// synthesis filter S of P_l = S(P_{l-1}) + D_l).
enum class MRBank
{
	/// New vertices at the midpoints of the edges they cut and the centroids
	/// of the faces they centre; old vertices stay. Any refinement pattern.
	Linear,
	/// The masks of loop_subdivision, boundary rules included. Every level
	/// above 0 must be a Triangular refinement of a triangle mesh.
	Loop,
	/// The masks of catmull_clark_subdivision, boundary rules included.
	/// Every level above 0 must be a Quadrangular refinement.
	CatmullClark,
};

/// Rebuilds the positions of levels from+1 ... max_level(m) from those of
/// level `from` and the detail vectors: P_l = S(P_{l-1}) + D_l, with S the
/// bank's rules read on level l - 1 and D_l the values of `details` at level
/// l (an attribute of vertices; zero details give the bank's subdivision).
/// Throws std::invalid_argument when a level is not the bank's refinement
/// (see MRBank). O(number of vertices of the levels rebuilt).
void synthesis(MRMap2& m, AttributeArray<Vec3>& pos, const AttributeArray<Vec3>& details, MRBank bank, uint32 from = 0);

/// The inverse of synthesis, from the finest level down to level `to`: for l
/// = max_level(m) ... to + 1, the positions of level l - 1 and the details
/// of level l, so that P_l = S(P_{l-1}) + D_l. Linear keeps the old vertices
/// where they are (an interpolating scheme). Loop and CatmullClark take the
/// positions of level l - 1 whose prediction S(P_{l-1}) is closest to P_l in
/// the least-squares sense (a sparse Cholesky factorization per level): the
/// best coarse fit, which is the level below itself (with zero details) when
/// level l was made by synthesis. Motions of level l - 1 that predict nothing
/// (Catmull-Clark on a cube: the vertices moving +v and -v alternately) are
/// taken from the old vertices' positions at level l. Writes the positions of
/// levels to ... max_level(m) - 1 and the details of levels to + 1 ...
/// max_level(m); the finest positions are not changed. Throws as synthesis,
/// and std::runtime_error when a factorization fails. O(vertices x levels)
/// for Linear; a sparse factorization per level otherwise.
void analysis(MRMap2& m, AttributeArray<Vec3>& pos, AttributeArray<Vec3>& details, MRBank bank, uint32 to = 0);

/// Keeps the shape of levels 0 ... `level` and drops the finer details: an
/// analysis down to level 0, the details of levels above `level` set to zero,
/// and a synthesis (a smoothing of the finest level). Same costs and throws
/// as analysis.
void filter_low_pass(MRMap2& m, AttributeArray<Vec3>& pos, MRBank bank, uint32 level);

/// Drops the details of levels 1 ... `level` and keeps the finer ones: the
/// coarse shape of level 0 with the fine features. Same costs and throws as
/// analysis.
void filter_high_pass(MRMap2& m, AttributeArray<Vec3>& pos, MRBank bank, uint32 level);

} // namespace cgogn::modeling
