// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/normal.h>

#include <Eigen/Geometry> // cross()

#include <cmath>

namespace cgogn::geometry
{

/// Corner angle, in [0, pi], of the face of dart d at the origin of d:
/// between d and the previous edge of the face. Measured in 3-D between the
/// two edge vectors, so never more than pi: at a reflex corner of a non-convex
/// polygon it is 2 pi minus the interior angle. O(face degree) (phi_1 is not
/// stored); O(1) on a G-map, where the corner's other edge is that of
/// beta1(d).
template <GeometricMesh MESH>
double corner_angle(const MESH& m, Dart d, const AttributeArray<Vec3>& pos)
{
	const Vec3& p = origin_position(m, pos, d);
	return angle_between(origin_position(m, pos, oriented_phi1(m, d)) - p,
						 origin_position(m, pos, oriented_phi_1(m, d)) - p);
}

/// Signed dihedral angle of edge e of a surface: the angle between the normals
/// of its two faces, in (-pi, pi], positive where the surface is convex (with
/// faces oriented outwards), 0 where it is flat and on boundary edges. The
/// interior angle between the faces is pi minus this. On a G-map the faces
/// are oriented as the face of e.dart (see face_normal): the sign is that of
/// a 2-map whose face of e.dart runs the same way, and flips with it.
/// O(degrees of the two faces).
template <SurfaceMesh MESH>
double dihedral_angle(const MESH& m, typename mesh_traits<MESH>::Edge e, const AttributeArray<Vec3>& pos)
{
	const Dart d = e.dart;
	const Dart d2 = oriented_phi2(m, d);
	if (is_boundary(m, d) || is_boundary(m, d2))
		return 0.0;
	using Face = typename mesh_traits<MESH>::Face;
	const Vec3 n1 = face_normal(m, Face(d), pos);
	const Vec3 n2 = face_normal(m, Face(d2), pos);
	const Vec3 dir = dart_vector(m, pos, d).normalized();
	return std::atan2(n1.cross(n2).dot(dir), n1.dot(n2));
}

/// Writes the signed dihedral angle of every edge into the edge attribute
/// `angle` (on a G-map, each edge in the orientation of its dart).
/// O(number of darts times the face degree).
template <SurfaceMesh MESH>
void compute_dihedral_angles(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& angle)
{
	using Edge = typename mesh_traits<MESH>::Edge;
	foreach_cell(m, [&](Edge e) { angle[e] = dihedral_angle(m, e, pos); });
}

/// Sum of the corner angles of the faces incident to vertex v of a surface
/// (boundary faces excluded). 2 pi at a flat interior vertex. O(degree).
template <SurfaceMesh MESH>
double vertex_angle_sum(const MESH& m, typename mesh_traits<MESH>::Vertex v, const AttributeArray<Vec3>& pos)
{
	const Vec3& p = origin_position(m, pos, v.dart);
	double s = 0.0;
	Dart prev = v.dart;
	Dart it = v.dart;
	do
	{
		prev = it;
		it = oriented_phi1(m, oriented_phi2(m, it));
		if (!is_boundary(m, it))
			s += angle_between(origin_position(m, pos, oriented_phi1(m, it)) - p,
							   origin_position(m, pos, oriented_phi1(m, prev)) - p);
	} while (it != v.dart);
	return s;
}

} // namespace cgogn::geometry
