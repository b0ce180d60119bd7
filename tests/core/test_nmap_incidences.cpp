// SPDX-License-Identifier: MIT
// The traversals once per incidence (each_incidence) of the maps of any
// dimension: on manifold grids they give the cells of the traversals that
// report each cell once; on a torus made of one cube, whose cells meet the
// cube many times, they give one cell per face of the cube; counted from
// either side, the incidences agree; in a G-map they are the orbits of the
// beta_k, k != i, j.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <nmap_test_support.h>
#include <numeric>
#include <set>
#include <string>
#include <vector>

namespace cgogn_test_nmap_incidences
{

using namespace cgogn;
using cgogn::test::binomial;
using cgogn::test::key_of;
using cgogn::test::relation;

namespace
{

template <typename MAP>
std::string name_of()
{
	return std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(MAP::dimension) + ">";
}

template <uint32 I, uint32 J, typename MAP, typename... EACH>
std::map<uint32, std::vector<uint32>> incidence(const MAP& m, EACH... each)
{
	return relation<CellD<I>>(m, [&](auto c, const auto& put) {
		foreach_incident_cell<J>(
			m, c, [&](CellD<J> x) { put(x); }, each...);
	});
}

template <uint32 I, uint32 K, typename MAP, typename... EACH>
std::map<uint32, std::vector<uint32>> adjacency(const MAP& m, EACH... each)
{
	return relation<CellD<I>>(m, [&](auto c, const auto& put) {
		foreach_adjacent_cell<K>(
			m, c, [&](CellD<I> x) { put(x); }, each...);
	});
}

// The rows with each key once.
std::map<uint32, std::vector<uint32>> distinct(std::map<uint32, std::vector<uint32>> r)
{
	for (auto& [key, row] : r)
		row.erase(std::unique(row.begin(), row.end()), row.end());
	return r;
}

// The number of incidences of the I-cells with J-cells, summed over the I-cells.
template <uint32 I, uint32 J, typename MAP>
uint64 nb_incidences(const MAP& m)
{
	uint64 n = 0;
	foreach_cell(m, [&](CellD<I> c) {
		foreach_incident_cell<J>(
			m, c, [&](CellD<J>) { ++n; }, each_incidence);
	});
	return n;
}

// Calls f<I, J>() for every pair of distinct dimensions of MAP.
template <typename MAP, typename FUNC>
void foreach_pair_of_dimensions(const FUNC& f)
{
	constexpr uint32 D = MAP::dimension;
	[&]<uint32... I>(std::integer_sequence<uint32, I...>)
	{
		(
			[&]<uint32 II>(std::integral_constant<uint32, II>) {
				[&]<uint32... J>(std::integer_sequence<uint32, J...>)
				{
					(
						[&]<uint32 JJ>(std::integral_constant<uint32, JJ>) {
							if constexpr (II != JJ)
								f.template operator()<II, JJ>();
						}(std::integral_constant<uint32, J>{}),
						...);
				}
				(std::make_integer_sequence<uint32, D + 1>{});
			}(std::integral_constant<uint32, I>{}),
			...);
	}
	(std::make_integer_sequence<uint32, D + 1>{});
}

template <typename MAP>
void check_manifold(const MAP& m)
{
	constexpr uint32 D = MAP::dimension;
	foreach_pair_of_dimensions<MAP>([&]<uint32 I, uint32 J>() {
		SCOPED_TRACE("I = " + std::to_string(I) + ", J = " + std::to_string(J));
		// every cell meets another at most once
		EXPECT_EQ((incidence<I, J>(m, each_incidence)), (incidence<I, J>(m)));
		EXPECT_EQ((nb_incidences<I, J>(m)), (nb_incidences<J, I>(m)));
		// a neighbour once per K-cell shared: the same cells
		const auto each = adjacency<I, J>(m, each_incidence);
		EXPECT_EQ(distinct(each), (adjacency<I, J>(m)));
		if constexpr ((I == 0 && J == 1) || (I == D && J + 1 == D))
		{
			EXPECT_EQ(each, (adjacency<I, J>(m))); // an edge has two ends, a facet two sides
		}
	});
}

// Sews the opposite facets of the D-cube of m (generate_cube) to each
// other, the first alignment the facets allow: a closed map of one D-cell.
template <typename MAP>
void close_into_torus(MAP& m)
{
	constexpr uint32 D = MAP::dimension;
	using Facet = CellD<D - 1>;
	Dart inside;
	foreach_dart(m, [&](Dart d) {
		inside = d;
		return is_boundary(m, d);
	});
	std::vector<std::pair<Facet, std::set<uint32>>> facets;
	foreach_incident_cell<D - 1>(m, CellD<D>(inside), [&](Facet f) {
		std::set<uint32> vertices;
		foreach_incident_cell<0>(m, f, [&](CellD<0> v) { vertices.insert(key_of(m, v)); });
		facets.emplace_back(f, vertices);
	});
	ASSERT_EQ(facets.size(), 2 * D);
	for (std::size_t a = 0; a < facets.size(); ++a)
		for (std::size_t b = a + 1; b < facets.size(); ++b)
		{
			std::vector<uint32> shared;
			std::set_intersection(facets[a].second.begin(), facets[a].second.end(), facets[b].second.begin(),
								  facets[b].second.end(), std::back_inserter(shared));
			if (!shared.empty())
				continue; // not opposite
			bool sewn = false;
			foreach_dart_of_orbit(m, facets[b].first, [&](Dart y) {
				if (!is_boundary(m, y) && can_sew_facets(m, facets[a].first, Facet(y)))
				{
					sew_facets(m, facets[a].first, Facet(y));
					sewn = true;
				}
				return !sewn;
			});
			ASSERT_TRUE(sewn);
			ASSERT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
		}
}

// In a G-map, the incidences of the I-cells with the J-cells are the orbits
// of the beta_k, k != I, J: their number, by a union of the darts.
template <uint32 I, uint32 J, uint32 D>
uint64 nb_beta_orbits(const GMapN<D>& m)
{
	std::vector<uint32> parent(container_of<Orbit::DART>(m).end_index());
	std::iota(parent.begin(), parent.end(), 0u);
	const auto root = [&](uint32 x) {
		while (parent[x] != x)
			x = parent[x] = parent[parent[x]];
		return x;
	};
	foreach_dart(m, [&](Dart d) {
		for (uint32 k = 0; k <= D; ++k)
			if (k != I && k != J)
				parent[root(d.index)] = root(k == 0 ? beta0(m, d).index : detail::relation(m, k, d).index);
	});
	uint64 n = 0;
	foreach_dart(m, [&](Dart d) { n += root(d.index) == d.index; });
	return n;
}

template <typename MAP>
void check_torus_of_one_cube()
{
	constexpr uint32 D = MAP::dimension;
	SCOPED_TRACE(name_of<MAP>());
	MAP m;
	generate_cube(m);
	close_into_torus(m);
	ASSERT_FALSE(has_boundary(m));
	ASSERT_EQ(f_vector(m).back(), 1u);
	CellD<D> cube;
	foreach_cell(m, [&](CellD<D> c) { cube = c; });
	foreach_pair_of_dimensions<MAP>([&]<uint32 I, uint32 J>() {
		SCOPED_TRACE("I = " + std::to_string(I) + ", J = " + std::to_string(J));
		EXPECT_EQ((nb_incidences<I, J>(m)), (nb_incidences<J, I>(m)));
		if constexpr (is_gmap_v<MAP>)
		{
			EXPECT_EQ((nb_incidences<I, J>(m)), (nb_beta_orbits<I, J>(m)));
		}
		if constexpr (J == D)
		{
			// the cube meets each I-cell once per I-face of the cube
			uint64 n = 0;
			foreach_incident_cell<I>(
				m, cube, [&](CellD<I>) { ++n; }, each_incidence);
			EXPECT_EQ(n, binomial(D, I) << (D - I));
			EXPECT_EQ((nb_incidences<I, D>(m)), n);
			n = 0;
			foreach_incident_cell<I>(m, cube, [&](CellD<I>) { ++n; });
			EXPECT_EQ(n, f_vector(m)[I]);
		}
	});
	// the cube's neighbours through its facets: itself, once per facet
	uint32 itself = 0;
	foreach_adjacent_cell<D - 1>(
		m, cube, [&](CellD<D> x) { itself += key_of(m, x) == key_of(m, cube); }, each_incidence);
	EXPECT_EQ(itself, 2 * D);
	bool any = false;
	foreach_adjacent_cell<D - 1>(m, cube, [&](CellD<D>) { any = true; });
	EXPECT_FALSE(any) << "each once, the cell itself excluded";
}

// f returning false stops the traversal, with or without marks
template <typename MAP>
void check_stop()
{
	SCOPED_TRACE(name_of<MAP>());
	constexpr uint32 D = MAP::dimension;
	MAP m;
	generate_cube_grid(m, 2);
	foreach_cell(m, [&](CellD<0> v) {
		uint32 calls = 0;
		foreach_incident_cell<D>(
			m, v, [&](CellD<D>) { return ++calls < 1; }, each_incidence);
		EXPECT_EQ(calls, 1u);
		calls = 0;
		foreach_adjacent_cell<1>(
			m, v, [&](CellD<0>) { return ++calls < 2; }, each_incidence);
		EXPECT_EQ(calls, 2u);
		calls = 0;
		foreach_adjacent_cell<D>(
			m, v, [&](CellD<0>) { return ++calls < 2; }, each_incidence);
		EXPECT_EQ(calls, 2u);
	});
}

} // namespace

TEST(NMapIncidences, ManifoldGridsGiveTheCellsEachOnce)
{
	const auto grids = []<typename MAP>() {
		SCOPED_TRACE(name_of<MAP>());
		MAP cubes, simplices;
		generate_cube_grid(cubes, 2);
		check_manifold(cubes);
		generate_freudenthal_grid(simplices, MAP::dimension < 4 ? 2 : 1); // 24 4-simplices
		check_manifold(simplices);
	};
	grids.template operator()<CMapN<2>>();
	grids.template operator()<GMapN<2>>();
	grids.template operator()<CMapN<3>>();
	grids.template operator()<GMapN<3>>();
	grids.template operator()<CMapN<4>>();
	grids.template operator()<GMapN<4>>();
}

TEST(NMapIncidences, ATorusOfOneCubeMeetsItsCellsOncePerFace)
{
	check_torus_of_one_cube<CMapN<2>>();
	check_torus_of_one_cube<GMapN<2>>();
	check_torus_of_one_cube<CMapN<3>>();
	check_torus_of_one_cube<GMapN<3>>();
	check_torus_of_one_cube<CMapN<4>>();
	check_torus_of_one_cube<GMapN<4>>();
}

TEST(NMapIncidences, TraversalsStopWhenAsked)
{
	check_stop<CMapN<2>>();
	check_stop<GMapN<2>>();
	check_stop<CMapN<3>>();
	check_stop<GMapN<4>>();
}

} // namespace cgogn_test_nmap_incidences
