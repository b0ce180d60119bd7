// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/normal.h>

#include <Eigen/Geometry> // cross()

#include <vector>

namespace cgogn::geometry
{

namespace detail
{
/// Share of triangle (p, q, r) given to its corner p by the mixed Voronoi
/// rule of Meyer et al. 2003: the Voronoi region of p in a non-obtuse
/// triangle, otherwise half the area when the angle at p is obtuse and a
/// quarter when another angle is. The three shares add up to the area. O(1).
inline double mixed_voronoi_share(const Vec3& p, const Vec3& q, const Vec3& r)
{
	const Vec3 pq = q - p, pr = r - p, qr = r - q;
	const double area = 0.5 * pq.cross(pr).norm();
	if (pq.dot(pr) < 0.0)
		return 0.5 * area;
	if (pq.dot(qr) > 0.0 || pr.dot(qr) < 0.0) // obtuse at q or at r
		return 0.25 * area;
	return (pq.squaredNorm() * cotan(p - r, q - r) + pr.squaredNorm() * cotan(p - q, r - q)) / 8.0;
}

/// Share of the face of dart d given to the origin of d: the mixed Voronoi
/// share on a triangle, area / degree on other polygons. O(face degree).
template <SurfaceMesh MESH>
double corner_area(const MESH& m, Dart d, const AttributeArray<Vec3>& pos)
{
	const Dart d1 = oriented_phi1(m, d);
	const Dart d2 = oriented_phi1(m, d1);
	if (oriented_phi1(m, d2) == d)
		return mixed_voronoi_share(origin_position(m, pos, d), origin_position(m, pos, d1),
								   origin_position(m, pos, d2));
	uint32 n = 0;
	Dart it = d;
	do
	{
		++n;
		it = oriented_phi1(m, it);
	} while (it != d);
	return 0.5 * newell_vector(m, pos, d).norm() / n;
}
} // namespace detail

/// Area of the region of vertex v of a surface: mixed Voronoi areas (Meyer,
/// Desbrun, Schroeder, Barr 2003) on incident triangles, an equal share of
/// the area on other incident polygons. The areas of all vertices add up to the
/// area of the surface. The same on a G-map (it needs no orientation).
/// O(sum of the degrees of the incident faces).
template <SurfaceMesh MESH>
double voronoi_area(const MESH& m, typename mesh_traits<MESH>::Vertex v, const AttributeArray<Vec3>& pos)
{
	double a = 0.0;
	// one dart per corner (a G-map has two per corner)
	foreach_oriented_corner(m, v, [&](Dart d) {
		if (!is_boundary(m, d))
			a += detail::corner_area(m, d, pos);
	});
	return a;
}

/// Writes voronoi_area of every vertex into the vertex attribute `area`.
/// O(number of darts).
template <SurfaceMesh MESH>
void compute_voronoi_areas(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& area)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	foreach_cell(m, [&](Vertex v) { area[v] = voronoi_area(m, v, pos); });
}

} // namespace cgogn::geometry
