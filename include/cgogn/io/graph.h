// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/graph.h>
#include <cgogn/io/error.h>

#include <string>

namespace cgogn::io
{

// Files of graphs (skeletons, curve networks), chosen by extension:
// - `.cg`: a header line `# D:3 NV:<vertices> NE:<edges>`, then one line
//   `v x y z` per vertex (D coordinates, D = 2 or 3; further tokens are
//   ignored) and one line `e a b` per edge, a and b vertex indices. Indices
//   start at 0 (the files of CGoGN 3 and of this library); the files of
//   CGoGN 2 start at 1 (GraphLoadOptions::index_base). Lines starting with #
//   after the header are comments.
// - `.cgr`: the same with a radius after the coordinates, `v x y z r`.
// - `.skel` (read only): a free first line, the number of vertices, then per
//   vertex `id x y z radius k n_1 ... n_k`, its neighbours' ids (0-based).
//   An edge listed by one end only is kept, and counted in
//   GraphLoadReport::nb_one_sided_edges.
// - `.obj`: the vertices (`v x y z`) and the polylines (`l a b c ...`, each
//   pair of consecutive vertices an edge; indices from 1, or negative:
//   relative to the last vertex). Faces are not part of a graph: they are
//   counted in GraphLoadReport::nb_faces_ignored. Written as one `l` per edge.
// - `.vtk` (legacy, UNSTRUCTURED_GRID) and `.vtu`: the points and the line
//   (type 3) and polyline (type 4) cells, a polyline giving an edge per pair
//   of consecutive points; a point array `radius` of one component becomes
//   the radii. Other cells are counted in
//   GraphLoadReport::nb_cells_ignored. Written (ascii) as one line cell per
//   edge, with `radius` as point data when the graph has radii.

/// How load_graph reads a file.
struct GraphLoadOptions
{
	/// The first vertex index of the edge lines of .cg and .cgr files: 0
	/// (default), or 1 for the files of CGoGN 2.
	uint32 index_base = 0;
};

/// What load_graph read.
struct GraphLoadReport
{
	uint32 nb_vertices_read = 0; ///< Vertices in the file (all added to the graph).
	uint32 nb_edges_read = 0;    ///< Edges in the file (all added, self-loops and repeated edges included).
	bool radius = false;         ///< Whether the file has radii (`.cgr`, `.skel`): the vertex attribute `radius`.
	/// `.skel`: edges listed by one of their ends only (added all the same).
	uint32 nb_one_sided_edges = 0;
	/// `.obj`: faces (`f` lines), which a graph does not hold: not loaded.
	uint32 nb_faces_ignored = 0;
	/// `.vtk`, `.vtu`: cells other than lines and polylines (triangles,
	/// tetrahedra, ...), which a graph does not hold: not loaded.
	uint32 nb_cells_ignored = 0;
};

/// Reads a graph file (.cg, .cgr, .skel, .obj, .vtk, .vtu) and appends its vertices and edges
/// to g: positions go to the Vec3 vertex attribute `position`, radii to the
/// double vertex attribute `radius` (created if missing). Edges are indexed,
/// so that save_graph writes the vertices and edges of a loaded file back in
/// the file's order and directions. The whole file is
/// read and checked first, so a failure leaves g unchanged. Throws io::Error
/// naming the file, the line and the problem for a malformed file: a
/// missing or wrong header, a count that does not match the lines, a
/// non-finite number, a vertex index out of range, an existing `position`
/// or `radius` attribute of another type. O(size of the file).
GraphLoadReport load_graph(Graph& g, const std::string& path, const GraphLoadOptions& options = {});

/// Writes g as a .cg, .obj, .vtk or .vtu file, or as a .cgr file with the double vertex
/// attribute `radius`: vertices in the order of their container, edges in
/// the order of theirs when they are indexed (from the vertex of their dart),
/// in the order of their darts otherwise; positions
/// exactly (the shortest decimal form that reads back to the same double),
/// indices from 0. An isolated vertex is written as a vertex without edge.
/// Throws io::Error when g has no Vec3 vertex attribute `position`, when a
/// .cgr is asked of a graph without `radius`, for another extension, or
/// when the file cannot be written. O(size of g).
void save_graph(const Graph& g, const std::string& path);

} // namespace cgogn::io
