// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/properties.h>
#include <cgogn/geometry/algos/angle.h>
#include <cgogn/geometry/algos/voronoi_area.h>

#include <numbers>

namespace cgogn::geometry
{

/// Integrated Gaussian curvature of vertex v (angle defect): 2 pi minus the
/// sum of its corner angles at an interior vertex, pi minus that sum at a
/// boundary vertex (its turning angle). With this boundary rule the defects of
/// all vertices add up to 2 pi chi (discrete Gauss-Bonnet) on any mesh with
/// planar faces, closed or not. O(sum of the degrees of the incident faces).
template <SurfaceMesh MESH>
double angle_defect(const MESH& m, typename mesh_traits<MESH>::Vertex v, const AttributeArray<Vec3>& pos)
{
	const double full = is_incident_to_boundary(m, v) ? std::numbers::pi : 2.0 * std::numbers::pi;
	return full - vertex_angle_sum(m, v, pos);
}

/// Pointwise Gaussian curvature at vertex v: angle_defect / voronoi_area
/// (Meyer et al. 2003). 0 for a vertex of zero area. O(sum of the degrees of
/// the incident faces).
template <SurfaceMesh MESH>
double gaussian_curvature(const MESH& m, typename mesh_traits<MESH>::Vertex v, const AttributeArray<Vec3>& pos)
{
	const double a = voronoi_area(m, v, pos);
	return a > 0.0 ? angle_defect(m, v, pos) / a : 0.0;
}

/// Writes gaussian_curvature (pointwise; angle_defect when `integrated`) of
/// every vertex into the vertex attribute `k`. O(number of darts).
template <SurfaceMesh MESH>
void compute_gaussian_curvatures(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& k,
								 bool integrated = false)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	foreach_cell(m, [&](Vertex v) { k[v] = integrated ? angle_defect(m, v, pos) : gaussian_curvature(m, v, pos); });
}

} // namespace cgogn::geometry
