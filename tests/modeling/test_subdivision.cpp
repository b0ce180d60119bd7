// SPDX-License-Identifier: MIT
#include <cgogn/cgogn.h>

#include "../geometry/geometry_test_meshes.h"
#include "modeling_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <vector>

namespace cgogn_test_subdivision
{

using namespace cgogn;
using namespace cgogn::modeling_test;
using test::polygon_soup;

namespace
{

using Vertex = CMap2::Vertex;

void load(CMap2& m, const std::string& path)
{
	io::load_surface(m, path);
}
void load(CMap3& m, const std::string& path)
{
	io::load_volume(m, path);
}

/// Loads a data file, or skips the test, naming the file, when it is a large
/// one that is not available.
#define LOAD_OR_SKIP(MAP, NAME)                                                                                        \
	CGOGN_DATA_PATH_OR_SKIP(path_##MAP, NAME);                                                                         \
	load(MAP, path_##MAP)

std::vector<Vec3> tetrahedron_points()
{
	return {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
}

SurfaceSoup tetrahedron_soup()
{
	return polygon_soup(tetrahedron_points(), {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}});
}

/// Every expected point is the position of exactly one vertex (to 1e-14),
/// and there are as many vertices as expected points.
void expect_positions(const CMap2& m, const AttributeArray<Vec3>& pos, const std::vector<Vec3>& expected)
{
	EXPECT_EQ(nb_cells<Vertex>(m), expected.size());
	for (const Vec3& p : expected)
	{
		uint32 close = 0;
		foreach_cell(m, [&](Vertex v) { close += (value<Vec3>(m, pos, v) - p).norm() < 1e-14 ? 1 : 0; });
		EXPECT_EQ(close, 1u) << "expected a vertex at " << p.transpose();
	}
}

bool all_faces_of_degree(const CMap2& m, uint32 k)
{
	bool ok = true;
	foreach_cell(m, [&](CMap2::Face f) { ok = ok && codegree(m, f) == k; });
	return ok;
}

/// The positions around the boundary face of d, starting at d's origin.
std::vector<Vec3> boundary_loop(const CMap2& m, const AttributeArray<Vec3>& pos, Dart d)
{
	std::vector<Vec3> loop;
	Dart x = d;
	do
	{
		loop.push_back(value<Vec3>(m, pos, Vertex(x)));
		x = phi1(m, x);
	} while (x != d);
	return loop;
}

Dart some_boundary_dart(const CMap2& m)
{
	Dart found;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			found = d;
		return !found.is_valid();
	});
	return found;
}

/// The boundary after Loop or Catmull-Clark: old boundary vertices at
/// 1/8 q0 + 3/4 p + 1/8 q1, boundary edges cut at their midpoints.
void expect_crease_rule(const std::vector<Vec3>& before, const std::vector<Vec3>& after)
{
	const std::size_t k = before.size();
	ASSERT_EQ(after.size(), 2 * k);
	for (std::size_t i = 0; i < k; ++i)
	{
		const Vec3& prev = before[(i + k - 1) % k];
		const Vec3& next = before[(i + 1) % k];
		EXPECT_LT((after[2 * i] - (0.125 * prev + 0.75 * before[i] + 0.125 * next)).norm(), 1e-14);
		EXPECT_LT((after[2 * i + 1] - 0.5 * (before[i] + next)).norm(), 1e-14);
	}
}

struct Counts
{
	uint32 v, e, f;
};
Counts counts(const CMap2& m)
{
	return {nb_cells<Vertex>(m), nb_cells<CMap2::Edge>(m), nb_cells<CMap2::Face>(m)};
}

} // namespace

// ---- Loop

TEST(LoopSubdivision, TetrahedronCountsAndMasks)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, tetrahedron_soup());
	const auto r = modeling::loop_subdivision(m, *pos);
	EXPECT_FALSE(r.cancelled);
	EXPECT_EQ(r.steps, 1u);
	EXPECT_EQ(nb_cells<Vertex>(m), 10u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 24u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 16u);
	EXPECT_TRUE(all_faces_of_degree(m, 3));
	EXPECT_TRUE(check_integrity(m).ok());
	// valence 3: n beta = 5/8 - (3/8 + 1/4 cos(2pi/3))^2 = 5/8 - 1/16 = 9/16
	const std::vector<Vec3> p = tetrahedron_points();
	const Vec3 sum = p[0] + p[1] + p[2] + p[3];
	std::vector<Vec3> expected;
	for (const Vec3& q : p)
		expected.push_back(7.0 / 16.0 * q + 3.0 / 16.0 * (sum - q));
	for (uint32 i = 0; i < 4; ++i)
		for (uint32 j = i + 1; j < 4; ++j)
			expected.push_back(3.0 / 8.0 * (p[i] + p[j]) + 1.0 / 8.0 * (sum - p[i] - p[j]));
	expect_positions(m, *pos, expected);
}

