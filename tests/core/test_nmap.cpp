// SPDX-License-Identifier: MIT
// Maps of any dimension: the f-vectors and Euler characteristics of the
// generated objects against their closed forms, for D = 2 ... 5, on CMapN
// and GMapN; their boundaries; the builders' errors; the conversions.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <nmap_test_support.h>
#include <set>
#include <utility>
#include <vector>

namespace cgogn_test_nmap
{

using namespace cgogn;
using cgogn::test::binomial;

namespace
{

uint64 power(uint64 b, uint32 e)
{
	uint64 r = 1;
	while (e-- > 0)
		r *= b;
	return r;
}

std::vector<uint32> simplex_f_vector(uint32 D)
{
	std::vector<uint32> f;
	for (uint32 k = 0; k <= D; ++k)
		f.push_back(uint32(binomial(D + 1, k + 1)));
	return f;
}

// the cells of the n^D grid; those of its boundary (k < D) with `boundary`
std::vector<uint32> grid_f_vector(uint32 D, uint32 n, bool boundary = false)
{
	std::vector<uint32> f;
	for (uint32 k = 0; k <= D; ++k)
	{
		if (boundary && k == D)
			break;
		const uint64 all = binomial(D, k) * power(n, k) * power(n + 1, D - k);
		const uint64 inner = binomial(D, k) * power(n, k) * power(n - 1, D - k);
		f.push_back(uint32(boundary ? all - inner : all));
	}
	return f;
}

// the proper faces of a polytope with f-vector f: its boundary's f-vector
std::vector<uint32> without_top(std::vector<uint32> f)
{
	f.pop_back();
	return f;
}

template <typename MAP>
void expect_ball(const MAP& m, const std::vector<uint32>& f)
{
	constexpr uint32 D = MAP::dimension;
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(f_vector(m), f);
	EXPECT_EQ(euler_characteristic(m), 1);
	EXPECT_EQ(nb_connected_components(m), 1u);
	const auto b = extract_boundary(m);
	EXPECT_TRUE(check_integrity(b).ok()) << check_integrity(b).to_string();
	EXPECT_FALSE(has_boundary(b));
	EXPECT_EQ(euler_characteristic(b), D % 2 == 1 ? 2 : 0); // 1 + (-1)^(D - 1)
	EXPECT_EQ(nb_connected_components(b), 1u);
}

template <typename MAP>
void check_generators(uint32 n, uint32 n_simplicial)
{
	constexpr uint32 D = MAP::dimension;
	SCOPED_TRACE(std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(D) + ">");
	{
		MAP m;
		generate_simplex(m);
		expect_ball(m, simplex_f_vector(D));
		EXPECT_EQ(f_vector(extract_boundary(m)), without_top(simplex_f_vector(D)));
		// (D + 1)! / 2 darts in the simplex of a CMapN, twice that in a GMapN, and as many outside
		EXPECT_EQ(
			nb_darts(m), power(2, is_gmap_v<MAP>) * [] {
				uint64 r = 1;
				for (uint32 i = 2; i <= D + 1; ++i)
					r *= i;
				return r;
			}());
	}
	{
		MAP m;
		generate_cube(m);
		expect_ball(m, grid_f_vector(D, 1));
		EXPECT_EQ(f_vector(extract_boundary(m)), without_top(grid_f_vector(D, 1)));
	}
	{
		MAP m;
		generate_cube_grid(m, n);
		expect_ball(m, grid_f_vector(D, n));
		EXPECT_EQ(f_vector(extract_boundary(m)), grid_f_vector(D, n, true));
	}
	{
		MAP m;
		generate_freudenthal_grid(m, n_simplicial);
		uint64 simplices = power(n_simplicial, D);
		for (uint32 i = 2; i <= D; ++i)
			simplices *= i;
		const std::vector<uint32> f = f_vector(m);
		EXPECT_EQ(f.front(), power(n_simplicial + 1, D));
		EXPECT_EQ(f.back(), simplices);
		expect_ball(m, f);
		// its boundary is the cube's boundary, triangulated: as many vertices as the grid's
		EXPECT_EQ(f_vector(extract_boundary(m)).front(), grid_f_vector(D, n_simplicial, true).front());
	}
}

} // namespace

TEST(NMapGenerators, FVectorsOfSimplicesCubesAndGridsForDimensions2To5)
{
	// the simplicial grid of the 5-cube: 120 simplices of 720 flags per cube
	check_generators<CMapN<2>>(4, 4);
	check_generators<GMapN<2>>(4, 4);
	check_generators<CMapN<3>>(3, 3);
	check_generators<GMapN<3>>(3, 3);
	check_generators<CMapN<4>>(2, 2);
	check_generators<GMapN<4>>(2, 2);
	check_generators<CMapN<5>>(2, 1);
	check_generators<GMapN<5>>(2, 1);
}

TEST(NMapGenerators, OneDimensionalMapsArePaths)
{
	CMapN<1> c;
	generate_cube_grid(c, 5);
	EXPECT_EQ(f_vector(c), (std::vector<uint32>{6, 5}));
	EXPECT_EQ(euler_characteristic(c), 1);
	EXPECT_TRUE(check_integrity(c).ok()) << check_integrity(c).to_string();
	GMapN<1> g;
	generate_cube_grid(g, 5);
	EXPECT_EQ(f_vector(g), (std::vector<uint32>{6, 5}));
	EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
}

TEST(NMapGenerators, PositionsAreTheGridPoints)
{
	CMapN<3> m;
	generate_cube_grid(m, 2);
	auto position = get_attribute<PointD<3>, CellD<0>>(m, "position");
	ASSERT_TRUE(position);
	std::set<std::vector<double>> points;
	foreach_cell(m, [&](CellD<0> v) {
		const PointD<3>& p = (*position)[v];
		points.insert({p[0], p[1], p[2]});
	});
	EXPECT_EQ(points.size(), 27u);
	EXPECT_TRUE(points.count({0.5, 0.5, 0.5}));
	EXPECT_TRUE(points.count({1.0, 0.0, 1.0}));
	EXPECT_THROW(generate_cube_grid(m, 2), Error); // not empty
}

TEST(NMapBuilder, BadComplexesThrowAndLeaveTheMapEmpty)
{
	CMapN<2> m;
	const std::vector<uint32> out_of_range{0, 1, 5};
	EXPECT_THROW(build_simplicial_complex(m, 3, out_of_range), Error);
	const std::vector<uint32> repeated{0, 1, 1};
	EXPECT_THROW(build_simplicial_complex(m, 3, repeated), Error);
	const std::vector<uint32> ragged{0, 1, 2, 3};
	EXPECT_THROW(build_simplicial_complex(m, 4, ragged), Error);
	// three triangles on one edge
	const std::vector<uint32> fin{0, 1, 2, 0, 1, 3, 0, 1, 4};
	EXPECT_THROW(build_simplicial_complex(m, 5, fin), Error);
	// two cubes on the square 1 3 5 7, the second one naming a diagonal of
	// it (1 7) as an edge
	const std::vector<uint32> twisted{0, 1, 2, 3, 4, 5, 6, 7, 1, 8, 7, 9, 3, 10, 5, 11};
	CMapN<3> cubes;
	EXPECT_THROW(build_cubical_complex(cubes, 12, twisted), Error);
	// the same square seen from its other side (a symmetry of the square) is fine
	const std::vector<uint32> flipped{0, 1, 2, 3, 4, 5, 6, 7, 1, 8, 5, 9, 3, 10, 7, 11};
	CMapN<3> glued;
	build_cubical_complex(glued, 12, flipped);
	EXPECT_EQ(f_vector(glued), (std::vector<uint32>{12, 20, 11, 2}));
	EXPECT_EQ(nb_darts(m), 0u);
	EXPECT_EQ(nb_darts(cubes), 0u);
}

TEST(NMapBuilder, NonOrientableComplexesFitOnlyGMaps)
{
	// a Möbius strip of 5 triangles: vertices 0..4 around, glued with a twist
	const std::vector<uint32> strip{0, 1, 2, 1, 2, 3, 2, 3, 4, 3, 4, 0, 4, 0, 1};
	CMapN<2> c;
	EXPECT_THROW(build_simplicial_complex(c, 5, strip), TopologyError);
	EXPECT_EQ(nb_darts(c), 0u);
	GMapN<2> g;
	build_simplicial_complex(g, 5, strip);
	EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
	EXPECT_FALSE(is_orientable(g));
	EXPECT_EQ(f_vector(g), (std::vector<uint32>{5, 10, 5}));
	EXPECT_EQ(euler_characteristic(g), 0);
	EXPECT_THROW(to_cmap(g), TopologyError);
}

TEST(NMapBuilder, VerticesAreReturnedById)
{
	GMapN<3> m;
	const std::vector<uint32> two_tets{0, 1, 2, 3, 1, 2, 3, 5};
	const std::vector<CellD<0>> v = build_simplicial_complex(m, 6, two_tets);
	ASSERT_EQ(v.size(), 6u);
	EXPECT_FALSE(v[4].is_valid()); // no tetrahedron uses id 4
	EXPECT_EQ(f_vector(m), (std::vector<uint32>{5, 9, 7, 2}));
	// vertex 0 and vertex 5 share no edge; 1, 2 and 3 are everybody's neighbours
	uint32 n0 = 0, n1 = 0;
	foreach_adjacent_cell<1>(m, v[0], [&](CellD<0>) { ++n0; });
	foreach_adjacent_cell<1>(m, v[1], [&](CellD<0>) { ++n1; });
	EXPECT_EQ(n0, 3u);
	EXPECT_EQ(n1, 4u);
	EXPECT_FALSE(same_cell(m, v[0], v[5]));
}

TEST(NMapConversions, CombinatorialAndGeneralizedMapsRoundTrip)
{
	CMapN<4> c;
	generate_cube_grid(c, 2);
	add_attribute<uint32, CellD<3>>(c, "tag");
	const GMapN<4> g = to_gmap(c);
	EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
	EXPECT_EQ(nb_darts(g), 2 * nb_darts(c));
	EXPECT_EQ(f_vector(g), f_vector(c));
	EXPECT_TRUE((get_attribute<PointD<4>, CellD<0>>(g, "position")));
	EXPECT_TRUE((get_attribute<uint32, CellD<3>>(g, "tag")));
	const CMapN<4> back = to_cmap(g);
	EXPECT_TRUE(check_integrity(back).ok()) << check_integrity(back).to_string();
	EXPECT_EQ(nb_darts(back), nb_darts(c));
	EXPECT_EQ(f_vector(back), f_vector(c));
}

TEST(NMapIntegrity, BrokenRelationsAreReported)
{
	CMapN<4> m;
	generate_cube(m);
	ASSERT_TRUE(check_integrity(m).ok());
	// unsew the 4-cube from the boundary along one dart
	Dart d;
	foreach_dart(m, [&](Dart x) {
		if (is_boundary(m, x))
			return true;
		d = x;
		return false;
	});
	phi_unsew<4>(m, d);
	const IntegrityReport r = check_integrity(m);
	EXPECT_FALSE(r.ok());
	EXPECT_TRUE(r.has(IntegrityError::Kind::PhiFixedPoint));
}

TEST(NMapCells, AttributesMarkersAndViewsWorkOnEveryDimension)
{
	GMapN<4> m;
	generate_cube_grid(m, 2);
	// attributes: lazily indexed, one value per cell
	auto tag = add_attribute<uint32, CellD<2>>(m, "tag");
	ASSERT_TRUE(tag);
	EXPECT_TRUE(is_indexed<CellD<2>>(m));
	EXPECT_EQ(container_of<Orbit::CELL2>(m).nb_lines(), nb_cells<2>(m));
	uint32 k = 0;
	foreach_cell(m, [&](CellD<2> f) { (*tag)[f] = k++; });
	foreach_cell(m, [&](CellD<2> f) {
		foreach_dart_of_orbit(m, f, [&](Dart d) { EXPECT_EQ((*tag)[CellD<2>(d)], (*tag)[f]); });
	});
	// markers of indexed and unindexed orbits
	CellMarker<GMapN<4>, CellD<3>> marked(m);
	uint32 n = 0;
	foreach_cell(m, [&](CellD<3> c) {
		if (n++ % 2 == 0)
			marked.mark(c);
	});
	uint32 seen = 0;
	foreach_cell(m, [&](CellD<3> c) { seen += marked.is_marked(c); });
	EXPECT_EQ(seen, (n + 1) / 2);
	// a filter and a cache of the 4-cells on the boundary
	CellFilter<GMapN<4>> filter(m);
	filter.set_filter<CellD<4>>([&](CellD<4> h) { return is_incident_to_boundary(m, h); });
	CellCache<GMapN<4>> cache(m);
	cache.build<CellD<4>>([&](CellD<4> h) { return is_incident_to_boundary(m, h); });
	EXPECT_EQ(nb_cells<CellD<4>>(filter), 16u); // every 4-cell of the 2^4 grid touches the boundary
	EXPECT_EQ(nb_cells<CellD<4>>(cache), 16u);
	CellCache<GMapN<4>> inner(m);
	inner.build<CellD<0>>([&](CellD<0> v) { return !is_incident_to_boundary(m, v); });
	EXPECT_EQ(nb_cells<CellD<0>>(inner), 1u); // the centre of the grid
}

namespace
{

// The smallest dart of the cell: a key that does not depend on indexing.
template <typename MAP, typename CELL>
uint32 smallest_dart(const MAP& m, CELL c)
{
	uint32 k = c.dart.index;
	foreach_dart_of_orbit(m, c, [&](Dart d) { k = std::min(k, d.index); });
	return k;
}

// Each vertex's 4-cells and each 4-cell's neighbours through 3-cells, as
// sorted keys per cell, with the total count of each.
template <typename MAP>
std::pair<std::set<std::vector<uint32>>, std::set<std::vector<uint32>>> stars_and_neighbours(const MAP& m)
{
	std::set<std::vector<uint32>> stars, neighbours;
	foreach_cell(m, [&](CellD<0> v) {
		std::vector<uint32> row{smallest_dart(m, v)};
		foreach_incident_cell<4>(m, v, [&](CellD<4> h) { row.push_back(smallest_dart(m, h)); });
		std::sort(row.begin() + 1, row.end());
		stars.insert(row);
	});
	foreach_cell(m, [&](CellD<4> h) {
		std::vector<uint32> row{smallest_dart(m, h)};
		foreach_adjacent_cell<3>(m, h, [&](CellD<4> n) { row.push_back(smallest_dart(m, n)); });
		std::sort(row.begin() + 1, row.end());
		neighbours.insert(row);
	});
	return {stars, neighbours};
}

template <typename MAP>
void check_stars_indexed_or_not()
{
	SCOPED_TRACE(is_gmap_v<MAP> ? "GMapN<4>" : "CMapN<4>");
	MAP m;
	generate_freudenthal_grid(m, 2);
	const auto plain = stars_and_neighbours(m);
	// the centre of the grid lies in 5! simplices (a corner with k of its 4
	// coordinates at 1 is in k! (4 - k)! simplices of its hypercube): more
	// than the small array of lines a star starts with
	std::size_t largest = 0, sides = 0;
	for (const auto& row : plain.first)
		largest = std::max(largest, row.size() - 1);
	for (const auto& row : plain.second)
		sides += row.size() - 1;
	EXPECT_EQ(largest, 120u);
	// every inner tetrahedron has a 4-simplex on each side
	const std::vector<uint32> f = f_vector(m);
	const uint32 boundary_facets = nb_cells<3>(extract_boundary(m));
	EXPECT_EQ(sides, 2u * (f[3] - boundary_facets));
	index_cells<CellD<4>>(m);
	EXPECT_EQ(stars_and_neighbours(m), plain);
}

} // namespace

TEST(NMapTraversals, StarsAndNeighboursAreTheSameIndexedOrNot)
{
	check_stars_indexed_or_not<CMapN<4>>();
	check_stars_indexed_or_not<GMapN<4>>();
}

} // namespace cgogn_test_nmap
