// SPDX-License-Identifier: MIT
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <numbers>

namespace cgogn_test_curvature
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

constexpr double pi = std::numbers::pi;

namespace
{
int64 euler(const CMap2& m)
{
	return int64(nb_cells<Vertex>(m)) - nb_cells<Edge>(m) + nb_cells<Face>(m);
}
double total_defect(const CMap2& m, const AttributeArray<Vec3>& pos)
{
	double s = 0.0;
	foreach_cell(m, [&](Vertex v) { s += angle_defect(m, v, pos); });
	return s;
}
} // namespace

TEST(Curvature, GaussBonnetOnClosedAndOpenMeshes)
{
	struct Case
	{
		const char* name;
		SurfaceSoup soup;
	};
	const std::vector<Case> cases = {
		{"sphere quads", sphere_soup(12, 7)},     {"sphere triangles", sphere_soup(12, 7, true)},
		{"torus quads", torus_soup(9, 6)},        {"torus triangles", torus_soup(9, 6, true)},
		{"grid quads", grid_soup(4, 5)},          {"grid triangles", grid_soup(4, 5, true)},
		{"cylinder quads", cylinder_soup(10, 3)}, {"cylinder triangles", cylinder_soup(10, 3, true)},
		{"box", test::box_soup(1, 2, 3)},
	};
	for (const auto& c : cases)
	{
		SCOPED_TRACE(c.name);
		CMap2 m;
		auto pos = build_with_positions(m, c.soup);
		// also on a noisy copy of the triangle meshes (any planar faces)
		EXPECT_NEAR(total_defect(m, *pos), 2 * pi * double(euler(m)), 1e-10);
		auto k = add_attribute<double, Vertex>(m, "k");
		compute_gaussian_curvatures(m, *pos, *k, true);
		double s = 0.0;
		for (double x : *k)
			s += x;
		EXPECT_NEAR(s, 2 * pi * double(euler(m)), 1e-10);
	}
	CMap2 m;
	auto pos = build_with_positions(m, torus_soup(9, 6, true));
	uint32 i = 0;
	for (Vec3& p : *pos)
		p += 0.1 * Vec3(test::noise(i), test::noise(i + 100), test::noise(i + 200)), ++i;
	EXPECT_NEAR(total_defect(m, *pos), 0.0, 1e-10);
}

TEST(Curvature, FlatGridHasNone)
{
	for (bool triangles : {false, true})
	{
		CMap2 m;
		auto pos = build_with_positions(m, grid_soup(6, 5, triangles));
		foreach_cell(m, [&](Vertex v) {
			if (is_incident_to_boundary(m, v))
				return;
			EXPECT_NEAR(angle_defect(m, v, *pos), 0.0, 1e-14);
			EXPECT_NEAR(gaussian_curvature(m, v, *pos), 0.0, 1e-13);
			EXPECT_NEAR(mean_curvature(m, v, *pos), 0.0, 1e-13);
			EXPECT_NEAR(cotan_laplacian_of_position(m, v, *pos).norm(), 0.0, 1e-13);
			const PrincipalCurvatures c = principal_curvatures(m, v, *pos);
			EXPECT_NEAR(c.kmin, 0.0, 1e-13);
			EXPECT_NEAR(c.kmax, 0.0, 1e-13);
		});
	}
}

TEST(Curvature, VoronoiAreasPartitionTheSurface)
{
	for (const SurfaceSoup& s :
		 {sphere_soup(16, 9, true), sphere_soup(16, 9), grid_soup(5, 3, true), torus_soup(10, 5, true)})
	{
		CMap2 m;
		auto pos = build_with_positions(m, s);
		auto a = add_attribute<double, Vertex>(m, "a");
		compute_voronoi_areas(m, *pos, *a);
		double sum = 0.0;
		foreach_cell(m, [&](Vertex v) {
			EXPECT_GT(value<double>(m, a, v), 0.0);
			sum += value<double>(m, a, v);
		});
		EXPECT_NEAR(sum, surface_area(m, *pos), 1e-12);
	}
	// an obtuse triangle: shares 1/2 at the obtuse corner, 1/4 elsewhere
	CMap2 m;
	auto pos = build_with_positions(m, test::polygon_soup({{0, 0, 0}, {4, 0, 0}, {2, 0.5, 0}}, {{0, 1, 2}}));
	foreach_cell(m, [&](Vertex v) {
		const double expected = value<Vec3>(m, pos, v).y() > 0 ? 0.5 : 0.25;
		EXPECT_NEAR(voronoi_area(m, v, *pos), expected * 1.0, 1e-15);
	});
}