TEST(LoopSubdivision, ValenceSixUsesLoopsOriginalWeight)
{
	// the centre of a flat hexagon fan with a raised centre: only the
	// normal component moves, by (1 - n beta) with n beta = 5/8 - (3/8 + 1/8)^2 = 3/8
	std::vector<Vec3> pts = {{0, 0, 1}};
	std::vector<std::vector<uint32>> faces;
	for (uint32 i = 0; i < 6; ++i)
	{
		const double a = 2.0 * std::numbers::pi * i / 6.0;
		pts.push_back({std::cos(a), std::sin(a), 0.0});
		faces.push_back({0, 1 + i, 1 + (i + 1) % 6});
	}
	CMap2 m;
	auto pos = test::build_with_positions(m, polygon_soup(pts, faces));
	modeling::loop_subdivision(m, *pos);
	const Vertex centre = test::closest_vertex(m, *pos, Vec3(0, 0, 1));
	EXPECT_NEAR(value<Vec3>(m, *pos, centre).z(), 1.0 - 3.0 / 8.0, 1e-15);
	EXPECT_NEAR(value<Vec3>(m, *pos, centre).head<2>().norm(), 0.0, 1e-15);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(LoopSubdivision, PolygonsAreRejectedAndTheMapIsUntouched)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, test::box_soup());
	EXPECT_FALSE(modeling::is_triangle_mesh(m));
	const uint32 darts = nb_darts(m);
	EXPECT_THROW(modeling::loop_subdivision(m, *pos), modeling::SubdivisionError);
	EXPECT_THROW(modeling::sqrt3_subdivision(m, *pos), modeling::SubdivisionError);
	EXPECT_EQ(nb_darts(m), darts);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(LoopSubdivision, HemisphereBoundaryFollowsTheCreaseRule)
{
	CMap2 m;
	LOAD_OR_SKIP(m, "surface/hemisphere.off");
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	const Counts c = counts(m);
	const Dart b = some_boundary_dart(m);
	const std::vector<Vec3> before = boundary_loop(m, *pos, b);
	EXPECT_EQ(before.size(), 120u);
	modeling::loop_subdivision(m, *pos);
	EXPECT_EQ(nb_cells<Vertex>(m), c.v + c.e);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 4 * c.f);
	EXPECT_EQ(nb_boundary_components(m), 1u);
	expect_crease_rule(before, boundary_loop(m, *pos, b));
	EXPECT_TRUE(check_integrity(m).ok());
}

// ---- Catmull-Clark

TEST(CatmullClarkSubdivision, UnitCubeExactPositions)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, test::box_soup());
	modeling::catmull_clark_subdivision(m, *pos);
	EXPECT_EQ(nb_cells<Vertex>(m), 26u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 48u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 24u);
	EXPECT_TRUE(all_faces_of_degree(m, 4));
	EXPECT_TRUE(check_integrity(m).ok());
	// corners: (Q + 2R) / 3 with Q = (1/3, 1/3, 1/3), R = (1/6, 1/6, 1/6) at
	// the origin: 2/9; edge points: 1/2 along, 1/8 across; face centres
	std::vector<Vec3> expected;
	for (double x : {2.0 / 9.0, 7.0 / 9.0})
		for (double y : {2.0 / 9.0, 7.0 / 9.0})
			for (double z : {2.0 / 9.0, 7.0 / 9.0})
				expected.push_back({x, y, z});
	for (uint32 axis = 0; axis < 3; ++axis)
		for (double u : {0.125, 0.875})
			for (double w : {0.125, 0.875})
			{
				Vec3 p;
				p[axis] = 0.5;
				p[(axis + 1) % 3] = u;
				p[(axis + 2) % 3] = w;
				expected.push_back(p);
			}
	for (uint32 axis = 0; axis < 3; ++axis)
		for (double u : {0.0, 1.0})
		{
			Vec3 p(0.5, 0.5, 0.5);
			p[axis] = u;
			expected.push_back(p);
		}
	expect_positions(m, *pos, expected);
}

