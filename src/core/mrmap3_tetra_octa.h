// SPDX-License-Identifier: MIT
// The tetrahedral-octahedral refinement of the finest map of a
// multiresolution 3-map (add_level with Refinement::TetraOcta).
#pragma once

#include "mrmap3_refine.h"

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace cgogn::detail
{

/// A tetrahedron or an octahedron of the finest map, read before the
/// refinement cuts anything: its corners are numbered, and each of its
/// darts (all of them remain, as the first pieces of their edges) knows the
/// corners at its two ends.
struct MRTetraOctaCell
{
	bool octahedron = false;
	/// Every dart of the volume (the first nb_darts) with the numbers of the
	/// corners it joins.
	std::array<std::pair<Dart, std::array<uint8, 2>>, 24> darts;
	uint32 nb_darts = 0;
};

/// What the splits of successive cells reuse, so that splitting allocates
/// nothing once the first cells are done: per dart index, the point of the
/// cell's regular shape at the dart's origin (encoded), and the lists of a
/// split.
struct MRTetraOctaScratch
{
	std::vector<uint8> point;
	std::vector<Dart> pieces, on_plane, path, polygon;
};

/// Reads volume w of the finest map as a tetrahedron (4 triangles, 3 edges
/// at each corner) or an octahedron (8 triangles, 4 edges at each corner);
/// nullopt when it is neither. O(size of w).
std::optional<MRTetraOctaCell> mr_read_tetra_octa(const CMap3& map, Dart w);

/// Splits cell c, whose edges are cut at their middle and whose faces are
/// cut into 4 triangles (r.triangulate), and nothing finer on its surface: a
/// tetrahedron into 4 tetrahedra at its corners and an octahedron in the
/// middle; an octahedron into 6 octahedra at its corners and 8 tetrahedra at
/// its faces, around a new centre vertex. The cuts follow planes of the
/// cell's regular shape: a corner's plane for a tetrahedron, the 4 planes
/// through the centre parallel to opposite faces for an octahedron; each
/// inner face is a triangle. Throws std::logic_error when an inner path
/// does not close. O(1).
void mr_split_tetra_octa(MRVolumeRefinement& r, const MRTetraOctaCell& c, MRTetraOctaScratch& scratch);

} // namespace cgogn::detail
