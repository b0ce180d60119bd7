// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <Eigen/Geometry> // cross()

#include <algorithm>
#include <cmath>

namespace cgogn::geometry
{

/// A 2-map or a 3-map: the meshes whose faces the geometry layer measures.
template <typename MESH>
concept GeometricMesh = MapType<MESH> &&(mesh_traits<MESH>::dimension == 2 || mesh_traits<MESH>::dimension == 3);

// Oriented walks. The geometry reads a face, a corner or an edge through the
// oriented relations below. On a combinatorial map they are phi1, phi_1 and
// phi2. On a G-map they are the even compositions of the involutions that
// to_cmap turns into phi1 and phi2 (phi1 = beta1 o beta0, phi2 = beta0 o
// beta2): they keep the colour of the dart they start from, so that a walk
// from a dart d sees the faces around it oriented as d's face is, whether
// or not the whole surface can be oriented. A dart d of a G-map goes from
// its vertex to that of beta0(d): a face seen from d runs in that direction.

/// Next dart of the face of d, in the orientation of d: phi1(d) on a
/// combinatorial map, beta1(beta0(d)) on a G-map. O(1).
template <GeometricMesh MESH>
Dart oriented_phi1(const MESH& m, Dart d)
{
	if constexpr (is_gmap_v<MESH>)
		return beta<0, 1>(m, d);
	else
		return phi1(m, d);
}

/// Previous dart of the face of d, in the orientation of d: phi_1(d) on a
/// combinatorial map (O(face degree), see phi_1), beta0(beta1(d)) on a
/// G-map (O(1)).
template <GeometricMesh MESH>
Dart oriented_phi_1(const MESH& m, Dart d)
{
	if constexpr (is_gmap_v<MESH>)
		return beta<1, 0>(m, d);
	else
		return phi_1(m, d);
}

/// The dart of the face across the edge of d, from the far end of that
/// edge, so that the two faces are oriented consistently: phi2(d) on a
/// 2-map, beta0(beta2(d)) on a 2-G-map. O(1).
template <SurfaceMesh MESH>
Dart oriented_phi2(const MESH& m, Dart d)
{
	if constexpr (is_gmap_v<MESH>)
		return beta<2, 0>(m, d);
	else
		return phi2(m, d);
}

/// Calls f on one dart per corner around vertex v of a surface (boundary
/// corners included), each the dart of its face that leaves v, all oriented
/// as v.dart: the darts of v on a 2-map; on a 2-G-map, half of them, walked
/// by beta1 o beta2 from v.dart. f may return false to stop. O(degree).
template <SurfaceMesh MESH, typename FUNC>
void foreach_oriented_corner(const MESH& m, typename mesh_traits<MESH>::Vertex v, const FUNC& f)
{
	if constexpr (is_gmap_v<MESH>)
	{
		Dart it = v.dart;
		do
		{
			if (!call_and_continue(f, it))
				return;
			it = oriented_phi1(m, oriented_phi2(m, it));
		} while (it != v.dart);
	}
	else
		foreach_dart_of_orbit(m, v, f);
}

/// Position of the origin of dart d (its vertex). O(1). Precondition: pos is a
/// vertex attribute of m.
template <GeometricMesh MESH>
const Vec3& origin_position(const MESH& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return value<Vec3>(m, pos, typename mesh_traits<MESH>::Vertex(d));
}

/// The vector of dart d: from its origin to the origin of phi1(d) (of
/// beta0(d) on a G-map). O(1).
template <GeometricMesh MESH>
Vec3 dart_vector(const MESH& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return origin_position(m, pos, oriented_phi1(m, d)) - origin_position(m, pos, d);
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
