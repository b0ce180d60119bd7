// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <Eigen/Geometry> // cross()

#include <algorithm>
#include <cmath>

namespace cgogn::geometry
{

/// A 2-map or a 3-map: the meshes whose faces the geometry layer measures.
template <typename MESH>
concept GeometricMesh = MapType<MESH> &&(mesh_traits<MESH>::dimension == 2 || mesh_traits<MESH>::dimension == 3);

/// Position of the origin of dart d (its vertex). O(1). Precondition: pos is a
/// vertex attribute of m.
template <GeometricMesh MESH>
const Vec3& origin_position(const MESH& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return value<Vec3>(m, pos, typename mesh_traits<MESH>::Vertex(d));
}

/// The vector of dart d: from its origin to the origin of phi1(d). O(1).
template <GeometricMesh MESH>
Vec3 dart_vector(const MESH& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return origin_position(m, pos, phi1(m, d)) - origin_position(m, pos, d);
}

/// Angle in [0, pi] between two vectors, robust for small and large angles
/// (atan2 of the cross and dot products). 0 when either vector is zero. O(1).
inline double angle_between(const Vec3& a, const Vec3& b)
{
	return std::atan2(a.cross(b).norm(), a.dot(b));
}

/// Cotangent of the angle between a and b. A degenerate corner (the vectors
/// nearly parallel or zero, |a x b| <= 1e-12 |a| |b|) gets 0 so that it adds
/// no weight instead of an infinite one. O(1).
inline double cotan(const Vec3& a, const Vec3& b)
{
	const double s = a.cross(b).norm();
	const double scale = a.norm() * b.norm();
	if (s <= 1e-12 * scale)
		return 0.0;
	return a.dot(b) / s;
}

} // namespace cgogn::geometry
