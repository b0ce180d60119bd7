// SPDX-License-Identifier: MIT
// Between MeshData and maps: building a map from what a reader produced, and
// extracting what a writer needs from a map.
#pragma once

#include <cgogn/core/build/generators.h>
#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/io/options.h>

#include "mesh_data.h"

#include <string>

namespace cgogn::io::detail
{

/// Appends d to m through build_surface / build_volume, then sets positions,
/// `original_vertex` (when vertices were split) and the columns as attributes.
/// Throws io::Error before touching m when an attribute of the same name but
/// another type exists. O(size of d).
LoadReport build_map(CMap2& m, const MeshData& d, const std::string& path);
LoadReport build_map(GMap2& m, const MeshData& d, const std::string& path);
LoadReport build_map(CMap3& m, const MeshData& d, const std::string& path);
LoadReport build_map(GMap3& m, const MeshData& d, const std::string& path);
/// Appends d to an incidence graph exactly: every vertex in the file's order,
/// every face through its vertices, edges found or added; faces with fewer
/// than 3 vertices or a repeated one are skipped and counted. The same
/// attributes as for a map; nothing is split, detached or turned over.
LoadReport build_map(IncidenceGraph& ig, const MeshData& d, const std::string& path);

/// Every cell of d (the standard ones by their faces, as build_volume
/// builds them, and the polyhedra) as build_polyhedra's input, in their
/// order. Precondition: the standard cells have 4, 5, 6 or 8 vertices.
/// O(size of d).
PolyhedronSoup cells_as_polyhedra(const MeshData& d);

/// Turns over volume cells of negative orientation (tetrahedra by their signed
/// volume; other cells by the side of the top relative to the bottom face's
/// normal; polyhedra by their signed volume, every face reversed). Returns
/// the number of cells turned over. O(size of the cells).
uint32 orient_cells(MeshData& d);

/// The faces of m (polygons) or volumes of m (cells of 4, 5, 6 or 8 vertices in
/// the builder's order, other volumes as polyhedra given by their faces) with
/// positions and, when `attributes`, the double, Vec2 and Vec3 vertex and
/// face/volume attributes. Throws io::Error (naming path) when there is no
/// `position`. A volume of a GMap3 is read in
/// the orientation of the dart it is reached by (a volume is a sphere: it can
/// always be oriented), then turned over when that gives it a negative
/// orientation (see orient_cells), so that every cell is written in the
/// format's order whatever the orientation of the darts. O(size of m).
MeshData extract_surface(const CMap2& m, const std::string& path, bool attributes);
MeshData extract_surface(const GMap2& m, const std::string& path, bool attributes);
MeshData extract_surface(const IncidenceGraph& ig, const std::string& path, bool attributes);
MeshData extract_volume(const CMap3& m, const std::string& path, bool attributes);
MeshData extract_volume(const GMap3& m, const std::string& path, bool attributes);

/// Adds to d (extracted from the surface map m) the edges of m with a
/// nonzero value in one of their attributes a file can hold, as listed
/// edges (MeshData::segments, over d's vertex numbering) with those
/// columns, and the names of their physical groups (dimension 1). For the
/// writers of the formats that list edges (.msh, .mesh, .vtk, .vtu).
/// O(cells of m).
void list_edges_with_data(const CMap2& m, MeshData& d, const std::string& path);
void list_edges_with_data(const GMap2& m, MeshData& d, const std::string& path);

} // namespace cgogn::io::detail