TEST(CatmullClarkSubdivision, SpotControlMeshBecomesQuads)
{
	CMap2 m;
	LOAD_OR_SKIP(m, "surface/spot_control_mesh.obj");
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	const Counts c = counts(m);
	modeling::catmull_clark_subdivision(m, *pos);
	// 4 triangles, 160 quads, 16 pentagons: 732 quads
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 732u);
	EXPECT_EQ(nb_cells<Vertex>(m), c.v + c.e + c.f);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 2 * c.e + 732u);
	EXPECT_EQ(euler_characteristic(m), 2);
	EXPECT_TRUE(all_faces_of_degree(m, 4));
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CatmullClarkSubdivision, HemisphereBoundaryFollowsTheCreaseRule)
{
	CMap2 m;
	LOAD_OR_SKIP(m, "surface/hemisphere.off");
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	const Dart b = some_boundary_dart(m);
	const std::vector<Vec3> before = boundary_loop(m, *pos, b);
	modeling::catmull_clark_subdivision(m, *pos);
	expect_crease_rule(before, boundary_loop(m, *pos, b));
	EXPECT_TRUE(all_faces_of_degree(m, 4));
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CatmullClarkSubdivision, OpenGridStaysFlat)
{
	// a flat grid stays flat; the middle of a straight boundary side stays put
	CMap2 m;
	auto pos = test::build_with_positions(m, grid_soup(3, 2));
	const auto r = modeling::subdivide(m, *pos, modeling::SurfaceScheme::CatmullClark, 2);
	EXPECT_EQ(r.steps, 2u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 6u * 16u);
	EXPECT_EQ(nb_cells<Vertex>(m), 13u * 9u);
	foreach_cell(m, [&](Vertex v) { EXPECT_EQ(value<Vec3>(m, *pos, v).z(), 0.0); });
	EXPECT_EQ(value<Vec3>(m, *pos, test::closest_vertex(m, *pos, Vec3(0, 1, 0))), Vec3(0, 1, 0));
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_TRUE(check_integrity(m).ok());
}

// ---- sqrt3

TEST(Sqrt3Subdivision, TetrahedronCountsPositionsAndFlips)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, tetrahedron_soup());
	modeling::sqrt3_subdivision(m, *pos);
	EXPECT_EQ(nb_cells<Vertex>(m), 8u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 18u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 12u);
	EXPECT_TRUE(all_faces_of_degree(m, 3));
	EXPECT_TRUE(check_integrity(m).ok());
	// every old edge was flipped: old vertices keep valence 3, now joined to centroids only
	uint32 valence3 = 0, valence6 = 0;
	foreach_cell(m, [&](Vertex v) {
		const uint32 d = degree(m, v);
		valence3 += d == 3 ? 1 : 0;
		valence6 += d == 6 ? 1 : 0;
	});
	EXPECT_EQ(valence3, 4u);
	EXPECT_EQ(valence6, 4u);
	// alpha_3 = (4 - 2 cos(2pi/3)) / 9 = 5/9
	const std::vector<Vec3> p = tetrahedron_points();
	const Vec3 sum = p[0] + p[1] + p[2] + p[3];
	std::vector<Vec3> expected;
	for (const Vec3& q : p)
		expected.push_back(4.0 / 9.0 * q + 5.0 / 27.0 * (sum - q));
	for (const Vec3& q : p)
		expected.push_back((sum - q) / 3.0);
	expect_positions(m, *pos, expected);
}

TEST(Sqrt3Subdivision, TwoStepsOfASphere)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, sphere_soup(12, 8, true));
	const Counts c = counts(m);
	modeling::subdivide(m, *pos, modeling::SurfaceScheme::Sqrt3, 2);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 9 * c.f);
	EXPECT_EQ(nb_cells<Vertex>(m), c.v + c.f + 3 * c.f);
	EXPECT_EQ(euler_characteristic(m), 2);
	EXPECT_TRUE(all_faces_of_degree(m, 3));
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(Sqrt3Subdivision, HemisphereBoundaryStaysFixed)
{
	CMap2 m;
	LOAD_OR_SKIP(m, "surface/hemisphere.off");
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	const Counts c = counts(m);
	const Dart b = some_boundary_dart(m);
	const std::vector<Vec3> before = boundary_loop(m, *pos, b);
	modeling::sqrt3_subdivision(m, *pos);
	EXPECT_EQ(boundary_loop(m, *pos, b), before);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 3 * c.f);
	EXPECT_EQ(nb_cells<Vertex>(m), c.v + c.f);
	EXPECT_TRUE(all_faces_of_degree(m, 3));
	EXPECT_TRUE(check_integrity(m).ok());
}

