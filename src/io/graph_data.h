// SPDX-License-Identifier: MIT
// Between the graph readers and graphs: what a graph file holds, read whole
// before the graph is touched (load_graph and the fuzz targets use both steps).
#pragma once

#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/graph.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cgogn::io::detail
{

/// The content of a graph file: vertex positions (and radii), edges as pairs
/// of vertex numbers (0-based, in range).
struct GraphData
{
	std::vector<Vec3> positions;
	std::vector<double> radii; ///< empty without radius
	std::vector<std::pair<uint32, uint32>> edges;
	uint32 nb_one_sided_edges = 0; ///< .skel: edges listed by one end only
	uint32 nb_faces_ignored = 0;   ///< .obj: faces (`f`), not part of a graph
	uint32 nb_cells_ignored = 0;   ///< .vtk, .vtu: cells other than lines, not part of a graph
};

enum class GraphFormat
{
	Cg,
	Cgr,
	Skel,
	Obj,
	Vtk,
	Vtu
};

/// Parses a whole graph file (see <cgogn/io/graph.h> for the formats).
/// Throws io::Error naming path and line on malformed input. O(size of text).
GraphData read_graph(std::string_view text, const std::string& path, GraphFormat format, uint32 index_base);

/// Appends d to g (positions, radii, edges). Throws io::Error before touching
/// g when g has a `position` or `radius` vertex attribute of another type.
/// O(size of d).
GraphLoadReport build_graph(Graph& g, const GraphData& d, const std::string& path);

} // namespace cgogn::io::detail
