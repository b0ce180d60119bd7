// SPDX-License-Identifier: MIT
// Analysis and synthesis of multiresolution 2-maps against the flat schemes.
#include <cgogn/cgogn.h>

#include "../geometry/geometry_test_meshes.h"
#include "modeling_test_utils.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace cgogn_test_multiresolution
{

using namespace cgogn;
using namespace cgogn::modeling;
using namespace cgogn::modeling_test;

namespace
{

/// The largest distance between the points of a and their closest points
/// in b, when each point of b is the closest of exactly one point of a;
/// infinity otherwise. Points closer than 1e-6 are found through a grid.
double matched_distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
	if (a.size() != b.size())
		return INFINITY;
	constexpr double h = 1e-6;
	using Key = std::tuple<int64_t, int64_t, int64_t>;
	const auto key = [](const Vec3& p, int dx, int dy, int dz) {
		return Key{int64_t(std::floor(p.x() / h)) + dx, int64_t(std::floor(p.y() / h)) + dy,
				   int64_t(std::floor(p.z() / h)) + dz};
	};
	std::map<Key, std::vector<uint32>> grid;
	for (uint32 i = 0; i < b.size(); ++i)
		grid[key(b[i], 0, 0, 0)].push_back(i);
	std::vector<bool> used(b.size(), false);
	double worst = 0.0;
	for (const Vec3& p : a)
	{
		double best = INFINITY;
		uint32 found = INVALID_INDEX;
		for (int dx = -1; dx <= 1; ++dx)
			for (int dy = -1; dy <= 1; ++dy)
				for (int dz = -1; dz <= 1; ++dz)
				{
					auto it = grid.find(key(p, dx, dy, dz));
					if (it == grid.end())
						continue;
					for (uint32 j : it->second)
						if ((b[j] - p).norm() < best)
						{
							best = (b[j] - p).norm();
							found = j;
						}
				}
		if (found == INVALID_INDEX || used[found])
			return INFINITY;
		used[found] = true;
		worst = std::max(worst, best);
	}
	return worst;
}

template <typename MESH>
std::vector<Vec3> vertex_positions(const MESH& m, const AttributeArray<Vec3>& pos)
{
	std::vector<Vec3> v;
	foreach_cell(m, [&](typename mesh_traits<MESH>::Vertex x) { v.push_back(value<Vec3>(m, pos, x)); });
	return v;
}

/// Level 0 in an MR map with positions, and a flat copy of it.
struct Pair
{
	CMap2 flat;
	std::shared_ptr<AttributeArray<Vec3>> flat_pos;
	MRMap2 mr;
	std::shared_ptr<AttributeArray<Vec3>> pos;
	std::shared_ptr<AttributeArray<Vec3>> details;
};
template <typename MAKE>
Pair make_pair_of(const MAKE& make)
{
	CMap2 a, b;
	make(a);
	make(b);
	auto fp = get_attribute<Vec3, CMap2::Vertex>(a, "position");
	MRMap2 mr(std::move(b));
	auto pos = get_attribute<Vec3, MRMap2::Vertex>(mr, "position");
	auto details = add_attribute<Vec3, MRMap2::Vertex>(mr, "details");
	return Pair{std::move(a), fp, std::move(mr), pos, details};
}

void load_into(CMap2& m, const std::string& name)
{
	ASSERT_TRUE(load_data(m, name));
}

/// Adds k levels and checks that, with zero details, each level has the
/// positions of as many steps of the flat scheme.
void expect_flat_scheme(Pair& p, MRBank bank, uint32 k)
{
	const Refinement r = bank == MRBank::Loop ? Refinement::Triangular : Refinement::Quadrangular;
	for (uint32 l = 1; l <= k; ++l)
		add_level(p.mr, r);
	synthesis(p.mr, *p.pos, *p.details, bank);
	for (uint32 l = 1; l <= k; ++l)
	{
		if (bank == MRBank::Loop)
			loop_subdivision(p.flat, *p.flat_pos);
		else
			catmull_clark_subdivision(p.flat, *p.flat_pos);
		const double d =
			matched_distance(vertex_positions(p.flat, *p.flat_pos), vertex_positions(level_view(p.mr, l), *p.pos));
		EXPECT_LE(d, 1e-12) << "level " << l;
	}
}

/// A deterministic perturbation of every finest position.
void perturb(Pair& p, double amplitude)
{
	uint32 i = 0;
	set_current_level(p.mr, max_level(p.mr));
	foreach_cell(p.mr, [&](MRMap2::Vertex v) {
		value<Vec3>(p.mr, p.pos, v) += amplitude * Vec3(test::noise(i), test::noise(i + 1), test::noise(i + 2));
		i += 3;
	});
}

std::vector<Vec3> finest(const Pair& p)
{
	return vertex_positions(level_view(p.mr, max_level(p.mr)), *p.pos);
}

double max_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
	double d = 0.0;
	for (std::size_t i = 0; i < a.size(); ++i)
		d = std::max(d, (a[i] - b[i]).norm());
	return a.size() == b.size() ? d : INFINITY;
}

} // namespace

