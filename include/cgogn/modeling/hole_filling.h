// SPDX-License-Identifier: MIT
// Filling the holes of a surface: minimal-weight triangulation (Liepa 2003),
// refinement and fairing.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/modeling/fairing.h>
#include <cgogn/modeling/progress.h>

#include <limits>

namespace cgogn::modeling
{

/// How fill_hole and fill_holes triangulate, refine and fair a hole.
struct HoleFillingOptions
{
	/// Insert vertices so that the patch's edge lengths match those around
	/// the hole (Liepa's density control, with Delaunay edge flips).
	bool refine = true;
	/// Fair the inserted vertices (needs refine; the hole's boundary is fixed).
	bool fair = true;
	/// Holes with more boundary edges are left open (counted as skipped).
	uint32 max_hole_size = std::numeric_limits<uint32>::max();
	/// Holes up to this size get the O(n^3) minimal-weight triangulation;
	/// larger ones are ear-clipped (ear_clip_face on the filled polygon) to
	/// bound the cost.
	uint32 max_optimal_size = 1000;
	/// Liepa's density factor: a triangle is split when its centroid is
	/// farther than (target length / density) from each of its corners.
	double density = 1.4142135623730951;
	FairingWeights fairing_weights = FairingWeights::Cotangent; ///< The Laplacian weights of the fairing.
	/// 1: bi-harmonic (tangent continuity with the surface around the hole).
	uint32 fairing_continuity = 1;
};

/// What fill_hole or fill_holes did.
struct HoleFillingResult
{
	uint32 holes_found = 0;  ///< Boundary loops found (1 for fill_hole).
	uint32 holes_filled = 0; ///< Holes triangulated (refined and faired or not).
	/// Larger than max_hole_size, or of fewer than 3 edges.
	uint32 holes_skipped = 0;
	/// Holes triangulated by ear clipping (larger than max_optimal_size).
	uint32 holes_ear_clipped = 0;
	uint32 faces_added = 0;    ///< Triangles created, by the triangulation and the refinement.
	uint32 vertices_added = 0; ///< Vertices inserted by the refinement.
	/// Fairing systems that were singular (those patches keep the refined positions).
	uint32 fairing_failures = 0;
	/// The callback asked to stop: holes not yet started are left open; a
	/// hole being filled is either untouched or filled (its refinement or
	/// fairing may be skipped).
	bool cancelled = false;
};

/// Fills the hole (boundary face) of dart d with triangles: the minimal
/// weight triangulation of its boundary loop (dynamic programming over the
/// loop, Liepa 2003), the weight of a triangulation being, lexicographically,
/// the largest dihedral angle between adjacent triangles (the faces around the
/// hole included) then the total area; edges already present in the mesh
/// between loop vertices are avoided. Then, with options.refine, triangles
/// are split at their centroid and edges flipped to Delaunay until the edge
/// lengths match the mean edge length at the loop's vertices, and with
/// options.fair the new vertices are placed by fair_vertices. The new faces
/// are oriented like the surface. Loops of fewer than 3 edges or more than
/// options.max_hole_size are left open (counted as skipped). `pos` is m's
/// vertex position attribute; new vertices get positions there. Precondition
/// (throws TopologyError): d is a boundary dart of m. Cost O(n^3) for a loop of n edges (n <= max_optimal_size),
/// O(n^2) to O(n^3) by ear clipping above, plus the refinement and a sparse
/// solve on the patch. Core's cgogn::fill_hole_with_face(m, d) is the purely
/// topological counterpart: it turns the hole into one polygon.
HoleFillingResult fill_hole(CMap2& m, AttributeArray<Vec3>& pos, Dart d, const HoleFillingOptions& options = {},
							const ProgressCallback& progress = {});
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
HoleFillingResult fill_hole(CMap3& m, AttributeArray<Vec3>& pos, Dart d, const HoleFillingOptions& options = {},
							const ProgressCallback& progress = {}) = delete;

/// fill_hole on every boundary loop of m (skipping those larger than
/// options.max_hole_size). Progress counts holes; cancelling leaves the
/// remaining holes open. O(sum of the costs of the holes).
HoleFillingResult fill_holes(CMap2& m, AttributeArray<Vec3>& pos, const HoleFillingOptions& options = {},
							 const ProgressCallback& progress = {});
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
HoleFillingResult fill_holes(CMap3& m, AttributeArray<Vec3>& pos, const HoleFillingOptions& options = {},
							 const ProgressCallback& progress = {}) = delete;

} // namespace cgogn::modeling
