// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/geometry/algos/bounding_box.h>
#include <cgogn/geometry/algos/centroid.h>

#include <algorithm>
#include <cmath>

namespace cgogn::geometry
{

/// Bits per axis of a Morton key (3 x 21 = 63 bits).
inline constexpr uint32 MORTON_BITS = 21;

/// Morton (Z-order) key of point p in box bb: each coordinate is quantized
/// to 21 bits over the box (clamped to it; a flat axis counts as 0) and the
/// bits are interleaved, x in the lowest bit. Points close in space get close
/// keys, so sorting cells by key makes traversals cache-friendly (for the
/// operators' reorder). The box minimum maps to 0, its maximum to 2^63 - 1. O(1).
inline uint64 morton_key(const Vec3& p, const BoundingBox& bb)
{
	constexpr double cells = double(1u << MORTON_BITS);
	uint64 key = 0;
	for (int axis = 0; axis < 3; ++axis)
	{
		const double extent = bb.max()(axis) - bb.min()(axis);
		double q = extent > 0.0 ? (p(axis) - bb.min()(axis)) / extent * cells : 0.0;
		q = std::clamp(q, 0.0, cells - 1.0);
		const uint64 c = uint64(q);
		for (uint32 b = 0; b < MORTON_BITS; ++b)
			key |= ((c >> b) & 1u) << (3 * b + uint32(axis));
	}
	return key;
}

/// Morton key of cell c (a vertex: its position; any other cell: its vertex
/// centroid) in box bb, usually bounding_box(m, pos). O(number of darts of c).
template <GeometricMesh MESH, typename CELL>
uint64 morton_key(const MESH& m, CELL c, const AttributeArray<Vec3>& pos, const BoundingBox& bb)
{
	if constexpr (std::is_same_v<CELL, typename mesh_traits<MESH>::Vertex>)
		return morton_key(value<Vec3>(m, pos, c), bb);
	else
		return morton_key(centroid(m, c, pos), bb);
}

/// Writes the Morton key of every cell of type CELL (in the mesh's bounding
/// box) into the CELL attribute `key`. O(number of darts).
template <typename CELL, GeometricMesh MESH>
void compute_morton_keys(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<uint64>& key)
{
	const BoundingBox bb = bounding_box(m, pos);
	foreach_cell(m, [&](CELL c) { key[c] = morton_key(m, c, pos, bb); });
}

} // namespace cgogn::geometry