TEST(Multiresolution, ZeroDetailsGiveCatmullClark)
{
	Pair cube = make_pair_of([](CMap2& m) { test::build_with_positions(m, test::box_soup(1.0, 2.0, 0.5)); });
	expect_flat_scheme(cube, MRBank::CatmullClark, 4);
	Pair torus = make_pair_of([](CMap2& m) { load_into(m, "torus_quad.off"); });
	expect_flat_scheme(torus, MRBank::CatmullClark, 3);
	// polygons of any degree and a boundary
	Pair grid = make_pair_of([](CMap2& m) { test::build_with_positions(m, grid_soup(4, 3, false)); });
	expect_flat_scheme(grid, MRBank::CatmullClark, 3);
}

TEST(Multiresolution, ZeroDetailsGiveLoop)
{
	Pair tet = make_pair_of([](CMap2& m) { load_into(m, "tetrahedron.off"); });
	expect_flat_scheme(tet, MRBank::Loop, 4);
	Pair grid = make_pair_of([](CMap2& m) { test::build_with_positions(m, grid_soup(4, 3, true)); });
	expect_flat_scheme(grid, MRBank::Loop, 3);
	Pair hemisphere = make_pair_of([](CMap2& m) { load_into(m, "hemisphere.off"); });
	expect_flat_scheme(hemisphere, MRBank::Loop, 1);
}

TEST(Multiresolution, AnalysisThenSynthesisIsExact)
{
	for (MRBank bank : {MRBank::Linear, MRBank::Loop, MRBank::CatmullClark})
	{
		Pair p = bank == MRBank::Loop
					 ? make_pair_of([](CMap2& m) { load_into(m, "tetrahedron.off"); })
					 : make_pair_of([](CMap2& m) { test::build_with_positions(m, test::box_soup(1.0, 2.0, 0.5)); });
		const Refinement r = bank == MRBank::Loop ? Refinement::Triangular : Refinement::Quadrangular;
		for (int l = 0; l < 3; ++l)
			add_level(p.mr, r);
		synthesis(p.mr, *p.pos, *p.details, bank);
		perturb(p, 0.05);
		const std::vector<Vec3> before = finest(p);
		analysis(p.mr, *p.pos, *p.details, bank);
		// the coarse levels changed, the finest did not
		EXPECT_EQ(max_difference(finest(p), before), 0.0);
		synthesis(p.mr, *p.pos, *p.details, bank);
		EXPECT_LE(max_difference(finest(p), before), 1e-12) << int(bank);
		EXPECT_TRUE(check_integrity(p.mr).ok());
	}
}

