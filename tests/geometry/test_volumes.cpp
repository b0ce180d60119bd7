// SPDX-License-Identifier: MIT
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <numbers>

namespace cgogn_test_volumes
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;

constexpr double pi = std::numbers::pi;

TEST(Volumes, BoxIsExactAndSigned)
{
	CMap2 m;
	auto pos = build_with_positions(m, test::box_soup(2, 3, 4));
	EXPECT_NEAR(signed_volume(m, *pos), 24.0, 1e-12);
	foreach_cell(m, [&](CMap2::Volume w) { EXPECT_NEAR(volume(m, w, *pos), 24.0, 1e-12); });
	// far from the origin: the reference point keeps the rounding small
	for (Vec3& p : *pos)
		p += Vec3(1e6, -2e6, 3e6);
	EXPECT_NEAR(signed_volume(m, *pos), 24.0, 1e-6);
	// mirrored: the faces now point inwards
	for (Vec3& p : *pos)
		p.x() = -p.x();
	EXPECT_NEAR(signed_volume(m, *pos), -24.0, 1e-6);
}

TEST(Volumes, OneVolumePerComponent)
{
	CMap2 m;
	build_with_positions(m, test::box_soup(1, 1, 1));
	auto pos = build_with_positions(m, test::box_soup(2, 2, 2));
	std::vector<double> v;
	foreach_cell(m, [&](CMap2::Volume w) { v.push_back(volume(m, w, *pos)); });
	ASSERT_EQ(v.size(), 2u);
	std::sort(v.begin(), v.end());
	EXPECT_NEAR(v[0], 1.0, 1e-12);
	EXPECT_NEAR(v[1], 8.0, 1e-12);
	EXPECT_NEAR(signed_volume(m, *pos), 9.0, 1e-12);
}

template <typename SOUP_FN>
void expect_volume_second_order(SOUP_FN soup, double exact)
{
	double previous = 0.0;
	for (uint32 k = 0; k < 3; ++k)
	{
		const uint32 n = 16u << k;
		CMap2 m;
		auto pos = build_with_positions(m, soup(n));
		const double err = exact - signed_volume(m, *pos);
		EXPECT_GT(err, 0.0); // inscribed in a convex-in-the-mean shape: below
		if (k > 0)
		{
			EXPECT_GT(previous / err, 3.6) << "n = " << n;
			EXPECT_LT(previous / err, 4.4) << "n = " << n;
		}
		previous = err;
	}
	EXPECT_LT(previous, 0.01 * exact);
}

TEST(Volumes, SphereAndTorusConvergeQuadratically)
{
	expect_volume_second_order([](uint32 n) { return sphere_soup(2 * n, n); }, 4.0 * pi / 3.0);
	expect_volume_second_order([](uint32 n) { return sphere_soup(2 * n, n, true); }, 4.0 * pi / 3.0);
	// R = 1, r = 0.5: 2 pi^2 R r^2
	expect_volume_second_order([](uint32 n) { return torus_soup(2 * n, n); }, pi * pi / 2.0);
	expect_volume_second_order([](uint32 n) { return torus_soup(2 * n, n, true); }, pi * pi / 2.0);
}

TEST(Volumes, TetGridIsExact)
{
	CMap3 m;
	auto pos = build_with_positions(m, tet_grid_soup(2, 3, 4));
	double sum = 0.0;
	foreach_cell(m, [&](CMap3::Volume w) {
		const double v = volume(m, w, *pos);
		EXPECT_NEAR(v, 1.0 / 6.0, 1e-14);
		sum += v;
	});
	EXPECT_NEAR(sum, 24.0, 1e-12);
	EXPECT_NEAR(solid_volume(m, *pos), 24.0, 1e-12);
	auto vol = add_attribute<double, CMap3::Volume>(m, "volume");
	compute_volumes(m, *pos, *vol);
	for (double v : *vol)
		EXPECT_NEAR(v, 1.0 / 6.0, 1e-14);
}

TEST(Volumes, HexGridIsExactWithCentroids)
{
	CMap3 m;
	auto pos = build_with_positions(m, hex_grid_soup(3, 2, 2));
	foreach_cell(m, [&](CMap3::Volume w) {
		EXPECT_NEAR(volume(m, w, *pos), 1.0, 1e-14);
		const Vec3 c = centroid(m, w, *pos);
		const Vec3 g = mass_center(m, w, *pos);
		EXPECT_NEAR((c - g).norm(), 0.0, 1e-14);
		const Vec3 frac = c - c.array().floor().matrix();
		EXPECT_NEAR((frac - Vec3(0.5, 0.5, 0.5)).norm(), 0.0, 1e-14);
	});
	EXPECT_NEAR(solid_volume(m, *pos), 12.0, 1e-12);
}

TEST(Volumes, TwistedHexahedraStayConsistent)
{
	// non-planar faces: cell volumes still add up to the volume of the solid
	CMap3 m;
	auto pos = build_with_positions(m, hex_grid_soup(3, 3, 3));
	uint32 i = 0;
	for (Vec3& p : *pos)
		p += 0.2 * Vec3(test::noise(3 * i), test::noise(3 * i + 1), test::noise(3 * i + 2)), ++i;
	double sum = 0.0;
	foreach_cell(m, [&](CMap3::Volume w) {
		const double v = volume(m, w, *pos);
		EXPECT_GT(v, 0.2);
		sum += v;
	});
	EXPECT_NEAR(sum, solid_volume(m, *pos), 1e-12);
}

TEST(Volumes, PyramidAndPrismCells)
{
	// a unit-square-based pyramid of height 3 (volume 1) and a right prism
	// over a triangle of area 1/2 with height 2 (volume 1)
	CMap3 m;
	VolumeSoup s;
	s.nb_vertices = 11;
	s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.3, 0.4, 3}, {5, 0, 0},
				   {6, 0, 0}, {5, 1, 0}, {5, 0, 2}, {6, 0, 2}, {5, 1, 2}};
	s.cell_sizes = {5, 6};
	s.cell_vertices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10};
	auto pos = build_with_positions(m, s);
	std::vector<double> v;
	foreach_cell(m, [&](CMap3::Volume w) { v.push_back(volume(m, w, *pos)); });
	ASSERT_EQ(v.size(), 2u);
	EXPECT_NEAR(v[0], 1.0, 1e-14);
	EXPECT_NEAR(v[1], 1.0, 1e-14);
	EXPECT_NEAR(solid_volume(m, *pos), 2.0, 1e-14);
	// the centre of mass of a pyramid is at a quarter of its height
	foreach_cell(m, [&](CMap3::Volume w) {
		uint32 nb_vertices = 0;
		foreach_incident_vertex(m, w, [&](CMap3::Vertex) { ++nb_vertices; });
		if (nb_vertices == 5)
		{
			const Vec3 g = mass_center(m, w, *pos);
			const Vec3 expected = 0.75 * Vec3(0.5, 0.5, 0) + 0.25 * Vec3(0.3, 0.4, 3);
			EXPECT_NEAR((g - expected).norm(), 0.0, 1e-14);
		}
	});
}

} // namespace cgogn_test_volumes
