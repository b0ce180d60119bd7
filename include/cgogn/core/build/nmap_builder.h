// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mesh_traits.h>

#include <span>
#include <vector>

namespace cgogn
{

/// Builds a pure D-dimensional simplicial complex into an empty D-map: each
/// D-simplex is given by its D + 1 vertex ids (cell after cell in
/// `cell_vertices`, ids in [0, nb_vertices)), in any order. Simplices that
/// share the D vertices of a facet are sewn along it; the facets of only one
/// simplex are closed by boundary D-cells. A CMapN needs an orientable
/// complex: the simplices are oriented consistently whatever the order of
/// their ids. Returns the vertex of each id (an invalid cell for ids no
/// simplex uses). Throws cgogn::Error when the map is not empty, an id is out
/// of range or repeated in a simplex, a facet is shared by more than two
/// simplices, or (CMapN) the complex is not orientable; the map is then left
/// empty. O(number of simplices x (D + 1)!) time and darts.
template <typename MAP>
requires is_nmap_v<MAP> std::vector<CellD<0>> build_simplicial_complex(MAP& m, uint32 nb_vertices,
																	   std::span<const uint32> cell_vertices);

/// Builds a pure D-dimensional cubical complex into an empty D-map: each
/// D-cube is given by its 2^D vertex ids, in the order of their coordinates
/// read as a binary number (vertex k of a cube is at (k_0, k_1, ..., k_{D-1}),
/// k_a the bit a of k: for a square, (0,0) (1,0) (0,1) (1,1); for a cube the
/// same square at z = 0 then at z = 1). Cubes are sewn along the facets whose
/// 2^(D-1) ids they share; the rest is closed by boundary D-cells. Returns
/// the vertex of each id. Throws cgogn::Error as build_simplicial_complex,
/// and when two cubes share the ids of a facet in orders no gluing of cubes
/// can give. O(number of cubes x 2^D x D!) time and darts.
template <typename MAP>
requires is_nmap_v<MAP> std::vector<CellD<0>> build_cubical_complex(MAP& m, uint32 nb_vertices,
																	std::span<const uint32> cell_vertices);

} // namespace cgogn
