// SPDX-License-Identifier: MIT
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <numbers>

namespace cgogn_test_measures
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

constexpr double pi = std::numbers::pi;

TEST(Measures, GridOfUnitQuads)
{
	CMap2 m;
	auto pos = build_with_positions(m, grid_soup(5, 4));
	foreach_cell(m, [&](Face f) {
		EXPECT_DOUBLE_EQ(face_area(m, f, *pos), 1.0);
		const Vec3 c = centroid(m, f, *pos);
		EXPECT_DOUBLE_EQ(c.x() - std::floor(c.x()), 0.5);
		EXPECT_DOUBLE_EQ(c.y() - std::floor(c.y()), 0.5);
		EXPECT_DOUBLE_EQ(c.z(), 0.0);
	});
	foreach_cell(m, [&](Edge e) { EXPECT_DOUBLE_EQ(edge_length(m, e, *pos), 1.0); });
	EXPECT_DOUBLE_EQ(surface_area(m, *pos), 20.0);
	EXPECT_DOUBLE_EQ(mean_edge_length(m, *pos), 1.0);
	const BoundingBox bb = bounding_box(m, *pos);
	EXPECT_EQ(bb.min(), Vec3(0, 0, 0));
	EXPECT_EQ(bb.max(), Vec3(5, 4, 0));

	auto area = add_attribute<double, Face>(m, "area");
	compute_face_areas(m, *pos, *area);
	for (double a : *area)
		EXPECT_DOUBLE_EQ(a, 1.0);
	auto length = add_attribute<double, Edge>(m, "length");
	compute_edge_lengths(m, *pos, *length);
	for (double l : *length)
		EXPECT_DOUBLE_EQ(l, 1.0);
	auto center = add_attribute<Vec3, Face>(m, "center");
	compute_centroids<Face>(m, *pos, *center);
	foreach_cell(m, [&](Face f) { EXPECT_EQ(value<Vec3>(m, center, f), centroid(m, f, *pos)); });
}

TEST(Measures, GridOfTriangles)
{
	CMap2 m;
	auto pos = build_with_positions(m, grid_soup(3, 2, true));
	foreach_cell(m, [&](Face f) { EXPECT_DOUBLE_EQ(face_area(m, f, *pos), 0.5); });
	EXPECT_DOUBLE_EQ(surface_area(m, *pos), 6.0);
	// 17 unit edges and 6 diagonals
	EXPECT_NEAR(mean_edge_length(m, *pos), (17.0 + 6.0 * std::sqrt(2.0)) / 23.0, 1e-15);
}

TEST(Measures, NonConvexPolygon)
{
	// an L-shaped hexagon of area 3, tilted out of the xy plane
	const Eigen::AngleAxisd rot(0.7, Vec3(1, 2, 3).normalized());
	std::vector<Vec3> pts = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
	for (Vec3& p : pts)
		p = rot * p + Vec3(10, -3, 7);
	CMap2 m;
	auto pos = build_with_positions(m, test::polygon_soup(pts, {{0, 1, 2, 3, 4, 5}}));
	Face f;
	foreach_cell(m, [&](Face x) { f = x; });
	EXPECT_NEAR(face_area(m, f, *pos), 3.0, 1e-12);
	EXPECT_NEAR((face_normal(m, f, *pos) - rot * Vec3(0, 0, 1)).norm(), 0.0, 1e-12);
	Vec3 mean = Vec3::Zero();
	for (const Vec3& p : pts)
		mean += p / 6.0;
	EXPECT_NEAR((centroid(m, f, *pos) - mean).norm(), 0.0, 1e-12);
}

// The area of a polyhedron inscribed in a smooth surface converges as h^2:
// doubling the resolution divides the error by about 4.
template <typename SOUP_FN>
void expect_second_order(SOUP_FN soup, double exact, bool inscribed_below)
{
	double previous = 0.0;
	for (uint32 k = 0; k < 3; ++k)
	{
		const uint32 n = 16u << k;
		CMap2 m;
		auto pos = build_with_positions(m, soup(n));
		const double a = surface_area(m, *pos);
		const double err = exact - a;
		if (inscribed_below)
		{
			EXPECT_GT(err, 0.0);
		}
		if (k > 0)
		{
			const double ratio = previous / err;
			EXPECT_GT(ratio, 3.6) << "n = " << n;
			EXPECT_LT(ratio, 4.4) << "n = " << n;
		}
		previous = err;
	}
	EXPECT_LT(std::abs(previous), 0.01 * exact);
}

TEST(Measures, SphereAreaConvergesQuadratically)
{
	expect_second_order([](uint32 n) { return sphere_soup(2 * n, n); }, 4.0 * pi, true);
	expect_second_order([](uint32 n) { return sphere_soup(2 * n, n, true); }, 4.0 * pi, true);
}

TEST(Measures, TorusAreaConvergesQuadratically)
{
	// R = 1, r = 0.5: area 4 pi^2 R r
	expect_second_order([](uint32 n) { return torus_soup(2 * n, n); }, 2.0 * pi * pi, true);
	expect_second_order([](uint32 n) { return torus_soup(2 * n, n, true); }, 2.0 * pi * pi, true);
}

TEST(Measures, CylinderAreaHasTheExactPolygonValue)
{
	// the lateral area of a prism over a regular n-gon inscribed in the unit circle
	for (uint32 n : {3u, 8u, 50u})
	{
		CMap2 m;
		auto pos = build_with_positions(m, cylinder_soup(n, 4));
		EXPECT_NEAR(surface_area(m, *pos), 2.0 * n * std::sin(pi / n), 1e-12);
	}
}

