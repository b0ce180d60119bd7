// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/dart_geometry.h>

#include <Eigen/Geometry>

namespace cgogn::geometry
{

/// Axis-aligned box (Eigen's AlignedBox: min(), max(), sizes(), center(),
/// contains(), extend()).
using BoundingBox = Eigen::AlignedBox3d;

/// Smallest axis-aligned box containing every vertex of the mesh; an empty
/// box (isEmpty()) for a mesh without vertices. O(number of vertices).
template <GeometricMesh MESH>
BoundingBox bounding_box(const MESH& m, const AttributeArray<Vec3>& pos)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	BoundingBox bb;
	foreach_cell(m, [&](Vertex v) { bb.extend(value<Vec3>(m, pos, v)); });
	return bb;
}

} // namespace cgogn::geometry
