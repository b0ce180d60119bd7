// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/functions/traversals/local_cmap3.h>
#include <cgogn/geometry/algos/dart_geometry.h>

namespace cgogn::geometry
{

/// Mean of the positions of the vertices of cell c (an edge, a face, a
/// volume, a 2-map component; any cell type with a vertex incidence). For
/// faces this is the vertex centroid, not the area centroid (they agree on
/// triangles and parallelograms). O(number of darts of c); for 3-map volumes
/// the traversal floods with pooled marks (no allocation once warm).
template <GeometricMesh MESH, typename CELL>
Vec3 centroid(const MESH& m, CELL c, const Attribute<Vec3>& pos)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	Vec3 s = Vec3::Zero();
	uint32 n = 0;
	foreach_incident_vertex(m, c, [&](Vertex v) {
		s += value<Vec3>(m, pos, v);
		++n;
	});
	return n > 0 ? Vec3(s / n) : s;
}

/// Writes the vertex centroid of every cell of the attribute's cell type
/// CELL into `out`. O(number of darts).
template <typename CELL, GeometricMesh MESH>
void compute_centroids(const MESH& m, const Attribute<Vec3>& pos, Attribute<Vec3>& out)
{
	foreach_cell(m, [&](CELL c) { value<Vec3>(m, out, c) = centroid(m, c, pos); });
}

} // namespace cgogn::geometry
