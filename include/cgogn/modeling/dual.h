// SPDX-License-Identifier: MIT
// The dual of a closed polygonal surface.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <memory>

namespace cgogn::modeling
{

/// Appends to `out` the dual of the closed surface m: one vertex per face of m
/// (at the face's vertex centroid), one face per vertex of m (joining the
/// centroids of the faces around it), one edge per edge; the dual faces are
/// oriented like m (a closed surface with outward faces gives outward faces).
/// Returns the "position" attribute of out (created if out has none), filled
/// for the new vertices. The dual of the dual has the counts of m.
/// Throws TopologyError (nothing appended) when m has boundary (the dual of a
/// surface with boundary is not a closed 2-map: choose to fill_holes first),
/// or when a vertex has fewer than 3 edges or meets a face twice (its dual
/// face would be degenerate), and Error (nothing appended) when out has a
/// vertex attribute "position" of another type than Vec3. O(size of m).
std::shared_ptr<AttributeArray<Vec3>> dual(const CMap2& m, const AttributeArray<Vec3>& pos, CMap2& out);
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
std::shared_ptr<AttributeArray<Vec3>> dual(const CMap3& m, const AttributeArray<Vec3>& pos, CMap2& out) = delete;
std::shared_ptr<AttributeArray<Vec3>> dual(const CMap2& m, const AttributeArray<Vec3>& pos, CMap3& out) = delete;
std::shared_ptr<AttributeArray<Vec3>> dual(const CMap3& m, const AttributeArray<Vec3>& pos, CMap3& out) = delete;

} // namespace cgogn::modeling
