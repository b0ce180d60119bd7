// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/io/error.h>
#include <cgogn/io/options.h>

#include <string>

namespace cgogn::io
{

/// Loads a volume mesh file (MEDIT .mesh, VTK legacy .vtk, VTK XML .vtu, gmsh
/// .msh v2/v4, TetGen .node/.ele) and appends it to m. Tetrahedra, pyramids,
/// prisms and hexahedra are read (other cells are rejected, boundary faces and
/// edges are ignored); cells given with negative orientation are turned over
/// and counted. The whole file is read and checked before building, so a
/// failure leaves m untouched. Positions go to the Vec3 vertex attribute
/// `position`. Throws io::Error naming file, line or byte and cause on
/// malformed input (NaN/inf coordinates are rejected). O(file size).
LoadReport load_volume(CMap3& m, const std::string& path, const LoadOptions& options = {});

/// Writes the volumes of m (MEDIT .mesh, VTK legacy .vtk, VTK XML .vtu, gmsh
/// .msh v4). Each volume must be a tetrahedron, pyramid, prism or hexahedron
/// (recognised by its faces); throws io::Error otherwise, or when m has no
/// Vec3 `position` vertex attribute, or the file cannot be written.
/// O(size of m).
void save_volume(const CMap3& m, const std::string& path, const SaveOptions& options = {});

} // namespace cgogn::io
