// SPDX-License-Identifier: MIT
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <map>

namespace cgogn_test_smoothing
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;
using Vertex = CMap2::Vertex;

namespace
{
// A 12 x 12 triangle grid whose inner vertices are lifted by noise of
// amplitude 0.1; the noise measure is the sum of z^2.
struct NoisyGrid
{
	CMap2 m;
	test::Pos pos;
	std::vector<Vec3> boundary_before;

	NoisyGrid(bool triangles = true)
	{
		pos = build_with_positions(m, grid_soup(12, 12, triangles));
		foreach_cell(m, [&](Vertex v) {
			Vec3& p = value<Vec3>(m, pos, v);
			if (is_incident_to_boundary(m, v))
				boundary_before.push_back(p);
			else
				p.z() = 0.1 * test::noise(index_of(m, v));
		});
	}
	double noise_measure() const
	{
		double s = 0.0;
		foreach_cell(m, [&](Vertex v) { s += value<Vec3>(m, pos, v).z() * value<Vec3>(m, pos, v).z(); });
		return s;
	}
	bool boundary_unchanged() const
	{
		std::vector<Vec3> now;
		foreach_cell(m, [&](Vertex v) {
			if (is_incident_to_boundary(m, v))
				now.push_back(value<Vec3>(m, pos, v));
		});
		return now == boundary_before;
	}
};

using Filter = std::function<void(CMap2&, AttributeArray<Vec3>&)>;
} // namespace

TEST(Smoothing, EveryFilterDenoisesAndKeepsTheBoundary)
{
	const std::vector<std::pair<const char*, Filter>> filters = {
		{"laplacian", [](CMap2& m, AttributeArray<Vec3>& p) { laplacian_smoothing(m, p, 10); }},
		{"taubin", [](CMap2& m, AttributeArray<Vec3>& p) { taubin_smoothing(m, p, 10); }},
		{"implicit cotan", [](CMap2& m, AttributeArray<Vec3>& p) { implicit_smoothing(m, p, 1.0); }},
		{"implicit uniform", [](CMap2& m, AttributeArray<Vec3>& p) { implicit_smoothing(m, p, 5.0, 2, true); }},
		{"bilateral", [](CMap2& m, AttributeArray<Vec3>& p) { bilateral_normal_filtering(m, p); }},
	};
	for (bool triangles : {true, false})
		for (const auto& [name, filter] : filters)
		{
			SCOPED_TRACE(name);
			NoisyGrid g(triangles);
			const double before = g.noise_measure();
			filter(g.m, *g.pos);
			EXPECT_LT(g.noise_measure(), 0.25 * before);
			EXPECT_TRUE(g.boundary_unchanged());
		}
}

TEST(Smoothing, FreeBoundaryMoves)
{
	NoisyGrid g;
	laplacian_smoothing(g.m, *g.pos, 3, 0.5, false);
	EXPECT_FALSE(g.boundary_unchanged());
}

TEST(Smoothing, TaubinShrinksLessThanLaplacian)
{
	auto make = [](CMap2& m) {
		auto pos = build_with_positions(m, sphere_soup(32, 16, true));
		uint32 i = 0;
		for (Vec3& p : *pos)
			p *= 1.0 + 0.02 * test::noise(i++);
		return pos;
	};
	CMap2 a, b, c;
	auto pa = make(a);
	auto pb = make(b);
	auto pc = make(c);
	const double v0 = signed_volume(a, *pa);
	laplacian_smoothing(a, *pa, 20);
	taubin_smoothing(b, *pb, 20);
	implicit_smoothing(c, *pc, 1e-3);
	const double lap = std::abs(signed_volume(a, *pa) - v0);
	const double tau = std::abs(signed_volume(b, *pb) - v0);
	const double imp = std::abs(signed_volume(c, *pc) - v0);
	// measured: laplacian loses 46 % of the volume, taubin 2.7 %, implicit 0.6 %
	EXPECT_LT(tau, 0.1 * lap);
	EXPECT_LT(tau, 0.05 * v0);
	EXPECT_LT(imp, 0.02 * v0);
}

TEST(Smoothing, FlatMeshesStayFlat)
{
	CMap2 m;
	auto pos = build_with_positions(m, grid_soup(6, 6, true));
	uint32 i = 0;
	for (Vec3& p : *pos)
		p += 0.3 * Vec3(test::noise(i), test::noise(i + 50), 0.0), ++i;
	implicit_smoothing(m, *pos, 0.5, 3, false, false);
	taubin_smoothing(m, *pos, 5, 0.5, -0.53, false);
	bilateral_normal_filtering(m, *pos);
	for (const Vec3& p : *pos)
		EXPECT_NEAR(p.z(), 0.0, 1e-12);
}

