// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/properties.h>
#include <cgogn/geometry/algos/cotan_stiffness.h>
#include <cgogn/geometry/algos/voronoi_area.h>

#include <vector>

namespace cgogn::geometry
{

/// Integrated cotangent Laplacian of the positions at vertex v: the sum over
/// the incident faces of their stiffness rows (see cotan_laplacian), i.e.
/// -2 H n A on a smooth surface (H the mean curvature, n the normal, A the
/// vertex area). The same on a G-map (it needs no orientation). O(sum of
/// the squared degrees of the incident faces).
template <SurfaceMesh MESH>
Vec3 cotan_laplacian_of_position(const MESH& m, typename mesh_traits<MESH>::Vertex v, const AttributeArray<Vec3>& pos)
{
	detail::FaceStiffness& k = detail::face_stiffness_scratch();
	Vec3 l = Vec3::Zero();
	foreach_oriented_corner(m, v, [&](Dart d) {
		if (is_boundary(m, d))
			return;
		const uint32 n = k.compute(m, pos, d); // d, the vertex v, is row 0
		for (uint32 j = 1; j < n; ++j)
			l += k(0, j) * (k.position(j) - k.position(0));
	});
	return l;
}

/// Mean curvature at vertex v (Meyer et al. 2003): |L x| / (2 A) with L x the
/// cotangent Laplacian of the positions and A the mixed Voronoi area, signed
/// positive where the surface bends away from its normal (a sphere with
/// outward faces has H = 1 / radius). 0 at boundary vertices (there L x
/// measures the boundary curve, not the surface). On a G-map the sign is
/// taken against the faces oriented as the face of v.dart (see face_normal):
/// |H| is that of the 2-map, the sign that of a 2-map oriented so. O(sum of
/// the squared degrees of the incident faces).
template <SurfaceMesh MESH>
double mean_curvature(const MESH& m, typename mesh_traits<MESH>::Vertex v, const AttributeArray<Vec3>& pos)
{
	if (is_incident_to_boundary(m, v))
		return 0.0;
	const double a = voronoi_area(m, v, pos);
	if (a <= 0.0)
		return 0.0;
	const Vec3 l = cotan_laplacian_of_position(m, v, pos);
	Vec3 n = Vec3::Zero(); // area-weighted normal: only its side matters
	foreach_oriented_corner(m, v, [&](Dart d) { n += newell_vector(m, pos, d); });
	const double h = l.norm() / (2.0 * a);
	return l.dot(n) > 0.0 ? -h : h;
}

/// Writes mean_curvature of every vertex into the vertex attribute `h` (on a
/// G-map, each signed in the orientation of its vertex's dart). O(number of
/// darts times the face degree).
template <SurfaceMesh MESH>
void compute_mean_curvatures(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& h)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	foreach_cell(m, [&](Vertex v) { h[v] = mean_curvature(m, v, pos); });
}

} // namespace cgogn::geometry
