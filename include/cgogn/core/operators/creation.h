// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/operators/dimension_guards.h>

namespace cgogn
{

/// Creates an isolated cycle of n darts (a polygon) in a 1-map and returns
/// it. With set_indices, its cells get new lines in every indexed orbit.
/// Precondition: n >= 1. O(n).
CMap1::Face add_face(CMap1& m, uint32 n, bool set_indices = true);

/// Creates an isolated polygon of n edges in a 2-map, closed by a boundary
/// face of n darts, and returns the (non-boundary) face. With set_indices,
/// its cells get new lines in every indexed orbit. Precondition: n >= 1; a
/// face of 1 or 2 edges is a degenerate case that only low-level code builds
/// (check_integrity reports it, algorithms may refuse it). O(n).
CMap2::Face add_face(CMap2& m, uint32 n, bool set_indices = true);

} // namespace cgogn
