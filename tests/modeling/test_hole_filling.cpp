// SPDX-License-Identifier: MIT
#include "../geometry/geometry_test_meshes.h"
#include "modeling_test_utils.h"

#include <set>

namespace cgogn_test_hole_filling
{

using namespace cgogn;
using namespace cgogn::modeling_test;

namespace
{

std::set<uint32> vertex_lines(const CMap2& m)
{
	std::set<uint32> lines;
	foreach_cell(m, [&](CMap2::Vertex v) { lines.insert(index_of(m, v)); });
	return lines;
}

/// Counts, closedness, Euler characteristic and integrity after fill_holes.
void expect_consistent_fill(const CMap2& m, uint32 nv, uint32 nf, int64_t chi, const modeling::HoleFillingResult& r)
{
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), nv + r.vertices_added);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), nf + r.faces_added);
	// each filled hole glues a disk: chi grows by one
	EXPECT_EQ(euler_characteristic(m), chi + r.holes_filled);
	EXPECT_EQ(nb_boundary_components(m), r.holes_found - r.holes_filled);
	foreach_cell(m, [&](CMap2::Face f) { EXPECT_LE(codegree(m, f), 3u); });
}

} // namespace

// hemisphere.off is a cap of the unit sphere (z >= 0.098) around the origin.
// Fairing pulls the patch from the flat disk of the boundary circle towards
// the missing cap: the bi-harmonic patch (tangent continuity) dips to
// z = -0.35, the tri-harmonic one to z = -0.62 (the sphere reaches -1: a
// faired patch is a smooth, not a round, fill).
TEST(HoleFilling, HemisphereBecomesASphere)
{
	struct Case
	{
		bool fair;
		uint32 continuity;
		double max_lowest_z;  // the lowest new vertex is below this
		double min_lowest_z;  // and above this
		double max_deviation; // from the unit sphere, over the new vertices
	};
	for (const Case c :
		 {Case{false, 1, 0.11, 0.09, 0.9}, Case{true, 1, -0.3, -0.4, 0.7}, Case{true, 2, -0.55, -0.7, 0.45}})
	{
		CMap2 m;
		if (!load_data(m, "hemisphere.off"))
			GTEST_SKIP() << cgogn_test_data::missing_large("surface/hemisphere.off");
		auto pos = positions(m);
		ASSERT_EQ(boundary_loop_sizes(m), std::vector<uint32>{120u});
		foreach_cell(m, [&](CMap2::Vertex v) { ASSERT_NEAR((*pos)[index_of(m, v)].norm(), 1.0, 1e-5); });
		const uint32 nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
		const std::set<uint32> old = vertex_lines(m);

		modeling::HoleFillingOptions o;
		o.fair = c.fair;
		o.fairing_continuity = c.continuity;
		const auto r = modeling::fill_holes(m, *pos, o);
		EXPECT_EQ(r.holes_found, 1u);
		EXPECT_EQ(r.holes_filled, 1u);
		EXPECT_FALSE(r.cancelled);
		EXPECT_EQ(r.fairing_failures, 0u);
		EXPECT_GT(r.vertices_added, 500u) << "refined to the density around the hole";
		EXPECT_EQ(r.faces_added, 118u + 2u * r.vertices_added);
		expect_consistent_fill(m, nv, nf, 1, r);
		EXPECT_EQ(euler_characteristic(m), 2);
		EXPECT_EQ(nb_boundary_components(m), 0u);
		EXPECT_EQ(nb_multiple_edges(m), 0u);
		EXPECT_GT(geometry::signed_volume(m, *pos), 0.0) << "new faces oriented like the surface";

		double deviation = 0.0, lowest = 1.0;
		foreach_cell(m, [&](CMap2::Vertex v) {
			if (old.count(index_of(m, v)))
				return;
			const Vec3& p = (*pos)[index_of(m, v)];
			deviation = std::max(deviation, std::abs(p.norm() - 1.0));
			lowest = std::min(lowest, p.z());
			EXPECT_LT(p.norm(), 1.001) << "no bulge out of the sphere";
		});
		EXPECT_LT(lowest, c.max_lowest_z);
		EXPECT_GT(lowest, c.min_lowest_z);
		EXPECT_LT(deviation, c.max_deviation);
	}
}

