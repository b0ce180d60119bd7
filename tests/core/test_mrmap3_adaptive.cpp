// SPDX-License-Identifier: MIT
// Multiresolution 3-maps: adaptive subdivision and coarsening of hexahedra,
// balance, attributes, random sequences with integrity at every level.
#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "volume_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <random>
#include <stdexcept>
#include <tuple>
#include <vector>

using namespace cgogn;

namespace
{

/// The hexahedral grid of a x b x c unit cells, with its positions.
MRMap3 adaptive_grid(uint32 a, uint32 b, uint32 c)
{
	return MRMap3(test::hex_grid_with_positions(a, b, c));
}

void expect_mr3_valid(const MRMap3& m)
{
	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.ok()) << r.to_string();
}

/// The labels of the darts of the finest map, as a sorted multiset.
std::vector<std::array<uint32, 3>> sorted_labels(const MRMap3& m)
{
	const detail::MRState3& s = detail::mr_state_of(m);
	std::vector<std::array<uint32, 3>> r;
	foreach_dart(finest_map(m), [&](Dart d) {
		r.push_back({dart_level(m, d), (*s.edge_id)[d.index], (*s.face_id)[d.index]});
	});
	std::sort(r.begin(), r.end());
	return r;
}

/// Whether the leaves (the volumes of the finest level) sharing an edge
/// differ by at most one level.
bool edge_balanced(const MRMap3& m)
{
	const MRLevelView3 v = level_view(m, max_level(m));
	const CMap3& finest = finest_map(m);
	// the level of each leaf, on its darts
	std::vector<uint32> level(detail::state_of(finest).darts->end_index(), 0);
	foreach_cell(v, [&](MRMap3::Volume w) {
		const uint32 k = volume_level(v, w);
		foreach_dart_of_orbit(finest, CMap3::Volume(w.dart), [&](Dart d) { level[d.index] = k; });
	});
	bool ok = true;
	foreach_cell(finest, [&](CMap3::Edge e) {
		uint32 lo = 255, hi = 0;
		foreach_dart_of_orbit(finest, e, [&](Dart d) {
			if (!is_boundary(finest, d))
			{
				lo = std::min(lo, level[d.index]);
				hi = std::max(hi, level[d.index]);
			}
		});
		ok = hi - lo <= 1;
		return ok;
	});
	return ok;
}

/// Every volume of the current level, by a dart.
std::vector<MRMap3::Volume> volumes_of(const MRLevelView3& v)
{
	std::vector<MRMap3::Volume> r;
	foreach_cell(v, [&](MRMap3::Volume w) { r.push_back(w); });
	return r;
}

/// The corner positions of volume w at the level of v, sorted.
std::vector<std::array<double, 3>> corner_points(const MRLevelView3& v, const AttributeArray<Vec3>& pos,
												 MRMap3::Volume w)
{
	std::vector<std::array<double, 3>> r;
	foreach_incident_vertex(v, w, [&](MRMap3::Vertex x) {
		const Vec3& p = value<Vec3>(v, pos, x);
		r.push_back({p[0], p[1], p[2]});
	});
	std::sort(r.begin(), r.end());
	return r;
}

} // namespace

