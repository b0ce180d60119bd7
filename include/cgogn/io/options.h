// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/build/map_builder.h>

#include <string>

namespace cgogn::io
{

/// File formats. `Auto` chooses from the file name's extension.
enum class Format
{
	Auto,
	// surfaces
	Off,
	Obj,
	Ply,
	Stl,
	// volumes
	Medit,
	VtkLegacy,
	Vtu,
	Gmsh,
	TetGen
};

/// The format of a path by its extension (case-insensitive): .off .obj .ply
/// .stl .mesh .vtk .vtu .msh .node/.ele. Returns Format::Auto when unknown.
/// O(length of the path).
Format format_from_extension(const std::string& path);

/// The usual name of a format ("OFF", "PLY", ...).
const char* format_name(Format f);

struct LoadOptions
{
	/// Format::Auto: by the extension of the path.
	Format format = Format::Auto;
};

struct SaveOptions
{
	Format format = Format::Auto;
	/// PLY, STL, VTK legacy, VTU and gmsh: write binary instead of ASCII.
	bool binary = false;
	/// Write the map's other vertex (and face/volume) attributes of type
	/// double, Vec2 or Vec3 where the format can hold them (PLY, OBJ normals
	/// and texture coordinates, VTK point and cell data).
	bool attributes = true;
};

/// What a load did. Counts refer to the file's content; `build` is the raw
/// report of the map builder.
struct LoadReport
{
	Format format = Format::Auto;
	uint32 nb_vertices_read = 0;
	/// Faces (surfaces) or volumes (volume meshes) found in the file.
	uint32 nb_cells_read = 0;
	uint32 nb_cells_built = 0;
	/// Degenerate cells (fewer than 3 vertices, a repeated vertex) skipped.
	uint32 nb_cells_skipped = 0;
	/// File vertices used by no cell (not in the map).
	uint32 nb_isolated_vertices = 0;
	/// File vertices whose cells form several fans: each extra fan got its own
	/// vertex, with the original's position and the file id in the vertex
	/// attribute `original_vertex` (uint32).
	uint32 nb_nonmanifold_vertices = 0;
	/// Vertices created by those splits.
	uint32 nb_vertices_split = 0;
	/// Edges (surfaces) or faces (volumes) with too many incident cells: the
	/// extra cells were detached there.
	uint32 nb_nonmanifold_edges = 0;
	uint32 nb_nonmanifold_faces = 0;
	/// Holes closed by a boundary face (surfaces) or boundary volumes (volumes).
	uint32 nb_holes_closed = 0;
	/// Volume cells given in negative orientation and turned over.
	uint32 nb_cells_reoriented = 0;
	BuildReport build;

	/// True when the input needed no repair: no non-manifold vertex, edge or
	/// face, and no degenerate cell (a face with a repeated vertex is not
	/// manifold either).
	bool manifold() const
	{
		return nb_nonmanifold_vertices == 0 && nb_nonmanifold_edges == 0 && nb_nonmanifold_faces == 0 &&
			   nb_cells_skipped == 0;
	}
};

} // namespace cgogn::io
