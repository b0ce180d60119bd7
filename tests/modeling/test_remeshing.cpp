// SPDX-License-Identifier: MIT
#include <cgogn/cgogn.h>

#include "../geometry/geometry_test_meshes.h"
#include "modeling_test_utils.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <set>

namespace cgogn_test_remeshing
{

using namespace cgogn;
using namespace cgogn::modeling_test;

namespace
{

using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;

struct Valences
{
	uint32 regular = 0; // 6 inside, 4 on the boundary
	uint32 total = 0;
};

Valences valences(const CMap2& m)
{
	Valences v;
	foreach_cell(m, [&](Vertex x) {
		const uint32 target = is_incident_to_boundary(m, x) ? 4 : 6;
		v.regular += degree(m, x) == target ? 1 : 0;
		++v.total;
	});
	return v;
}

double boundary_length(const CMap2& m, const AttributeArray<Vec3>& pos)
{
	double l = 0.0;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			l += (pos[index_of(m, Vertex(phi2(m, d)))] - pos[index_of(m, Vertex(phi1(m, phi2(m, d))))]).norm();
	});
	return l;
}

bool all_triangles(const CMap2& m)
{
	bool ok = true;
	foreach_cell(m, [&](CMap2::Face f) { ok = ok && codegree(m, f) == 3; });
	return ok;
}

} // namespace

TEST(Remeshing, SphereGetsTheTargetLengthAndRegularValences)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, sphere_soup(32, 16, true));
	const modeling::TriangleTree input(m, *pos);
	modeling::RemeshingOptions o;
	o.target_edge_length = 0.1;
	const auto r = modeling::isotropic_remeshing(m, *pos, o);
	EXPECT_EQ(r.iterations, 10u);
	EXPECT_FALSE(r.cancelled);
	EXPECT_GT(r.splits, 0u);
	EXPECT_GT(r.collapses, 0u);
	EXPECT_GT(r.flips, 0u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_TRUE(all_triangles(m));
	EXPECT_EQ(nb_cells<Vertex>(m) - nb_cells<Edge>(m) + nb_cells<CMap2::Face>(m), 2u);
	EXPECT_NEAR(geometry::mean_edge_length(m, *pos), 0.1, 0.01);
	const Valences v = valences(m);
	EXPECT_GT(v.regular, v.total * 7 / 10) << v.regular << " of " << v.total;
	// every vertex was projected onto the input polyhedron
	EXPECT_LT(modeling::vertex_distance_to_surface(m, *pos, input).max, 1e-9);
	// which is within its sagitta (edges of about 0.2) of the unit sphere
	foreach_cell(m, [&](Vertex x) { EXPECT_NEAR((*pos)[index_of(m, x)].norm(), 1.0, 0.01); });
}

TEST(Remeshing, HemisphereKeepsItsBoundaryLoop)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/hemisphere.off");
	CMap2 m;
	io::load_surface(m, path);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	const modeling::TriangleTree input(m, *pos);
	const double loop = boundary_length(m, *pos);
	const double mean = geometry::mean_edge_length(m, *pos);
	std::vector<Vec3> corners;
	foreach_cell(m, [&](Vertex x) {
		if (is_incident_to_boundary(m, x))
			corners.push_back((*pos)[index_of(m, x)]);
	});
	const double target = 1.5 * mean; // coarser than the input: collapses and relaxation at work
	modeling::RemeshingOptions o;
	o.target_edge_length = target;
	const auto r = modeling::isotropic_remeshing(m, *pos, o);
	EXPECT_EQ(r.iterations, 10u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_TRUE(all_triangles(m));
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_NEAR(boundary_length(m, *pos), loop, 1e-12 * loop);
	EXPECT_NEAR(geometry::mean_edge_length(m, *pos), target, 0.1 * target);
	// boundary vertices are locked: every original one is still there, unmoved
	std::set<std::array<double, 3>> after;
	foreach_cell(m, [&](Vertex x) {
		const Vec3& p = (*pos)[index_of(m, x)];
		after.insert({p.x(), p.y(), p.z()});
	});
	for (const Vec3& p : corners)
		EXPECT_TRUE(after.count({p.x(), p.y(), p.z()}));
	const Valences v = valences(m);
	EXPECT_GT(v.regular, v.total * 6 / 10) << v.regular << " of " << v.total;
	EXPECT_LT(modeling::vertex_distance_to_surface(m, *pos, input).max, 1e-9);
}

