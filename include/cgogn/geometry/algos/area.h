// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/normal.h>

namespace cgogn::geometry
{

/// Area of face f: half the norm of its Newell vector. Exact for any planar
/// polygon, convex or not; for a non-planar one, the area of its projection
/// on the best-fitting plane. O(face degree).
template <GeometricMesh MESH>
double face_area(const MESH& m, typename mesh_traits<MESH>::Face f, const AttributeArray<Vec3>& pos)
{
	return 0.5 * newell_vector(m, pos, f.dart).norm();
}

/// Writes the area of every face into the face attribute `area`.
/// O(number of darts).
template <GeometricMesh MESH>
void compute_face_areas(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& area)
{
	using Face = typename mesh_traits<MESH>::Face;
	foreach_cell(m, [&](Face f) { area[f] = face_area(m, f, pos); });
}

/// Sum of the areas of the faces of the mesh (boundary faces excluded; in a
/// 3-map, every face once, inner faces included). O(number of darts).
template <GeometricMesh MESH>
double surface_area(const MESH& m, const AttributeArray<Vec3>& pos)
{
	using Face = typename mesh_traits<MESH>::Face;
	double a = 0.0;
	foreach_cell(m, [&](Face f) { a += face_area(m, f, pos); });
	return a;
}

/// Area of the boundary surface of a 3-map or a 3-G-map: the faces between a
/// volume and the outside. O(number of darts).
template <VolumeMesh MESH>
double boundary_area(const MESH& m, const AttributeArray<Vec3>& pos)
{
	double a = 0.0;
	foreach_cell(m, [&](typename mesh_traits<MESH>::Face f) {
		if (is_incident_to_boundary(m, f))
			a += face_area(m, f, pos);
	});
	return a;
}

} // namespace cgogn::geometry
