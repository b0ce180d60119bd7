// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/core/map/nmap.h>

namespace cgogn
{

/// The 2-G-map of a 2-map: each dart d of m becomes two darts, one at each
/// end of its edge side (beta0 between them), so the result has exactly twice
/// the darts. Every cell of m is a cell of the result, boundary faces
/// included, and every attribute of m (vertex, edge, face, volume and dart
/// attributes, the indices of each indexed orbit) is copied: a cell's values
/// go to the same cell, a dart's values to both of its darts. Lines are
/// renumbered in the order of m's live lines (the same numbers when m is
/// compact). O(size of m x number of attributes).
GMap2 to_gmap(const CMap2& m);

/// The 2-map of an orientable 2-G-map: in each connected component, the darts
/// of one class of the two-colouring (the class of the component's smallest
/// dart) become the darts of the result, with phi1 = beta1 o beta0 and
/// phi2 = beta0 o beta2 (so the result has exactly half the darts). Cells and
/// attributes are carried as by to_gmap; a dart attribute takes the value of
/// the kept dart. Throws TopologyError when g is not orientable (see
/// is_orientable: no CMap2 can hold it). O(size of g x number of attributes).
CMap2 to_cmap(const GMap2& g);

/// The 3-G-map of a 3-map, as to_gmap of a 2-map: twice the darts, beta3
/// joining each dart's origin to the end of its phi3; every cell (3-D
/// cells, the cells of one volume, boundary volumes) and attribute carried.
/// O(size of m x number of attributes).
GMap3 to_gmap(const CMap3& m);

/// The 3-map of an orientable 3-G-map, as to_cmap of a 2-G-map (phi3 =
/// beta0 o beta3). Throws TopologyError when g is not orientable.
/// O(size of g x number of attributes).
CMap3 to_cmap(const GMap3& g);

/// The D-G-map of a D-map, as to_gmap of a 2-map: twice the darts, every
/// cell (CellD<0> ... CellD<D>, boundary D-cells) and attribute carried.
/// O(size of m x number of attributes).
template <uint32 D>
GMapN<D> to_gmap(const CMapN<D>& m);

/// The D-map of an orientable D-G-map, as to_cmap of a 2-G-map: phi1 =
/// beta1 o beta0, phi_i = beta0 o beta_i. Throws TopologyError when g is not
/// orientable. O(size of g x number of attributes).
template <uint32 D>
CMapN<D> to_cmap(const GMapN<D>& g);

/// The same map as a map of any dimension: the darts of m in the order of
/// their indices (the same indices when m is compact), the same relations
/// and boundary, and every attribute (vertices become CellD<0>, edges
/// CellD<1>, faces CellD<2>, volumes CellD<3>; the cells of one volume of a
/// 3-map and its connected components are not carried). O(size of m x
/// number of attributes).
CMapN<2> to_nmap(const CMap2& m);
CMapN<3> to_nmap(const CMap3& m);
GMapN<2> to_nmap(const GMap2& m);
GMapN<3> to_nmap(const GMap3& m);

/// The inverse of to_nmap: a map of dimension 2 or 3 as the tuned map of
/// that dimension, darts, relations, boundary and attributes of the cells
/// of each dimension carried. O(size of m x number of attributes).
CMap2 to_fixed_map(const CMapN<2>& m);
CMap3 to_fixed_map(const CMapN<3>& m);
GMap2 to_fixed_map(const GMapN<2>& m);
GMap3 to_fixed_map(const GMapN<3>& m);

/// The 1-skeleton of m as a graph: a vertex per vertex of m and an edge per
/// edge of m (boundary cells excluded), each edge joining the two ends of
/// the map's edge, and the vertex and edge attributes of m carried (lines
/// renumbered in the order of the traversals; the graph's vertices and
/// edges are indexed). O(size of m x number of attributes).
Graph to_graph(const CMap2& m);
Graph to_graph(const GMap2& m);
Graph to_graph(const CMap3& m);
Graph to_graph(const GMap3& m);
/// The 1-skeleton of an incidence graph: its vertices and edges, with their
/// attributes (lines renumbered in traversal order). O(size x attributes).
Graph to_graph(const IncidenceGraph& ig);

/// The incidence graph of a 2-map: a vertex, an edge and a face per real
/// vertex, edge and face of m (boundary faces are not faces of the complex;
/// their edges are the border), each face running along its phi1 cycle.
/// The vertex, edge and face attributes of m are carried (lines renumbered in
/// traversal order; faces are indexed when m's are). Throws TopologyError
/// when an edge of m has the same vertex at both ends or a face meets a
/// vertex twice (the complex has neither). O(size of m x attributes).
IncidenceGraph to_incidence_graph(const CMap2& m);

/// The 2-map of an incidence graph, built from its faces as a polygon soup
/// by build_surface: exact when every edge has at most two faces listing it
/// in opposite directions and every vertex is manifold (one fan; see
/// is_manifold_vertex), and otherwise repaired as build_surface repairs,
/// the report telling what was detached, split or dropped (vertices without
/// face are dropped: a 2-map has no isolated vertex). Vertex attributes
/// follow to every copy of a split vertex; edge and face attributes are
/// carried. Faces keep their order and orientation; soup vertex i is the
/// i-th live vertex of ig. O(size of ig x attributes).
CMap2 to_cmap2(const IncidenceGraph& ig, BuildReport* report = nullptr);

} // namespace cgogn