TEST(Measures, VolumeMeshFacesAndEdges)
{
	CMap3 m;
	auto pos = build_with_positions(m, hex_grid_soup(3, 2, 2));
	foreach_cell(m, [&](CMap3::Face f) { EXPECT_DOUBLE_EQ(face_area(m, f, *pos), 1.0); });
	foreach_cell(m, [&](CMap3::Edge e) { EXPECT_DOUBLE_EQ(edge_length(m, e, *pos), 1.0); });
	// faces: 4*2*2 + 3*3*2 + 3*2*3
	EXPECT_DOUBLE_EQ(surface_area(m, *pos), 16.0 + 18.0 + 18.0);
	EXPECT_DOUBLE_EQ(mean_edge_length(m, *pos), 1.0);
	EXPECT_DOUBLE_EQ(boundary_area(m, *pos), 2.0 * (6.0 + 6.0 + 4.0));
	const BoundingBox bb = bounding_box(m, *pos);
	EXPECT_EQ(bb.min(), Vec3(0, 0, 0));
	EXPECT_EQ(bb.max(), Vec3(3, 2, 2));
	foreach_cell(m, [&](CMap3::Face f) {
		const Vec3 n = face_normal(m, f, *pos);
		EXPECT_NEAR(n.cwiseAbs().sum(), 1.0, 1e-15); // axis-aligned unit
	});
}

TEST(Measures, EmptyMesh)
{
	CMap2 m;
	auto pos = add_attribute<Vec3, Vertex>(m, "position");
	EXPECT_TRUE(bounding_box(m, *pos).isEmpty());
	EXPECT_EQ(mean_edge_length(m, *pos), 0.0);
	EXPECT_EQ(surface_area(m, *pos), 0.0);
	EXPECT_EQ(signed_volume(m, *pos), 0.0);
}

namespace
{
// The mean of the positions by one running sum over the vertices, the
// reference for mean_position (which sums in four partial sums).
template <typename MAP>
Vec3 mean_by_traversal(const MAP& m, const AttributeArray<Vec3>& pos)
{
	Vec3 s = Vec3::Zero();
	uint32 n = 0;
	foreach_cell(m, [&](typename mesh_traits<MAP>::Vertex v) {
		s += value<Vec3>(m, pos, v);
		++n;
	});
	return s / double(n);
}
} // namespace

TEST(Measures, MeanPositionOfGridsOfEveryRemainder)
{
	// 1 x k grids have 2(k+1) vertices (0 or 2 modulo 4), one more once a face
	// is fanned (1 or 3): k = 1..4 ends the four partial sums at every place
	for (uint32 k = 1; k <= 4; ++k)
	{
		CMap2 m;
		auto pos = build_with_positions(m, grid_soup(k, 1));
		EXPECT_EQ(mean_position(m, *pos), Vec3(k / 2.0, 0.5, 0.0)) << k;
		// a fan vertex in one face, at y = 1/2: the mean keeps y
		Face f;
		foreach_cell(m, [&](Face x) {
			f = x;
			return false;
		});
		const Vertex c = triangulate_face(m, f);
		value<Vec3>(m, pos, c) = Vec3(0.5, 0.5, 0.0);
		const Vec3 mean = mean_position(m, *pos);
		EXPECT_NEAR((mean - mean_by_traversal(m, *pos)).norm(), 0.0, 1e-15) << k;
		EXPECT_DOUBLE_EQ(mean.y(), 0.5) << k;
	}
}

TEST(Measures, MeanPositionSkipsTheLinesOfRemovedVertices)
{
	CMap2 m;
	auto pos = build_with_positions(m, grid_soup(6, 5, true));
	// a collapse frees a vertex line: the attribute's range then skips it, as
	// foreach_cell does
	Edge collapsible;
	foreach_cell(m, [&](Edge e) {
		collapsible = e;
		return !can_collapse_edge(m, e);
	});
	ASSERT_TRUE(can_collapse_edge(m, collapsible));
	collapse_edge(m, collapsible);
	ASSERT_EQ(nb_cells<Vertex>(m), 7u * 6u - 1u);
	EXPECT_NEAR((mean_position(m, *pos) - mean_by_traversal(m, *pos)).norm(), 0.0, 1e-14);
	// a value written in a freed line would show if the range read it
	const Vec3 before = mean_position(m, *pos);
	uint32 freed = 0;
	for (uint32 i = 0; i < pos->container()->end_index(); ++i)
		if (pos->container()->key()[i] == INVALID_INDEX)
		{
			(*pos)[i] = Vec3(1e6, 1e6, 1e6);
			++freed;
		}
	ASSERT_GE(freed, 1u);
	EXPECT_EQ(mean_position(m, *pos), before);
}

TEST(Measures, MeanPositionOfAVolumeMeshAndOfAnEmptyMap)
{
	CMap3 m3;
	auto pos = build_with_positions(m3, tet_grid_soup(3, 2, 2));
	EXPECT_NEAR((mean_position(m3, *pos) - Vec3(1.5, 1.0, 1.0)).norm(), 0.0, 1e-15);
	EXPECT_NEAR((mean_position(m3, *pos) - mean_by_traversal(m3, *pos)).norm(), 0.0, 1e-15);
	CMap2 empty;
	auto epos = add_attribute<Vec3, Vertex>(empty, "position");
	EXPECT_EQ(mean_position(empty, *epos), Vec3::Zero());
}

} // namespace cgogn_test_measures
