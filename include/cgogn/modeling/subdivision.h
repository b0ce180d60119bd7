// SPDX-License-Identifier: MIT
// Uniform subdivision: Loop, Catmull-Clark and sqrt3 on surfaces, 1-to-8
// refinement of hexahedral and tetrahedral volume meshes.
#pragma once

#include <cgogn/core/map/cmap2.h>
#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/modeling/progress.h>

namespace cgogn::modeling
{

/// Thrown when a scheme is given cells it does not handle (a polygon to Loop
/// or sqrt3, a non-hexahedron to hex_subdivision, ...). The map is untouched.
class SubdivisionError : public Error
{
public:
	using Error::Error;
};

/// What one subdivision call did.
struct SubdivisionResult
{
	/// The progress callback asked to stop. Each step either did not start
	/// changing the map (cancelled while computing the new positions: the map
	/// and its positions are untouched) or was completed (a request arriving
	/// while the connectivity changes is honoured at the end of the step); an
	/// iterated subdivision stops after that step. The map always passes
	/// check_integrity.
	bool cancelled = false;
	/// Steps completed (1 for the one-step functions unless cancelled).
	uint32 steps = 0;
};

// Common to the surface schemes: new positions are computed from the old
// ones, then the connectivity is refined with the core operators (cut_edge,
// cut_face, triangulate_face, flip_edge), which keep every indexed orbit
// indexed. Old vertices keep their lines (their other attributes keep their
// values); new vertices, edges and faces get new lines whose attribute values
// are the attributes' defaults (zero vectors, 0, ...). Only `pos` is
// computed. Boundary faces are never subdivided; the boundary edges are cut
// like the others. Each function does one step in O(size of the map).
// The surface schemes run on a CMap2 and on a GMap2, orientable or not,
// with the same rules: on a G-map, the result has the same vertices, edges
// and faces as the CMap2's result on the same surface.

/// True when every non-boundary face of m is a triangle. O(darts).
bool is_triangle_mesh(const CMap2& m);
/// True when every non-boundary face of m is a triangle. O(darts).
bool is_triangle_mesh(const GMap2& m);
/// Not for 3-G-maps: deleted.
bool is_triangle_mesh(const GMap3& m) = delete;
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
bool is_triangle_mesh(const CMap3& m) = delete;

/// One step of Loop subdivision (Loop 1987, with Loop's original weights, as
/// OpenMesh's LoopT): each edge gets a vertex at 3/8 (a + b) + 1/8 (c + d)
/// (a, b its ends, c, d the opposite vertices), each triangle is cut into 4,
/// and an interior vertex of valence n moves to (1 - n beta) p + beta sum(q)
/// with n beta = 5/8 - (3/8 + 1/4 cos(2 pi / n))^2. Boundary rules: a
/// boundary edge's vertex is its midpoint, a boundary vertex moves to
/// 1/8 q0 + 3/4 p + 1/8 q1 (q0, q1 its boundary neighbours; a vertex with
/// more than two boundary edges stays). Throws SubdivisionError (map
/// untouched) when a face is not a triangle (see is_triangle_mesh).
/// V + E vertices, 4F faces afterwards. O(n).
SubdivisionResult loop_subdivision(CMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});
/// Loop subdivision of a 2-G-map (see the CMap2 version). O(n).
SubdivisionResult loop_subdivision(GMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});
/// Not for 3-G-maps: deleted.
SubdivisionResult loop_subdivision(GMap3& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {}) = delete;
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
SubdivisionResult loop_subdivision(CMap3& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {}) = delete;

/// One step of Catmull-Clark subdivision on any polygons (the rules of
/// CGAL's CatmullClark_subdivision): a face of degree k gets its centroid f
/// and becomes k quads; an interior edge gets (a + b + f1 + f2) / 4; an
/// interior vertex of valence n moves to (Q + 2R + (n - 3) p) / n with Q the
/// mean of its faces' centroids and R the mean of its edges' midpoints.
/// Boundary (crease) rules: a boundary edge's vertex is its midpoint, a
/// boundary vertex moves to 1/8 q0 + 3/4 p + 1/8 q1 (a vertex with more than
/// two boundary edges stays). Afterwards every face is a quad. Throws
/// SubdivisionError (map untouched) when a face has fewer than 3 edges. O(n).
SubdivisionResult catmull_clark_subdivision(CMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});
/// Catmull-Clark subdivision of a 2-G-map (see the CMap2 version). O(n).
SubdivisionResult catmull_clark_subdivision(GMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});
/// Not for 3-G-maps: deleted.
SubdivisionResult catmull_clark_subdivision(GMap3& m, AttributeArray<Vec3>& pos,
											const ProgressCallback& progress = {}) = delete;
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
SubdivisionResult catmull_clark_subdivision(CMap3& m, AttributeArray<Vec3>& pos,
											const ProgressCallback& progress = {}) = delete;

