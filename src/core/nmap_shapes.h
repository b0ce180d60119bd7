// SPDX-License-Identifier: MIT
// The darts of one D-simplex or D-cube of a D-G-map, as the flags of the
// cell: chains (vertex, edge, ..., facet) of its faces, beta_i exchanging the
// i-face of a chain for the other one between its (i - 1)- and (i + 1)-faces.
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <vector>

namespace cgogn::detail
{

/// The flags of one top cell, numbered so that flags 2k and 2k + 1 differ by
/// their vertex only (each other's beta0, as the darts of a G-map pair).
struct CellShape
{
	uint32 dimension = 0;   ///< D.
	uint32 nb_vertices = 0; ///< D + 1 for a simplex, 2^D for a cube.
	uint32 nb_flags = 0;    ///< (D + 1)! for a simplex, 2^D D! for a cube.
	/// beta[(i - 1) * nb_flags + f]: beta_i of flag f, 1 <= i <= D - 1 (beta0
	/// is f ^ 1, beta_D leaves the cell).
	std::vector<uint32> beta;
	/// chain[f * D + k], k < D: the local vertex that the k-face of flag f
	/// adds to its (k - 1)-face (the vertex of the flag for k = 0). Two flags
	/// of cells glued along a facet are glued when their chains name the same
	/// vertices.
	std::vector<uint32> chain;
	std::vector<uint32> facet_of_flag;               ///< The local facet of each flag (its (D - 1)-face).
	std::vector<std::vector<uint32>> facet_vertices; ///< The local vertices of each facet.
	std::vector<std::vector<uint32>> facet_flags;    ///< The flags of each facet.
	std::vector<uint32> flag_at_vertex;              ///< A flag whose vertex is the local vertex v.
};

/// The flags of the D-simplex of vertices 0 ... D: the permutations
/// (p_0, ..., p_D) of them, the k-face of the chain being {p_0, ..., p_k};
/// beta_i swaps p_i and p_{i + 1}; the facet is the one opposite p_D.
CellShape simplex_shape(uint32 dimension);

/// The flags of the D-cube of vertices 0 ... 2^D - 1 (bit a of a vertex is
/// its coordinate along axis a): a vertex v and an order (s_0, ..., s_{D-1})
/// of the axes, the k-face of the chain spanning axes s_0 ... s_{k-1} from
/// v; beta0 moves v along s_0, beta_i swaps s_{i-1} and s_i.
CellShape cube_shape(uint32 dimension);

} // namespace cgogn::detail
