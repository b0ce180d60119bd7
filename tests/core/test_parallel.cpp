// parallel_foreach_cell gives the same results as foreach_cell for every cell
// type of CMap2, CMap3, GMap2, GMap3 and the maps of any dimension, indexed or
// not, with 1, 2 and more workers than cores; thread indices are dense and
// never shared by two running callables.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <random>
#include <tuple>
#include <vector>

namespace cgogn_test_parallel
{

using namespace cgogn;

// The smallest dart of c's orbit: a name for the cell independent of its
// representative dart.
template <typename MAP, typename CELL>
uint32 cell_id(const MAP& m, CELL c)
{
	uint32 id = INVALID_INDEX;
	foreach_dart_of_orbit(m, c, [&](Dart d) { id = std::min(id, d.index); });
	return id;
}

class Parallel : public ::testing::TestWithParam<uint32>
{
protected:
	void SetUp() override
	{
		set_nb_workers(GetParam());
	}
	void TearDown() override
	{
		set_nb_workers(0);
	}

	// Visits every CELL both ways; compares the cell sets (no cell twice), a
	// per-thread reduction and the dense, exclusive use of thread indices.
	template <typename CELL, typename MAP>
	void check_cells(const MAP& m)
	{
		SCOPED_TRACE(std::string(orbit_name(CELL::ORBIT)));
		std::vector<uint32> expected;
		foreach_cell(m, [&](CELL c) { expected.push_back(cell_id(m, c)); });
		std::sort(expected.begin(), expected.end());

		const uint32 nw = thread_pool()->nb_workers();
		EXPECT_EQ(nw, GetParam());
		std::vector<std::vector<uint32>> per_thread(nw);
		std::vector<uint64> darts_per_thread(nw, 0);
		auto busy = std::make_unique<std::atomic<bool>[]>(nw);
		std::atomic<uint32> bad_index{0}, shared_index{0};
		parallel_foreach_cell(m, [&](CELL c) {
			const uint32 t = current_thread_index();
			if (t >= nw)
			{
				++bad_index;
				return;
			}
			if (busy[t].exchange(true))
				++shared_index;
			per_thread[t].push_back(cell_id(m, c));
			foreach_dart_of_orbit(m, c, [&](Dart) { ++darts_per_thread[t]; });
			busy[t].store(false);
		});
		EXPECT_EQ(bad_index.load(), 0u);
		EXPECT_EQ(shared_index.load(), 0u);
		std::vector<uint32> got;
		for (const auto& v : per_thread)
			got.insert(got.end(), v.begin(), v.end());
		std::sort(got.begin(), got.end());
		EXPECT_EQ(got, expected);

		uint64 seq_darts = 0, par_darts = 0;
		foreach_cell(m, [&](CELL c) { foreach_dart_of_orbit(m, c, [&](Dart) { ++seq_darts; }); });
		for (uint64 n : darts_per_thread)
			par_darts += n;
		EXPECT_EQ(par_darts, seq_darts);
	}

