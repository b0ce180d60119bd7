// SPDX-License-Identifier: MIT
#pragma once

// BENCH-ONLY minimal readers, written so that the suites produce numbers on
// real meshes before the io layer is merged. They read only what the
// benchmarks need (OBJ `v` and `f` lines; MEDIT `Vertices` and `Tetrahedra`)
// and are to be replaced by the io layer's soup loaders: inputs.cpp calls
// them through load_surface_soup / load_volume_soup only.

#include <cgogn/core/builder/generators.h>

#include <optional>
#include <string>

namespace cgogn_bench
{

/// Polygon soup of an OBJ file (vertices and faces; `f a/b/c` keeps the vertex
/// index, negative indices are relative). nullopt when the file cannot be read.
std::optional<cgogn::SurfaceSoup> read_obj_soup(const std::string& path);

/// Tetrahedra of a MEDIT .mesh file (other cells ignored). nullopt when the
/// file cannot be read.
std::optional<cgogn::VolumeSoup> read_medit_tet_soup(const std::string& path);

} // namespace cgogn_bench
