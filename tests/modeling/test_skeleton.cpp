#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace cgogn_test_skeleton
{

using namespace cgogn;

struct Surface
{
	CMap2 m;
	std::shared_ptr<AttributeArray<Vec3>> pos;
};

Surface from_soup(const SurfaceSoup& s)
{
	Surface out;
	const BuildReport r = build_surface(out.m, s);
	out.pos = add_attribute<Vec3, CMap2::Vertex>(out.m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*out.pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return out;
}

Surface from_file(const std::string& name)
{
	Surface out;
	io::load_surface(out.m, cgogn_test_data::path("surface/" + name));
	out.pos = get_attribute<Vec3, CMap2::Vertex>(out.m, "position");
	return out;
}

// The skeleton is a valid, connected graph of the given cycle rank, inside
// the surface's bounding box.
void expect_skeleton(const Surface& s, uint32 genus)
{
	std::vector<double> fractions;
	modeling::SkeletonOptions options;
	options.progress = [&](double f) {
		fractions.push_back(f);
		return true;
	};
	const Graph g = modeling::skeleton(s.m, *s.pos, options);
	EXPECT_TRUE(check_integrity(g).ok());
	EXPECT_GT(nb_cells<Graph::Edge>(g), 0u);
	EXPECT_EQ(nb_connected_components(g), 1u);
	EXPECT_EQ(cycle_rank(g), genus);
	Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
	foreach_cell(s.m, [&](CMap2::Vertex v) {
		lo = lo.cwiseMin(value<Vec3>(s.m, s.pos, v));
		hi = hi.cwiseMax(value<Vec3>(s.m, s.pos, v));
	});
	auto gpos = get_attribute<Vec3, Graph::Vertex>(g, "position");
	ASSERT_TRUE(gpos);
	const Vec3 slack = 1e-9 * (hi - lo);
	foreach_cell(g, [&](Graph::Vertex v) {
		const Vec3& p = value<Vec3>(g, gpos, v);
		EXPECT_TRUE((p.array() >= (lo - slack).array()).all() && (p.array() <= (hi + slack).array()).all()) << p;
	});
	ASSERT_FALSE(fractions.empty());
	EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
	EXPECT_EQ(fractions.back(), 1.0);
}

TEST(Skeleton, SphereGivesATree)
{
	expect_skeleton(from_soup(sphere_soup(24, 12, true)), 0);
}

TEST(Skeleton, TorusGivesOneLoop)
{
	const Surface s = from_soup(torus_soup(32, 12, true));
	expect_skeleton(s, 1);
	// the loop follows the tube's core: the circle of radius 1 in z = 0
	// (the tube's radius is 0.5)
	const Graph g = modeling::skeleton(s.m, *s.pos);
	auto gpos = get_attribute<Vec3, Graph::Vertex>(g, "position");
	EXPECT_GE(nb_cells<Graph::Vertex>(g), 3u);
	foreach_cell(g, [&](Graph::Vertex v) {
		const Vec3& p = value<Vec3>(g, gpos, v);
		EXPECT_LT(std::abs(p[2]), 0.1) << p;
		EXPECT_NEAR(std::hypot(p[0], p[1]), 1.0, 0.3) << p;
	});
}

TEST(Skeleton, ClosedMeshesFromFiles)
{
	expect_skeleton(from_file("torus_quad.off"), 1);
	expect_skeleton(from_file("tetrahedron.off"), 0);
	expect_skeleton(from_file("fandisk_quads.off"), 0);
}

TEST(Skeleton, CancelledEarlyStillGivesAGraph)
{
	const Surface s = from_soup(torus_soup(32, 12, true));
	modeling::SkeletonOptions options;
	options.progress = [](double) { return false; };
	const Graph g = modeling::skeleton(s.m, *s.pos, options);
	EXPECT_TRUE(check_integrity(g).ok());
	EXPECT_EQ(nb_connected_components(g), 1u);
}

TEST(Skeleton, OpenSurfacesAreRefused)
{
	const Surface s = from_file("hemisphere.off");
	EXPECT_THROW(modeling::skeleton(s.m, *s.pos), Error);
}

} // namespace cgogn_test_skeleton
