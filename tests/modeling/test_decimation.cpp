// SPDX-License-Identifier: MIT
#include <cgogn/cgogn.h>

#include "../geometry/geometry_test_meshes.h"
#include "modeling_test_utils.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>

namespace cgogn_test_decimation
{

using namespace cgogn;
using namespace cgogn::modeling_test;

namespace
{

using Vertex = CMap2::Vertex;

uint32 count_faces(const CMap2& m)
{
	uint32 n = 0;
	foreach_cell(m, [&](CMap2::Face) { ++n; });
	return n;
}

/// Largest distance of a vertex to the unit sphere.
double max_sphere_deviation(const CMap2& m, const AttributeArray<Vec3>& pos)
{
	double d = 0.0;
	foreach_cell(m, [&](Vertex v) { d = std::max(d, std::abs(pos[index_of(m, v)].norm() - 1.0)); });
	return d;
}

/// A sphere of 2 * 64 * 31 = 3968 triangles.
test::Pos fine_sphere(CMap2& m)
{
	return test::build_with_positions(m, sphere_soup(64, 32, true));
}

} // namespace

TEST(Decimation, SphereReachesTheTargetExactlyAndStaysOnTheSphere)
{
	CMap2 m;
	auto pos = fine_sphere(m);
	ASSERT_EQ(count_faces(m), 3968u);
	uint32 checks = 0;
	modeling::DecimationOptions o;
	o.target_faces = 500;
	// integrity at intermediate states (the callback runs every 1/256 of the work)
	const auto check = [&](double) {
		EXPECT_TRUE(check_integrity(m).ok());
		++checks;
		return true;
	};
	const modeling::DecimationResult r = modeling::decimate(m, *pos, o, check);
	EXPECT_EQ(r.faces, 500u);
	EXPECT_EQ(count_faces(m), 500u);
	EXPECT_EQ(r.collapses, (3968u - 500u) / 2);
	EXPECT_FALSE(r.cancelled);
	EXPECT_GT(r.max_error, 0.0);
	EXPECT_GT(checks, 100u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_boundary_components(m), 0u);
	EXPECT_EQ(euler_characteristic(m), 2);
	EXPECT_EQ(nb_cells<Vertex>(m), 252u); // V = F / 2 + 2 on a closed genus-0 triangulation
	// 500 triangles: edges of about 0.19, whose sagitta is about 0.005
	EXPECT_LT(max_sphere_deviation(m, *pos), 0.01);
}

TEST(Decimation, OddTargetOnAClosedMeshStopsOneBelow)
{
	CMap2 m;
	auto pos = fine_sphere(m);
	modeling::DecimationOptions o;
	o.target_faces = 301;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_EQ(r.faces, 300u); // each collapse removes two triangles
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(Decimation, MidpointVariantStaysOnTheSphere)
{
	CMap2 m;
	auto pos = fine_sphere(m);
	modeling::DecimationOptions o;
	o.target_faces = 500;
	o.placement = modeling::CollapsePlacement::Midpoint;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_EQ(r.faces, 500u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(euler_characteristic(m), 2);
	// midpoints lie inside the sphere, by up to the sagitta of the collapsed edges
	EXPECT_LT(max_sphere_deviation(m, *pos), 0.03);
}

TEST(Decimation, MaxErrorStopsEarly)
{
	CMap2 m;
	auto pos = fine_sphere(m);
	modeling::DecimationOptions o;
	o.max_error = 1e-6;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_LE(r.max_error, 1e-6);
	EXPECT_GT(r.collapses, 0u);
	EXPECT_GT(r.faces, 500u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(Decimation, CancellationLeavesAValidMap)
{
	CMap2 m;
	auto pos = fine_sphere(m);
	modeling::DecimationOptions o;
	o.target_faces = 100;
	const auto r = modeling::decimate(m, *pos, o, [](double f) { return f < 0.3; });
	EXPECT_TRUE(r.cancelled);
	EXPECT_GT(r.faces, 100u);
	EXPECT_LT(r.faces, 3968u);
	EXPECT_EQ(count_faces(m), r.faces);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(euler_characteristic(m), 2);
}

TEST(Decimation, RejectsPolygons)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, sphere_soup(8, 6, false)); // quads between the poles
	modeling::DecimationOptions o;
	o.target_faces = 10;
	EXPECT_THROW(modeling::decimate(m, *pos, o), Error);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(Decimation, TorusKeepsItsGenus)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, torus_soup(48, 24, true));
	modeling::DecimationOptions o;
	o.target_faces = 200;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_EQ(r.faces, 200u);
	EXPECT_EQ(euler_characteristic(m), 0);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(Decimation, NefertitiToTenPercent)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/nefertiti.obj");
	CMap2 m;
	io::load_surface(m, path);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	ASSERT_EQ(count_faces(m), 99938u);
	modeling::DecimationOptions o;
	o.target_faces = 9994;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_EQ(r.faces, 9994u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(euler_characteristic(m), 2); // closed, genus 0
	EXPECT_EQ(nb_boundary_components(m), 0u);
	EXPECT_EQ(nb_connected_components(m), 1u);
}

TEST(Decimation, HemisphereKeepsItsBoundaryWhenAsked)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/hemisphere.off");
	CMap2 m;
	io::load_surface(m, path);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	std::map<uint32, Vec3> boundary; // vertex line -> position
	foreach_cell(m, [&](Vertex v) {
		if (is_incident_to_boundary(m, v))
			boundary[index_of(m, v)] = (*pos)[index_of(m, v)];
	});
	ASSERT_EQ(boundary.size(), 120u);
	modeling::DecimationOptions o;
	o.target_faces = 400;
	o.keep_boundary = true;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_EQ(r.faces, 400u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_boundary_components(m), 1u);
	uint32 nb_boundary = 0;
	foreach_cell(m, [&](Vertex v) {
		if (!is_incident_to_boundary(m, v))
			return;
		++nb_boundary;
		const auto it = boundary.find(index_of(m, v));
		ASSERT_NE(it, boundary.end());
		EXPECT_EQ((*pos)[index_of(m, v)], it->second);
	});
	EXPECT_EQ(nb_boundary, 120u);
}

TEST(Decimation, HemisphereBoundaryMayCollapseOtherwise)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/hemisphere.off");
	CMap2 m;
	io::load_surface(m, path);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	modeling::DecimationOptions o;
	o.target_faces = 200;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_LE(r.faces, 200u);
	EXPECT_GE(r.faces, 199u); // boundary collapses remove one face
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_EQ(euler_characteristic(m), 1);
	uint32 nb_boundary = 0;
	foreach_cell(m, [&](Vertex v) { nb_boundary += is_incident_to_boundary(m, v) ? 1 : 0; });
	EXPECT_LT(nb_boundary, 120u);
}

TEST(Decimation, BunnyWithHolesKeepsItsFiveBoundaryLoops)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/stanford-bunny.obj");
	CMap2 m;
	io::load_surface(m, path);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	ASSERT_EQ(nb_boundary_components(m), 5u);
	const int64 chi = euler_characteristic(m);
	uint32 boundary_before = 0;
	foreach_cell(m, [&](Vertex v) { boundary_before += is_incident_to_boundary(m, v) ? 1 : 0; });
	modeling::DecimationOptions o;
	o.target_faces = 6945; // 10%
	o.keep_boundary = true;
	const auto r = modeling::decimate(m, *pos, o);
	EXPECT_EQ(r.faces, 6945u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_boundary_components(m), 5u);
	EXPECT_EQ(euler_characteristic(m), chi);
	uint32 boundary_after = 0;
	foreach_cell(m, [&](Vertex v) { boundary_after += is_incident_to_boundary(m, v) ? 1 : 0; });
	EXPECT_EQ(boundary_after, boundary_before);
}

} // namespace cgogn_test_decimation