TEST(MRMap3Adaptive, SubdivideAndCoarsenOneHexahedron)
{
	MRMap3 m = adaptive_grid(1, 1, 1);
	auto pos = get_attribute<Vec3, MRMap3::Vertex>(m, "position");
	auto tag = add_attribute<uint32, MRMap3::Volume>(m, "tag");
	auto ftag = add_attribute<uint32, MRMap3::Face>(m, "ftag");
	const MRMap3::Volume w = volumes_of(level_view(m, 0))[0];
	value<uint32>(m, tag, w) = 7;
	uint32 t = 0;
	foreach_cell(m, [&](MRMap3::Face f) { value<uint32>(m, ftag, f) = ++t; });
	const auto labels = sorted_labels(m);
	EXPECT_EQ(volume_level(m, w), 0u);
	EXPECT_FALSE(volume_is_subdivided(m, w));

	subdivide_volume(m, w);
	expect_mr3_valid(m);
	EXPECT_EQ(max_level(m), 1u);
	EXPECT_EQ(current_level(m), 0u);
	EXPECT_TRUE(volume_is_subdivided(m, w));
	EXPECT_THROW(subdivide_volume(m, w), std::invalid_argument);
	foreach_incident_face(m, w, [&](MRMap3::Face f) { EXPECT_TRUE(face_is_subdivided(m, f)); });
	foreach_incident_edge(m, w, [&](MRMap3::Edge e) { EXPECT_TRUE(edge_is_subdivided(m, e)); });
	// the same level as one regular Hexahedral level
	const MRLevelView3 v1 = level_view(m, 1);
	EXPECT_EQ(f_vector(v1), (std::vector<uint32>{27, 54, 36, 8}));
	EXPECT_EQ(nb_darts(finest_map(m)), 24u * 8u + 24u * 4u);
	EXPECT_EQ(nb_darts_at_level(m, 0) + nb_darts_at_level(m, 1), nb_darts(finest_map(m)));
	// the children: level 1, copies of the parent's value, trilinear corners
	for (MRMap3::Volume c : volumes_of(v1))
	{
		EXPECT_EQ(volume_level(v1, c), 1u);
		EXPECT_FALSE(volume_is_subdivided(v1, c));
		EXPECT_EQ(value<uint32>(v1, tag, c), 7u);
		EXPECT_NE(index_of(v1, c), index_of(m, w));
		const auto corners = corner_points(v1, *pos, c);
		ASSERT_EQ(corners.size(), 8u);
		for (uint32 i = 0; i < 3; ++i)
			EXPECT_DOUBLE_EQ(corners.back()[i] - corners.front()[i], 0.5);
	}
	// each face of the parent: 4 children with the parent's value
	foreach_cell(v1, [&](MRMap3::Face f) {
		if (face_level(v1, f) == 1)
		{
			bool inner = true;
			foreach_dart_of_orbit(v1, f, [&](Dart d) { inner = inner && dart_level(m, d) == 1; });
			if (inner)
				EXPECT_EQ(value<uint32>(v1, ftag, f), 0u);
			else
				EXPECT_GE(value<uint32>(v1, ftag, f), 1u);
		}
	});

	ASSERT_TRUE(can_coarsen_volume(m, w));
	coarsen_volume(m, w);
	expect_mr3_valid(m);
	EXPECT_EQ(max_level(m), 0u);
	EXPECT_EQ(nb_darts(finest_map(m)), 48u);
	EXPECT_EQ(f_vector(m), (std::vector<uint32>{8, 12, 6, 1}));
	EXPECT_EQ(sorted_labels(m), labels);
	EXPECT_EQ(value<uint32>(m, tag, w), 7u);
	t = 0;
	foreach_cell(m, [&](MRMap3::Face f) { EXPECT_EQ(value<uint32>(m, ftag, f), ++t); });
	EXPECT_FALSE(can_coarsen_volume(m, w));
}

TEST(MRMap3Adaptive, SubdividingEveryVolumeGivesTheRegularLevel)
{
	MRMap3 adaptive = adaptive_grid(2, 2, 1), regular = adaptive_grid(2, 2, 1);
	auto pos_a = get_attribute<Vec3, MRMap3::Vertex>(adaptive, "position");
	auto pos_r = get_attribute<Vec3, MRMap3::Vertex>(regular, "position");
	for (uint32 k = 0; k < 2; ++k)
	{
		set_current_level(adaptive, k);
		for (MRMap3::Volume w : volumes_of(level_view(adaptive, k)))
			subdivide_volume(adaptive, w);
		add_level(regular, Refinement::Hexahedral);
		expect_mr3_valid(adaptive);
		for (uint32 l = 0; l <= k + 1; ++l)
		{
			const MRLevelView3 va = level_view(adaptive, l), vr = level_view(regular, l);
			EXPECT_EQ(f_vector(va), f_vector(vr)) << "level " << l;
			EXPECT_EQ(nb_darts(va), nb_darts(vr)) << "level " << l;
			std::vector<std::array<double, 3>> pa, pr;
			foreach_cell(va, [&](MRMap3::Vertex x) {
				const Vec3& p = value<Vec3>(va, pos_a, x);
				pa.push_back({p[0], p[1], p[2]});
			});
			foreach_cell(vr, [&](MRMap3::Vertex x) {
				const Vec3& p = value<Vec3>(vr, pos_r, x);
				pr.push_back({p[0], p[1], p[2]});
			});
			std::sort(pa.begin(), pa.end());
			std::sort(pr.begin(), pr.end());
			EXPECT_EQ(pa, pr) << "level " << l;
		}
	}
	// and coarsening everything gives the grid back
	for (uint32 k = 2; k-- > 0;)
	{
		set_current_level(adaptive, k);
		for (MRMap3::Volume w : volumes_of(level_view(adaptive, k)))
		{
			ASSERT_TRUE(can_coarsen_volume(adaptive, w));
			coarsen_volume(adaptive, w);
		}
		expect_mr3_valid(adaptive);
		EXPECT_EQ(max_level(adaptive), k);
	}
	EXPECT_EQ(f_vector(adaptive), (std::vector<uint32>{18, 33, 20, 4}));
	EXPECT_EQ(nb_darts(finest_map(adaptive)), 4u * 24u + 16u * 4u);
}

