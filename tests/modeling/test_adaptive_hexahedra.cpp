// SPDX-License-Identifier: MIT
// The adaptive hexahedral driver: refinement toward a point, balance, the
// hexahedral scheme's positions.
#include <cgogn/core.h>
#include <cgogn/modeling/adaptive_hexahedra.h>
#include <cgogn/modeling/subdivision.h>

#include "volume_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

using namespace cgogn;

namespace
{

/// The hexahedral grid of n^3 cells scaled to [0, 1]^3, with positions.
MRMap3 unit_grid(uint32 n)
{
	return MRMap3(test::hex_grid_with_positions(n, n, n, 1.0 / double(n)));
}

/// The bounding box of volume w at the level of v.
std::array<Vec3, 2> box_of(const MRLevelView3& v, const AttributeArray<Vec3>& pos, MRMap3::Volume w)
{
	Vec3 lo = Vec3::Constant(1e9), hi = Vec3::Constant(-1e9);
	foreach_incident_vertex(v, w, [&](MRMap3::Vertex x) {
		lo = lo.cwiseMin(value<Vec3>(v, pos, x));
		hi = hi.cwiseMax(value<Vec3>(v, pos, x));
	});
	return {lo, hi};
}

} // namespace

TEST(AdaptiveHexahedra, RefinementTowardAPointIsBalancedAndTrilinear)
{
	MRMap3 m = unit_grid(2);
	auto pos = get_attribute<Vec3, MRMap3::Vertex>(m, "position");
	const Vec3 target(0.3, 0.2, 0.35);
	const auto contains = [&](const MRMap3& mm, MRMap3::Volume w) {
		const auto [lo, hi] = box_of(level_view(mm, current_level(mm)), *pos, w);
		return (target.array() >= lo.array()).all() && (target.array() <= hi.array()).all();
	};
	const uint32 subdivided = modeling::refine_hexahedra(m, *pos, contains, 4);
	EXPECT_EQ(max_level(m), 4u);
	EXPECT_EQ(current_level(m), 0u);
	const IntegrityReport r = check_integrity(m);
	ASSERT_TRUE(r.ok()) << r.to_string();
	// balance made the driver refine more than the 4 volumes along the path
	EXPECT_GT(subdivided, 4u);
	const MRLevelView3 finest = level_view(m, 4);
	EXPECT_EQ(nb_cells<MRMap3::Volume>(finest), 8u + 7u * subdivided);
	uint32 at_target = 0;
	double volume = 0.0;
	foreach_cell(finest, [&](MRMap3::Volume w) {
		const uint32 k = volume_level(finest, w);
		const auto [lo, hi] = box_of(finest, *pos, w);
		// every leaf is a box of side 2^-(k+1) on the grid of its level
		const double side = 1.0 / double(2u << k);
		for (int c = 0; c < 3; ++c)
		{
			EXPECT_DOUBLE_EQ(hi[c] - lo[c], side);
			EXPECT_DOUBLE_EQ(lo[c] / side, std::round(lo[c] / side));
		}
		volume += side * side * side;
		at_target += (target.array() >= lo.array()).all() && (target.array() <= hi.array()).all() && k == 4;
		// leaves sharing an edge differ by at most one level
		foreach_incident_edge(finest, w, [&](MRMap3::Edge e) {
			foreach_incident_volume(finest, e, [&](MRMap3::Volume x) {
				const uint32 kx = volume_level(finest, x);
				EXPECT_LE(std::max(k, kx) - std::min(k, kx), 1u);
			});
		});
	});
	EXPECT_EQ(at_target, 1u);
	EXPECT_NEAR(volume, 1.0, 1e-12);
	// nothing is selected any more
	EXPECT_EQ(modeling::refine_hexahedra(m, *pos, contains, 4), 0u);
}

TEST(AdaptiveHexahedra, RefiningEverythingGivesTheHexahedralSubdivision)
{
	MRMap3 m = unit_grid(2);
	auto pos = get_attribute<Vec3, MRMap3::Vertex>(m, "position");
	// a rule other than the scheme's is set aside during the refinement
	set_attribute_rule(m, pos, AttributeRule::Copy);
	EXPECT_EQ(modeling::refine_hexahedra(
				  m, *pos, [](const MRMap3&, MRMap3::Volume) { return true; }, 2),
			  8u + 64u);
	EXPECT_EQ(pos->rule(), AttributeRule::Copy);
	// the flat hexahedral subdivision of the same grid, twice
	CMap3 flat = test::hex_grid_with_positions(2, 2, 2, 0.5);
	auto fpos = get_attribute<Vec3, CMap3::Vertex>(flat, "position");
	modeling::hex_subdivision(flat, *fpos);
	modeling::hex_subdivision(flat, *fpos);
	const MRLevelView3 finest = level_view(m, 2);
	EXPECT_EQ(f_vector(finest), f_vector(flat));
	std::vector<std::array<double, 3>> a, b;
	foreach_cell(finest, [&](MRMap3::Vertex x) {
		const Vec3& p = value<Vec3>(finest, pos, x);
		a.push_back({p[0], p[1], p[2]});
	});
	foreach_cell(flat, [&](CMap3::Vertex x) {
		const Vec3& p = (*fpos)[x];
		b.push_back({p[0], p[1], p[2]});
	});
	std::sort(a.begin(), a.end());
	std::sort(b.begin(), b.end());
	ASSERT_EQ(a.size(), b.size());
	for (std::size_t i = 0; i < a.size(); ++i)
		for (int c = 0; c < 3; ++c)
			EXPECT_NEAR(a[i][c], b[i][c], 1e-12);
}

TEST(AdaptiveHexahedra, APositionOfAnotherMapIsRefused)
{
	MRMap3 m = unit_grid(1);
	CMap3 other;
	add_hexa(other);
	auto p = add_attribute<Vec3, CMap3::Vertex>(other, "position");
	EXPECT_THROW(modeling::refine_hexahedra(
					 m, *p, [](const MRMap3&, MRMap3::Volume) { return true; }, 1),
				 std::invalid_argument);
	EXPECT_EQ(max_level(m), 0u);
}
