// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mrmap3_attributes.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <functional>

namespace cgogn::modeling
{

/// Refines a multiresolution hexahedral mesh where a criterion asks for it
/// (adaptive refinement for simulation: refine where an error indicator is
/// high). In rounds: every leaf hexahedron w of the finest level made
/// before level `max_level` for which refine(m, w) holds (m read at its
/// finest level) is subdivided with balance (subdivide_volume), so that
/// leaves sharing an edge stay within one level; the rounds end when one
/// selects nothing. The new vertices get the positions of the hexahedral
/// scheme (edge midpoints, face and volume centroids of the corners: the
/// trilinear points), whatever the rule of `position`; the other attributes
/// follow their rules. The current level of m is kept. Returns the number
/// of hexahedra subdivided, balancing ones included. Throws as
/// subdivide_volume when a selected volume is not a hexahedron.
/// O(rounds x (leaves x cost of refine) + subdivisions).
uint32 refine_hexahedra(MRMap3& m, AttributeArray<Vec3>& position,
						const std::function<bool(const MRMap3&, MRMap3::Volume)>& refine, uint32 max_level);

} // namespace cgogn::modeling