TEST(Multiresolution, AnalysisInvertsSynthesis)
{
	for (MRBank bank : {MRBank::Linear, MRBank::Loop, MRBank::CatmullClark})
	{
		Pair p = bank == MRBank::Loop ? make_pair_of([](CMap2& m) { load_into(m, "tetrahedron.off"); })
									  : make_pair_of([](CMap2& m) { load_into(m, "torus_quad.off"); });
		const std::vector<Vec3> coarse = vertex_positions(p.mr, *p.pos);
		const Refinement r = bank == MRBank::Loop ? Refinement::Triangular : Refinement::Quadrangular;
		add_level(p.mr, r);
		add_level(p.mr, r);
		synthesis(p.mr, *p.pos, *p.details, bank);
		// scramble the coarse levels: analysis must find them again
		set_current_level(p.mr, 0);
		foreach_cell(p.mr, [&](MRMap2::Vertex v) { value<Vec3>(p.mr, p.pos, v) = Vec3(7.0, 7.0, 7.0); });
		analysis(p.mr, *p.pos, *p.details, bank);
		EXPECT_LE(max_difference(vertex_positions(level_view(p.mr, 0), *p.pos), coarse), 1e-9) << int(bank);
		double largest = 0.0;
		for (uint32 l = 1; l <= 2; ++l)
			foreach_cell(level_view(p.mr, l), [&](MRMap2::Vertex v) {
				largest = std::max(largest, value<Vec3>(level_view(p.mr, l), *p.details, v).norm());
			});
		EXPECT_LE(largest, 1e-9) << int(bank);
	}
}

TEST(Multiresolution, BandFilters)
{
	Pair p = make_pair_of([](CMap2& m) { load_into(m, "torus_quad.off"); });
	for (int l = 0; l < 3; ++l)
		add_level(p.mr, Refinement::Quadrangular);
	synthesis(p.mr, *p.pos, *p.details, MRBank::CatmullClark);
	const std::vector<Vec3> smooth = finest(p);
	perturb(p, 0.01);
	const std::vector<Vec3> rough = finest(p);
	// keeping every level changes nothing
	filter_low_pass(p.mr, *p.pos, MRBank::CatmullClark, 3);
	EXPECT_LE(max_difference(finest(p), rough), 1e-12);
	// keeping level 0 only: the subdivision surface of the analysed level 0,
	// which the noise moved a little only
	filter_low_pass(p.mr, *p.pos, MRBank::CatmullClark, 0);
	const std::vector<Vec3> low = finest(p);
	EXPECT_LT(max_difference(low, smooth), max_difference(rough, smooth));
	// dropping levels 1 ... 3 is keeping level 0
	Pair q = make_pair_of([](CMap2& m) { load_into(m, "torus_quad.off"); });
	for (int l = 0; l < 3; ++l)
		add_level(q.mr, Refinement::Quadrangular);
	synthesis(q.mr, *q.pos, *q.details, MRBank::CatmullClark);
	perturb(q, 0.01);
	filter_high_pass(q.mr, *q.pos, MRBank::CatmullClark, 3);
	EXPECT_LE(max_difference(finest(q), low), 1e-12);
	EXPECT_TRUE((get_attribute<Vec3, MRMap2::Vertex>(q.mr, "filter details") == nullptr));
}

TEST(Multiresolution, BanksRefuseOtherRefinements)
{
	Pair p = make_pair_of([](CMap2& m) { load_into(m, "tetrahedron.off"); });
	add_level(p.mr, Refinement::Quadrangular);
	EXPECT_THROW(synthesis(p.mr, *p.pos, *p.details, MRBank::Loop), std::invalid_argument);
	Pair q = make_pair_of([](CMap2& m) { load_into(m, "tetrahedron.off"); });
	add_level(q.mr, Refinement::Triangular);
	EXPECT_THROW(synthesis(q.mr, *q.pos, *q.details, MRBank::CatmullClark), std::invalid_argument);
	EXPECT_NO_THROW(synthesis(q.mr, *q.pos, *q.details, MRBank::Linear));
}

} // namespace cgogn_test_multiresolution
