// SPDX-License-Identifier: MIT
// The uniform volume refinements as the distributed layer sees them: for
// each scheme, how many new cells of each dimension lie inside an old cell
// of each dimension, the faces of a child, and the old corners around each
// point of a cell's refinement (which old cell a new cell lies in).
#pragma once

#include <cgogn/core/utils/numeric.h>

#include "distribute_common.h"

#include <array>
#include <vector>

namespace cgogn::dist::detail::refinement
{

/// [j][k]: the new cells of dimension j lying inside an old cell of dimension k.
using ChildCounts = std::array<std::array<uint64, 4>, 4>;

/// A scheme: its points and children, its counts, and the faces of a child (counterclockwise
/// seen from outside, over the child's points in VTK order).
struct Scheme
{
	const char* wrong_cells; ///< The error when a volume is not the scheme's cell.
	uint32 nb_points;
	uint32 child_size;
	ChildCounts counts;
	std::vector<std::vector<uint32>> child_faces;
};

inline const Scheme tet_scheme{"tetrahedral subdivision: every volume must be a tetrahedron",
							   10,
							   4,
							   {{{1, 1, 0, 0}, {0, 2, 3, 1}, {0, 0, 4, 8}, {0, 0, 0, 8}}},
							   {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}}};
inline const Scheme hex_scheme{"hexahedral subdivision: every volume must be a hexahedron",
							   27,
							   8,
							   {{{1, 1, 1, 1}, {0, 2, 4, 6}, {0, 0, 4, 12}, {0, 0, 0, 8}}},
							   {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};

/// The corners of the old volume around each point of its refinement, one
/// bit per corner: a corner its own bit, a midpoint its edge's two, ...
inline std::array<uint8, 27> point_masks(bool hex)
{
	std::array<uint8, 27> mask{};
	if (!hex)
	{
		constexpr std::array<std::array<uint32, 2>, 6> edges = {{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
		for (uint32 i = 0; i < 4; ++i)
			mask[i] = uint8(1u << i);
		for (uint32 e = 0; e < 6; ++e)
			mask[4 + e] = uint8((1u << edges[e][0]) | (1u << edges[e][1]));
		return mask;
	}
	// grid coordinate 0 or 2: that side's corners only; 1: both sides
	const auto sides = [](uint32 c) { return c == 0 ? 1u : c == 2 ? 2u : 3u; };
	for (uint32 i = 0; i < 27; ++i)
		for (uint32 b = 0; b < 8; ++b)
			if ((sides(i % 3) >> (b & 1)) & (sides(i / 3 % 3) >> (b >> 1 & 1)) & (sides(i / 9) >> (b >> 2)) & 1u)
				mask[i] = uint8(mask[i] | (1u << b));
	return mask;
}

/// An old cell of a volume, by the corners of the volume it holds.
struct Carrier
{
	uint8 mask;
	uint8 dim;
	uint32 line;
};

/// A new edge or face inside a volume: its carrier's mask and its sorted
/// vertex ids (unused slots NO_GID), then its global id once numbered.
struct Child
{
	uint8 mask;
	std::array<uint64, 4> vertices;
	uint64 gid = NO_GID;
	bool operator<(const Child& o) const
	{
		return mask != o.mask ? mask < o.mask : vertices < o.vertices;
	}
	bool operator==(const Child& o) const
	{
		return mask == o.mask && vertices == o.vertices;
	}
};

} // namespace cgogn::dist::detail::refinement
