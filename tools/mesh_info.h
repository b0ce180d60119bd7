// SPDX-License-Identifier: MIT
// What `cgogn info` reports about a loaded map, as a JSON object.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/core/map/mrmap2.h>
#include <cgogn/core/map/mrmap3.h>
#include <cgogn/io/graph.h>
#include <cgogn/io/options.h>

#include <nlohmann/json.hpp>

#include <string>

namespace cgogn::tool
{

/// Cell counts (boundary cells excluded), boundary and connected components,
/// Euler characteristic, genus (closed surfaces), what the load repaired,
/// bounding box, edge lengths and face degrees (and cell kinds for volumes).
/// Keys: see the README's `cgogn info` section. O(size of m).
nlohmann::json surface_info(const CMap2& m, const io::LoadReport& r);
nlohmann::json surface_info(const GMap2& m, const io::LoadReport& r);
nlohmann::json volume_info(const CMap3& m, const io::LoadReport& r);
nlohmann::json volume_info(const GMap3& m, const io::LoadReport& r);

/// A graph's counts (vertices, edges, components, Euler characteristic V -
/// E, cycle rank, isolated vertices, self-loops, open and closed branches,
/// the degree histogram), whether the file had radii and one-sided .skel
/// edges, bounding box and edge lengths. O(size of g).
nlohmann::json graph_info(const Graph& g, const io::GraphLoadReport& r);

/// The true counts of a surface file loaded into an incidence graph (nothing
/// split or detached): vertices, edges, faces, components, Euler
/// characteristic, non-manifold edges (three faces or more) and vertices
/// (with edges, but not one fan of faces), wire edges (no face), isolated
/// vertices, the largest number of faces on an edge, and what the load
/// skipped. O(size of ig).
nlohmann::json complex_info(const IncidenceGraph& ig, const io::LoadReport& r);

/// A multiresolution map: surface_info (volume_info for an MRMap3) of its
/// current level (counts, topology, geometry), its finest and current levels
/// ("max_level", "current_level"), per level its darts and f-vector (V, E,
/// F[, W]) ("levels"), and its attributes with their cells and value types
/// ("attributes"). O(darts x levels).
nlohmann::json mrmap_info(const MRMap2& m);
nlohmann::json mrmap_info(const MRMap3& m);

/// The same information as readable text lines.
std::string info_text(const nlohmann::json& info);

} // namespace cgogn::tool
