// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/io/error.h>
#include <cgogn/io/options.h>

#include <string>

namespace cgogn::io
{

/// Loads a volume mesh file (MEDIT .mesh, VTK legacy .vtk, VTK XML .vtu, gmsh
/// .msh v2/v4, TetGen .node/.ele, OpenVolumeMesh .ovm) and appends it to m.
/// Tetrahedra, pyramids, prisms, hexahedra and polyhedra are read (other
/// cells are rejected); the faces the file lists beside them (boundary
/// faces) give their data, such as gmsh tags and MEDIT references, to the
/// faces of m with the same vertices, as face attributes (docs/io.md,
/// "Region and boundary tags"); line and point elements are reported in
/// LoadReport::dropped. Cells given with negative orientation are turned
/// over and counted. The whole file is read and checked before building, so
/// a failure leaves m untouched. Positions go to the Vec3 vertex attribute
/// `position`. Throws io::Error naming file, line or byte and cause on
/// malformed input (NaN/inf coordinates are rejected). O(file size).
LoadReport load_volume(CMap3& m, const std::string& path, const LoadOptions& options = {});

/// Writes the volumes of m (MEDIT .mesh, VTK legacy .vtk, VTK XML .vtu, gmsh
/// .msh v4, TetGen, .ovm) with their attributes, and (.mesh, .vtk, .vtu,
/// .msh) the faces with a nonzero value in a face attribute, with their tags.
/// Volumes other than tetrahedra, pyramids, prisms and hexahedra are
/// polyhedra, which .mesh, .msh and TetGen files cannot hold: throws
/// io::Error then, or when m has no Vec3 `position` vertex attribute, or the
/// file cannot be written. O(size of m).
void save_volume(const CMap3& m, const std::string& path, const SaveOptions& options = {});

/// The same into a GMap3, built by build_volume for a GMap3: the same
/// formats, cells, attributes, report and errors as for a CMap3 (a failure
/// leaves m untouched), and the same cells (twice the darts). Cells given
/// with negative orientation are turned over and counted as for a CMap3.
/// O(file size).
LoadReport load_volume(GMap3& m, const std::string& path, const LoadOptions& options = {});
/// Writes the volumes of a GMap3 as save_volume for a CMap3 does. Each
/// volume is oriented on its own (a volume is a sphere, so it can be, even
/// when the whole map cannot), in the orientation that its positions make
/// positive, and written in the format's vertex order. O(size of m).
void save_volume(const GMap3& m, const std::string& path, const SaveOptions& options = {});

} // namespace cgogn::io