TEST(Curvature, UnitSphere)
{
	for (bool triangles : {true, false})
	{
		CMap2 m;
		auto pos = build_with_positions(m, sphere_soup(96, 48, triangles));
		auto h = add_attribute<double, Vertex>(m, "h");
		auto k = add_attribute<double, Vertex>(m, "k");
		compute_mean_curvatures(m, *pos, *h);
		compute_gaussian_curvatures(m, *pos, *k);
		foreach_cell(m, [&](Vertex v) {
			if (std::abs(value<Vec3>(m, pos, v).z()) > 0.9) // away from the pole fans
				return;
			EXPECT_NEAR(value<double>(m, h, v), 1.0, 2e-3);
			EXPECT_NEAR(value<double>(m, k, v), 1.0, 2e-3);
			const PrincipalCurvatures c = principal_curvatures(m, v, *pos);
			EXPECT_NEAR(c.kmin, 1.0, 0.02);
			EXPECT_NEAR(c.kmax, 1.0, 0.02);
		});
	}
}

TEST(Curvature, CylinderPrincipalDirections)
{
	for (bool triangles : {false, true})
	{
		CMap2 m;
		auto pos = build_with_positions(m, cylinder_soup(64, 10, triangles));
		foreach_cell(m, [&](Vertex v) {
			if (is_incident_to_boundary(m, v))
				return;
			const Vec3& p = value<Vec3>(m, pos, v);
			const PrincipalCurvatures c = principal_curvatures(m, v, *pos);
			EXPECT_NEAR(c.kmax, 1.0, 0.01);
			EXPECT_NEAR(c.kmin, 0.0, 0.01);
			EXPECT_NEAR(std::abs(c.dmin.z()), 1.0, 1e-2);                         // along the axis
			EXPECT_NEAR(std::abs(c.dmax.dot(Vec3(-p.y(), p.x(), 0))), 1.0, 1e-2); // around it
			EXPECT_NEAR(mean_curvature(m, v, *pos), 0.5, 0.01);
			EXPECT_NEAR(gaussian_curvature(m, v, *pos), 0.0, 1e-10);
		});
	}
}

TEST(Curvature, TorusSignsAndValues)
{
	// R = 1, r = 0.5. Outer equator: k = 1/r = 2 and 1/(R + r) = 2/3;
	// inner equator: k = 2 and -1/(R - r) = -2.
	CMap2 m;
	auto pos = build_with_positions(m, torus_soup(192, 96, true));
	auto kmin = add_attribute<double, Vertex>(m, "kmin");
	auto kmax = add_attribute<double, Vertex>(m, "kmax");
	auto dmin = add_attribute<Vec3, Vertex>(m, "dmin");
	auto dmax = add_attribute<Vec3, Vertex>(m, "dmax");
	compute_principal_curvatures(m, *pos, *kmin, *kmax, *dmin, *dmax);
	const Vertex outer = test::closest_vertex(m, *pos, Vec3(1.5, 0, 0));
	const Vertex inner = test::closest_vertex(m, *pos, Vec3(0.5, 0, 0));
	EXPECT_NEAR(value<double>(m, kmax, outer), 2.0, 0.02);
	EXPECT_NEAR(value<double>(m, kmin, outer), 2.0 / 3.0, 0.02);
	EXPECT_NEAR(value<double>(m, kmax, inner), 2.0, 0.02);
	EXPECT_NEAR(value<double>(m, kmin, inner), -2.0, 0.02);
	EXPECT_NEAR(mean_curvature(m, outer, *pos), 4.0 / 3.0, 0.01);
	EXPECT_NEAR(mean_curvature(m, inner, *pos), 0.0, 0.01);
	EXPECT_NEAR(gaussian_curvature(m, outer, *pos), 4.0 / 3.0, 0.01);
	EXPECT_NEAR(gaussian_curvature(m, inner, *pos), -4.0, 0.04);
	// at the outer equator the direction of kmax goes around the tube (along z)
	EXPECT_NEAR(std::abs(value<Vec3>(m, dmax, outer).z()), 1.0, 1e-2);
}

} // namespace cgogn_test_curvature
