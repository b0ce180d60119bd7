// SPDX-License-Identifier: MIT
// Fairing: smooth positions for chosen vertices, the others fixed.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <span>

namespace cgogn::modeling
{

/// Edge weights of the Laplacian used by fair_vertices.
enum class FairingWeights
{
	Uniform,  ///< every edge counts 1 (umbrella operator): robust on bad triangles
	Cotangent ///< (cot a + cot b) / 2 on the triangles of the edge, clamped to stay positive
};

/// Moves the `free` vertices so that the surface around them is as smooth as
/// the fixed vertices allow: solves L^k x = 0 at the free vertices with the
/// other vertices fixed, where L is the row-normalized Laplacian (weights
/// `w`) and k = `continuity` + 1 (continuity 0: membrane, harmonic; 1: thin
/// plate, bi-harmonic, tangent continuity with the fixed part; 2: tri-harmonic).
/// Only the free vertices and their (continuity + 1)-ring enter the sparse
/// system (Eigen::SparseLU), so the cost depends on the region, not on the
/// mesh. Returns false (positions unchanged) when the system is singular,
/// e.g. when a free component touches no fixed vertex.
/// Preconditions: continuity <= 2; the free vertices are distinct.
bool fair_vertices(const CMap2& m, AttributeArray<Vec3>& pos, std::span<const CMap2::Vertex> free,
				   FairingWeights w = FairingWeights::Cotangent, uint32 continuity = 1);
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
bool fair_vertices(const CMap3& m, AttributeArray<Vec3>& pos, std::span<const CMap2::Vertex> free,
				   FairingWeights w = FairingWeights::Cotangent, uint32 continuity = 1) = delete;

} // namespace cgogn::modeling