TEST(HoleFilling, WithoutRefinementOnlyTriangles)
{
	CMap2 m;
	if (!load_data(m, "hemisphere.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/hemisphere.off");
	auto pos = positions(m);
	const uint32 nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
	modeling::HoleFillingOptions o;
	o.refine = false;
	const auto r = modeling::fill_holes(m, *pos, o);
	EXPECT_EQ(r.vertices_added, 0u);
	EXPECT_EQ(r.faces_added, 118u);
	expect_consistent_fill(m, nv, nf, 1, r);
	EXPECT_EQ(nb_multiple_edges(m), 0u);
}

TEST(HoleFilling, ElephantAllHoles)
{
	CMap2 m;
	if (!load_data(m, "elephant-with-holes.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/elephant-with-holes.off");
	auto pos = positions(m);
	const std::vector<uint32> sizes = boundary_loop_sizes(m);
	ASSERT_EQ(sizes.size(), 106u);
	const uint32 nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
	const int64_t chi = euler_characteristic(m);
	const uint32 multiple = nb_multiple_edges(m);
	std::vector<double> progress;
	const auto r = modeling::fill_holes(m, *pos, {}, [&](double f) {
		progress.push_back(f);
		return true;
	});
	EXPECT_EQ(r.holes_found, 106u);
	EXPECT_EQ(r.holes_filled, uint32(std::count_if(sizes.begin(), sizes.end(), [](uint32 n) { return n >= 3; })));
	EXPECT_FALSE(r.cancelled);
	expect_consistent_fill(m, nv, nf, chi, r);
	EXPECT_EQ(nb_multiple_edges(m), multiple) << "no edge doubles an existing one";
	ASSERT_FALSE(progress.empty());
	EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
	EXPECT_EQ(progress.back(), 1.0);
	EXPECT_LE(progress.size(), 600u) << "throttled";
}

TEST(HoleFilling, MaxSizeLeavesLargeHolesOpen)
{
	CMap2 m;
	if (!load_data(m, "elephant-with-holes.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/elephant-with-holes.off");
	auto pos = positions(m);
	const std::vector<uint32> sizes = boundary_loop_sizes(m);
	const uint32 nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
	const int64_t chi = euler_characteristic(m);
	modeling::HoleFillingOptions o;
	o.max_hole_size = 10;
	const auto r = modeling::fill_holes(m, *pos, o);
	const uint32 small = uint32(std::count_if(sizes.begin(), sizes.end(), [](uint32 n) { return n >= 3 && n <= 10; }));
	EXPECT_GT(small, 0u);
	EXPECT_LT(small, 106u);
	EXPECT_EQ(r.holes_filled, small);
	EXPECT_EQ(r.holes_skipped, 106u - small);
	expect_consistent_fill(m, nv, nf, chi, r);
	for (uint32 n : boundary_loop_sizes(m))
		EXPECT_GT(n, 10u);
}

TEST(HoleFilling, EarClippingAboveTheOptimalSize)
{
	CMap2 m;
	if (!load_data(m, "hemisphere.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/hemisphere.off");
	auto pos = positions(m);
	const uint32 nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
	modeling::HoleFillingOptions o;
	o.max_optimal_size = 100;
	const auto r = modeling::fill_holes(m, *pos, o);
	EXPECT_EQ(r.holes_ear_clipped, 1u);
	expect_consistent_fill(m, nv, nf, 1, r);
	EXPECT_EQ(euler_characteristic(m), 2);
}

TEST(HoleFilling, StanfordBunny)
{
	CMap2 m;
	if (!load_data(m, "stanford-bunny.obj"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/stanford-bunny.obj");
	auto pos = positions(m);
	ASSERT_EQ(boundary_loop_sizes(m).size(), 5u);
	const uint32 nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
	const int64_t chi = euler_characteristic(m);
	const auto r = modeling::fill_holes(m, *pos);
	EXPECT_EQ(r.holes_filled, 5u);
	EXPECT_EQ(r.fairing_failures, 0u);
	expect_consistent_fill(m, nv, nf, chi, r);
	EXPECT_EQ(nb_boundary_components(m), 0u);
	EXPECT_EQ(euler_characteristic(m), 2) << "the bunny is a sphere once closed";
	EXPECT_EQ(nb_multiple_edges(m), 0u);
}

TEST(HoleFilling, LShapeGetsAFlatBackFace)
{
	for (const bool refine : {false, true})
	{
		CMap2 m;
		if (!load_data(m, "L.off"))
			GTEST_SKIP() << cgogn_test_data::missing_large("surface/L.off");
		auto pos = positions(m);
		modeling::HoleFillingOptions o;
		o.refine = refine;
		const auto r = modeling::fill_holes(m, *pos, o);
		EXPECT_EQ(r.holes_filled, 1u);
		EXPECT_TRUE(check_integrity(m).ok());
		EXPECT_EQ(nb_boundary_components(m), 0u);
		EXPECT_EQ(euler_characteristic(m), 2);
		if (!refine)
		{
			EXPECT_EQ(nb_cells<CMap2::Vertex>(m), 6u);
			EXPECT_EQ(nb_cells<CMap2::Edge>(m), 9u);
			EXPECT_EQ(nb_cells<CMap2::Face>(m), 5u);
		}
		// the back of the hexagon (area 3, facing +z) is covered exactly once, facing -z
		double back_area = 0.0;
		foreach_cell(m, [&](CMap2::Face f) {
			const Vec3 n = geometry::newell_vector(m, *pos, f.dart);
			if (codegree(m, f) == 3)
			{
				EXPECT_LT(n.z(), 0.0);
				back_area += 0.5 * n.norm();
			}
		});
		EXPECT_NEAR(back_area, 3.0, 1e-12);
	}
}

TEST(HoleFilling, SingleTriangle)
{
	CMap2 m;
	if (!load_data(m, "triangle.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/triangle.off");
	auto pos = positions(m);
	const auto r = modeling::fill_holes(m, *pos);
	EXPECT_EQ(r.holes_filled, 1u);
	EXPECT_EQ(r.faces_added, 1u);
	EXPECT_EQ(r.vertices_added, 0u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 2u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 3u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_boundary_components(m), 0u);
}

TEST(HoleFilling, OneHoleByDart)
{
	CMap2 m;
	if (!load_data(m, "stanford-bunny.obj"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/stanford-bunny.obj");
	auto pos = positions(m);
	Dart boundary;
	foreach_dart(m, [&](Dart d) {
		boundary = d;
		return !is_boundary(m, d);
	});
	const auto r = modeling::fill_hole(m, *pos, boundary);
	EXPECT_EQ(r.holes_found, 1u);
	EXPECT_EQ(r.holes_filled, 1u);
	EXPECT_EQ(nb_boundary_components(m), 4u);
	EXPECT_TRUE(check_integrity(m).ok());
	// a dart of a real face is not a hole
	Dart inner;
	foreach_dart(m, [&](Dart d) {
		inner = d;
		return is_boundary(m, d);
	});
	EXPECT_THROW(modeling::fill_hole(m, *pos, inner), TopologyError);
}

TEST(HoleFilling, CancellationLeavesAValidMap)
{
	for (const uint32 calls : {0u, 1u, 5u, 40u})
	{
		CMap2 m;
		if (!load_data(m, "elephant-with-holes.off"))
			GTEST_SKIP() << cgogn_test_data::missing_large("surface/elephant-with-holes.off");
		auto pos = positions(m);
		const uint32 nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
		const int64_t chi = euler_characteristic(m);
		uint32 n = 0;
		const auto r = modeling::fill_holes(m, *pos, {}, [&](double) { return n++ < calls; });
		EXPECT_TRUE(r.cancelled) << calls;
		EXPECT_LT(r.holes_filled, 106u);
		if (calls == 0)
		{
			EXPECT_EQ(r.holes_filled, 0u);
		}
		expect_consistent_fill(m, nv, nf, chi, r);
	}
}

TEST(HoleFilling, AvoidsDiagonalsThatExistOutside)
{
	// two triangles (a, b, c), (a, c, d): their back is a hole of loop a, d, c,
	// b whose diagonal a-c already exists; every quad shape, even one where
	// a-c is the better diagonal for the back, must get b-d
	for (const double lift : {0.0, 0.5, -0.5})
	{
		CMap2 m;
		auto pos = test::build_with_positions(
			m, test::polygon_soup({{0, 0, 0}, {1, 0, lift}, {1, 1, 0}, {0, 1, lift}}, {{0, 1, 2}, {0, 2, 3}}));
		modeling::HoleFillingOptions o;
		o.refine = false;
		const auto r = modeling::fill_holes(m, *pos, o);
		EXPECT_EQ(r.holes_filled, 1u);
		EXPECT_TRUE(check_integrity(m).ok());
		EXPECT_EQ(nb_multiple_edges(m), 0u) << lift;
		EXPECT_EQ(nb_cells<CMap2::Edge>(m), 6u);
		EXPECT_EQ(nb_cells<CMap2::Face>(m), 4u);
		foreach_cell(m, [&](CMap2::Vertex v) { EXPECT_EQ(degree(m, v), 3u) << "a tetrahedron"; });
	}
}

} // namespace cgogn_test_hole_filling
