// SPDX-License-Identifier: MIT
// Decimation of triangle surfaces by edge collapses ordered by quadric error.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/modeling/progress.h>

#include <limits>

namespace cgogn::modeling
{

/// Where the vertex left by a collapse goes.
enum class CollapsePlacement
{
	/// Minimizer of the summed quadric (a 3x3 solve); when the system is
	/// singular (flat or cylindrical neighbourhood), the best of the two ends
	/// and the midpoint.
	Optimal,
	/// The midpoint of the edge, always (the "mid-edge" variant). The priority
	/// is still the quadric error, evaluated at the midpoint, so the order of
	/// collapses follows the geometry and not only the edge lengths.
	Midpoint
};

/// When decimate stops and how it places and accepts collapses.
struct DecimationOptions
{
	/// Stop when the number of faces is at most this. A collapse removes the
	/// two triangles of an interior edge (one for a boundary edge), so a
	/// closed mesh, whose face count stays even, stops at target - 1 when the
	/// target is odd.
	uint32 target_faces = 0;
	/// Stop before the first collapse whose quadric error (sum of squared
	/// distances to the planes of the merged neighbourhoods) exceeds this.
	double max_error = std::numeric_limits<double>::infinity();
	CollapsePlacement placement = CollapsePlacement::Optimal; ///< Where the vertex left by a collapse goes.
	/// true: boundary vertices neither move nor disappear (boundary edges are
	/// not collapsed; an edge from an interior vertex to a boundary one
	/// collapses onto the boundary vertex, which keeps its position), so the
	/// boundary polylines stay exactly as they are. false: boundary edges
	/// collapse too, held in place by boundary quadrics (the plane through
	/// each boundary edge perpendicular to its face, weight
	/// `boundary_weight`).
	bool keep_boundary = false;
	/// Weight of the boundary quadrics against the face quadrics (weight 1),
	/// when keep_boundary is false: larger keeps the boundary closer to its
	/// place.
	double boundary_weight = 10.0;
	/// A collapse is rejected when a surviving face's normal turns by more
	/// than the angle whose cosine this is (0: rejects fold-overs, normals
	/// turning by 90 degrees or more), or when a face degenerates.
	double min_normal_cosine = 0.0;
};

/// What decimate did.
struct DecimationResult
{
	uint32 faces = 0;       ///< faces left
	uint32 collapses = 0;   ///< collapses done
	double max_error = 0.0; ///< largest quadric error among them
	bool cancelled = false; ///< the progress callback asked to stop
};

/// Garland-Heckbert decimation: collapses edges by increasing quadric error
/// until `target_faces` is reached, the next error exceeds `max_error`, or no
/// edge can be collapsed any more (link condition, normal test, boundary).
/// Every vertex carries the sum of the plane quadrics of its original faces
/// (unweighted, as in the paper); a collapse adds its ends' quadrics. The
/// candidates wait in a binary heap; a collapse stamps the darts it touches,
/// so outdated entries are skipped when they come out. A candidate that
/// fails the link condition or the normal test is dropped until a collapse
/// changes its neighbourhood. Only vertex positions are written; the map
/// stays closed, manifold and valid (check_integrity) after every collapse,
/// also when the progress callback cancels. Throws cgogn::Error when a face
/// is not a triangle. O(n log n).
/// `progress` (optional, as for every modeling function) receives the
/// fraction done and may return false to stop.
DecimationResult decimate(CMap2& m, AttributeArray<Vec3>& pos, const DecimationOptions& options,
						  const ProgressCallback& progress = {});
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
DecimationResult decimate(CMap3& m, AttributeArray<Vec3>& pos, const DecimationOptions& options,
						  const ProgressCallback& progress = {}) = delete;

} // namespace cgogn::modeling
