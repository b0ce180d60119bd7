// SPDX-License-Identifier: MIT
// The operators of the maps of any dimension: exact f-vectors on known
// objects, inverse pairs, the sewing of D-cells, and randomized sequences with
// check_integrity after every step, for D = 2 ... 4, on CMapN and GMapN, with
// every orbit indexed.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <array>
#include <nmap_test_support.h>
#include <random>
#include <string>
#include <vector>

namespace cgogn_test_nmap_operators
{

using namespace cgogn;
using cgogn::test::binomial;

namespace
{

template <uint32 I, typename MAP>
std::vector<CellD<I>> cells_of(const MAP& m)
{
	std::vector<CellD<I>> v;
	foreach_cell(m, [&](CellD<I> c) { v.push_back(c); });
	return v;
}

template <typename MAP>
void index_every_dimension(MAP& m)
{
	[&]<std::size_t... K>(std::index_sequence<K...>)
	{
		(add_attribute<uint32, CellD<uint32(K)>>(m, "tag" + std::to_string(K)), ...);
	}
	(std::make_index_sequence<MAP::dimension + 1>{});
}

// The next corner of the side of a face (phi1, beta1 o beta0), k times.
template <typename MAP>
Dart next_corner(const MAP& m, Dart d, uint32 k = 1)
{
	for (uint32 i = 0; i < k; ++i)
		if constexpr (is_gmap_v<MAP>)
			d = beta<0, 1>(m, d);
		else
			d = phi<1>(m, d);
	return d;
}

std::vector<uint32> plus(std::vector<uint32> f, uint32 k, int delta)
{
	f[k] = uint32(int(f[k]) + delta);
	return f;
}

template <typename MAP>
void expect_ok(const MAP& m)
{
	const IntegrityReport r = check_integrity(m);
	ASSERT_TRUE(r.ok()) << r.to_string();
}

template <typename MAP>
void check_inverse_pairs()
{
	constexpr uint32 D = MAP::dimension;
	SCOPED_TRACE(std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(D) + ">");
	MAP m;
	generate_cube_grid(m, 2);
	index_every_dimension(m);
	const std::vector<uint32> f = f_vector(m);
	// a vertex in an edge, removed
	const CellD<0> v = insert_vertex_in_edge(m, cells_of<1>(m)[3]);
	expect_ok(m);
	EXPECT_EQ(f_vector(m), plus(plus(f, 0, 1), 1, 1));
	ASSERT_TRUE(can_remove_cell<0>(m, v));
	remove_cell<0>(m, v);
	expect_ok(m);
	EXPECT_EQ(f_vector(m), f);
	// a vertex in an edge, then one of the two halves contracted
	const CellD<0> w = insert_vertex_in_edge(m, cells_of<1>(m)[5]);
	ASSERT_TRUE(can_contract_cell<1>(m, CellD<1>(w.dart)));
	contract_cell<1>(m, CellD<1>(w.dart));
	expect_ok(m);
	EXPECT_EQ(f_vector(m), f);
	// an edge across a square face, removed
	const Dart d = cells_of<2>(m)[2].dart;
	const Dart across = next_corner(m, d, 2);
	ASSERT_TRUE(can_insert_edge_in_face(m, d, across));
	const CellD<1> e = insert_edge_in_face(m, d, across);
	expect_ok(m);
	EXPECT_EQ(f_vector(m), plus(plus(f, 1, 1), 2, 1));
	ASSERT_TRUE(can_remove_cell<1>(m, e));
	remove_cell<1>(m, e);
	expect_ok(m);
	EXPECT_EQ(f_vector(m), f);
	// a digon made by an edge between two neighbour vertices, contracted
	const Dart g = cells_of<2>(m)[1].dart;
	const Dart next = next_corner(m, g);
	ASSERT_TRUE(can_insert_edge_in_face(m, g, next));
	const CellD<1> chord = insert_edge_in_face(m, g, next);
	expect_ok(m);
	EXPECT_EQ(f_vector(m), plus(plus(f, 1, 1), 2, 1));
	// the digon is the face of the chord that holds one edge more
	CellD<2> digon;
	foreach_incident_cell<2>(m, chord, [&](CellD<2> x) {
		uint32 n = 0;
		foreach_incident_cell<1>(m, x, [&](CellD<1>) { ++n; });
		if (n == 2)
			digon = x;
	});
	ASSERT_TRUE(digon.is_valid());
	ASSERT_TRUE(can_contract_cell<2>(m, digon));
	contract_cell<2>(m, digon);
	expect_ok(m);
	EXPECT_EQ(f_vector(m), f);
	// the (D-1)-cell between two D-cells of the grid, removed
	for (CellD<D - 1> c : cells_of<D - 1>(m))
		if (can_remove_cell<D - 1>(m, c))
		{
			remove_cell<D - 1>(m, c);
			break;
		}
	expect_ok(m);
	EXPECT_EQ(f_vector(m), plus(plus(f, D - 1, -1), D, -1));
	EXPECT_EQ(euler_characteristic(m), 1);
}

// A random cell of dimension I, or an invalid one when there is none.
template <uint32 I, typename MAP>
CellD<I> random_cell(const MAP& m, std::mt19937& rng)
{
	const std::vector<CellD<I>> v = cells_of<I>(m);
	return v.empty() ? CellD<I>() : v[rng() % v.size()];
}

template <uint32 I, typename MAP>
bool try_remove(MAP& m, std::mt19937& rng)
{
	const CellD<I> c = random_cell<I>(m, rng);
	if (!c.is_valid() || !can_remove_cell<I>(m, c))
		return false;
	remove_cell<I>(m, c);
	return true;
}

template <uint32 I, typename MAP>
bool try_contract(MAP& m, std::mt19937& rng)
{
	const CellD<I> c = random_cell<I>(m, rng);
	if (!c.is_valid() || !can_contract_cell<I>(m, c))
		return false;
	contract_cell<I>(m, c);
	return true;
}

template <typename MAP>
void random_editing(uint32 steps, uint32 seed)
{
	constexpr uint32 D = MAP::dimension;
	SCOPED_TRACE(std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(D) + ">");
	std::mt19937 rng(seed);
	MAP m;
	generate_cube_grid(m, 2);
	index_every_dimension(m);
	std::vector<uint32> done(4, 0);
	for (uint32 step = 0; step < steps; ++step)
	{
		SCOPED_TRACE("step " + std::to_string(step));
		const uint32 op = rng() % 4;
		bool applied = false;
		if (op == 0)
		{
			insert_vertex_in_edge(m, random_cell<1>(m, rng));
			applied = true;
		}
		else if (op == 1)
		{
			// two corners of one side of a random face
			const CellD<2> f = random_cell<2>(m, rng);
			std::vector<Dart> side;
			Dart it = f.dart;
			do
			{
				side.push_back(it);
				it = next_corner(m, it);
			} while (it != f.dart);
			const Dart d2 = side[rng() % side.size()];
			if (can_insert_edge_in_face(m, f.dart, d2))
			{
				insert_edge_in_face(m, f.dart, d2);
				applied = true;
			}
		}
		else if (op == 2)
		{
			const uint32 i = rng() % D;
			[&]<std::size_t... K>(std::index_sequence<K...>)
			{
				((i == K ? (applied = try_remove<uint32(K)>(m, rng)) : false), ...);
			}
			(std::make_index_sequence<D>{});
		}
		else
		{
			const uint32 i = 1 + rng() % D;
			[&]<std::size_t... K>(std::index_sequence<K...>)
			{
				((i == K + 1 ? (applied = try_contract<uint32(K) + 1>(m, rng)) : false), ...);
			}
			(std::make_index_sequence<D>{});
		}
		if (!applied)
			continue;
		++done[op];
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << "after operation " << op << ":\n" << r.to_string();
		ASSERT_EQ(euler_characteristic(m), 1) << "after operation " << op;
		ASSERT_EQ(nb_connected_components(m), 1u);
	}
	// every kind of operation was exercised
	for (uint32 op = 0; op < 4; ++op)
		EXPECT_GT(done[op], 0u) << "operation " << op;
}

// Relation D of d: beta_D or phi_D.
template <typename MAP>
Dart across(const MAP& m, Dart d)
{
	if constexpr (is_gmap_v<MAP>)
		return beta<MAP::dimension>(m, d);
	else
		return phi<MAP::dimension>(m, d);
}

// Unsewing every inner facet of the grid 2^D leaves 2^D separate cubes;
// sewing the same darts back gives the grid again.
template <typename MAP>
void check_unsew_all_and_sew_back()
{
	constexpr uint32 D = MAP::dimension;
	SCOPED_TRACE(std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(D) + ">");
	MAP m;
	generate_cube_grid(m, 2);
	index_every_dimension(m);
	const std::vector<uint32> grid = f_vector(m);
	std::vector<std::pair<Dart, Dart>> glued;
	for (const CellD<D - 1> f : cells_of<D - 1>(m))
		if (can_unsew_facets(m, f))
			glued.emplace_back(f.dart, across(m, f.dart));
	ASSERT_EQ(glued.size(), D * (1u << (D - 1))); // D directions, 2^(D-1) facets each
	for (const auto& [x, y] : glued)
	{
		ASSERT_TRUE(can_unsew_facets(m, CellD<D - 1>(x)));
		unsew_facets(m, CellD<D - 1>(x));
		expect_ok(m);
		ASSERT_TRUE(is_boundary(m, across(m, x)));
		ASSERT_TRUE(is_boundary(m, across(m, y)));
	}
	const uint32 nb_cubes = 1u << D;
	std::vector<uint32> cubes(D + 1);
	for (uint32 k = 0; k <= D; ++k)
		cubes[k] = nb_cubes * uint32(binomial(D, k) << (D - k));
	EXPECT_EQ(f_vector(m), cubes);
	EXPECT_EQ(nb_connected_components(m), nb_cubes);
	EXPECT_EQ(euler_characteristic(m), int64(nb_cubes));
	for (const auto& [x, y] : glued)
	{
		ASSERT_TRUE(can_sew_facets(m, CellD<D - 1>(x), CellD<D - 1>(y)));
		sew_facets(m, CellD<D - 1>(x), CellD<D - 1>(y));
		expect_ok(m);
		ASSERT_EQ(across(m, x), y);
	}
	EXPECT_EQ(f_vector(m), grid);
	EXPECT_EQ(nb_connected_components(m), 1u);
}

// Random unsewing of inner facets and sewing of boundary facets, in any
// alignment their sides allow, with check_integrity after every step.
template <typename MAP>
void random_sewing(uint32 steps, uint32 seed)
{
	constexpr uint32 D = MAP::dimension;
	SCOPED_TRACE(std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(D) + ">");
	std::mt19937 rng(seed);
	MAP m;
	generate_cube_grid(m, 2);
	index_every_dimension(m);
	std::array<uint32, 2> done{};
	for (uint32 step = 0; step < steps; ++step)
	{
		SCOPED_TRACE("step " + std::to_string(step));
		const bool sew = rng() % 2 == 0;
		if (sew)
		{
			std::vector<Dart> open;
			foreach_dart(m, [&](Dart d) {
				if (!is_boundary(m, d) && is_boundary(m, across(m, d)))
					open.push_back(d);
			});
			if (open.empty())
				continue; // everything is sewn: the map is closed
			const CellD<D - 1> f1(open[rng() % open.size()]), f2(open[rng() % open.size()]);
			if (!can_sew_facets(m, f1, f2))
				continue;
			sew_facets(m, f1, f2);
			ASSERT_EQ(across(m, f1.dart), f2.dart);
		}
		else
		{
			const CellD<D - 1> f = random_cell<D - 1>(m, rng);
			if (!can_unsew_facets(m, f))
				continue;
			unsew_facets(m, f);
			ASSERT_TRUE(is_boundary(m, across(m, f.dart)));
		}
		++done[sew];
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << (sew ? "after a sew:\n" : "after an unsew:\n") << r.to_string();
	}
	EXPECT_GT(done[0], 0u);
	EXPECT_GT(done[1], 0u);
}

// Attribute rules through insertions: a vertex inserted in an edge gets the
// mean of the edge's two ends; both halves of the edge keep its tag; an
// edge inserted across a face splits it into two faces of its tag, and
// the new edge itself holds the default (0).
template <typename MAP>
void check_insertion_rules()
{
	SCOPED_TRACE(std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(MAP::dimension) + ">");
	MAP m;
	generate_cube_grid(m, 2);
	index_every_dimension(m);
	auto heat = add_attribute<double, CellD<0>>(m, "heat");
	auto edge_tag = add_attribute<int32, CellD<1>>(m, "tag");
	auto face_tag = add_attribute<int32, CellD<2>>(m, "tag");
	foreach_cell(m, [&](CellD<0> v) { (*heat)[index_of(m, v)] = 1.5 * double(index_of(m, v)); });
	foreach_cell(m, [&](CellD<1> e) { (*edge_tag)[index_of(m, e)] = 1 + int32(index_of(m, e)); });
	foreach_cell(m, [&](CellD<2> f) { (*face_tag)[index_of(m, f)] = 1 + int32(index_of(m, f)); });
	auto count = [&](const auto& attribute, int32 value, auto cell) {
		uint32 n = 0;
		foreach_cell(m, [&](decltype(cell) c) { n += (*attribute)[index_of(m, c)] == value; });
		return n;
	};

	const CellD<1> e = cells_of<1>(m)[3];
	Dart far;
	if constexpr (is_gmap_v<MAP>)
		far = beta<0>(m, e.dart);
	else
		far = phi<1>(m, e.dart);
	const double mean = 0.5 * ((*heat)[index_of(m, CellD<0>(e.dart))] + (*heat)[index_of(m, CellD<0>(far))]);
	const int32 t = (*edge_tag)[index_of(m, e)];
	const CellD<0> v = insert_vertex_in_edge(m, e);
	expect_ok(m);
	EXPECT_DOUBLE_EQ((*heat)[index_of(m, v)], mean);
	EXPECT_EQ(count(edge_tag, t, CellD<1>()), 2u);

	const CellD<2> f = cells_of<2>(m)[2];
	const int32 ft = (*face_tag)[index_of(m, f)];
	const CellD<1> across = insert_edge_in_face(m, f.dart, next_corner(m, f.dart, 2));
	expect_ok(m);
	EXPECT_EQ(count(face_tag, ft, CellD<2>()), 2u);
	EXPECT_EQ((*edge_tag)[index_of(m, across)], 0);
}

} // namespace

TEST(NMapOperators, InsertionsFollowTheAttributeRules)
{
	check_insertion_rules<CMapN<2>>();
	check_insertion_rules<GMapN<2>>();
	check_insertion_rules<CMapN<3>>();
	check_insertion_rules<GMapN<3>>();
	check_insertion_rules<CMapN<4>>();
	check_insertion_rules<GMapN<4>>();
}

TEST(NMapOperators, InsertionsAreUndoneByRemovalAndContraction)
{
	check_inverse_pairs<CMapN<2>>();
	check_inverse_pairs<GMapN<2>>();
	check_inverse_pairs<CMapN<3>>();
	check_inverse_pairs<GMapN<3>>();
	check_inverse_pairs<CMapN<4>>();
	check_inverse_pairs<GMapN<4>>();
}

TEST(NMapOperators, RandomSequencesKeepTheMapValid)
{
	random_editing<CMapN<2>>(300, 1);
	random_editing<GMapN<2>>(300, 2);
	random_editing<CMapN<3>>(200, 3);
	random_editing<GMapN<3>>(200, 4);
	random_editing<CMapN<4>>(120, 5);
	random_editing<GMapN<4>>(120, 6);
}

TEST(NMapOperators, ImpossibleOperationsAreRefused)
{
	CMapN<3> m;
	generate_cube(m);
	// a vertex of a cube has three edges, a face of it lies on the boundary,
	// a square is not a digon, a cube is not flat
	const CellD<0> v = cells_of<0>(m)[0];
	EXPECT_FALSE(can_remove_cell<0>(m, v));
	EXPECT_FALSE(can_remove_cell<2>(m, cells_of<2>(m)[0]));
	EXPECT_FALSE(can_contract_cell<2>(m, cells_of<2>(m)[0]));
	EXPECT_FALSE(can_contract_cell<3>(m, cells_of<3>(m)[0]));
	EXPECT_TRUE(can_contract_cell<1>(m, cells_of<1>(m)[0]));
	const Dart d = cells_of<2>(m)[0].dart;
	EXPECT_FALSE(can_insert_edge_in_face(m, d, d));
	EXPECT_FALSE(can_insert_edge_in_face(m, d, phi<2>(m, d)));
}

TEST(NMapOperators, UnsewingEveryInnerFacetAndSewingBackRestoresTheGrid)
{
	check_unsew_all_and_sew_back<CMapN<2>>();
	check_unsew_all_and_sew_back<GMapN<2>>();
	check_unsew_all_and_sew_back<CMapN<3>>();
	check_unsew_all_and_sew_back<GMapN<3>>();
	check_unsew_all_and_sew_back<CMapN<4>>();
	check_unsew_all_and_sew_back<GMapN<4>>();
}

TEST(NMapOperators, RandomSewingKeepsTheMapValid)
{
	random_sewing<CMapN<2>>(200, 7);
	random_sewing<GMapN<2>>(200, 8);
	random_sewing<CMapN<3>>(150, 9);
	random_sewing<GMapN<3>>(150, 10);
	random_sewing<CMapN<4>>(80, 11);
	random_sewing<GMapN<4>>(80, 12);
}

TEST(NMapOperators, ImpossibleSewsAreRefused)
{
	GMapN<3> m;
	generate_cube_grid(m, 2);
	Dart inner, open;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			return;
		(is_boundary(m, beta<3>(m, d)) ? open : inner) = d;
	});
	// an inner facet is not sewn again, a boundary facet is not unsewn, a
	// facet is not sewn to itself, a boundary dart is not sewn
	EXPECT_FALSE(can_sew_facets(m, CellD<2>(inner), CellD<2>(open)));
	EXPECT_FALSE(can_unsew_facets(m, CellD<2>(open)));
	EXPECT_FALSE(can_sew_facets(m, CellD<2>(open), CellD<2>(beta<0>(m, open))));
	EXPECT_FALSE(can_sew_facets(m, CellD<2>(open), CellD<2>(beta<3>(m, open))));
	EXPECT_TRUE(can_unsew_facets(m, CellD<2>(inner)));
	// a triangle does not face a square: a diagonal cuts a boundary square
	Dart square;
	foreach_dart(m, [&](Dart d) {
		if (!is_boundary(m, d) && is_boundary(m, beta<3>(m, d)) && !same_orbit(m, CellD<2>(d), CellD<2>(open)))
			square = d;
	});
	EXPECT_TRUE(can_sew_facets(m, CellD<2>(open), CellD<2>(square)));
	const CellD<1> diagonal = insert_edge_in_face(m, open, next_corner(m, open, 2));
	ASSERT_FALSE(is_boundary(m, diagonal.dart));
	EXPECT_FALSE(can_sew_facets(m, CellD<2>(diagonal.dart), CellD<2>(square)));
}

} // namespace cgogn_test_nmap_operators
