// Strategies for traversing the cells of a flooded, non-indexed orbit (3-D
// vertices, volumes) in parallel, side by side on one map, to justify the one
// parallel_foreach_cell uses (docs/performance.md, "Parallel traversals of flooded orbits"). Each variant
// reports every cell once (checked against foreach_cell before timing) with a
// trivial callable, so the traversal itself is measured.
// - seq:        foreach_cell (one mark for the traversal and its floods)
// - per_chunk:  the previous parallel version: one shared mark, each chunk
//               floods a cell once per chunk it meets, with a pooled mark per
//               flood (foreach_dart_of_orbit)
// - per_worker: each worker keeps a "flooded" and an "owner" mark for the
//               whole traversal, and floods each cell at most once
// - claim_all:  darts claimed in a shared mark with atomic fetch_or (every
//               dart of every flood), one flood per cell in total, reported by
//               the claimer of its smallest dart
// - library:    parallel_foreach_cell's: as claim_all, but the darts are
//               marked "seen" with relaxed loads and stores (a hint, no atomic
//               read-modify-write), only outside the flooding chunk (the
//               others are skipped through the worker's mark), and one
//               fetch_or per cell, on its smallest dart, picks the reporter
// - union_find: two phases, lock-free union-find on darts (links towards the
//               smaller key, non-boundary darts first), then every root reported
// Meshes: CGOGN_BENCH_VOLUME=armadillo (default), elephant, or grid (a
// generated 998,250-tet grid). Arguments of each benchmark: number of workers.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <memory>
#include <string>
#include <sys/resource.h>
#include <utility>
#include <vector>

using namespace cgogn;
using Vertex = CMap3::Vertex;
using Volume = CMap3::Volume;