// ---- every scheme on a mesh with many holes

TEST(Subdivision, ElephantWithHolesEveryScheme)
{
	for (auto scheme :
		 {modeling::SurfaceScheme::Loop, modeling::SurfaceScheme::CatmullClark, modeling::SurfaceScheme::Sqrt3})
	{
		CMap2 m;
		LOAD_OR_SKIP(m, "surface/elephant-with-holes.off");
		auto pos = get_attribute<Vec3, Vertex>(m, "position");
		const Counts c = counts(m);
		const uint32 holes = nb_boundary_components(m);
		const int64_t chi = euler_characteristic(m);
		modeling::subdivide(m, *pos, scheme, 1);
		EXPECT_TRUE(check_integrity(m).ok());
		EXPECT_EQ(nb_boundary_components(m), holes);
		EXPECT_EQ(euler_characteristic(m), chi);
		switch (scheme)
		{
		case modeling::SurfaceScheme::Loop:
			EXPECT_EQ(nb_cells<CMap2::Face>(m), 4 * c.f);
			EXPECT_EQ(nb_cells<Vertex>(m), c.v + c.e);
			break;
		case modeling::SurfaceScheme::CatmullClark:
			EXPECT_EQ(nb_cells<CMap2::Face>(m), 3 * c.f);
			EXPECT_EQ(nb_cells<Vertex>(m), c.v + c.e + c.f);
			break;
		case modeling::SurfaceScheme::Sqrt3:
			EXPECT_EQ(nb_cells<CMap2::Face>(m), 3 * c.f);
			EXPECT_EQ(nb_cells<Vertex>(m), c.v + c.f);
			break;
		}
		bool finite = true;
		foreach_cell(m, [&](Vertex v) { finite = finite && value<Vec3>(m, *pos, v).allFinite(); });
		EXPECT_TRUE(finite);
	}
}

// ---- cancellation

TEST(Subdivision, CancelWhileComputingLeavesTheMapUntouched)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, sphere_soup(16, 10, true));
	const Counts c = counts(m);
	const Vertex v = test::closest_vertex(m, *pos, Vec3(0, 0, 1));
	const Vec3 p = value<Vec3>(m, *pos, v);
	for (auto scheme :
		 {modeling::SurfaceScheme::Loop, modeling::SurfaceScheme::CatmullClark, modeling::SurfaceScheme::Sqrt3})
	{
		const auto r = modeling::subdivide(m, *pos, scheme, 3, [](double) { return false; });
		EXPECT_TRUE(r.cancelled);
		EXPECT_EQ(r.steps, 0u);
		EXPECT_EQ(nb_cells<Vertex>(m), c.v);
		EXPECT_EQ(nb_cells<CMap2::Face>(m), c.f);
		EXPECT_EQ(value<Vec3>(m, *pos, v), p);
		EXPECT_TRUE(check_integrity(m).ok());
	}
}

TEST(Subdivision, CancelWhileRefiningCompletesTheStep)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, tetrahedron_soup());
	std::vector<double> seen;
	const auto r = modeling::subdivide(m, *pos, modeling::SurfaceScheme::Loop, 3, [&](double f) {
		seen.push_back(f);
		return f <= 0.34; // the second step's refinement starts at 1/2
	});
	EXPECT_TRUE(r.cancelled);
	EXPECT_EQ(r.steps, 2u);
	EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 64u);
	EXPECT_TRUE(all_faces_of_degree(m, 3));
	EXPECT_TRUE(check_integrity(m).ok());
}

// ---- volumes

TEST(HexSubdivision, GridBecomesTheFinerGrid)
{
	CMap3 m;
	auto pos = test::build_with_positions(m, hex_grid_soup(2, 2, 2));
	EXPECT_TRUE(modeling::is_hex_mesh(m));
	const auto r = modeling::hex_subdivision(m, *pos);
	EXPECT_FALSE(r.cancelled);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 64u);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), 125u);
	EXPECT_EQ(nb_cells<CMap3::Edge>(m), 300u);
	EXPECT_EQ(nb_cells<CMap3::Face>(m), 240u);
	EXPECT_TRUE(modeling::is_hex_mesh(m));
	EXPECT_TRUE(check_integrity(m).ok());
	foreach_cell(m, [&](CMap3::Volume w) { EXPECT_NEAR(geometry::volume(m, w, *pos), 0.125, 1e-14); });
	EXPECT_NEAR(geometry::solid_volume(m, *pos), 8.0, 1e-12);
	// every vertex on the grid of step 1/2
	foreach_cell(m, [&](CMap3::Vertex v) {
		const Vec3 p = 2.0 * value<Vec3>(m, *pos, v);
		EXPECT_LT((p - p.array().round().matrix()).norm(), 1e-14);
	});
}

