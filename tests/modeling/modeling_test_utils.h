// SPDX-License-Identifier: MIT
// What the modeling tests share: data meshes, Euler characteristic, edge checks.
#pragma once

#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace cgogn::modeling_test
{

/// The path of a data surface (empty for a large one that is not available).
inline std::string data_path(const std::string& name)
{
	return cgogn_test_data::path("surface/" + name);
}

/// Loads a data surface; false (the caller skips) only when it is a large
/// mesh that is not available. A missing small mesh throws (the test fails).
inline bool load_data(CMap2& m, const std::string& name)
{
	const std::string path = data_path(name);
	if (path.empty())
		return false;
	io::load_surface(m, path);
	return true;
}

inline std::shared_ptr<AttributeArray<Vec3>> positions(const CMap2& m)
{
	return get_attribute<Vec3, CMap2::Vertex>(m, "position");
}

inline int64_t euler_characteristic(const CMap2& m)
{
	return int64_t(nb_cells<CMap2::Vertex>(m)) - int64_t(nb_cells<CMap2::Edge>(m)) + int64_t(nb_cells<CMap2::Face>(m));
}

/// Number of edges joining a pair of vertices already joined by another edge.
inline uint32 nb_multiple_edges(const CMap2& m)
{
	std::vector<std::pair<uint32, uint32>> ends;
	foreach_cell(m, [&](CMap2::Edge e) {
		const uint32 a = index_of(m, CMap2::Vertex(e.dart)), b = index_of(m, CMap2::Vertex(phi2(m, e.dart)));
		ends.emplace_back(std::min(a, b), std::max(a, b));
	});
	std::sort(ends.begin(), ends.end());
	uint32 n = 0;
	for (std::size_t i = 1; i < ends.size(); ++i)
		n += ends[i] == ends[i - 1];
	return n;
}

/// Sizes (in edges) of the boundary loops of m.
inline std::vector<uint32> boundary_loop_sizes(const CMap2& m)
{
	std::vector<uint32> sizes;
	DartMarker<CMap2> seen(m);
	foreach_dart(m, [&](Dart d) {
		if (!is_boundary(m, d) || seen.is_marked(d))
			return;
		uint32 n = 0;
		foreach_dart_of_orbit(m, CMap2::Face(d), [&](Dart x) {
			seen.mark(x);
			++n;
		});
		sizes.push_back(n);
	});
	return sizes;
}

} // namespace cgogn::modeling_test
