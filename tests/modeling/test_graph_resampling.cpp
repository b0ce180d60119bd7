#include <cgogn/cgogn.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace cgogn_test_graph_resampling
{

using namespace cgogn;
using Vertex = Graph::Vertex;
using Edge = Graph::Edge;

struct Polyline
{
	Graph g;
	std::shared_ptr<AttributeArray<Vec3>> pos = add_attribute<Vec3, Vertex>(g, "position");
	std::vector<Vertex> v;
	Vertex add(const Vec3& p)
	{
		v.push_back(add_vertex(g));
		value<Vec3>(g, pos, v.back()) = p;
		return v.back();
	}
};

TEST(GraphResampling, PathGetsEvenSpacingAndKeepsItsEnds)
{
	Polyline in;
	for (int i = 0; i < 10; ++i)
		in.add(Vec3(i, 0, 0));
	for (int i = 0; i + 1 < 10; ++i)
		connect_vertices(in.g, in.v[i], in.v[i + 1]);
	auto radius = add_attribute<double, Vertex>(in.g, "radius");
	for (int i = 0; i < 10; ++i)
		value<double>(in.g, radius, in.v[i]) = double(i);
	Graph out;
	auto pos = modeling::resample_graph(in.g, *in.pos, 2.5, out); // length 9: 4 edges of 2.25
	EXPECT_TRUE(check_integrity(out).ok());
	EXPECT_EQ(nb_cells<Vertex>(out), 5u);
	EXPECT_EQ(nb_cells<Edge>(out), 4u);
	auto out_radius = get_attribute<double, Vertex>(out, "radius");
	ASSERT_TRUE(out_radius);
	std::vector<double> xs;
	foreach_cell(out, [&](Vertex v) {
		const Vec3& p = value<Vec3>(out, pos, v);
		xs.push_back(p[0]);
		EXPECT_EQ(p[1], 0.0);
		EXPECT_NEAR(value<double>(out, out_radius, v), p[0], 1e-12); // the radius was x
	});
	std::sort(xs.begin(), xs.end());
	for (int i = 0; i < 5; ++i)
		EXPECT_NEAR(xs[i], 2.25 * i, 1e-12);
	// the same as a new graph
	const Graph fresh = modeling::resample_graph(in.g, *in.pos, 2.5);
	EXPECT_EQ(nb_cells<Vertex>(fresh), 5u);
	EXPECT_EQ(nb_cells<Edge>(fresh), 4u);
	EXPECT_TRUE((get_attribute<Vec3, Vertex>(fresh, "position")));
	foreach_cell(out, [&](Edge e) {
		EXPECT_NEAR((value<Vec3>(out, pos, Vertex(e.dart)) - value<Vec3>(out, pos, Vertex(alpha0(out, e.dart)))).norm(),
					2.25, 1e-12);
	});
}

TEST(GraphResampling, StarCycleAndIsolatedVertexKeepTheirTopology)
{
	Polyline in;
	// a star: centre and 3 arms of length 4 in 4 edges each
	const Vertex centre = in.add(Vec3(0, 0, 0));
	for (int arm = 0; arm < 3; ++arm)
	{
		Vertex prev = centre;
		for (int i = 1; i <= 4; ++i)
		{
			const Vertex x = in.add(Vec3(arm == 0 ? i : 0, arm == 1 ? i : 0, arm == 2 ? i : 0));
			connect_vertices(in.g, prev, x);
			prev = x;
		}
	}
	// a circle of 8 vertices, radius 1, centred at (10, 0, 0)
	std::vector<Vertex> ring;
	for (int i = 0; i < 8; ++i)
		ring.push_back(in.add(Vec3(10 + std::cos(i * std::numbers::pi / 4), std::sin(i * std::numbers::pi / 4), 0)));
	for (int i = 0; i < 8; ++i)
		connect_vertices(in.g, ring[i], ring[(i + 1) % 8]);
	in.add(Vec3(-5, -5, -5)); // isolated
	Graph out;
	auto pos = modeling::resample_graph(in.g, *in.pos, 1.0 / 3.0, out);
	EXPECT_TRUE(check_integrity(out).ok());
	EXPECT_EQ(nb_connected_components(out), nb_connected_components(in.g));
	EXPECT_EQ(cycle_rank(out), cycle_rank(in.g));
	// arms: 12 edges each; the ring's perimeter 8 x 2 sin(pi/8) = 6.12: 18 edges
	EXPECT_EQ(nb_cells<Edge>(out), 3u * 12u + 18u);
	EXPECT_EQ(nb_cells<Vertex>(out), 1u + 3u * 12u + 18u + 1u);
	uint32 centres = 0, isolated = 0;
	foreach_cell(out, [&](Vertex v) {
		centres += degree(out, v) == 3 && value<Vec3>(out, pos, v) == Vec3(0, 0, 0);
		isolated += degree(out, v) == 0 && value<Vec3>(out, pos, v) == Vec3(-5, -5, -5);
	});
	EXPECT_EQ(centres, 1u);
	EXPECT_EQ(isolated, 1u);
	EXPECT_FALSE((get_attribute<double, Vertex>(out, "radius"))); // the input had none
}

TEST(GraphResampling, BadSpacingOrOutputAttributeAppendsNothing)
{
	Polyline in;
	connect_vertices(in.g, in.add(Vec3(0, 0, 0)), in.add(Vec3(1, 0, 0)));
	Graph out;
	for (double s : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()})
		EXPECT_THROW(modeling::resample_graph(in.g, *in.pos, s, out), Error);
	EXPECT_THROW(modeling::resample_graph(in.g, *in.pos, 1e-12, out), Error); // 10^12 edges
	EXPECT_EQ(nb_darts(out), 0u);
	add_attribute<double, Vertex>(out, "position");
	EXPECT_THROW(modeling::resample_graph(in.g, *in.pos, 0.5, out), Error);
	EXPECT_EQ(nb_darts(out), 0u);
}

} // namespace cgogn_test_graph_resampling
