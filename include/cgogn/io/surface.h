// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/map/incidence_graph.h>
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

/// The same into an incidence graph, exactly as written: every vertex in the
/// file's order (those no face uses included), every face through its
/// vertices in the file's order, edges shared by any number of faces in any
/// directions. Nothing is split, detached or turned over: a non-manifold
/// or non-orientable file keeps its true counts. Only faces that no complex
/// holds (fewer than 3 vertices, a repeated vertex) are skipped, and
/// counted. The same attributes as for a map (positions, per-vertex and
/// per-face data), the same errors; a failed load leaves ig unchanged.
/// O(file size x vertex degree).
LoadReport load_surface(IncidenceGraph& ig, const std::string& path, const LoadOptions& options = {});
/// Writes the faces of an incidence graph, vertices in the order of their
/// container and faces in traversal order: a loaded file comes back with
/// its vertex and face order. Edges without face and vertices without edge
/// are written only as vertices (the surface formats have no wires).
/// O(size of ig).
void save_surface(const IncidenceGraph& ig, const std::string& path, const SaveOptions& options = {});

// A CMap3 is a CMap2 and a GMap3 a GMap2: without these, a volume map would
// be read as a surface.
LoadReport load_surface(CMap3& m, const std::string& path, const LoadOptions& options = {}) = delete;
void save_surface(const CMap3& m, const std::string& path, const SaveOptions& options = {}) = delete;
LoadReport load_surface(GMap3& m, const std::string& path, const LoadOptions& options = {}) = delete;
void save_surface(const GMap3& m, const std::string& path, const SaveOptions& options = {}) = delete;

} // namespace cgogn::io
