// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/io/error.h>

#include <string>

namespace cgogn::io
{

// The incidence graph's own text file, `.ig`: every vertex, edge (faceless
// ones included) and face, exactly.
//   IG <vertices> <edges> <faces>
//   v x y z            one line per vertex
//   e a b              one line per edge: its first and second vertex
//   f k e_1 ... e_k    one line per face: its k edges in cycle order
// Indices start at 0. A face runs along e_1 toward the vertex e_1 shares
// with e_2 (so the file keeps its orientation). Lines starting with # are
// comments. Surface files (OFF, OBJ, PLY, STL) load into an incidence graph
// through io::load_surface.

/// What load_incidence_graph read.
struct IncidenceGraphLoadReport
{
	uint32 nb_vertices_read = 0; ///< Vertices in the file, all added.
	uint32 nb_edges_read = 0;    ///< Edges in the file, all added.
	uint32 nb_faces_read = 0;    ///< Faces in the file, all added.
};

/// Reads an `.ig` file and appends its vertices, edges and faces to ig, in
/// the file's order; positions go to the Vec3 vertex attribute `position`.
/// The whole file is read and checked first, so a failure leaves ig
/// unchanged. Throws io::Error naming the file, the line and the problem: a
/// wrong header, a count that does not match the lines, a non-finite
/// coordinate, an index out of range, an edge with one vertex twice, a face
/// whose edges are fewer than 3, repeat or are not a simple cycle in the
/// order given, an existing `position` of another type. O(size of the file).
IncidenceGraphLoadReport load_incidence_graph(IncidenceGraph& ig, const std::string& path);

/// Writes ig as an `.ig` file: vertices, edges and faces in the order of
/// their traversals, positions exactly (the shortest decimal form that reads
/// back to the same double). Throws io::Error when ig has no Vec3 vertex
/// attribute `position` or the file cannot be written. O(size of ig).
void save_incidence_graph(const IncidenceGraph& ig, const std::string& path);

} // namespace cgogn::io
