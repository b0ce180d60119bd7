// SPDX-License-Identifier: MIT
// The readers and writers of every format, on memory buffers. Readers throw
// io::Error (file, line or byte, cause); writers return the file's content.
#pragma once

#include <cgogn/io/options.h>

#include "mesh_data.h"

#include <string>
#include <string_view>

namespace cgogn::io::detail
{

/// The extension of path's file name in lower case, without the dot; empty
/// when it has none. O(length of the path).
std::string lower_extension(const std::string& path);

// ---- surfaces (cells are polygons)
MeshData read_off(std::string_view text, const std::string& path);
MeshData read_obj(std::string_view text, const std::string& path);
MeshData read_ply(std::string_view data, const std::string& path);
MeshData read_stl(std::string_view data, const std::string& path);
std::string write_off(const MeshData& d);
std::string write_obj(const MeshData& d);
/// Throws io::Error naming `path` when two columns would write the same
/// property (a double attribute `nx` beside a Vec3 `normal`, `x` beside the
/// position): the file would not read back.
std::string write_ply(const MeshData& d, bool binary, const std::string& path);
/// Polygons are written as triangle fans.
std::string write_stl(const MeshData& d, bool binary);

// ---- volumes (cells of 4, 5, 6 or 8 vertices in the builder's order)
MeshData read_medit(std::string_view text, const std::string& path);
MeshData read_vtk(std::string_view data, const std::string& path);
MeshData read_vtu(std::string_view data, const std::string& path);
MeshData read_gmsh(std::string_view data, const std::string& path);
/// `node` and `ele` are the contents of the .node and .ele files.
MeshData read_tetgen(std::string_view node, const std::string& node_path, std::string_view ele,
					 const std::string& ele_path);
std::string write_medit(const MeshData& d, const std::string& path);
std::string write_vtk(const MeshData& d, bool binary);
std::string write_vtu(const MeshData& d, bool binary);
std::string write_gmsh(const MeshData& d, bool binary, const std::string& path);
/// The .node and .ele files.
std::pair<std::string, std::string> write_tetgen(const MeshData& d);
/// OpenVolumeMesh ascii (.ovm): every cell as a polyhedron (vertices, edges,
/// faces of half-edges, cells of half-faces whose normals point into the
/// cell), vertex and cell properties as vertex and cell columns; what the
/// map cannot hold (other properties, faces in no cell) goes to d.dropped.
MeshData read_ovm(std::string_view text, const std::string& path);

/// The pieces of the parallel VTU index at `path`, merged into one mesh:
/// vertices by their GlobalNodeIds point array when every piece has one;
/// cells and listed faces (a surface's polygons) flagged in a vtkGhostType
/// array dropped, the rest ordered by GlobalCellIds when every piece has
/// them; listed faces and edges shared by pieces come once. Throws
/// io::Error naming the index or the piece. O(size of the pieces x log).
MeshData read_pvtu(const std::string& path);
/// Writes d as a .pvtu of one piece: the piece foo_0.vtu beside path, then
/// the index. Throws io::Error as write_file and write_pvtu_index do.
void write_single_piece_pvtu(const MeshData& d, const std::string& path, bool binary);
std::string write_ovm(const MeshData& d);

/// The mesh in `data` by the reader of format f: every format held in one
/// file (not TetGen's two). O(size of data).
MeshData read_mesh(Format f, std::string_view data, const std::string& path);

/// Throws io::Error (no position) when a cell refers to a vertex that does not
/// exist, a column does not have one value per element, or two columns of the
/// same elements conflict in name (data_name_conflict): the safety net behind
/// each reader's own checks. O(size of d + columns squared).
void validate(const MeshData& d, const std::string& path);

/// Throws io::Error naming `path` when a vertex column has a name the loader
/// reserves (data_name_conflict): for the writers of named data (PLY, VTK,
/// VTU), whose file would not read back. O(number of columns).
void check_written_names(const MeshData& d, const std::string& path);

} // namespace cgogn::io::detail
