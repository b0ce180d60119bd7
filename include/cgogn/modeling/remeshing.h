// SPDX-License-Identifier: MIT
// Isotropic remeshing of triangle surfaces (Botsch and Kobbelt 2004).
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/modeling/progress.h>

namespace cgogn::modeling
{

/// What isotropic_remeshing aims at and how long it works.
struct RemeshingOptions
{
	/// Target edge length L; 0 (the default) means the mean edge length of the input.
	double target_edge_length = 0.0;
	uint32 iterations = 10; ///< Iterations of split, collapse, flip, relax (and project).
	/// Feature edges: interior edges whose dihedral angle exceeds this many
	/// degrees are kept like the boundary (0, the default: no feature edges).
	double feature_angle = 0.0;
	/// Project the moved vertices back onto the input surface after each
	/// relaxation (recommended; false lets the surface shrink slowly).
	bool project = true;
};

/// What isotropic_remeshing did.
struct RemeshingResult
{
	uint32 iterations = 0;           ///< iterations completed
	uint64 splits = 0;               ///< edge splits, over all iterations
	uint64 collapses = 0;            ///< edge collapses, over all iterations
	uint64 flips = 0;                ///< edge flips, over all iterations
	double target_edge_length = 0.0; ///< the L used
	bool cancelled = false;          ///< the progress callback asked to stop
};

/// Botsch-Kobbelt isotropic remeshing towards edge length L. Each iteration:
/// (1) splits edges longer than 4/3 L at their midpoint (cut_edge, then
/// cut_face towards the opposite corners), until none is left; (2) collapses
/// edges shorter than 4/5 L into their midpoint (onto the locked end when one
/// end is locked) when can_collapse_edge allows it, no edge of the result is
/// longer than 4/3 L and no face normal turns over; (3) flips edges
/// (can_flip_edge) that bring the valences of their four vertices closer to
/// 6 (4 on the boundary) without folding a face; (4) moves every free vertex
/// to the uniform centroid of its neighbours, in its tangent plane (area-
/// weighted normal); (5) projects the moved vertices onto the input surface
/// (closest point, through a TriangleTree built once).
/// Boundary and feature edges are never collapsed nor flipped and their
/// vertices ("locked") never move; they may be split, at their midpoints,
/// so boundary polylines keep their exact shape and length. The map stays
/// valid (check_integrity) at every step; the progress callback is asked
/// after each phase and a cancel stops between phases. Throws cgogn::Error
/// when a face is not a triangle or L is not a positive finite number.
/// O(iterations n log n).
RemeshingResult isotropic_remeshing(CMap2& m, AttributeArray<Vec3>& pos, const RemeshingOptions& options = {},
									const ProgressCallback& progress = {});
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
RemeshingResult isotropic_remeshing(CMap3& m, AttributeArray<Vec3>& pos, const RemeshingOptions& options = {},
									const ProgressCallback& progress = {}) = delete;

} // namespace cgogn::modeling
