// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/nmap.h>

namespace cgogn
{

/// The boundary of a map of any dimension D >= 2 as a closed map of
/// dimension D - 1: the darts of its boundary D-cells, with the relations
/// 1 ... D - 1 they have there (the boundary of a D-ball is a (D - 1)-sphere:
/// Euler characteristic 1 + (-1)^(D - 1)). Vertex attributes are carried: each
/// vertex of the result takes the values of the vertex of m it lies on (a
/// vertex where the boundary is not a manifold becomes several vertices, with
/// the same values). O(number of boundary darts x number of vertex attributes).
template <uint32 D>
requires(D >= 2) CMapN<D - 1> extract_boundary(const CMapN<D>& m);
template <uint32 D>
requires(D >= 2) GMapN<D - 1> extract_boundary(const GMapN<D>& m);

} // namespace cgogn