	template <typename MAP>
	void check_all_cell_types(const MAP& m)
	{
		[&]<typename... C>(std::tuple<C...>*) {
			(check_cells<C>(m), ...);
		}(static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
	}

	template <typename MAP>
	void index_all_cell_types(MAP& m)
	{
		[&]<typename... C>(std::tuple<C...>*) {
			(index_cells<C>(m), ...);
		}(static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
	}
};

TEST_P(Parallel, SurfaceWithBoundaryAllCellTypes)
{
	CMap2 m;
	build_surface(m, grid_soup(40, 30, true)); // one boundary loop
	check_all_cell_types(m);
	index_all_cell_types(m);
	check_all_cell_types(m);
}

TEST_P(Parallel, ClosedSurfaceAllCellTypes)
{
	CMap2 m;
	build_surface(m, torus_soup(30, 20)); // quads
	build_surface(m, sphere_soup(12, 6)); // a second connected component
	check_all_cell_types(m);
	index_all_cell_types(m);
	check_all_cell_types(m);
}

TEST_P(Parallel, TetVolumeAllCellTypes)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(5, 4, 3));
	check_all_cell_types(m);
	index_all_cell_types(m);
	check_all_cell_types(m);
}

TEST_P(Parallel, MapsOfAnyDimensionAllCellTypes)
{
	CMapN<4> c;
	generate_cube_grid(c, 2);
	check_all_cell_types(c); // vertices indexed (positions), the others not
	index_all_cell_types(c);
	check_all_cell_types(c);
	GMapN<3> g;
	generate_freudenthal_grid(g, 2);
	check_all_cell_types(g);
	CMapN<1> path;
	generate_cube_grid(path, 5); // its last vertex is the start of a boundary edge
	check_all_cell_types(path);
}

TEST_P(Parallel, GraphAllCellTypes)
{
	// a random multigraph with self-loops and isolated vertices (passed over
	// by the edge traversals)
	Graph g;
	std::mt19937 rng(3);
	std::vector<Graph::Vertex> v;
	for (uint32 i = 0; i < 3000; ++i)
		v.push_back(add_vertex(g));
	std::uniform_int_distribution<std::size_t> any(0, 2499);
	for (uint32 i = 0; i < 5000; ++i)
		connect_vertices(g, v[any(rng)], v[any(rng)]);
	check_all_cell_types(g);
	index_all_cell_types(g);
	check_all_cell_types(g);
}

TEST_P(Parallel, HexVolumeAllCellTypes)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(6, 5, 4));
	check_all_cell_types(m);
	index_all_cell_types(m);
	check_all_cell_types(m);
}

TEST_P(Parallel, PerCellWritesEqualSequential)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(6, 5, 4));
	using Vertex = CMap3::Vertex;
	using Volume = CMap3::Volume;
	auto seq = add_attribute<uint32, Vertex>(m, "seq");
	auto par = add_attribute<uint32, Vertex>(m, "par");
	auto wseq = add_attribute<uint32, Volume>(m, "wseq");
	auto wpar = add_attribute<uint32, Volume>(m, "wpar");
	// markers and local traversals inside the callable (pooled, per thread)
	auto neighbourhood = [&](Vertex v) {
		uint32 n = 0;
		foreach_adjacent_vertex_through_volume(m, v, [&](Vertex) { ++n; });
		CellMarkerStore<CMap3, Volume> cm(m);
		foreach_incident_volume(m, v, [&](Volume w) { cm.mark(w); });
		return n * 1000 + uint32(cm.marked_cells().size());
	};
	foreach_cell(m, [&](Vertex v) { value<uint32>(m, seq, v) = neighbourhood(v); });
	parallel_foreach_cell(m, [&](Vertex v) { value<uint32>(m, par, v) = neighbourhood(v); });
	foreach_cell(m, [&](Vertex v) { EXPECT_EQ(value<uint32>(m, seq, v), value<uint32>(m, par, v)); });

	auto volume_degree = [&](Volume w) {
		uint32 n = 0;
		foreach_adjacent_volume_through_vertex(m, w, [&](Volume) { ++n; });
		return n;
	};
	foreach_cell(m, [&](Volume w) { value<uint32>(m, wseq, w) = volume_degree(w); });
	parallel_foreach_cell(m, [&](Volume w) { value<uint32>(m, wpar, w) = volume_degree(w); });
	foreach_cell(m, [&](Volume w) { EXPECT_EQ(value<uint32>(m, wseq, w), value<uint32>(m, wpar, w)); });
	EXPECT_TRUE(check_integrity(m).ok()); // every marker was given back cleared
}

TEST_P(Parallel, NestedTraversalRunsSequentially)
{
	CMap2 m;
	build_surface(m, grid_soup(8, 8));
	const uint32 nf = nb_cells<CMap2::Face>(m);
	std::atomic<uint64> total{0};
	parallel_foreach_cell(m, [&](CMap2::Face) {
		uint32 n = 0;
		parallel_foreach_cell(m, [&](CMap2::Face) { ++n; }); // no race on n: sequential
		total += n;
	});
	EXPECT_EQ(total.load(), uint64(nf) * nf);
}

