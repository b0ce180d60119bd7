// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mrmap3.h>

namespace cgogn
{

/// Adds a level above the finest one by refining every volume of the finest
/// level with pattern r. Hexahedral: every edge is cut at its middle, every
/// face into quads around a centre, every hexahedron into 8 around a centre
/// by 12 inner quads. The new darts get the new level; the pieces of a cut
/// edge (face) keep its edge (face) id; a new inner edge of a face takes an
/// edge id different from the edges whose midpoints it leaves, and a new
/// inner face the smallest face id not used around its edges (see MRState3).
/// The cells of the new level get lines by the rules of the attributes (see
/// mrmap3_attributes.h). The current level becomes the new finest level. Throws
/// std::invalid_argument, leaving m unchanged, when r is not Hexahedral or a
/// volume of the finest level is not a hexahedron (6 quads, 3 edges at each
/// corner). O(number of darts).
void add_level(MRMap3& m, Refinement r);

/// Removes the finest level: every dart of that level goes, and the darts
/// left get back the relations of the level below (the inverse of
/// add_level). The current level is clamped to the new finest level. Throws
/// std::invalid_argument when m has no level above 0. O(number of darts x
/// cost of a level step).
void remove_finest_level(MRMap3& m);

/// The mesh of level l as a flat CMap3: one dart per dart of the level (in
/// the order of the finest map), with the relations of the level, the
/// boundary marks, the per-dart attributes and the attributes of the cells
/// with their values at level l. Throws std::out_of_range when
/// l > max_level(m). O(number of darts of the finest map x cost of a level
/// step).
CMap3 extract_level(const MRMap3& m, uint32 l);

} // namespace cgogn
