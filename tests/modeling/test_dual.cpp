// SPDX-License-Identifier: MIT
#include "../geometry/geometry_test_meshes.h"
#include "modeling_test_utils.h"

namespace cgogn_test_dual
{

using namespace cgogn;
using namespace cgogn::modeling_test;

namespace
{

struct Counts
{
	uint32 v, e, f;
	bool operator==(const Counts&) const = default;
};

Counts counts(const CMap2& m)
{
	return {nb_cells<CMap2::Vertex>(m), nb_cells<CMap2::Edge>(m), nb_cells<CMap2::Face>(m)};
}

} // namespace

TEST(Dual, CubeAndOctahedron)
{
	CMap2 cube;
	auto pos = test::build_with_positions(cube, test::box_soup(2.0, 2.0, 2.0));
	CMap2 octa;
	auto opos = modeling::dual(cube, *pos, octa);
	EXPECT_TRUE(check_integrity(octa).ok());
	EXPECT_EQ(counts(octa), (Counts{6, 12, 8}));
	foreach_cell(octa, [&](CMap2::Face f) { EXPECT_EQ(codegree(octa, f), 3u); });
	foreach_cell(octa, [&](CMap2::Vertex v) {
		EXPECT_EQ(degree(octa, v), 4u);
		// a face centre of the cube [0, 2]^3: one coordinate 0 or 2, the others 1
		const Vec3 p = (*opos)[index_of(octa, v)] - Vec3(1, 1, 1);
		EXPECT_NEAR(p.cwiseAbs().sum(), 1.0, 1e-15);
		EXPECT_NEAR(p.cwiseAbs().maxCoeff(), 1.0, 1e-15);
	});
	// the octahedron |x| + |y| + |z| <= 1: volume 4/3, faces outwards
	EXPECT_NEAR(geometry::signed_volume(octa, *opos), 4.0 / 3.0, 1e-12);

	CMap2 back;
	auto bpos = modeling::dual(octa, *opos, back);
	EXPECT_TRUE(check_integrity(back).ok());
	EXPECT_EQ(counts(back), (Counts{8, 12, 6}));
	foreach_cell(back, [&](CMap2::Face f) { EXPECT_EQ(codegree(back, f), 4u); });
	// the octahedron's face centres: the cube (+-1/3)^3 around (1, 1, 1)
	EXPECT_NEAR(geometry::signed_volume(back, *bpos), 8.0 / 27.0, 1e-12);
}

TEST(Dual, TetrahedronIsSelfDual)
{
	CMap2 m;
	if (!load_data(m, "tetrahedron.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/tetrahedron.off");
	auto pos = positions(m);
	CMap2 d;
	auto dpos = modeling::dual(m, *pos, d);
	EXPECT_TRUE(check_integrity(d).ok());
	EXPECT_EQ(counts(d), (Counts{4, 6, 4}));
	EXPECT_EQ(geometry::signed_volume(d, *dpos) > 0.0, geometry::signed_volume(m, *pos) > 0.0);
}

TEST(Dual, SpotControlMeshSwapsVerticesAndFaces)
{
	CMap2 m;
	if (!load_data(m, "spot_control_mesh.obj"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/spot_control_mesh.obj");
	auto pos = positions(m);
	CMap2 d;
	auto dpos = modeling::dual(m, *pos, d);
	EXPECT_TRUE(check_integrity(d).ok());
	EXPECT_EQ(counts(m), (Counts{188, 366, 180}));
	EXPECT_EQ(counts(d), (Counts{180, 366, 188}));
	// face degrees of the dual are the vertex degrees of the primal
	std::vector<uint32> primal, dual;
	foreach_cell(m, [&](CMap2::Vertex v) { primal.push_back(degree(m, v)); });
	foreach_cell(d, [&](CMap2::Face f) { dual.push_back(codegree(d, f)); });
	std::sort(primal.begin(), primal.end());
	std::sort(dual.begin(), dual.end());
	EXPECT_EQ(primal, dual);
	EXPECT_GT(geometry::signed_volume(d, *dpos), 0.0);
}

TEST(Dual, ElephantKeepsEulerCharacteristicAndGenus)
{
	CMap2 m;
	if (!load_data(m, "refined_elephant.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/refined_elephant.off");
	auto pos = positions(m);
	ASSERT_EQ(euler_characteristic(m), -4) << "genus 3";
	CMap2 d;
	auto dpos = modeling::dual(m, *pos, d);
	EXPECT_TRUE(check_integrity(d).ok());
	EXPECT_EQ(counts(d), (Counts{nb_cells<CMap2::Face>(m), nb_cells<CMap2::Edge>(m), nb_cells<CMap2::Vertex>(m)}));
	EXPECT_EQ(euler_characteristic(d), -4);
	EXPECT_EQ(nb_connected_components(d), 1u);
	EXPECT_EQ(nb_boundary_components(d), 0u);
	CMap2 dd;
	modeling::dual(d, *dpos, dd);
	EXPECT_EQ(counts(dd), counts(m));
	EXPECT_TRUE(check_integrity(dd).ok());
}

TEST(Dual, SurfaceWithBoundaryIsRejected)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, test::polygon_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
	CMap2 out;
	EXPECT_THROW(modeling::dual(m, *pos, out), TopologyError);
	EXPECT_EQ(nb_darts(out), 0u) << "nothing appended";
}

TEST(Dual, OutputWithANonVec3PositionIsRejectedBeforeAnythingIsAppended)
{
	CMap2 cube;
	auto pos = test::build_with_positions(cube, test::box_soup(2.0, 2.0, 2.0));
	CMap2 out;
	add_attribute<double, CMap2::Vertex>(out, "position");
	EXPECT_THROW(modeling::dual(cube, *pos, out), Error);
	EXPECT_EQ(nb_darts(out), 0u);
}

} // namespace cgogn_test_dual