TEST_P(Parallel, FilterAndCache)
{
	CMap2 m;
	build_surface(m, torus_soup(40, 20, true));
	using Vertex = CMap2::Vertex;
	auto id = add_attribute<uint32, Vertex>(m, "id");
	uint32 k = 0;
	foreach_cell(m, [&](Vertex v) { value<uint32>(m, id, v) = k++; });
	CellFilter<CMap2> filter(m);
	filter.set_filter<Vertex>([&](Vertex v) { return value<uint32>(m, id, v) % 3 == 0; });
	CellCache<CMap2> cache(m);
	cache.build<Vertex>([&](Vertex v) { return value<uint32>(m, id, v) % 5 == 0; });
	const uint32 nw = thread_pool()->nb_workers();
	std::vector<uint64> f_sum(nw, 0), c_sum(nw, 0);
	parallel_foreach_cell(filter, [&](Vertex v) { f_sum[current_thread_index()] += value<uint32>(m, id, v); });
	parallel_foreach_cell(cache, [&](Vertex v) { c_sum[current_thread_index()] += value<uint32>(m, id, v); });
	uint64 fe = 0, ce = 0;
	for (uint32 i = 0; i < k; ++i)
	{
		fe += i % 3 == 0 ? i : 0;
		ce += i % 5 == 0 ? i : 0;
	}
	uint64 fs = 0, cs = 0;
	for (uint32 t = 0; t < nw; ++t)
	{
		fs += f_sum[t];
		cs += c_sum[t];
	}
	EXPECT_EQ(fs, fe);
	EXPECT_EQ(cs, ce);
}

TEST_P(Parallel, ParallelIncidenceCacheBuildMatchesTraversal)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(4, 4, 3));
	using Vertex = CMap3::Vertex;
	IncidenceCache<CMap3, Vertex, Vertex, CMap3::Volume>::build(m);
	EXPECT_TRUE(check_integrity(m).ok());
}

// Removes the index of orbit O from m, as if no attribute had ever been added
// on it (builders index 3-D vertices): the traversals then take the
// non-indexed path.
template <typename CELL, typename MAP>
void drop_index(MAP& m)
{
	AttributeArray<uint32>*& idx = cgogn::detail::state_of(m).cell_index[orbit_index(CELL::ORBIT)];
	ASSERT_NE(idx, nullptr);
	ASSERT_TRUE(cgogn::detail::state_of(m).darts->remove_attribute(idx));
	idx = nullptr;
}

// The flooded orbits (3-D vertices, volumes, connected components), not
// indexed, on maps large enough to be split among the workers (hundreds of
// chunks): each cell exactly once, with boundary volumes, on tets and hexes.
TEST_P(Parallel, FloodedOrbitsNotIndexedLargeMaps)
{
	using Vertex = CMap3::Vertex;
	using Volume = CMap3::Volume;
	for (bool hexes : {false, true})
	{
		SCOPED_TRACE(hexes ? "hexes" : "tets");
		CMap3 m;
		build_volume(m, hexes ? hex_grid_soup(20, 18, 16) : tet_grid_soup(14, 12, 11));
		if (!hexes)
			build_volume(m, tet_grid_soup(3, 3, 3)); // a second connected component
		drop_index<Vertex>(m);
		ASSERT_FALSE(is_indexed<Vertex>(m));
		ASSERT_FALSE(is_indexed<Volume>(m));
		const uint32 nx = hexes ? 20 : 14, ny = hexes ? 18 : 12, nz = hexes ? 16 : 11;
		EXPECT_EQ(nb_cells<Vertex>(m), (nx + 1) * (ny + 1) * (nz + 1) + (hexes ? 0 : 64));
		EXPECT_EQ(nb_cells<Volume>(m), nx * ny * nz * (hexes ? 1 : 6) + (hexes ? 0 : 27 * 6));
		check_cells<Vertex>(m);
		check_cells<Volume>(m);
		check_cells<CMap3::CC>(m);
		EXPECT_TRUE(check_integrity(m).ok()); // the claim and worker marks were given back cleared
		// the same answer on the next traversals (the marks were cleared)
		check_cells<Vertex>(m);
		check_cells<Volume>(m);
	}
}

