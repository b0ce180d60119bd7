// SPDX-License-Identifier: MIT
// What the peer cross-checks of the subdivision share: the mesh as a soup
// (to build the peer's mesh from the same data) and the comparison of two
// point sets whose numberings differ.
#pragma once

#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace cgogn::peer_test
{

struct Soup
{
	std::vector<Vec3> points;
	std::vector<std::vector<uint32>> faces;
};

/// The vertices (densely numbered) and faces of m.
inline Soup soup_of(const CMap2& m, const AttributeArray<Vec3>& pos)
{
	Soup s;
	std::vector<uint32> id(pos.container()->end_index(), 0);
	foreach_cell(m, [&](CMap2::Vertex v) {
		id[index_of(m, v)] = uint32(s.points.size());
		s.points.push_back(pos[index_of(m, v)]);
	});
	foreach_cell(m, [&](CMap2::Face f) {
		std::vector<uint32> face;
		foreach_incident_vertex(m, f, [&](CMap2::Vertex v) { face.push_back(id[index_of(m, v)]); });
		s.faces.push_back(face);
	});
	return s;
}

inline std::vector<Vec3> positions_of(const CMap2& m, const AttributeArray<Vec3>& pos)
{
	std::vector<Vec3> p;
	foreach_cell(m, [&](CMap2::Vertex v) { p.push_back(pos[index_of(m, v)]); });
	return p;
}

/// The largest distance from a point of `a` to its nearest point of `b`, and
/// the other way round (so each set must cover the other), searched in a
/// window of `window` along x after sorting; infinity when a point has no
/// partner in its window or the sizes differ. O(n log n) for spread points.
inline double max_mismatch(std::vector<Vec3> a, std::vector<Vec3> b, double window = 1e-6)
{
	if (a.size() != b.size())
		return std::numeric_limits<double>::infinity();
	const auto by_x = [](const Vec3& p, const Vec3& q) { return p.x() < q.x(); };
	auto one_way = [&](const std::vector<Vec3>& from, std::vector<Vec3>& to) {
		std::sort(to.begin(), to.end(), by_x);
		double worst = 0.0;
		for (const Vec3& p : from)
		{
			double best = std::numeric_limits<double>::infinity();
			for (auto it = std::lower_bound(to.begin(), to.end(), Vec3(p.x() - window, 0, 0), by_x);
				 it != to.end() && it->x() <= p.x() + window; ++it)
				best = std::min(best, (*it - p).norm());
			worst = std::max(worst, best);
		}
		return worst;
	};
	return std::max(one_way(a, b), one_way(b, a));
}

/// Loads a data surface with its positions; false only when it is a large
/// mesh that is not available.
inline bool load(CMap2& m, const std::string& name)
{
	const std::string path = cgogn_test_data::path("surface/" + name);
	if (path.empty())
		return false;
	io::load_surface(m, path);
	return true;
}

} // namespace cgogn::peer_test