TEST(Smoothing, VolumeMeshInnerVertexReturnsToCentre)
{
	CMap3 m;
	auto pos = build_with_positions(m, hex_grid_soup(2, 2, 2));
	const CMap3::Vertex centre = test::closest_vertex(m, *pos, Vec3(1, 1, 1));
	value<Vec3>(m, pos, centre) = Vec3(1.3, 0.8, 1.1);
	laplacian_smoothing(m, *pos, 60);
	EXPECT_NEAR((value<Vec3>(m, pos, centre) - Vec3(1, 1, 1)).norm(), 0.0, 1e-12);
	foreach_cell(m, [&](CMap3::Vertex v) {
		if (!is_incident_to_boundary(m, v))
			return;
		const Vec3& p = value<Vec3>(m, pos, v);
		EXPECT_EQ(p, p.array().round().matrix()); // still on the integer lattice
	});
}

TEST(Smoothing, BilateralKeepsASharpEdge)
{
	// a box with noisy vertices: the filter restores flat faces, so the edges
	// stay at right angles instead of being rounded
	CMap2 m;
	auto pos = build_with_positions(m, test::box_soup(1, 1, 1));
	CMap2 fine;
	SurfaceSoup s;
	// subdivide each box face into a 6 x 6 grid of quads, merging shared vertices
	std::map<std::array<long, 3>, uint32> ids;
	auto vid = [&](const Vec3& p) {
		const std::array<long, 3> key = {std::lround(p.x() * 6), std::lround(p.y() * 6), std::lround(p.z() * 6)};
		auto [it, inserted] = ids.emplace(key, s.nb_vertices);
		if (inserted)
		{
			s.positions.push_back({p.x(), p.y(), p.z()});
			++s.nb_vertices;
		}
		return it->second;
	};
	foreach_cell(m, [&](CMap2::Face f) {
		std::vector<Vec3> c;
		foreach_incident_vertex(m, f, [&](Vertex v) { c.push_back(value<Vec3>(m, pos, v)); });
		for (int j = 0; j < 6; ++j)
			for (int i = 0; i < 6; ++i)
			{
				auto at = [&](double u, double w) { return c[0] + u * (c[1] - c[0]) + w * (c[3] - c[0]); };
				s.face_sizes.push_back(4);
				s.face_vertices.insert(s.face_vertices.end(),
									   {vid(at(i / 6.0, j / 6.0)), vid(at((i + 1) / 6.0, j / 6.0)),
										vid(at((i + 1) / 6.0, (j + 1) / 6.0)), vid(at(i / 6.0, (j + 1) / 6.0))});
			}
	});
	auto fpos = build_with_positions(fine, s);
	ASSERT_EQ(nb_cells<Vertex>(fine), 6u * 49u - 12u * 7u + 8u);
	uint32 i = 0;
	for (Vec3& p : *fpos)
		p += 0.01 * Vec3(test::noise(i), test::noise(i + 999), test::noise(i + 1999)), ++i;
	auto flatness = [&] { // mean distance of the vertices to their box face plane
		double d = 0.0;
		for (const Vec3& p : *fpos)
		{
			const Vec3 q = (p - Vec3(0.5, 0.5, 0.5)).cwiseAbs();
			d += std::abs(0.5 - q.maxCoeff());
		}
		return d / nb_cells<Vertex>(fine);
	};
	const double before = flatness();
	bilateral_normal_filtering(fine, *fpos, {.normal_iterations = 20, .vertex_iterations = 20, .sigma_r = 0.35});
	EXPECT_LT(flatness(), 0.5 * before);
	// corners stay corners: the angle-weighted normal there is still diagonal
	const Vertex corner = test::closest_vertex(fine, *fpos, Vec3(1, 1, 1));
	EXPECT_GT(vertex_normal(fine, corner, *fpos).dot(Vec3(1, 1, 1).normalized()), 0.98);
}

TEST(Smoothing, ImplicitReportsASingularSystem)
{
	CMap2 m;
	auto pos = build_with_positions(m, sphere_soup(8, 5, true));
	for (Vec3& p : *pos)
		p = Vec3(1, 2, 3); // collapsed: no area, no weights
	EXPECT_THROW(implicit_smoothing(m, *pos, 1.0), Error);
}

} // namespace cgogn_test_smoothing