namespace
{

template <typename T>
struct alignas(64) PerThread
{
	T v{};
};

CMap3& volume_map()
{
	static CMap3 m = [] {
		CMap3 map;
		const char* w = std::getenv("CGOGN_BENCH_VOLUME");
		const std::string which = w != nullptr ? w : "armadillo";
		if (which == "grid")
			build_volume(map, tet_grid_soup(55, 55, 55));
		else
			io::load_volume(
				map, cgogn_test_data::path(std::string("volume/") + (which == "elephant" ? "elephant_hex_110k.mesh"
																						 : "armadillo_tet_461k.mesh")));
		// the non-indexed path for vertices: drop the index the reader made
		AttributeArray<uint32>*& idx = cgogn::detail::state_of(map).cell_index[orbit_index(Orbit::PHI21_PHI31)];
		cgogn::detail::state_of(map).darts->remove_attribute(idx);
		idx = nullptr;
		return map;
	}();
	return m;
}

using Chunk = detail::ChunkBody;
constexpr uint32 GRAIN = detail::PARALLEL_DART_BLOCKS_GRAIN;

template <typename CELL, typename FUNC>
void per_chunk(const CMap3& m, const FUNC& f)
{
	const uint32 end = cgogn::detail::state_of(m).darts->end_index();
	const AttributeArray<uint32>& key = cgogn::detail::state_of(m).darts->key();
	MarkAttribute* seen = cgogn::detail::state_of(m).darts->acquire_mark();
	detail::parallel_for_chunks((end + 63) / 64, GRAIN, Chunk([&](uint32 bb, uint32 be) {
									const uint32 b = bb * 64, e = std::min(be * 64, end);
									for (uint32 i = b; i < e; ++i)
									{
										if (key[i] == INVALID_INDEX || seen->test(i) || is_boundary(m, Dart(i)))
											continue;
										uint32 smallest = i;
										foreach_dart_of_orbit(m, CELL(Dart(i)), [&](Dart x) {
											if (x.index >= b && x.index < e)
												seen->set(x.index);
											if (x.index < smallest && !is_boundary(m, x))
												smallest = x.index;
										});
										if (smallest == i)
											f(CELL(Dart(i)));
									}
									for (uint32 i = b; i < e; ++i)
										seen->reset(i);
								}));
	cgogn::detail::state_of(m).darts->release_mark(seen);
}

struct alignas(64) Worker
{
	MarkAttribute* flooded = nullptr;
	MarkAttribute* owner = nullptr;
	std::vector<Dart> work;
};

template <typename CELL, typename FUNC>
void per_worker(const CMap3& m, const FUNC& f)
{
	const uint32 end = cgogn::detail::state_of(m).darts->end_index();
	const AttributeArray<uint32>& key = cgogn::detail::state_of(m).darts->key();
	std::vector<Worker> workers(thread_pool()->nb_workers());
	detail::parallel_for_chunks((end + 63) / 64, GRAIN, Chunk([&](uint32 bb, uint32 be) {
									Worker& w = workers[current_thread_index()];
									if (w.flooded == nullptr)
									{
										w.flooded = cgogn::detail::state_of(m).darts->acquire_mark();
										w.owner = cgogn::detail::state_of(m).darts->acquire_mark();
									}
									for (uint32 i = bb * 64, e = std::min(be * 64, end); i < e; ++i)
									{
										if (key[i] == INVALID_INDEX || is_boundary(m, Dart(i)))
											continue;
										if (w.flooded->test(i))
										{
											if (w.owner->test(i))
												f(CELL(Dart(i)));
											continue;
										}
										uint32 smallest = i;
										detail::flood_orbit_keep_marks<CELL::ORBIT>(
											m, Dart(i), *w.flooded, w.work, [&](Dart x) {
												if (x.index < smallest && !is_boundary(m, x))
													smallest = x.index;
											});
										if (smallest == i)
											f(CELL(Dart(i)));
										else
											w.owner->set(smallest);
									}
								}));
	for (Worker& w : workers)
		for (MarkAttribute* mark : {w.flooded, w.owner})
			if (mark != nullptr)
			{
				mark->clear_all();
				cgogn::detail::state_of(m).darts->release_mark(mark);
			}
}

template <typename CELL, typename FUNC>
void claim_all(const CMap3& m, const FUNC& f)
{
	const uint32 end = cgogn::detail::state_of(m).darts->end_index();
	const AttributeArray<uint32>& key = cgogn::detail::state_of(m).darts->key();
	std::vector<Worker> workers(thread_pool()->nb_workers());
	MarkAttribute* claimed = cgogn::detail::state_of(m).darts->acquire_mark();
	detail::parallel_for_chunks(
		(end + 63) / 64, GRAIN, Chunk([&](uint32 bb, uint32 be) {
			Worker& w = workers[current_thread_index()];
			if (w.flooded == nullptr)
				w.flooded = cgogn::detail::state_of(m).darts->acquire_mark();
			for (uint32 i = bb * 64, e = std::min(be * 64, end); i < e; ++i)
			{
				if (key[i] == INVALID_INDEX || claimed->atomic_test(i) || is_boundary(m, Dart(i)))
					continue;
				uint32 owner = i;
				bool owner_is_mine = false;
				detail::flood_orbit_keep_marks<CELL::ORBIT>(m, Dart(i), *w.flooded, w.work, [&](Dart x) {
					const bool mine = claimed->atomic_test_and_set(x.index);
					if (x.index <= owner && !is_boundary(m, x))
					{
						owner = x.index;
						owner_is_mine = mine;
					}
				});
				if (owner_is_mine)
					f(CELL(Dart(owner)));
			}
		}));
	claimed->clear_all();
	cgogn::detail::state_of(m).darts->release_mark(claimed);
	for (Worker& w : workers)
		if (w.flooded != nullptr)
		{
			w.flooded->clear_all();
			cgogn::detail::state_of(m).darts->release_mark(w.flooded);
		}
}

template <typename CELL, typename FUNC>
void union_find(const CMap3& m, const FUNC& f)
{
	const uint32 end = cgogn::detail::state_of(m).darts->end_index();
	const AttributeArray<uint32>& key = cgogn::detail::state_of(m).darts->key();
	// a dart's rank: non-boundary darts first, then by index
	auto rank = [&](uint32 d) { return is_boundary(m, Dart(d)) ? d + 0x80000000u : d; };
	std::unique_ptr<std::atomic<uint32>[]> parent(new std::atomic<uint32>[end]);
	auto find = [&](uint32 x) {
		uint32 p = parent[x].load(std::memory_order_relaxed);
		while (p != x)
		{
			const uint32 gp = parent[p].load(std::memory_order_relaxed);
			parent[x].compare_exchange_weak(p, gp, std::memory_order_relaxed); // path halving
			x = p;
			p = parent[x].load(std::memory_order_relaxed);
		}
		return x;
	};
	auto unite = [&](uint32 a, uint32 b) {
		while (true)
		{
			a = find(a);
			b = find(b);
			if (a == b)
				return;
			if (rank(a) < rank(b))
				std::swap(a, b); // link the larger rank below the smaller
			uint32 expected = a;
			if (parent[a].compare_exchange_strong(expected, b, std::memory_order_relaxed))
				return;
		}
	};
	detail::parallel_for_chunks(end, 4096, Chunk([&](uint32 b, uint32 e) {
									for (uint32 i = b; i < e; ++i)
										parent[i].store(i, std::memory_order_relaxed);
								}));
	detail::parallel_for_chunks(end, 4096, Chunk([&](uint32 b, uint32 e) {
									for (uint32 i = b; i < e; ++i)
									{
										if (key[i] == INVALID_INDEX)
											continue;
										const Dart d(i);
										if constexpr (CELL::ORBIT == Orbit::PHI21_PHI31)
										{
											unite(i, phi1(m, phi2(m, d)).index);
											unite(i, phi1(m, phi3(m, d)).index);
										}
										else
										{
											if (is_boundary(m, d)) // boundary volumes are not reported
												continue;
											unite(i, phi1(m, d).index);
											unite(i, phi2(m, d).index);
										}
									}
								}));
	detail::parallel_for_chunks(end, 4096, Chunk([&](uint32 b, uint32 e) {
									for (uint32 i = b; i < e; ++i)
										if (key[i] != INVALID_INDEX && !is_boundary(m, Dart(i)) && find(i) == i)
											f(CELL(Dart(i)));
								}));
}

enum class Strategy
{
	seq,
	per_chunk,
	per_worker,
	claim_all,
	library,
	union_find
};

template <typename CELL, typename FUNC>
void traverse(Strategy s, const CMap3& m, const FUNC& f)
{
	switch (s)
	{
	case Strategy::seq:
		foreach_cell(m, f);
		break;
	case Strategy::per_chunk:
		per_chunk<CELL>(m, f);
		break;
	case Strategy::per_worker:
		per_worker<CELL>(m, f);
		break;
	case Strategy::claim_all:
		claim_all<CELL>(m, f);
		break;
	case Strategy::library:
		// the parallel code itself, also with one worker (parallel_foreach_cell
		// would then run foreach_cell)
		detail::parallel_foreach_cell_of_map<CELL>(m, f);
		break;
	case Strategy::union_find:
		union_find<CELL>(m, f);
		break;
	}
}

double process_cpu_ms()
{
	rusage u;
	getrusage(RUSAGE_SELF, &u);
	return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}

template <typename CELL>
void run(benchmark::State& state, Strategy s)
{
	const CMap3& m = volume_map();
	set_nb_workers(uint32(state.range(0)));
	// correctness first: the same number of cells, each once
	const uint32 expected = nb_cells<CELL>(m);
	{
		std::vector<PerThread<uint64>> count(thread_pool()->nb_workers());
		auto g = [&](CELL) { ++count[current_thread_index()].v; };
		traverse<CELL>(s, m, g);
		uint64 n = 0;
		for (auto& c : count)
			n += c.v;
		if (n != expected)
			state.SkipWithError("wrong number of cells");
	}
	const double cpu0 = process_cpu_ms();
	for (auto _ : state)
	{
		std::vector<PerThread<uint64>> sum(thread_pool()->nb_workers());
		auto g = [&](CELL c) { sum[current_thread_index()].v += c.dart.index; };
		traverse<CELL>(s, m, g);
		benchmark::DoNotOptimize(sum.data());
	}
	state.counters["proc_cpu_ms"] = (process_cpu_ms() - cpu0) / double(std::max<int64>(1, state.iterations()));
	state.counters["cells"] = expected;
	set_nb_workers(0);
}

void volumes(benchmark::State& state, Strategy s)
{
	run<Volume>(state, s);
}
void vertices(benchmark::State& state, Strategy s)
{
	run<Vertex>(state, s);
}

} // namespace

#define CGOGN_FLOOD_BENCH(CELL, S)                                                                                     \
	BENCHMARK_CAPTURE(CELL, S, Strategy::S)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

CGOGN_FLOOD_BENCH(volumes, seq)
CGOGN_FLOOD_BENCH(volumes, per_chunk)
CGOGN_FLOOD_BENCH(volumes, per_worker)
CGOGN_FLOOD_BENCH(volumes, claim_all)
CGOGN_FLOOD_BENCH(volumes, library)
CGOGN_FLOOD_BENCH(volumes, union_find)
CGOGN_FLOOD_BENCH(vertices, seq)
CGOGN_FLOOD_BENCH(vertices, per_chunk)
CGOGN_FLOOD_BENCH(vertices, per_worker)
CGOGN_FLOOD_BENCH(vertices, claim_all)
CGOGN_FLOOD_BENCH(vertices, library)
CGOGN_FLOOD_BENCH(vertices, union_find)

BENCHMARK_MAIN();