TEST(HexSubdivision, LiverCountsAndIntegrity)
{
	CMap3 m;
	LOAD_OR_SKIP(m, "volume/liver_hex_624.mesh");
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	const uint32 v = nb_cells<CMap3::Vertex>(m), e = nb_cells<CMap3::Edge>(m), f = nb_cells<CMap3::Face>(m),
				 w = nb_cells<CMap3::Volume>(m);
	modeling::hex_subdivision(m, *pos);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 8 * w);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), v + e + f + w);
	EXPECT_TRUE(modeling::is_hex_mesh(m));
	EXPECT_TRUE(check_integrity(m).ok());
	foreach_cell(m, [&](CMap3::Volume x) { EXPECT_GT(geometry::volume(m, x, *pos), 0.0); });
}

TEST(TetSubdivision, ElephantVolumesTimesEightVolumePreserved)
{
	CMap3 m;
	LOAD_OR_SKIP(m, "volume/elephant_tet_8k.mesh");
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	const uint32 v = nb_cells<CMap3::Vertex>(m), e = nb_cells<CMap3::Edge>(m), w = nb_cells<CMap3::Volume>(m);
	double before = 0.0;
	foreach_cell(m, [&](CMap3::Volume x) { before += geometry::volume(m, x, *pos); });
	EXPECT_FALSE(modeling::is_hex_mesh(m));
	EXPECT_THROW(modeling::hex_subdivision(m, *pos), modeling::SubdivisionError);
	modeling::tet_subdivision(m, *pos);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 8 * w);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), v + e);
	EXPECT_TRUE(modeling::is_tet_mesh(m));
	EXPECT_TRUE(check_integrity(m).ok());
	double after = 0.0, smallest = 1e300;
	foreach_cell(m, [&](CMap3::Volume x) {
		const double vol = geometry::volume(m, x, *pos);
		after += vol;
		smallest = std::min(smallest, vol);
	});
	EXPECT_NEAR(after, before, 1e-12 * before);
	EXPECT_GT(smallest, 0.0);
}

TEST(TetSubdivision, GridTwiceAndCancellation)
{
	CMap3 m;
	auto pos = test::build_with_positions(m, tet_grid_soup(2, 1, 1));
	const uint32 w = nb_cells<CMap3::Volume>(m);
	const auto cancelled = modeling::tet_subdivision(m, *pos, [](double) { return false; });
	EXPECT_TRUE(cancelled.cancelled);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), w);
	modeling::tet_subdivision(m, *pos);
	modeling::tet_subdivision(m, *pos);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 64 * w);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_NEAR(geometry::solid_volume(m, *pos), 2.0, 1e-12);
	double sum = 0.0;
	foreach_cell(m, [&](CMap3::Volume x) { sum += geometry::volume(m, x, *pos); });
	EXPECT_NEAR(sum, 2.0, 1e-12);
}

// ---- degenerate inputs

TEST(Subdivision, PillowOfTwoTriangles)
{
	// two triangles glued along their three edges: sqrt3 joins the two
	// centroids by the first flip and must not double that edge
	for (auto scheme :
		 {modeling::SurfaceScheme::Loop, modeling::SurfaceScheme::CatmullClark, modeling::SurfaceScheme::Sqrt3})
	{
		CMap2 m;
		auto pos =
			test::build_with_positions(m, polygon_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 1}}));
		ASSERT_EQ(nb_cells<CMap2::Face>(m), 2u);
		modeling::subdivide(m, *pos, scheme, 2);
		EXPECT_TRUE(check_integrity(m).ok());
		EXPECT_EQ(euler_characteristic(m), 2);
	}
}

TEST(Subdivision, FacesWithFewerThanThreeEdgesAreRejected)
{
	CMap2 m;
	add_face(m, 2);
	auto pos = add_attribute<Vec3, Vertex>(m, "position");
	const uint32 darts = nb_darts(m);
	EXPECT_THROW(modeling::catmull_clark_subdivision(m, *pos), modeling::SubdivisionError);
	EXPECT_THROW(modeling::loop_subdivision(m, *pos), modeling::SubdivisionError);
	EXPECT_EQ(nb_darts(m), darts);
}

} // namespace cgogn_test_subdivision
