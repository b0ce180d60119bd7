// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap2.h>

#include <vector>

namespace cgogn::detail
{

/// Closes the hole along the phi2 fixed point d with a new face whose darts
/// are appended to `created` (marked boundary when asked). The new darts get
/// the vertex index of their origin when vertices are indexed; other orbits
/// are left to the caller. O(size of the hole x degree of its vertices).
void close_hole_topology(CMap2& m, Dart d, bool mark_boundary, std::vector<Dart>& created);

} // namespace cgogn::detail
