// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/build/map_builder.h>

#include <string>
#include <vector>

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
	TetGen,
	Ovm, ///< OpenVolumeMesh's ascii files (polyhedra)
	/// Parallel VTU: an index naming one .vtu piece per rank, read as one
	/// mesh (see io/pvtu.h).
	Pvtu
};

/// The format of a path by its extension (case-insensitive): .off .obj .ply
/// .stl .mesh .vtk .vtu .pvtu .msh .node/.ele .ovm. Returns Format::Auto when unknown.
/// O(length of the path).
Format format_from_extension(const std::string& path);

/// The usual name of a format ("OFF", "PLY", ...).
const char* format_name(Format f);

/// How load_surface and load_volume read a file.
struct LoadOptions
{
	/// Format::Auto: by the extension of the path.
	Format format = Format::Auto;
};

/// How save_surface and save_volume write a file.
struct SaveOptions
{
	Format format = Format::Auto; ///< Format::Auto: by the extension of the path.
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
	Format format = Format::Auto; ///< The format the file was read as (never Auto after a load).
	uint32 nb_vertices_read = 0;  ///< Vertices found in the file.
	/// Faces (surfaces) or volumes (volume meshes) found in the file.
	uint32 nb_cells_read = 0;
	/// Faces or volumes added to the map: those read that were not skipped.
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
	/// Edges (surfaces) shared by more faces than a manifold allows, or by
	/// faces of incompatible orientation: the extra faces were detached there.
	uint32 nb_nonmanifold_edges = 0;
	/// Faces (volume meshes) shared by more volumes than a manifold allows:
	/// the extra volumes were detached there.
	uint32 nb_nonmanifold_faces = 0;
	/// Holes closed by a boundary face (surfaces) or boundary volumes (volumes).
	uint32 nb_holes_closed = 0;
	/// Volume cells given in negative orientation and turned over.
	uint32 nb_cells_reoriented = 0;
	/// Edges (surfaces) shared by two faces listing it in the same direction:
	/// a CMap2 detaches the faces there (they are among nb_nonmanifold_edges),
	/// a GMap2 glues them.
	uint32 nb_orientation_conflicts = 0;
	/// False when the surface cannot be oriented (a Möbius strip, a Klein
	/// bottle, a projective plane): a CMap2 holds it cut along the conflicts
	/// above; load it into a GMap2 to keep it whole. Volume meshes are always
	/// orientable: their cells are oriented by their geometry.
	bool orientable = true;
	/// What the file held that the map does not, each with why (e.g. an
	/// .ovm edge property, faces in no cell): never dropped silently.
	std::vector<std::string> dropped;
	BuildReport build; ///< The map builder's own report.

	/// True when the input needed no repair: no non-manifold vertex, edge or
	/// face, and no degenerate cell (a face with a repeated vertex is not
	/// manifold either).
	bool manifold() const
	{
		return nb_nonmanifold_vertices == 0 && nb_nonmanifold_edges == 0 && nb_nonmanifold_faces == 0 &&
			   nb_cells_skipped == 0;
	}

	/// What the load changed in the input, one sentence per line (empty when
	/// nothing), for programs to show their users; `map_type` names the map
	/// loaded into ("CMap2", "GMap2", "CMap3", "GMap3"), whose abilities the advice
	/// depends on.
	std::string summary(const std::string& map_type) const;
};

} // namespace cgogn::io
