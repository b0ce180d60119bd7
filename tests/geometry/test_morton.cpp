// SPDX-License-Identifier: MIT
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace cgogn_test_morton
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;
using Vertex = CMap2::Vertex;

TEST(Morton, KeysOfKnownPoints)
{
	const BoundingBox bb(Vec3(0, 0, 0), Vec3(1, 1, 1));
	EXPECT_EQ(morton_key(Vec3(0, 0, 0), bb), 0u);
	EXPECT_EQ(morton_key(Vec3(1, 1, 1), bb), (uint64(1) << 63) - 1);
	// x = 3/4 is 0b11 followed by zeros on 21 bits: bits 20 and 19 of x
	EXPECT_EQ(morton_key(Vec3(0.75, 0, 0), bb), (uint64(1) << 60) | (uint64(1) << 57));
	EXPECT_EQ(morton_key(Vec3(0, 0.75, 0), bb), (uint64(1) << 61) | (uint64(1) << 58));
	EXPECT_EQ(morton_key(Vec3(0, 0, 0.5), bb), uint64(1) << 62);
	// outside points are clamped to the box
	EXPECT_EQ(morton_key(Vec3(-3, -3, -3), bb), 0u);
	EXPECT_EQ(morton_key(Vec3(7, 7, 7), bb), (uint64(1) << 63) - 1);
	// the Z order of the four quadrants of a square
	const uint64 k00 = morton_key(Vec3(0.1, 0.1, 0), bb), k10 = morton_key(Vec3(0.6, 0.1, 0), bb);
	const uint64 k01 = morton_key(Vec3(0.1, 0.6, 0), bb), k11 = morton_key(Vec3(0.6, 0.6, 0), bb);
	EXPECT_LT(k00, k10);
	EXPECT_LT(k10, k01);
	EXPECT_LT(k01, k11);
}

TEST(Morton, GridCellsHaveDistinctLocalKeys)
{
	CMap2 m;
	auto pos = build_with_positions(m, grid_soup(16, 16));
	auto vkey = add_attribute<uint64, Vertex>(m, "vkey");
	auto fkey = add_attribute<uint64, CMap2::Face>(m, "fkey");
	compute_morton_keys<Vertex>(m, *pos, *vkey);
	compute_morton_keys<CMap2::Face>(m, *pos, *fkey);
	std::set<uint64> vk, fk;
	foreach_cell(m, [&](Vertex v) { vk.insert(value<uint64>(m, vkey, v)); });
	foreach_cell(m, [&](CMap2::Face f) { fk.insert(value<uint64>(m, fkey, f)); });
	EXPECT_EQ(vk.size(), nb_cells<Vertex>(m));
	EXPECT_EQ(fk.size(), nb_cells<CMap2::Face>(m));
	// the grid is flat (no z extent): the keys use the x and y bits only
	for (uint64 k : vk)
		EXPECT_EQ(k & 0x4924924924924924ull, 0u);
	// sorted by key, consecutive faces are closer on average than in row order
	std::vector<std::pair<uint64, Vec3>> faces;
	foreach_cell(m, [&](CMap2::Face f) { faces.emplace_back(value<uint64>(m, fkey, f), centroid(m, f, *pos)); });
	std::sort(faces.begin(), faces.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
	double jump = 0.0;
	for (std::size_t i = 1; i < faces.size(); ++i)
		jump += (faces[i].second - faces[i - 1].second).norm();
	const double row_order = (16.0 * 15.0 + 15.0 * std::sqrt(15.0 * 15.0 + 1.0)) / 255.0;
	EXPECT_LT(jump / double(faces.size() - 1), 0.9 * row_order);
}

TEST(Morton, VolumeMeshVertices)
{
	CMap3 m;
	auto pos = build_with_positions(m, hex_grid_soup(3, 3, 3));
	const BoundingBox bb = bounding_box(m, *pos);
	std::set<uint64> keys;
	foreach_cell(m, [&](CMap3::Vertex v) { keys.insert(morton_key(m, v, *pos, bb)); });
	EXPECT_EQ(keys.size(), 64u);
	EXPECT_EQ(*keys.begin(), 0u);
	EXPECT_EQ(*keys.rbegin(), (uint64(1) << 63) - 1);
	std::set<uint64> vkeys;
	foreach_cell(m, [&](CMap3::Volume w) { vkeys.insert(morton_key(m, w, *pos, bb)); });
	EXPECT_EQ(vkeys.size(), 27u);
}

} // namespace cgogn_test_morton
