// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mesh_traits.h>

#include <array>

namespace cgogn
{

/// A point of D-dimensional space: the positions the generators of the maps
/// of any dimension give their vertices (the core has no vector type).
template <uint32 D>
using PointD = std::array<double, D>;

// The generators build a D-dimensional object into an empty map of dimension D
// (a CMapN<D> or a GMapN<D>), closed by its boundary D-cells, and give each
// vertex its position in a vertex attribute `position` of type PointD<D>
// (CellD<0>). They throw cgogn::Error when the map is not empty. Each
// costs O(number of darts made).

/// The D-simplex of vertices 0 (the origin) and e_1 ... e_D (the unit
/// vectors): C(D + 1, k + 1) k-cells, (D + 1)! darts (twice in a G-map) and as
/// many in the boundary.
template <typename MAP>
requires is_nmap_v<MAP>
void generate_simplex(MAP& m);

/// The unit D-cube [0, 1]^D: C(D, k) 2^(D - k) k-cells.
template <typename MAP>
requires is_nmap_v<MAP>
void generate_cube(MAP& m);

/// The grid of n^D cubes of side 1 / n filling [0, 1]^D (n >= 1): C(D, k)
/// n^k (n + 1)^(D - k) k-cells. Vertex (i_1, ..., i_D) of the grid has the
template <typename MAP>
requires is_nmap_v<MAP>
void generate_cube_grid(MAP& m, uint32 n);

/// The Freudenthal (Kuhn) triangulation of the grid of generate_cube_grid:
/// each cube, of corner x, cut into the D! simplices x, x + e_p(1),
/// x + e_p(1) + e_p(2), ..., one per permutation p of the axes, all of them
/// around the cube's main diagonal; the cuts of neighbour cubes agree. n^D D!
/// D-simplices on the (n + 1)^D vertices of the grid.
template <typename MAP>
requires is_nmap_v<MAP>
void generate_freudenthal_grid(MAP& m, uint32 n);

} // namespace cgogn
