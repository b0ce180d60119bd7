// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mesh_traits.h>

namespace cgogn
{

// The operators of the maps of any dimension (CMapN, GMapN): insertion of a
// vertex in an edge and of an edge in a face, Damiand and Lienhardt's
// removal and contraction of an i-cell, and the sewing of two D-cells along
// (D - 1)-cells (facets), with their can_* predicates. Each
// keeps every indexed orbit indexed (set_indices = false: pure topology,
// see index_cells): the cells an operator merges keep one of their lines,
// the cells it makes get new ones (attribute values of a new line are the
// attributes' defaults), the lines of the cells it destroys are released.
// Each costs O(size of the cells it changes), whatever the size of the map.

/// Inserts a vertex in edge e, cutting it in two edges (in every face and
/// cell around it). Returns the new vertex. Always possible.
template <typename MAP>
requires is_nmap_v<MAP> CellD<0> insert_vertex_in_edge(MAP& m, CellD<1> e, bool set_indices = true);

/// Whether insert_edge_in_face(m, d1, d2) is possible: d1 and d2 two
/// distinct darts of one side of a face (one phi1 cycle of a CMapN, one
/// beta0 beta1 cycle of a GMapN), at two distinct vertices of it, the face
/// not a boundary cell (in a 2-map, the outside), and no other dart of the
/// side at the vertex of d1 or of d2 (a face that passes twice by a vertex
/// cannot be cut there). O(size of the face).
template <typename MAP>
requires is_nmap_v<MAP>
bool can_insert_edge_in_face(const MAP& m, Dart d1, Dart d2);

/// Cuts the face of d1 and d2 in two by a new edge from the vertex of d1 to
/// the vertex of d2 (in each side of the face: in every D-cell around it).
/// Returns the new edge. Precondition: can_insert_edge_in_face(m, d1, d2).
template <typename MAP>
requires is_nmap_v<MAP> CellD<1> insert_edge_in_face(MAP& m, Dart d1, Dart d2, bool set_indices = true);

/// Whether the I-cell c (I < D) can be removed: it separates two distinct
/// (I + 1)-cells only (for I <= D - 2, phi_{I+1} and phi_{I+2}, or beta_{I+1}
/// and beta_{I+2}, commute on its darts: a vertex of two edges, an edge of
/// two faces, ...; for I = 0 no edge goes from the vertex to itself), and,
/// for I = D - 1, it is not on the boundary (which would merge a D-cell with
/// the outside). The operators' cell dimension is not
/// deduced: `can_remove_cell<1>(m, e)`. O(size of c and of an
/// (I + 1)-cell around it).
template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&(I < MAP::dimension) bool can_remove_cell(const MAP& m, CellD<I> c);

/// Removes the I-cell c (I < D), merging the two (I + 1)-cells it separates
/// into one: a vertex of two edges joins them into one edge, an edge
/// between two faces makes one face of them, a 3-cell between two 4-cells
/// one 4-cell. Precondition: can_remove_cell(m, c).
template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&(I < MAP::dimension) void remove_cell(MAP& m, CellD<I> c, bool set_indices = true);

/// Whether the I-cell c (1 <= I <= D) can be contracted: for I >= 2,
/// phi_{I-1} and phi_{I-2} (beta_{I-1} and beta_{I-2}) commute on its darts
/// (a face of two edges, a 3-cell whose faces are all digons ... collapse
/// onto one cell of dimension I - 1), the two (I - 1)-cells it merges are
/// distinct (a face of one edge is not contracted), an edge has two distinct
/// vertices, and
/// a D-cell is not a boundary cell and is glued to no boundary cell. O(size
/// of c).
template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&(I >= 1 && I <= MAP::dimension) bool can_contract_cell(const MAP& m, CellD<I> c);

/// Contracts the I-cell c (1 <= I <= D) onto an (I - 1)-cell: an edge
/// becomes a vertex (its two vertices merge), a digon face an edge, ...
/// Precondition: can_contract_cell(m, c).
template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&
	(I >= 1 && I <= MAP::dimension) void contract_cell(MAP& m, CellD<I> c, bool set_indices = true);

/// Whether sew_facets(m, f1, f2) is possible: f1.dart and f2.dart are darts
/// of inner D-cells whose facets lie on the boundary (relation D leads to a
/// boundary cell), the facets are distinct, and their sides are isomorphic
/// with f1.dart facing f2.dart (in a G-map beta_i(x) faces beta_i(y) for
/// i <= D - 2; in a combinatorial map phi1(x) faces phi_1(y), the sides
/// facing each other, and phi_i(x) faces phi_i(y) for 2 <= i <= D - 2).
/// O(size of the facets).
template <typename MAP>
requires is_nmap_v<MAP> &&
	(MAP::dimension >= 2) bool can_sew_facets(const MAP& m, CellD<MAP::dimension - 1> f1, CellD<MAP::dimension - 1> f2);

/// Glues the D-cells of f1 and f2 along those facets, f1.dart facing
/// f2.dart: relation D links the facing darts, and the boundary facets in
/// between disappear (each boundary dart beside them is linked by relation
/// D - 1 to the dart its (D - 2)-cell leads to across them). The cells
/// brought together merge (the vertices, edges, ... of the two facets, and
/// the facets themselves) and keep one of their lines; the others are
/// released. Precondition: can_sew_facets(m, f1, f2). O(size of the facets
/// and of the merged cells; in a CMapN<2>, plus the size of the two boundary
/// faces, walked for phi_1).
template <typename MAP>
requires is_nmap_v<MAP> &&(MAP::dimension >= 2) void sew_facets(MAP& m, CellD<MAP::dimension - 1> f1,
																CellD<MAP::dimension - 1> f2, bool set_indices = true);

/// Whether unsew_facets(m, f) is possible: f separates two inner D-cells
/// (neither side is a boundary cell). O(1).
template <typename MAP>
requires is_nmap_v<MAP> &&(MAP::dimension >= 2) bool can_unsew_facets(const MAP& m, CellD<MAP::dimension - 1> f);

/// Separates the two D-cells of facet f (sew_facets undone): each side gets
/// a boundary facet, glued into the boundary cells around it (or making a
/// new boundary cell where the facet's (D - 2)-cells were inner). The side
/// of f.dart keeps the facet's line, the other gets a new one; the vertices,
/// edges, ... that no longer meet split (new lines for the parts without
/// f.dart). Precondition: can_unsew_facets(m, f). O(size of the facet and of
/// the cells around its (D - 2)-cells; in a CMapN<2>, of the faces around
/// its two vertices, walked for phi_1).
template <typename MAP>
requires is_nmap_v<MAP> &&
	(MAP::dimension >= 2) void unsew_facets(MAP& m, CellD<MAP::dimension - 1> f, bool set_indices = true);

} // namespace cgogn
