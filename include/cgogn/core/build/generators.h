// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/build/map_builder.h>

#include <array>

namespace cgogn
{

/// A polygon soup with one position per vertex, as produced by the generators
/// (the core has no vector type: positions are plain arrays).
struct SurfaceSoup
{
	uint32 nb_vertices = 0;                       ///< Number of vertices; their ids are [0, nb_vertices).
	std::vector<uint32> face_sizes;               ///< Number of vertices of each face.
	std::vector<uint32> face_vertices;            ///< The vertex ids of the faces, face after face.
	std::vector<std::array<double, 3>> positions; ///< x, y, z of each vertex, by id.
};

/// A cell soup (tetrahedra, pyramids, prisms, hexahedra) with positions.
struct VolumeSoup
{
	uint32 nb_vertices = 0;                       ///< Number of vertices; their ids are [0, nb_vertices).
	std::vector<uint32> cell_sizes;               ///< Number of vertices of each cell (4, 5, 6 or 8).
	std::vector<uint32> cell_vertices;            ///< The vertex ids of the cells, in build_volume's order.
	std::vector<std::array<double, 3>> positions; ///< x, y, z of each vertex, by id.
};

/// Polyhedra given by their faces (build_polyhedra's input) with positions.
struct PolyhedronSoup
{
	uint32 nb_vertices = 0;                       ///< Number of vertices; their ids are [0, nb_vertices).
	std::vector<uint32> cell_nb_faces;            ///< Number of faces of each cell.
	std::vector<uint32> face_sizes;               ///< Number of vertices of each face, cell after cell.
	std::vector<uint32> face_vertices;            ///< The vertex ids of the faces, face after face.
	std::vector<std::array<double, 3>> positions; ///< x, y, z of each vertex, by id.
};

/// The cells of a volume soup as polyhedra: each cell's faces as
/// build_volume builds them (seen counterclockwise from outside). Cells of
/// an unknown size are left out. O(size of s).
PolyhedronSoup polyhedra_of(const VolumeSoup& s);

/// A column of `layers` prisms on a regular n-gon (n >= 3) of radius 1 in
/// the z = 0 plane, layers of height 1: ring l holds vertices l n ... l n +
/// n - 1, each prism's faces (its two n-gons and n quads) counterclockwise
/// seen from outside. O(n x layers).
PolyhedronSoup prism_column_soup(uint32 n, uint32 layers);

/// A flat nx x ny grid of unit squares in the z = 0 plane, (nx+1)(ny+1)
/// vertices, one boundary loop; quads, or each quad split in two triangles.
SurfaceSoup grid_soup(uint32 nx, uint32 ny, bool triangles = false);
/// An open cylinder of radius 1 and height 1: nu around, nv along; two
/// boundary loops. Precondition: nu >= 3.
SurfaceSoup cylinder_soup(uint32 nu, uint32 nv, bool triangles = false);
/// A closed genus-0 polyhedron on the unit sphere: nu meridians, nv parallels
/// (nv >= 2), triangle fans at the poles, quads or triangles between them.
SurfaceSoup sphere_soup(uint32 nu, uint32 nv, bool triangles = false);
/// A closed torus (radii 1 and 0.5): nu x nv quads, or 2 nu nv triangles.
/// Precondition: nu, nv >= 3.
SurfaceSoup torus_soup(uint32 nu, uint32 nv, bool triangles = false);
/// A Möbius strip of n quads (n >= 3) around a circle of radius 1, width
/// 0.5: 2n vertices, one boundary loop, Euler characteristic 0, not
/// orientable. Built into a GMap2 it stays whole; a CMap2 cannot hold it.
SurfaceSoup mobius_soup(uint32 n, bool triangles = false);
/// A Klein bottle: the nu x nv quad torus whose last ring is glued back to
/// the first one reversed ((nu, j) ~ (0, -j)); closed, Euler characteristic
/// 0, not orientable. Positions are those of the torus (the glued ring does
/// not meet in space). Precondition: nu, nv >= 3.
SurfaceSoup klein_bottle_soup(uint32 nu, uint32 nv, bool triangles = false);
/// The projective plane as a hemi-icosahedron: 6 vertices, 15 edges, 10
/// triangles (the icosahedron with opposite points identified); closed,
/// Euler characteristic 1, not orientable. Positions: one vertex of each
/// antipodal pair of the unit icosahedron.
SurfaceSoup hemi_icosahedron_soup();
/// The projective plane as a hemi-cube: 4 vertices, 6 edges, 3 quads (the
/// cube with opposite points identified); Euler characteristic 1.
SurfaceSoup hemi_cube_soup();
/// An nx x ny x nz grid of unit cubes, each split into 6 positively oriented
/// tetrahedra (conforming across cubes).
VolumeSoup tet_grid_soup(uint32 nx, uint32 ny, uint32 nz);
/// An nx x ny x nz grid of unit hexahedra.
VolumeSoup hex_grid_soup(uint32 nx, uint32 ny, uint32 nz);
/// The solid Klein bottle: a ring of n >= 2 hexahedra of square section
/// around the z axis, the last one glued back to the first through a
/// reflection of the section (the ring's vertices are placed on a torus, the
/// last cell crosses itself). Not orientable, so only a GMap3 holds it whole:
/// 4n vertices, 8n edges, 5n faces, n volumes, one boundary component (a
/// Klein bottle), Euler characteristic 0.
VolumeSoup solid_klein_bottle_soup(uint32 n);

inline BuildReport build_surface(CMap2& m, const SurfaceSoup& s)
{
	return build_surface(m, s.nb_vertices, s.face_sizes, s.face_vertices);
}
inline BuildReport build_surface(GMap2& m, const SurfaceSoup& s)
{
	return build_surface(m, s.nb_vertices, s.face_sizes, s.face_vertices);
}
inline BuildReport build_volume(CMap3& m, const VolumeSoup& s)
{
	return build_volume(m, s.nb_vertices, s.cell_sizes, s.cell_vertices);
}
inline BuildReport build_volume(GMap3& m, const VolumeSoup& s)
{
	return build_volume(m, s.nb_vertices, s.cell_sizes, s.cell_vertices);
}
inline BuildReport build_polyhedra(CMap3& m, const PolyhedronSoup& s)
{
	return build_polyhedra(m, s.nb_vertices, s.cell_nb_faces, s.face_sizes, s.face_vertices);
}
inline BuildReport build_polyhedra(GMap3& m, const PolyhedronSoup& s)
{
	return build_polyhedra(m, s.nb_vertices, s.cell_nb_faces, s.face_sizes, s.face_vertices);
}

} // namespace cgogn
