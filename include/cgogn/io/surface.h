// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/io/error.h>
#include <cgogn/io/options.h>

#include <string>

namespace cgogn::io
{

/// Loads a surface mesh file (OFF, OBJ, PLY, STL; by extension unless
/// `options.format` says otherwise) and appends it to m. The whole file is read
/// and checked first, then built with build_surface, so a failure leaves m
/// untouched. Positions go to the Vec3 vertex attribute `position` (created if
/// missing); other per-vertex and per-face data become attributes named as in
/// the file (double, Vec2 or Vec3). Non-manifold input is repaired as the
/// builder does and reported; degenerate faces are skipped and counted.
/// Throws io::Error naming file, line or byte and cause on any malformed
/// input, including NaN or infinite coordinates (rejected) and indices out of
/// range. O(file size).
LoadReport load_surface(CMap2& m, const std::string& path, const LoadOptions& options = {});

/// Writes the non-boundary faces of m (OFF, OBJ, PLY ascii or binary, STL
/// ascii or binary). Precondition-free: throws io::Error when m has no Vec3
/// vertex attribute `position`, when the format cannot hold the faces (STL:
/// triangles only) or the file cannot be written. Vertices are numbered in
/// the order of the vertex container. O(size of m).
void save_surface(const CMap2& m, const std::string& path, const SaveOptions& options = {});

/// The same into a GMap2: as for a CMap2, except that faces sharing an edge
/// are glued whatever their orientations, so a surface that cannot be
/// oriented (LoadReport::orientable false) is loaded whole, with its exact
/// cells; the load into a CMap2 cuts it instead. O(file size).
LoadReport load_surface(GMap2& m, const std::string& path, const LoadOptions& options = {});
/// Writes the non-boundary faces of a GMap2, each polygon in the order of
/// its darts (a non-orientable surface has no consistent order to keep), as
/// save_surface for a CMap2. O(size of m).
void save_surface(const GMap2& m, const std::string& path, const SaveOptions& options = {});

// A CMap3 is a CMap2 and a GMap3 a GMap2: without these, a volume map would
// be read as a surface.
LoadReport load_surface(CMap3& m, const std::string& path, const LoadOptions& options = {}) = delete;
void save_surface(const CMap3& m, const std::string& path, const SaveOptions& options = {}) = delete;
LoadReport load_surface(GMap3& m, const std::string& path, const LoadOptions& options = {}) = delete;
void save_surface(const GMap3& m, const std::string& path, const SaveOptions& options = {}) = delete;

} // namespace cgogn::io