TEST(Remeshing, FeatureEdgesOfACubeStay)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, test::box_soup());
	modeling::triangulate_faces(m, *pos);
	modeling::RemeshingOptions o;
	o.target_edge_length = 0.2;
	o.feature_angle = 45.0;
	const auto r = modeling::isotropic_remeshing(m, *pos, o);
	EXPECT_GT(r.splits, 0u);
	EXPECT_TRUE(check_integrity(m).ok());
	uint32 corners = 0;
	foreach_cell(m, [&](Vertex x) {
		const Vec3& p = (*pos)[index_of(m, x)];
		// on the cube's surface: one coordinate is 0 or 1, all in [0, 1]
		const double to_face = std::min({p.x(), 1 - p.x(), p.y(), 1 - p.y(), p.z(), 1 - p.z()});
		EXPECT_NEAR(to_face, 0.0, 1e-12);
		uint32 extreme = 0;
		for (int k = 0; k < 3; ++k)
			extreme += (p[k] == 0.0 || p[k] == 1.0) ? 1 : 0;
		corners += extreme == 3 ? 1 : 0;
	});
	EXPECT_EQ(corners, 8u);
	// the 12 cube edges, split into pieces of at most 4/3 L, are still edges of the mesh
	double sharp = 0.0;
	foreach_cell(m, [&](Edge e) {
		if (std::abs(geometry::dihedral_angle(m, e, *pos)) > 1.0)
			sharp += geometry::edge_length(m, e, *pos);
	});
	EXPECT_NEAR(sharp, 12.0, 1e-9);
}

TEST(Remeshing, CancellationLeavesAValidMap)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, sphere_soup(32, 16, true));
	modeling::RemeshingOptions o;
	o.target_edge_length = 0.05;
	const auto r = modeling::isotropic_remeshing(m, *pos, o, [](double f) { return f < 0.3; });
	EXPECT_TRUE(r.cancelled);
	EXPECT_LT(r.iterations, 10u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_TRUE(all_triangles(m));
}

TEST(Remeshing, BadInputThrows)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, test::box_soup());
	EXPECT_THROW(modeling::isotropic_remeshing(m, *pos), Error); // quads
	modeling::triangulate_faces(m, *pos);
	modeling::RemeshingOptions o;
	o.target_edge_length = -1.0;
	EXPECT_THROW(modeling::isotropic_remeshing(m, *pos, o), Error);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(TriangleTree, ClosestPointsOnAGrid)
{
	CMap2 m;
	auto pos = test::build_with_positions(m, grid_soup(10, 10, true));
	const modeling::TriangleTree tree(m, *pos);
	EXPECT_EQ(tree.size(), 200u);
	const auto h = tree.closest_point(Vec3(3.25, 4.5, 2.0));
	EXPECT_NEAR(h.squared_distance, 4.0, 1e-12);
	EXPECT_NEAR((h.point - Vec3(3.25, 4.5, 0.0)).norm(), 0.0, 1e-12);
	const auto outside = tree.closest_point(Vec3(-1.0, 12.0, 1.0)); // nearest: the corner (0, 10, 0)
	EXPECT_NEAR((outside.point - Vec3(0.0, 10.0, 0.0)).norm(), 0.0, 1e-12);
	EXPECT_NEAR(outside.squared_distance, 1.0 + 4.0 + 1.0, 1e-12);
}

TEST(Remeshing, NefertitiAtItsMeanEdgeLength)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/nefertiti.obj");
	CMap2 m;
	io::load_surface(m, path);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	const modeling::TriangleTree input(m, *pos);
	modeling::RemeshingOptions o;
	o.iterations = 3;
	const auto r = modeling::isotropic_remeshing(m, *pos, o); // L = the mean edge length
	EXPECT_NEAR(r.target_edge_length, 2.98, 0.01);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_TRUE(all_triangles(m));
	EXPECT_EQ(nb_cells<Vertex>(m) - nb_cells<Edge>(m) + nb_cells<CMap2::Face>(m), 2u); // still genus 0
	EXPECT_NEAR(geometry::mean_edge_length(m, *pos), r.target_edge_length, 0.1 * r.target_edge_length);
	const Valences v = valences(m);
	EXPECT_GT(v.regular, v.total * 7 / 10) << v.regular << " of " << v.total;
	EXPECT_LT(modeling::vertex_distance_to_surface(m, *pos, input).max, 1e-9);
}

} // namespace cgogn_test_remeshing
