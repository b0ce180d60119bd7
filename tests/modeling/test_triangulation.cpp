// SPDX-License-Identifier: MIT
#include <cgogn/cgogn.h>

#include "../geometry/geometry_test_meshes.h"
#include "cgogn_test_data.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace cgogn_test_triangulation
{

using namespace cgogn;
using test::polygon_soup;

namespace
{

/// Every face of m is a triangle whose normal points to the same side as `up`.
void expect_triangles_facing(const CMap2& m, const AttributeArray<Vec3>& pos, const Vec3& up)
{
	foreach_cell(m, [&](CMap2::Face f) {
		EXPECT_EQ(codegree(m, f), 3u);
		EXPECT_GT(geometry::newell_vector(m, pos, f.dart).dot(up), 0.0);
	});
}

CMap2::Face some_face(const CMap2& m)
{
	CMap2::Face face;
	foreach_cell(m, [&](CMap2::Face f) {
		face = f;
		return false;
	});
	return face;
}

} // namespace

TEST(EarClipping, NonConvexLShapeKeepsItsArea)
{
	// an L-shaped hexagon: the fan from corner 0 would leave the polygon
	CMap2 m;
	auto pos = test::build_with_positions(
		m, polygon_soup({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}}, {{0, 1, 2, 3, 4, 5}}));
	const CMap2::Face f = some_face(m);
	EXPECT_EQ(modeling::ear_clip_face(m, *pos, f), 4u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 4u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 9u);
	EXPECT_NEAR(geometry::surface_area(m, *pos), 3.0, 1e-12);
	expect_triangles_facing(m, *pos, Vec3::UnitZ());
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(EarClipping, TriangleIsLeftAlone)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, polygon_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}));
	EXPECT_EQ(modeling::ear_clip_face(m, *pos, some_face(m)), 0u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 1u);
}

TEST(EarClipping, SpiralPolygonFacingDown)
{
	// a comb with 4 teeth, clockwise in xy (so its normal is -z)
	std::vector<Vec3> pts;
	for (int k = 0; k < 4; ++k)
	{
		pts.push_back({2.0 * k, 0, 0});
		pts.push_back({2.0 * k + 1, 0, 0});
		pts.push_back({2.0 * k + 1, -3, 0});
		pts.push_back({2.0 * k + 2, -3, 0});
	}
	pts.push_back({8, 1, 0});
	pts.push_back({0, 1, 0});
	std::vector<uint32> face(pts.size());
	for (uint32 i = 0; i < face.size(); ++i)
		face[i] = uint32(face.size() - 1 - i);
	CMap2 m;
	auto pos = test::build_with_positions(m, polygon_soup(pts, {face}));
	const double area = geometry::surface_area(m, *pos);
	EXPECT_EQ(modeling::triangulate_faces(m, *pos), 1u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), pts.size() - 2);
	EXPECT_NEAR(geometry::surface_area(m, *pos), area, 1e-12);
	expect_triangles_facing(m, *pos, -Vec3::UnitZ());
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(EarClipping, PolygonalDataMeshes)
{
	for (const char* name :
		 {"surface/polygon_mesh.off", "surface/fandisk_quads.off", "surface/spot_quadrangulated.obj"})
	{
		const std::string path = cgogn_test_data::path(name);
		CMap2 m;
		io::load_surface(m, path);
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		uint32 expected_triangles = 0;
		foreach_cell(m, [&](CMap2::Face f) { expected_triangles += codegree(m, f) - 2; });
		const uint32 nv = nb_cells<CMap2::Vertex>(m);
		const double area = geometry::surface_area(m, *pos);
		modeling::triangulate_faces(m, *pos);
		EXPECT_EQ(nb_cells<CMap2::Face>(m), expected_triangles) << name;
		EXPECT_EQ(nb_cells<CMap2::Vertex>(m), nv) << name;
		foreach_cell(m, [&](CMap2::Face f) { EXPECT_EQ(codegree(m, f), 3u); });
		// planar-ish quads: two triangles cover the quad up to its non-planarity
		EXPECT_NEAR(geometry::surface_area(m, *pos), area, 1e-2 * area) << name;
		EXPECT_TRUE(check_integrity(m).ok()) << name;
	}
}

} // namespace cgogn_test_triangulation
