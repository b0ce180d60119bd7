// SPDX-License-Identifier: MIT
// An `.ig` file as read, before it becomes an incidence graph: the reader
// and the builder apart, for the fuzzer.
#pragma once

#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/incidence_graph.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace cgogn::io::detail
{

/// What an `.ig` file holds: positions, edges as vertex pairs, faces as
/// edge lists in cycle order (face_sizes[f] edges each).
struct IgData
{
	std::vector<Vec3> positions;
	std::vector<std::array<uint32, 2>> edges;
	std::vector<uint32> face_sizes, face_edges;
};

/// Parses and checks an `.ig` file: every index in range, every edge between
/// two different vertices, every face a simple cycle of 3 or more edges in
/// the order given. Throws io::Error naming path and line. O(size of text).
IgData read_ig(std::string_view text, const std::string& path);

/// Appends d to ig (see io::load_incidence_graph); throws io::Error, before
/// changing ig, when `position` exists with another type or ig would
/// overflow 32-bit indices. O(size of d).
IncidenceGraphLoadReport build_incidence_graph(IncidenceGraph& ig, const IgData& d, const std::string& path);

} // namespace cgogn::io::detail