TEST(MRMap3Adaptive, BalanceKeepsLeavesWithinOneLevel)
{
	MRMap3 m = adaptive_grid(3, 3, 3);
	// the same corner refined 3 times: the volumes around follow
	Dart d = volumes_of(level_view(m, 0))[0].dart;
	for (uint32 k = 0; k < 3; ++k)
	{
		set_current_level(m, max_level(m));
		subdivide_volume(m, MRMap3::Volume(d));
		expect_mr3_valid(m);
		EXPECT_TRUE(edge_balanced(m)) << "after " << k + 1;
	}
	EXPECT_EQ(max_level(m), 3u);
	// the volumes around the corner were refined to keep the balance
	EXPECT_GT(nb_cells<MRMap3::Volume>(level_view(m, 1)), 27u + 7u);
	// a parent of a parent cannot be coarsened
	set_current_level(m, 0);
	EXPECT_FALSE(can_coarsen_volume(m, MRMap3::Volume(d)));
	set_current_level(m, 2);
	EXPECT_TRUE(can_coarsen_volume(m, MRMap3::Volume(d)));
}

TEST(MRMap3Adaptive, WithoutBalanceACoarseNeighbourIsRefusedLater)
{
	MRMap3 m = adaptive_grid(3, 1, 1);
	auto pos = get_attribute<Vec3, MRMap3::Vertex>(m, "position");
	// the middle volume and then its child at x = 1 (next to the first volume)
	std::vector<MRMap3::Volume> row = volumes_of(level_view(m, 0));
	const auto x_min = [&](MRMap3::Volume w) { return corner_points(level_view(m, 0), *pos, w).front()[0]; };
	std::sort(row.begin(), row.end(), [&](auto a, auto b) { return x_min(a) < x_min(b); });
	subdivide_volume(m, row[1], false);
	set_current_level(m, 1);
	MRMap3::Volume child;
	foreach_cell(m, [&](MRMap3::Volume w) {
		const auto c = corner_points(level_view(m, 1), *pos, w);
		if (volume_level(m, w) == 1 && c.front() == std::array<double, 3>{1, 0, 0})
			child = w;
	});
	ASSERT_TRUE(child.dart.is_valid());
	subdivide_volume(m, child, false);
	expect_mr3_valid(m);
	EXPECT_FALSE(edge_balanced(m));
	// the first volume's surface now holds cuts two levels finer than it
	set_current_level(m, 0);
	const uint32 darts = nb_darts(finest_map(m));
	EXPECT_THROW(subdivide_volume(m, row[0]), std::invalid_argument);
	EXPECT_EQ(nb_darts(finest_map(m)), darts);
	expect_mr3_valid(m);
	// with balance from the start, the first volume is refined first
	MRMap3 b = adaptive_grid(3, 1, 1);
	subdivide_volume(b, volumes_of(level_view(b, 0))[1]);
	set_current_level(b, 1);
	for (MRMap3::Volume w : volumes_of(level_view(b, 1)))
		if (volume_level(b, w) == 1)
			subdivide_volume(b, w);
	expect_mr3_valid(b);
	EXPECT_TRUE(edge_balanced(b));
}

