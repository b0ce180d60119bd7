// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/geometry/algos/angle.h>
#include <cgogn/geometry/algos/normal.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <cmath>

namespace cgogn::geometry
{

/// Principal curvatures (kmin <= kmax) and their unit tangent directions; all
/// zero where they cannot be estimated (no area or no normal at the vertex).
struct PrincipalCurvatures
{
	double kmin = 0.0;        ///< The smaller principal curvature (1 / length unit).
	double kmax = 0.0;        ///< The larger principal curvature (1 / length unit).
	Vec3 dmin = Vec3::Zero(); ///< The unit direction of kmin, in the tangent plane.
	Vec3 dmax = Vec3::Zero(); ///< The unit direction of kmax, orthogonal to dmin.
};

/// Principal curvatures and directions at vertex v of a surface, by the
/// normal cycle curvature tensor of Cohen-Steiner and Morvan (2003) over the
/// one-ring B of v: T = (1 / area(B)) sum_e beta(e) |e n B| e e^T with beta the
/// signed dihedral angle (positive where convex) and e the unit edge
/// direction; edges incident to v count fully, the other edges of the
/// incident faces (on the border of B) by half. Restricted to the tangent
/// plane of the area-weighted vertex normal, T has the principal curvatures
/// as eigenvalues with their directions swapped (the eigenvector of the
/// largest one is the direction of least curvature). Signs follow
/// mean_curvature (a sphere with outward faces has k = 1 / radius). Works on
/// any polygons; at boundary vertices the estimate only sees the inner side.
/// On a G-map the one-ring is oriented as the face of v.dart (see
/// face_normal); turning it over gives (-kmax, -kmin) with the directions
/// swapped. O(sum of the squared degrees of the incident faces).
template <SurfaceMesh MESH>
PrincipalCurvatures principal_curvatures(const MESH& m, typename mesh_traits<MESH>::Vertex v,
										 const AttributeArray<Vec3>& pos)
{
	using Edge = typename mesh_traits<MESH>::Edge;
	Mat3 t = Mat3::Zero();
	double area = 0.0;
	auto add_edge = [&](Dart d, double weight) {
		const double beta = dihedral_angle(m, Edge(d), pos);
		const Vec3 e = dart_vector(m, pos, d);
		const double l = e.norm();
		if (l > 0.0)
			t += (weight * beta / l) * e * e.transpose(); // beta |e| (e/|e|)(e/|e|)^T
	};
	// each dart oriented as v.dart, so that the dihedral angles agree in sign
	foreach_oriented_corner(m, v, [&](Dart d) {
		add_edge(d, 1.0);
		if (is_boundary(m, d))
			return;
		area += 0.5 * newell_vector(m, pos, d).norm();
		// edges of the face of d that do not touch v: all but d and the one before d
		for (Dart x = oriented_phi1(m, d); oriented_phi1(m, x) != d; x = oriented_phi1(m, x))
			add_edge(x, 0.5);
	});
	PrincipalCurvatures r;
	const Vec3 n = vertex_normal(m, v, pos, NormalWeighting::Area);
	if (area <= 0.0 || n.isZero())
		return r;
	// T restricted to the tangent plane: along the normal, T has an eigenvalue
	// near zero that may tie with a principal one (a cylinder), so its
	// eigenvectors cannot tell the normal apart
	const Vec3 t1 = n.unitOrthogonal();
	const Vec3 t2 = n.cross(t1);
	Eigen::Matrix2d s;
	s(0, 0) = t1.dot(t * t1);
	s(1, 1) = t2.dot(t * t2);
	s(0, 1) = s(1, 0) = t1.dot(t * t2);
	s /= area;
	Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(s);
	// eigenvalues ascending; each is the curvature across its eigenvector
	const Eigen::Vector2d w0 = es.eigenvectors().col(0), w1 = es.eigenvectors().col(1);
	r.kmin = es.eigenvalues()(0);
	r.kmax = es.eigenvalues()(1);
	r.dmin = (t1 * w1(0) + t2 * w1(1)).normalized();
	r.dmax = (t1 * w0(0) + t2 * w0(1)).normalized();
	return r;
}

/// Writes principal_curvatures of every vertex into the vertex attributes
/// kmin, kmax, dmin, dmax (on a G-map, each vertex in the orientation of its
/// dart). O(number of darts times the face degree).
template <SurfaceMesh MESH>
void compute_principal_curvatures(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& kmin,
								  AttributeArray<double>& kmax, AttributeArray<Vec3>& dmin, AttributeArray<Vec3>& dmax)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	foreach_cell(m, [&](Vertex v) {
		const PrincipalCurvatures c = principal_curvatures(m, v, pos);
		kmin[v] = c.kmin;
		kmax[v] = c.kmax;
		dmin[v] = c.dmin;
		dmax[v] = c.dmax;
	});
}

} // namespace cgogn::geometry
