// SPDX-License-Identifier: MIT
// Triangulation of polygonal faces by ear clipping.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/geometry/types/vector_traits.h>

namespace cgogn::modeling
{

/// Cuts face f (any simple polygon, convex or not, roughly planar) into
/// degree - 2 triangles by ear clipping in the plane of its Newell normal,
/// without new vertices. Among the ears of the remaining polygon it cuts the
/// one of largest smallest angle, so fans of slivers are avoided on convex
/// faces too. Faces that are not simple in projection (self-intersecting,
/// repeated positions) still get a valid triangulation: when no true ear is
/// left, the most convex corner is cut. Returns the number of triangles
/// created (0 for a triangle). Precondition: f is not a boundary face.
/// O(degree^3) worst case, O(degree^2) for convex faces.
uint32 ear_clip_face(CMap2& m, const AttributeArray<Vec3>& pos, CMap2::Face f);
/// The same on a 2-G-map: the polygon is walked from f.dart (its corners in
/// the order of beta1 o beta0). Same cost.
uint32 ear_clip_face(GMap2& m, const AttributeArray<Vec3>& pos, GMap2::Face f);
/// Not for 3-G-maps: deleted.
uint32 ear_clip_face(GMap3& m, const AttributeArray<Vec3>& pos, GMap2::Face f) = delete;
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
uint32 ear_clip_face(CMap3& m, const AttributeArray<Vec3>& pos, CMap2::Face f) = delete;

/// ear_clip_face on every face of degree > 3; returns the number of faces cut.
/// The map's faces are then all triangles (boundary faces excepted).
uint32 triangulate_faces(CMap2& m, const AttributeArray<Vec3>& pos);
/// The same on a 2-G-map, orientable or not.
uint32 triangulate_faces(GMap2& m, const AttributeArray<Vec3>& pos);
/// Not for 3-G-maps: deleted.
uint32 triangulate_faces(GMap3& m, const AttributeArray<Vec3>& pos) = delete;
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
uint32 triangulate_faces(CMap3& m, const AttributeArray<Vec3>& pos) = delete;

} // namespace cgogn::modeling