TEST(MRMap3Adaptive, RefusalsLeaveTheMapUnchanged)
{
	CMap3 tets;
	add_tetra(tets);
	MRMap3 t(std::move(tets));
	const uint32 tet_darts = nb_darts(finest_map(t));
	EXPECT_THROW(subdivide_volume(t, volumes_of(level_view(t, 0))[0]), std::invalid_argument);
	EXPECT_EQ(max_level(t), 0u);
	EXPECT_EQ(nb_darts(finest_map(t)), tet_darts);
	expect_mr3_valid(t);
	// add_level refuses a finest level with volumes of several levels
	MRMap3 m = adaptive_grid(2, 1, 1);
	subdivide_volume(m, volumes_of(level_view(m, 0))[0]);
	const uint32 darts = nb_darts(finest_map(m));
	EXPECT_THROW(add_level(m, Refinement::Hexahedral), std::invalid_argument);
	EXPECT_EQ(nb_darts(finest_map(m)), darts);
	// remove_finest_level takes the adaptive level away
	remove_finest_level(m);
	expect_mr3_valid(m);
	EXPECT_EQ(f_vector(m), (std::vector<uint32>{12, 20, 11, 2}));
}

TEST(MRMap3Adaptive, RandomRefinementAndCoarsening)
{
	MRMap3 m = adaptive_grid(2, 2, 1);
	auto pos = get_attribute<Vec3, MRMap3::Vertex>(m, "position");
	add_attribute<uint32, MRMap3::Edge>(m, "e");
	add_attribute<uint32, MRMap3::Face>(m, "f");
	add_attribute<uint32, MRMap3::Volume>(m, "w");
	std::mt19937 rng(5u);
	uint32 subdivisions = 0, coarsenings = 0;
	for (uint32 step = 0; step < 1000; ++step)
	{
		const bool refine = std::uniform_int_distribution<int>(0, 9)(rng) < 6 || max_level(m) == 0;
		if (refine)
		{
			set_current_level(m, max_level(m));
			std::vector<MRMap3::Volume> leaves;
			foreach_cell(m, [&](MRMap3::Volume w) {
				if (volume_level(m, w) < 2)
					leaves.push_back(w);
			});
			if (leaves.empty())
				continue;
			subdivide_volume(m, leaves[std::uniform_int_distribution<std::size_t>(0, leaves.size() - 1)(rng)]);
			++subdivisions;
		}
		else
		{
			std::vector<std::pair<uint32, MRMap3::Volume>> parents;
			for (uint32 k = 0; k < max_level(m); ++k)
			{
				set_current_level(m, k);
				foreach_cell(m, [&](MRMap3::Volume w) {
					if (can_coarsen_volume(m, w))
						parents.emplace_back(k, w);
				});
			}
			if (parents.empty())
				continue;
			const auto [k, w] = parents[std::uniform_int_distribution<std::size_t>(0, parents.size() - 1)(rng)];
			set_current_level(m, k);
			coarsen_volume(m, w);
			++coarsenings;
		}
		const IntegrityReport report = check_integrity(m);
		ASSERT_TRUE(report.ok()) << "step " << step << ": " << report.to_string();
		ASSERT_TRUE(edge_balanced(m)) << "step " << step;
		uint32 sum = 0;
		for (uint32 l = 0; l <= max_level(m); ++l)
			sum += nb_darts_at_level(m, l);
		ASSERT_EQ(sum, nb_darts(finest_map(m)));
		ASSERT_GT(nb_darts_at_level(m, max_level(m)), 0u);
		const MRLevelView3 finest = level_view(m, max_level(m));
		ASSERT_EQ(euler_characteristic(finest), 1);
		// every leaf is a box of side 2^-level with grid-aligned corners
		for (MRMap3::Volume w : volumes_of(finest))
		{
			const auto c = corner_points(finest, *pos, w);
			const double side = 1.0 / double(1u << volume_level(finest, w));
			for (uint32 i = 0; i < 3; ++i)
				ASSERT_DOUBLE_EQ(c.back()[i] - c.front()[i], side) << "step " << step;
		}
	}
	EXPECT_GT(subdivisions, 300u);
	EXPECT_GT(coarsenings, 100u);
}