// Each cell is reported from its smallest non-boundary dart, as foreach_cell
// reports it.
TEST_P(Parallel, FloodedOrbitReportedFromItsSmallestDart)
{
	using Vertex = CMap3::Vertex;
	CMap3 m;
	build_volume(m, tet_grid_soup(8, 7, 6));
	drop_index<Vertex>(m);
	std::vector<uint32> seq, par;
	foreach_cell(m, [&](Vertex v) { seq.push_back(v.dart.index); });
	std::vector<std::vector<uint32>> per_thread(thread_pool()->nb_workers());
	parallel_foreach_cell(m, [&](Vertex v) {
		uint32 smallest = INVALID_INDEX;
		foreach_dart_of_orbit(m, v, [&](Dart d) {
			if (!is_boundary(m, d))
				smallest = std::min(smallest, d.index);
		});
		EXPECT_EQ(v.dart.index, smallest);
		per_thread[current_thread_index()].push_back(v.dart.index);
	});
	for (const auto& t : per_thread)
		par.insert(par.end(), t.begin(), t.end());
	std::sort(seq.begin(), seq.end());
	std::sort(par.begin(), par.end());
	EXPECT_EQ(par, seq);
}

// Filters on non-indexed flooded orbits: exactly the accepted cells, once.
TEST_P(Parallel, FloodedOrbitsNotIndexedThroughFilter)
{
	using Vertex = CMap3::Vertex;
	using Volume = CMap3::Volume;
	CMap3 m;
	build_volume(m, tet_grid_soup(10, 9, 8));
	drop_index<Vertex>(m);
	CellFilter<CMap3> filter(m);
	filter.set_filter<Vertex>([&](Vertex v) { return cell_id(m, v) % 3 == 0; });
	filter.set_filter<Volume>([&](Volume w) { return cell_id(m, w) % 5 == 0; });
	auto expected = [&]<typename CELL>(CELL*, auto pred) {
		std::vector<uint32> ids;
		foreach_cell(m, [&](CELL c) {
			if (pred(cell_id(m, c)))
				ids.push_back(cell_id(m, c));
		});
		std::sort(ids.begin(), ids.end());
		return ids;
	};
	auto got = [&]<typename CELL>(CELL*) {
		std::vector<std::vector<uint32>> per_thread(thread_pool()->nb_workers());
		parallel_foreach_cell(filter, [&](CELL c) { per_thread[current_thread_index()].push_back(cell_id(m, c)); });
		std::vector<uint32> ids;
		for (const auto& t : per_thread)
			ids.insert(ids.end(), t.begin(), t.end());
		std::sort(ids.begin(), ids.end());
		return ids;
	};
	const auto ev = expected(static_cast<Vertex*>(nullptr), [](uint32 id) { return id % 3 == 0; });
	const auto ew = expected(static_cast<Volume*>(nullptr), [](uint32 id) { return id % 5 == 0; });
	EXPECT_FALSE(ev.empty());
	EXPECT_FALSE(ew.empty());
	EXPECT_EQ(got(static_cast<Vertex*>(nullptr)), ev);
	EXPECT_EQ(got(static_cast<Volume*>(nullptr)), ew);
}

