// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/dart_geometry.h>

namespace cgogn::geometry
{

/// Length of edge e. O(1).
template <GeometricMesh MESH>
double edge_length(const MESH& m, typename mesh_traits<MESH>::Edge e, const AttributeArray<Vec3>& pos)
{
	return dart_vector(m, pos, e.dart).norm();
}

/// Writes the length of every edge into the edge attribute `length`.
/// O(number of edges).
template <GeometricMesh MESH>
void compute_edge_lengths(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<double>& length)
{
	using Edge = typename mesh_traits<MESH>::Edge;
	foreach_cell(m, [&](Edge e) { length[e] = edge_length(m, e, pos); });
}

/// Mean length of the edges of the mesh; 0 when it has none.
/// O(number of edges) (O(number of darts) when edges are not indexed).
template <GeometricMesh MESH>
double mean_edge_length(const MESH& m, const AttributeArray<Vec3>& pos)
{
	using Edge = typename mesh_traits<MESH>::Edge;
	double sum = 0.0;
	uint32 n = 0;
	foreach_cell(m, [&](Edge e) {
		sum += edge_length(m, e, pos);
		++n;
	});
	return n > 0 ? sum / n : 0.0;
}

} // namespace cgogn::geometry
