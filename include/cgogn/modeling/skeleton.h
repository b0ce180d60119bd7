// SPDX-License-Identifier: MIT
// Curve skeletons of closed surfaces by mean-curvature contraction.
#pragma once

#include <cgogn/core/map/cmap2.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/modeling/progress.h>

namespace cgogn::modeling
{

/// How skeleton() contracts the surface (Au, Tai, Chu, Cohen-Or, Lee:
/// "Skeleton extraction by mesh contraction", SIGGRAPH 2008).
struct SkeletonOptions
{
	/// At most this many contraction steps (each one sparse solve).
	uint32 max_iterations = 20;
	/// Contraction stops when the surface's area falls below this fraction of
	/// its initial area.
	double area_ratio = 1e-6;
	/// The factor by which the contraction weight grows at each step (the
	/// paper's s_L): larger contracts faster and keeps less of the shape.
	double contraction_growth = 2.0;
	/// Reports the fraction done (contraction, then collapses); returning
	/// false stops the contraction where it is, and the skeleton is then
	/// extracted from the surface as contracted so far.
	ProgressCallback progress;
};

/// The curve skeleton of a closed surface: its vertices are moved by
/// implicit mean-curvature (cotangent Laplacian) contraction, each step
/// solving (w_L^2 L^T L + W_H^2) P' = W_H^2 P by a sparse Cholesky
/// factorization, with w_L growing and each vertex's attraction W_H growing
/// as its one-ring area shrinks, until the area vanishes. The contracted
/// surface becomes an incidence graph (polygons fanned into triangles),
/// whose edges are collapsed, shortest first (the survivor at the midpoint),
/// until no face remains: its 1-skeleton is the result, with the Vec3 vertex
/// attribute "position". On a closed connected surface of genus g, the
/// skeleton is connected with cycle rank g, inside the surface's bounding
/// box. Throws Error when the surface has a boundary or a face of fewer
/// than 3 vertices, or a position is not finite. O(iterations x the sparse
/// factorization, about n^1.5 for n vertices, + n log n for the collapses).
Graph skeleton(const CMap2& surface, const AttributeArray<Vec3>& pos, const SkeletonOptions& options = {});

} // namespace cgogn::modeling