// After operators changed the map (new darts in the middle of the dart range,
// freed darts reused, cells merged), the non-indexed flooded orbits are still
// reported once each.
TEST_P(Parallel, FloodedOrbitsNotIndexedAfterOperators)
{
	using Vertex = CMap3::Vertex;
	using Volume = CMap3::Volume;
	using Edge = CMap3::Edge;
	CMap3 m;
	build_volume(m, tet_grid_soup(9, 8, 7));
	drop_index<Vertex>(m);
	const uint32 nv = nb_cells<Vertex>(m), nw = nb_cells<Volume>(m);
	// split every 5th tetrahedron at its centre (+1 vertex, +3 volumes each),
	// then collapse every other centre back (darts freed in the middle of the
	// range), then cut every 7th edge (+1 vertex each; reuses freed darts)
	std::vector<Volume> tets;
	foreach_cell(m, [&](Volume w) { tets.push_back(w); });
	std::vector<Vertex> centres;
	for (std::size_t k = 0; k < tets.size(); k += 5)
		centres.push_back(split_tetra(m, tets[k]));
	check_cells<Vertex>(m);
	check_cells<Volume>(m);
	uint32 collapsed = 0;
	for (std::size_t k = 0; k < centres.size(); k += 2, ++collapsed)
	{
		ASSERT_TRUE(can_collapse_edge(m, Edge(centres[k].dart)));
		collapse_edge(m, Edge(centres[k].dart));
	}
	const uint32 split = uint32(centres.size()) - collapsed;
	std::vector<Edge> edges;
	foreach_cell(m, [&](Edge e) { edges.push_back(e); });
	uint32 cut = 0;
	for (std::size_t k = 0; k < edges.size(); k += 7, ++cut)
		cut_edge(m, edges[k]);
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_GT(collapsed, 0u);
	EXPECT_EQ(nb_cells<Vertex>(m), nv + split + cut);
	EXPECT_EQ(nb_cells<Volume>(m), nw + 3 * split);
	check_cells<Vertex>(m);
	check_cells<Volume>(m);
	check_cells<CMap3::CC>(m);
}

// The generalized maps, on surfaces and volume meshes that cannot be
// oriented (each with a second, orientable component), and a 3-G-map after
// operators changed it.
TEST_P(Parallel, GeneralizedMapsAllCellTypes)
{
	GMap2 s;
	build_surface(s, klein_bottle_soup(30, 20));
	build_surface(s, mobius_soup(24));
	check_all_cell_types(s);
	index_all_cell_types(s);
	check_all_cell_types(s);
	GMap3 v;
	build_volume(v, solid_klein_bottle_soup(40));
	build_volume(v, hex_grid_soup(5, 4, 3));
	check_all_cell_types(v);
	index_all_cell_types(v);
	check_all_cell_types(v);
}

TEST_P(Parallel, GMap3FloodedOrbitsAfterOperators)
{
	GMap3 m;
	build_volume(m, tet_grid_soup(6, 5, 4));
	drop_index<GMap3::Vertex>(m);
	const uint32 nv = nb_cells<GMap3::Vertex>(m);
	std::vector<GMap3::Edge> edges;
	foreach_cell(m, [&](GMap3::Edge e) { edges.push_back(e); });
	uint32 cut = 0;
	for (std::size_t k = 0; k < edges.size(); k += 7, ++cut)
		cut_edge(m, edges[k]);
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_cells<GMap3::Vertex>(m), nv + cut);
	check_cells<GMap3::Vertex>(m);
	check_cells<GMap3::Volume>(m);
	check_cells<GMap3::CC>(m);
}

INSTANTIATE_TEST_SUITE_P(Workers, Parallel, ::testing::Values(1u, 2u, 7u),
						 [](const ::testing::TestParamInfo<uint32>& p) { return std::to_string(p.param) + "workers"; });

TEST(ThreadPool, IndexOutsideTraversalsIsZeroAndDefaultRestored)
{
	EXPECT_EQ(current_thread_index(), 0u);
	set_nb_workers(3);
	EXPECT_EQ(thread_pool()->nb_workers(), 3u);
	set_nb_workers(0);
	EXPECT_EQ(thread_pool()->nb_workers(), ThreadPool::default_nb_workers());
	EXPECT_GE(thread_pool()->nb_workers(), 1u);
}

} // namespace cgogn_test_parallel
