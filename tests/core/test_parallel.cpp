// parallel_foreach_cell gives the same results as foreach_cell for every cell
// type of CMap2 and CMap3, indexed or not, with 1, 2 and more workers than
// cores; thread indices are dense and never shared by two running callables.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <memory>
#include <tuple>
#include <vector>

using namespace cgogn;

namespace
{

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

} // namespace

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
	build_surface(m, sphere_soup(12, 6));  // a second connected component
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
