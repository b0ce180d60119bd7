// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/gmap3.h>

#include <span>
#include <utility>
#include <vector>

namespace cgogn
{

/// What a builder did with its input. Builders never throw on bad topology:
/// they build what they can and count the rest here.
struct BuildReport
{
	/// Soup vertex i is the vertex of line `vertex_offset + i` (0 in an empty map).
	uint32 vertex_offset = 0;
	uint32 nb_cells_read = 0;  ///< Faces (surface) or volumes (volume) in the input.
	uint32 nb_cells_built = 0; ///< Of those, the cells added to the map (not degenerate nor invalid).
	/// Cells with fewer than 3 vertices (surface) or a repeated vertex.
	uint32 nb_cells_degenerate = 0;
	/// Cells referring to a vertex id >= nb_vertices, or of an unknown kind.
	uint32 nb_cells_invalid = 0;
	/// Soup vertices used by no cell: their lines are released.
	uint32 nb_isolated_vertices = 0;
	/// Edges (surface) shared by more faces than a manifold allows, or by faces
	/// of incompatible orientation: the extra faces were detached along them
	/// (the map stays valid, with boundary there).
	uint32 nb_nonmanifold_edges = 0;
	/// Faces (volume) shared by more volumes than a manifold allows: the extra
	/// volumes were detached along them, as for edges.
	uint32 nb_nonmanifold_faces = 0;
	/// Boundary cells created to close the map (holes, outside of volumes).
	uint32 nb_boundary_cells = 0;
	/// Vertices whose cells form several fans (surface) or several
	/// face-connected groups (volume): each extra group got its own vertex.
	/// Pairs (new vertex line, original soup vertex id).
	std::vector<std::pair<uint32, uint32>> split_vertices;
	/// Number of distinct soup vertices that were split.
	uint32 nb_nonmanifold_vertices = 0;
	/// Edges shared by exactly two faces that list it in the same direction
	/// (surfaces). A CMap2 cannot glue them: its builder detaches the faces
	/// there (they are counted in nb_nonmanifold_edges too); a GMap2 glues them.
	uint32 nb_orientation_conflicts = 0;
	/// False when the faces cannot be oriented consistently, whatever faces
	/// are turned over (a Möbius strip, a Klein bottle): only a GMap2 keeps
	/// such a surface whole. Judged on the faces glued as the GMap2 builder
	/// glues them (see soup_orientation). For volumes, the GMap3 builder
	/// tells whether the cells it glued can be oriented consistently (a
	/// solid Klein bottle cannot); the CMap3 builder leaves it true.
	bool orientable = true;
};

/// Whether the faces of a polygon soup can be oriented consistently, and the
/// number of edges shared by exactly two faces listing it in the same
/// direction (see BuildReport). The faces sharing an edge are glued two by
/// two in the soup's order (the first with the second, the third with the
/// fourth...), as the GMap2 builder glues them; they are coloured "kept" or
/// "turned over" across each glued pair by a search over the faces; the soup
/// is orientable when no face needs both colours, that is exactly when the
/// GMap2 built from it is orientable. The faces the builders skip (fewer than 3 vertices, a
/// repeated vertex, an id out of range) are ignored. O(total size x log).
std::pair<bool, uint32> soup_orientation(uint32 nb_vertices, std::span<const uint32> face_sizes,
										 std::span<const uint32> face_vertices);

/// Builds closed 2-map faces from a polygon soup and appends them to m.
/// `face_sizes[f]` is the number of vertices of face f and `face_vertices` their
/// ids, face after face, in [0, nb_vertices). Opposite half-edges are sewn,
/// holes are closed by boundary faces. Vertices are indexed: soup vertex i is
/// the vertex of line `report.vertex_offset + i`. Other indexed orbits of m get
/// their new cells indexed too. Faces with fewer than 3 vertices, a repeated
/// vertex or an id out of range are skipped and counted; non-manifold edges are
/// detached and non-manifold vertices split (see BuildReport). O(total size).
BuildReport build_surface(CMap2& m, uint32 nb_vertices, std::span<const uint32> face_sizes,
						  std::span<const uint32> face_vertices);

/// Builds closed 2-G-map faces from a polygon soup and appends them to m, as
/// build_surface for a CMap2 does, with one difference: two faces sharing an
/// edge are glued whatever their orientations, so a soup that cannot be
/// oriented consistently (a Möbius strip, a Klein bottle) is kept whole, with
/// no face flipped and no edge detached. A face of n vertices has 2n darts,
/// consecutive, starting at its first vertex. Edges shared by more than two
/// faces are detached past the second face (nb_nonmanifold_edges), and
/// non-manifold vertices split, as for CMap2. O(total size).
BuildReport build_surface(GMap2& m, uint32 nb_vertices, std::span<const uint32> face_sizes,
						  std::span<const uint32> face_vertices);

/// Builds a closed 3-map from a list of cells and appends them to m. A cell of 4
/// vertices is a tetrahedron (a, b, c, d with d on the side of the normal of
/// (a, b, c)), 5 a pyramid (base quad then apex), 6 a prism (triangle then the
/// triangle above it), 8 a hexahedron (bottom quad then the top quad, VTK and
/// MEDIT order). Faces of adjacent cells are sewn; the outside is closed by
/// boundary volumes. Vertices are indexed as for build_surface. Cells of other
/// sizes or with out-of-range ids are skipped and counted. O(total size).
BuildReport build_volume(CMap3& m, uint32 nb_vertices, std::span<const uint32> cell_sizes,
						 std::span<const uint32> cell_vertices);

/// Builds a closed 3-map from polyhedra given by their faces and appends
/// them to m: cell c has `cell_nb_faces[c]` faces, taken in order from
/// `face_sizes` (the number of vertices of each face) and `face_vertices`
/// (their ids in [0, nb_vertices), face after face), each seen
/// counterclockwise from outside the cell (VTK's polyhedron convention).
/// Any polyhedron whose faces close one consistently oriented surface is
/// built (of any genus; faces of any degree), its faces sewn to the
/// matching faces of the other cells as build_volume sews them; the outside
/// is closed by boundary volumes, vertices indexed as for build_surface. A
/// cell with fewer than 4 faces, a face of fewer than 3 vertices or a
/// repeated vertex is skipped as degenerate; one with an id out of range,
/// faces that do not close a surface, or faces of opposite orientations is
/// skipped as invalid (BuildReport). O(total size x log).
BuildReport build_polyhedra(CMap3& m, uint32 nb_vertices, std::span<const uint32> cell_nb_faces,
							std::span<const uint32> face_sizes, std::span<const uint32> face_vertices);
/// The same into a GMap3, whose cells are glued whatever the direction in
/// which each lists a shared face (see build_volume for a GMap3); each
/// cell's own faces must still close one consistently oriented surface. A
/// face of n vertices has 2n darts, a cell's darts are consecutive.
/// O(total size x log).
BuildReport build_polyhedra(GMap3& m, uint32 nb_vertices, std::span<const uint32> cell_nb_faces,
							std::span<const uint32> face_sizes, std::span<const uint32> face_vertices);

/// Whether build_polyhedra builds the polyhedron of these faces (the sizes
/// of its faces, and their vertex ids, face after face): at least 4 faces,
/// each of at least 3 vertices with none repeated, closing one consistently
/// oriented surface. Readers use it to know which cells a build keeps.
/// O(size x log).
bool is_buildable_polyhedron(std::span<const uint32> face_sizes, std::span<const uint32> face_vertices);

/// Builds closed 3-G-map volumes from a list of cells and appends them to m,
/// as build_volume for a CMap3 does (same cells and vertex orders, same
/// report), with one difference: two cells sharing a face are glued whatever
/// the direction each lists it in, so a cell given in the opposite
/// orientation (a tetrahedron with two vertices swapped) is glued to its
/// neighbours, and a mesh that cannot be oriented is kept whole
/// (BuildReport::orientable tells). A face of n vertices has 2n darts; a
/// cell's darts are consecutive (the cells in their order, the boundary
/// after them). Faces shared by more than two cells are glued two by two in
/// the order of the cells, the face left over closed by the boundary
/// (nb_nonmanifold_faces); non-manifold vertices are split. The result has
/// twice the darts of the CMap3 of the same cells. O(total size x log).
BuildReport build_volume(GMap3& m, uint32 nb_vertices, std::span<const uint32> cell_sizes,
						 std::span<const uint32> cell_vertices);

} // namespace cgogn
