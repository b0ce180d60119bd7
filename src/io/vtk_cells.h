// SPDX-License-Identifier: MIT
// VTK cell types shared by the legacy (.vtk) and XML (.vtu) formats.
#pragma once

#include "mesh_data.h"

#include <functional>
#include <string>

namespace cgogn::io::detail
{

/// Appends the volume cells of a VTK cell list to d (tetra 10, voxel 11,
/// hexahedron 12, wedge 13, pyramid 14, corners of quadratic tetra 24 and
/// hexahedron 25, pentagonal and hexagonal prisms 15 and 16 and polyhedra 42
/// as polyhedra; lines 3 and polylines 4 go to d.segments; triangles 5,
/// pixels 8, quads 9, polygons 7 and the corners of quadratic triangles 22
/// and quads 23 go to d's listed faces; vertex cells and triangle strips
/// are counted in d.dropped) and the matching rows of `cell_data` to d's
/// cell columns and, when there are listed faces, to its face columns.
/// `offsets` has one more entry than `types` (starting at 0). A polyhedron's faces are a face stream (its number of
/// faces, then each face's number of points and point ids): its
/// connectivity in a legacy file, where `face_offsets` is empty; in a VTU
/// file, `faces` from the end of the previous polyhedron's stream to
/// `face_offsets[c]` (-1 for the other cells). `fail(message)` must throw.
void vtk_cells_to_mesh(MeshData& d, const std::vector<int64>& offsets, const std::vector<int64>& connectivity,
					   const std::vector<int64>& types, const std::vector<Column>& cell_data,
					   const std::function<void(const std::string&)>& fail, const std::vector<int64>& faces = {},
					   const std::vector<int64>& face_offsets = {});

/// The VTK cell type of a listed face of n vertices: triangle 5, quad 9,
/// polygon 7.
inline uint32 vtk_face_type(uint32 n)
{
	return n == 3 ? 5 : n == 4 ? 9 : 7;
}

/// The cell data a VTK file holds for d: one row per cell, then one per
/// listed face, then one per segment. A name of several kinds is one array
/// (of the first kind's type, double when the types differ); a name of one
/// kind has zeros on the others' rows. Columns of 1 to 3 components only; a
/// column whose component count differs from the first column of its name
/// is left out. O(size of the columns).
std::vector<Column> vtk_cell_data(const MeshData& d);

/// The face stream of each polyhedron of d, by cell (empty for the cells of
/// the standard kinds): its number of faces, then each face's number of
/// points and point ids, as VTK's type-42 cells hold them. O(size of the
/// polyhedra).
std::vector<std::vector<uint32>> polyhedron_streams(const MeshData& d);

/// An integer read as a double, converted without overflow: values out of
/// the int64 range (or NaN) become -1, which every consumer rejects.
inline int64 to_int64(double v)
{
	return (v >= -4.0e18 && v <= 4.0e18) ? int64(v) : -1;
}
inline std::vector<int64> to_int64(const std::vector<double>& v)
{
	std::vector<int64> out(v.size());
	for (std::size_t i = 0; i < v.size(); ++i)
		out[i] = to_int64(v[i]);
	return out;
}

/// The VTK type of a cell of n vertices (4, 5, 6 or 8).
inline int32 vtk_cell_type(uint32 n)
{
	return n == 4 ? 10 : n == 5 ? 14 : n == 6 ? 13 : 12;
}
/// Which of our vertices is the i-th VTK vertex of a cell of n vertices (VTK's
/// wedge has its base triangle the other way round).
inline uint32 vtk_order(uint32 n, uint32 i)
{
	static constexpr uint32 wedge[6] = {0, 2, 1, 3, 5, 4};
	return n == 6 ? wedge[i] : i;
}

} // namespace cgogn::io::detail