/// One step of sqrt3 subdivision (Kobbelt 2000, as OpenMesh's Sqrt3T): each
/// triangle gets its centroid and is split in 3, each old interior vertex of
/// valence n moves to (1 - a) p + a/n sum(q) with a = (4 - 2 cos(2 pi / n)) / 9,
/// and every old interior edge is flipped (unless the flip would double an
/// edge: two triangles sharing two edges). Boundary choice: boundary
/// vertices stay where they are and boundary edges are not flipped (each
/// boundary triangle simply becomes 3); Kobbelt's every-other-step boundary
/// rule is not applied, so a step on a mesh with boundary equals OpenMesh's
/// first step (its generation 0), not its odd generations. Throws
/// SubdivisionError (map untouched) when a face is not a triangle.
/// V + F vertices, 3F faces afterwards. O(n).
SubdivisionResult sqrt3_subdivision(CMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});
/// sqrt3 subdivision of a 2-G-map (see the CMap2 version). O(n).
SubdivisionResult sqrt3_subdivision(GMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});
/// Not for 3-G-maps: deleted.
SubdivisionResult sqrt3_subdivision(GMap3& m, AttributeArray<Vec3>& pos,
									const ProgressCallback& progress = {}) = delete;
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
SubdivisionResult sqrt3_subdivision(CMap3& m, AttributeArray<Vec3>& pos,
									const ProgressCallback& progress = {}) = delete;

enum class SurfaceScheme
{
	Loop,
	CatmullClark,
	Sqrt3
};

/// `iterations` steps of a scheme; progress goes from 0 to 1 over all steps.
/// Stops after the step during which the callback asked to stop.
SubdivisionResult subdivide(CMap2& m, AttributeArray<Vec3>& pos, SurfaceScheme scheme, uint32 iterations,
							const ProgressCallback& progress = {});
/// The same on a 2-G-map.
SubdivisionResult subdivide(GMap2& m, AttributeArray<Vec3>& pos, SurfaceScheme scheme, uint32 iterations,
							const ProgressCallback& progress = {});
/// Not for 3-G-maps: deleted.
SubdivisionResult subdivide(GMap3& m, AttributeArray<Vec3>& pos, SurfaceScheme scheme, uint32 iterations,
							const ProgressCallback& progress = {}) = delete;
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
SubdivisionResult subdivide(CMap3& m, AttributeArray<Vec3>& pos, SurfaceScheme scheme, uint32 iterations,
							const ProgressCallback& progress = {}) = delete;

// Volume refinements. The map is rebuilt from the refined cell list with
// build_volume (every cell of the result is a new cell): positions are
// computed for every vertex; every other attribute of the map is kept but
// all its values are reset to the attribute's default, and Dart/Cell values
// held by the caller are invalid afterwards. Precondition: no marker of the
// map is alive. Throws SubdivisionError (map untouched) on other cells.
// Cancelling is possible while the new cells are computed (map untouched).

/// True when every volume of m is a hexahedron (6 quads). O(darts).
bool is_hex_mesh(const CMap3& m);
/// True when every volume of m is a tetrahedron. O(darts).
bool is_tet_mesh(const CMap3& m);

/// Cuts every hexahedron into 8 through its edge midpoints, face centroids
/// and vertex centroid. V + E + F + W vertices, 8W volumes. O(n).
SubdivisionResult hex_subdivision(CMap3& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});

/// Cuts every tetrahedron into 8 (Bey's red refinement): 4 corner tetrahedra
/// through the edge midpoints and the inner octahedron split into 4 around its
/// shortest diagonal (among diagonals of the same length, the one whose ends
/// come first by (x, y, z): see tet_cut_diagonal, so the cut does not depend
/// on how the tetrahedron is stored). The sum of the volumes is preserved (up to rounding).
/// V + E vertices, 8W volumes. O(n).
SubdivisionResult tet_subdivision(CMap3& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress = {});

} // namespace cgogn::modeling
