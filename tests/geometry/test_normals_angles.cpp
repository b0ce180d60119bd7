// SPDX-License-Identifier: MIT
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <numbers>

namespace cgogn_test_normals_angles
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

constexpr double pi = std::numbers::pi;
constexpr NormalWeighting all_weightings[] = {NormalWeighting::Uniform, NormalWeighting::Area, NormalWeighting::Angle};

TEST(Normals, GridPointsUp)
{
	for (bool triangles : {false, true})
	{
		CMap2 m;
		auto pos = build_with_positions(m, grid_soup(4, 3, triangles));
		foreach_cell(m, [&](Face f) { EXPECT_EQ(face_normal(m, f, *pos), Vec3(0, 0, 1)); });
		for (NormalWeighting w : all_weightings)
			foreach_cell(
				m, [&](Vertex v) { EXPECT_NEAR((vertex_normal(m, v, *pos, w) - Vec3(0, 0, 1)).norm(), 0.0, 1e-15); });
		auto fn = add_attribute<Vec3, Face>(m, "fn");
		compute_face_normals(m, *pos, *fn);
		for (const Vec3& n : *fn)
			EXPECT_EQ(n, Vec3(0, 0, 1));
	}
}

TEST(Normals, BoxCornersUnderEachWeighting)
{
	CMap2 m;
	auto pos = build_with_positions(m, test::box_soup(1, 1, 1));
	for (NormalWeighting w : all_weightings)
		foreach_cell(m, [&](Vertex v) {
			const Vec3 expected = (value<Vec3>(m, pos, v) - Vec3(0.5, 0.5, 0.5)).normalized();
			EXPECT_NEAR((vertex_normal(m, v, *pos, w) - expected).norm(), 0.0, 1e-15);
		});
	// a flat box: area weighting leans to the big faces, uniform and angle do not
	CMap2 flat;
	auto fpos = build_with_positions(flat, test::box_soup(4, 4, 1));
	const Vertex corner = test::closest_vertex(flat, *fpos, Vec3(4, 4, 1));
	EXPECT_NEAR((vertex_normal(flat, corner, *fpos, NormalWeighting::Uniform) - Vec3(1, 1, 1).normalized()).norm(), 0.0,
				1e-15);
	EXPECT_NEAR((vertex_normal(flat, corner, *fpos, NormalWeighting::Angle) - Vec3(1, 1, 1).normalized()).norm(), 0.0,
				1e-15);
	EXPECT_NEAR((vertex_normal(flat, corner, *fpos, NormalWeighting::Area) - Vec3(4, 4, 16).normalized()).norm(), 0.0,
				1e-15);
}

TEST(Normals, AllAtOnceMatchesOneByOne)
{
	for (bool triangles : {false, true})
	{
		CMap2 m;
		auto pos = build_with_positions(m, torus_soup(12, 7, triangles));
		uint32 i = 0;
		for (Vec3& p : *pos)
			p += 0.05 * Vec3(test::noise(i), test::noise(i + 1000), test::noise(i + 2000)), ++i;
		auto vn = add_attribute<Vec3, Vertex>(m, "vn");
		for (NormalWeighting w : all_weightings)
		{
			compute_vertex_normals(m, *pos, *vn, w);
			foreach_cell(m, [&](Vertex v) {
				EXPECT_NEAR((value<Vec3>(m, vn, v) - vertex_normal(m, v, *pos, w)).norm(), 0.0, 1e-13);
			});
		}
	}
}

TEST(Normals, SphereNormalsAreRadial)
{
	// the triangles split the quads along one diagonal: the error is first
	// order in the edge length h, below h / 5 here and at least halving with h
	for (NormalWeighting w : all_weightings)
	{
		double previous = 0.0;
		for (uint32 n : {32u, 64u, 128u})
		{
			CMap2 m;
			auto pos = build_with_positions(m, sphere_soup(2 * n, n, true));
			double err = 0.0;
			foreach_cell(m, [&](Vertex v) {
				err = std::max(err, (vertex_normal(m, v, *pos, w) - value<Vec3>(m, pos, v)).norm());
			});
			EXPECT_LT(err, 0.2 * pi / n);
			if (previous > 0.0)
			{
				EXPECT_GT(previous / err, 1.8); // at least first order (2nd for area and angle)
			}
			previous = err;
		}
	}
}

TEST(Angles, CornersOfAGrid)
{
	CMap2 m;
	auto pos = build_with_positions(m, grid_soup(3, 3));
	foreach_dart(m, [&](Dart d) {
		if (!is_boundary(m, d))
		{
			EXPECT_NEAR(corner_angle(m, d, *pos), pi / 2, 1e-15);
		}
	});
	foreach_cell(m, [&](Vertex v) {
		const double expected = is_incident_to_boundary(m, v) ? (degree(m, v) == 2 ? pi / 2 : pi) : 2 * pi;
		EXPECT_NEAR(vertex_angle_sum(m, v, *pos), expected, 1e-14);
	});
	foreach_cell(m, [&](Edge e) { EXPECT_EQ(dihedral_angle(m, e, *pos), 0.0); });
}

TEST(Angles, DihedralAnglesOfABoxAndATent)
{
	CMap2 m;
	auto pos = build_with_positions(m, test::box_soup(1, 2, 3));
	auto angle = add_attribute<double, Edge>(m, "angle");
	compute_dihedral_angles(m, *pos, *angle);
	for (double a : *angle)
		EXPECT_NEAR(a, pi / 2, 1e-15);
	// mirrored, the box is seen from inside: concave edges
	for (Vec3& p : *pos)
		p.x() = -p.x();
	foreach_cell(m, [&](Edge e) { EXPECT_NEAR(dihedral_angle(m, e, *pos), -pi / 2, 1e-15); });

	// two triangles folded by 60 degrees along the x axis
	const double t = pi / 3;
	CMap2 tent;
	auto tpos = build_with_positions(
		tent, test::polygon_soup({{0, 0, 0}, {1, 0, 0}, {0.5, std::cos(t), std::sin(t)}, {0.5, -1, 0}},
								 {{0, 1, 2}, {1, 0, 3}}));
	uint32 inner = 0;
	foreach_cell(tent, [&](Edge e) {
		if (is_incident_to_boundary(tent, e))
			return;
		++inner;
		EXPECT_NEAR(std::abs(dihedral_angle(tent, e, *tpos)), t, 1e-15);
	});
	EXPECT_EQ(inner, 1u);
}

} // namespace cgogn_test_normals_angles
