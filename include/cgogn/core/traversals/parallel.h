// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/traversals/global.h>

#include <algorithm>
#include <vector>

namespace cgogn
{

namespace detail
{

/// Container lines per chunk of an indexed traversal, darts per chunk of the
/// others: large enough to amortise the scheduling, small enough to balance.
inline constexpr uint32 PARALLEL_LINE_GRAIN = 1024;
inline constexpr uint32 PARALLEL_DART_BLOCKS_GRAIN = 16; // blocks of 64 darts

/// True for the orbits that foreach_dart_of_orbit walks as one or two cycles
/// (no mark): faces, edges, 2-D vertices, 3-D faces and edges. The others
/// (volumes, 3-D vertices, connected components) are flooded with a mark.
constexpr bool orbit_is_cyclic(Orbit o)
{
	return o == Orbit::PHI1 || o == Orbit::PHI2 || o == Orbit::PHI21 || o == Orbit::PHI1_PHI3 ||
		   o == Orbit::PHI2_PHI3 || o == Orbit::BETA0 || o == Orbit::BETA1 || o == Orbit::BETA0_BETA1 ||
		   o == Orbit::BETA0_BETA2 || o == Orbit::BETA1_BETA2 || o == Orbit::ALPHA0 || o == Orbit::ALPHA1;
}

/// What one worker of a flooded traversal keeps from chunk to chunk: a mark
/// of its own (no other thread touches it) and its work list, on cache lines
/// of its own.
struct alignas(64) FloodWorker
{
	MarkAttribute* flooded = nullptr; // darts of the cells this worker has flooded
	std::vector<Dart> work;
};

/// Parallel traversal of the cells of a non-indexed orbit. The dart range is
/// cut into chunks of whole 64-dart blocks, scheduled by work stealing. A cell
/// is reported from its smallest dart not passed over (its owner, see
/// passed_over_by_traversals: a non-boundary dart in the maps of dimension 1
/// to 3); no thread
/// waits for another or for a sequential pass.
/// - Cyclic orbits (see orbit_is_cyclic): from each non-boundary dart d, walk
///   the orbit until a smaller non-boundary dart shows up (d is not the owner:
///   stop) or the walk ends (d is the owner: report). Read-only, no mark.
/// - Flooded orbits (see orbit_is_flooded): a worker scanning its chunk [b, e)
///   skips the darts it has flooded (a mark of its own, kept for the whole
///   traversal) and those marked "seen" by others; at any other non-boundary
///   dart it floods the cell with its own mark, marks "seen" the cell's darts
///   outside [b, e) (the darts other workers scan; those of [b, e) only this
///   worker scans) and finds the cell's owner. The cell is reported by the
///   worker that first sets the owner's bit in a "reported" mark (atomic
///   fetch_or: one winner; a cell lying entirely in [b, e) is flooded by no
///   other worker and is reported directly). So each cell is reported exactly
///   once, and flooded once in total, except when two workers start on the
///   same cell at the same moment (both flood it, one reports it). "seen" is a
///   hint, written with relaxed loads and stores (no read-modify-write, as
///   cheap as a plain mark): a bit lost to a concurrent write of the same word
///   only costs a second flood, never a second report. Neither the darts of a
///   cell nor the cells need to be contiguous: 3-D vertices, whose darts lie
///   in all their incident volumes, are flooded once although most of their
///   darts lie in other chunks (a per-worker mark alone made every worker
///   flood almost every vertex). No pooled mark is reserved per cell (a per-
///   cell reservation made the cores fight over the pool's cache line). Cost:
///   one flood per cell, one atomic read-modify-write per cell that straddles
///   chunks; the marks are cleared at the end by the workers, O(darts / 64)
///   each. Measured in docs/performance.md ("Parallel traversals of flooded orbits").
template <typename CELL, typename MAP, typename FUNC>
void parallel_foreach_cell_by_darts(const MAP& m, const FUNC& f)
{
	const uint32 end = detail::state_of(m).darts->end_index();
	const uint32 nb_blocks = (end + 63) / 64;
	const AttributeArray<uint32>& key = detail::state_of(m).darts->key();
	if constexpr (orbit_is_cyclic(CELL::ORBIT))
	{
		parallel_for_chunks(nb_blocks, PARALLEL_DART_BLOCKS_GRAIN, ChunkBody([&](uint32 bb, uint32 be) {
								held_callable_t<FUNC> fc = f; // see held_callable_t
								for (uint32 i = bb * 64, e = std::min(be * 64, end); i < e; ++i)
								{
									if (key[i] == INVALID_INDEX ||
										detail::passed_over_by_traversals<CELL::ORBIT>(m, Dart(i)))
										continue;
									const bool owner = foreach_dart_of_orbit(m, CELL(Dart(i)), [&](Dart x) {
										return x.index >= i || detail::passed_over_by_traversals<CELL::ORBIT>(m, x);
									});
									if (owner)
										fc(CELL(Dart(i)));
								}
							}));
		return;
	}
	else
	{
		static_assert(orbit_is_flooded(CELL::ORBIT));
		std::vector<FloodWorker> workers(thread_pool()->nb_workers());
		std::vector<MarkAttribute*> marks{detail::state_of(m).darts->acquire_mark(),
										  detail::state_of(m).darts->acquire_mark()};
		MarkAttribute& seen = *marks[0];     // darts flooded by a worker other than their scanner (hints)
		MarkAttribute& reported = *marks[1]; // owners of the reported cells
		auto clear_and_release = [&](bool in_parallel) {
			for (FloodWorker& w : workers)
				if (w.flooded != nullptr)
					marks.push_back(w.flooded);
			auto clear = [&](uint32 b, uint32 e) {
				for (uint32 k = b; k < e; ++k)
					marks[k]->clear_all();
			};
			if (in_parallel)
				parallel_for_chunks(uint32(marks.size()), 1, ChunkBody(clear));
			else
				clear(0, uint32(marks.size()));
			for (MarkAttribute* mark : marks)
				detail::state_of(m).darts->release_mark(mark);
		};
		try
		{
			parallel_for_chunks(
				nb_blocks, PARALLEL_DART_BLOCKS_GRAIN, ChunkBody([&](uint32 bb, uint32 be) {
					held_callable_t<FUNC> fc = f; // see held_callable_t
					FloodWorker& w = workers[current_thread_index()];
					if (w.flooded == nullptr)
						w.flooded = detail::state_of(m).darts->acquire_mark();
					const uint32 b = bb * 64, e = std::min(be * 64, end);
					for (uint32 i = b; i < e; ++i)
					{
						if (key[i] == INVALID_INDEX || w.flooded->test(i) || seen.atomic_test(i) ||
							detail::passed_over_by_traversals<CELL::ORBIT>(m, Dart(i)))
							continue;
						uint32 owner = i;
						bool inside = true; // all the cell's darts in [b, e)
						flood_orbit_keep_marks<CELL::ORBIT>(m, Dart(i), *w.flooded, w.work, [&](Dart x) {
							// the darts of [b, e) are scanned by this worker only:
							// its own mark is enough to skip them
							if (x.index < b || x.index >= e)
							{
								seen.atomic_set_lossy(x.index);
								inside = false;
							}
							if (x.index < owner && !detail::passed_over_by_traversals<CELL::ORBIT>(m, x))
								owner = x.index;
						});
						// a cell inside [b, e) is flooded by no other worker: no race
						if (inside || reported.atomic_test_and_set(owner))
							fc(CELL(Dart(owner)));
					}
				}));
		}
		catch (...)
		{
			clear_and_release(false);
			throw;
		}
		clear_and_release(true);
	}
}

/// Parallel traversal of the cells of type CELL of a map (see parallel_foreach_cell).
template <typename CELL, typename MAP, typename FUNC>
void parallel_foreach_cell_of_map(const MAP& m, const FUNC& f)
{
	constexpr Orbit O = CELL::ORBIT;
	if constexpr (is_direct_orbit(O))
	{
		// a record's line is the cell itself
		const AttributeContainer& c = *detail::state_of(m).cells[orbit_index(O)];
		const AttributeArray<uint32>& key = c.key();
		parallel_for_chunks(c.end_index(), PARALLEL_LINE_GRAIN, ChunkBody([&](uint32 b, uint32 e) {
								held_callable_t<FUNC> fc = f; // see held_callable_t
								for (uint32 i = b; i < e; ++i)
									if (key[i] != INVALID_INDEX)
										fc(CELL(Dart(i)));
							}));
	}
	else if constexpr (O == Orbit::DART)
	{
		const uint32 end = detail::state_of(m).darts->end_index();
		const AttributeArray<uint32>& key = detail::state_of(m).darts->key();
		parallel_for_chunks(end, PARALLEL_LINE_GRAIN, ChunkBody([&](uint32 b, uint32 e) {
								held_callable_t<FUNC> fc = f; // see held_callable_t
								for (uint32 i = b; i < e; ++i)
									if (key[i] != INVALID_INDEX && !is_boundary(m, Dart(i)))
										fc(CELL(Dart(i)));
							}));
	}
	else if (is_indexed<CELL>(m))
	{
		// split the cell container's line range: one representative dart per live line
		const AttributeContainer& c = *detail::state_of(m).cells[orbit_index(O)];
		const AttributeArray<uint32>& rep = c.key();
		parallel_for_chunks(c.end_index(), PARALLEL_LINE_GRAIN, ChunkBody([&](uint32 b, uint32 e) {
								held_callable_t<FUNC> fc = f; // see held_callable_t
								for (uint32 i = b; i < e; ++i)
								{
									const uint32 d = rep[i];
									if (d != INVALID_INDEX)
										fc(CELL(Dart(d)));
								}
							}));
	}
	else if constexpr (O == Orbit::PHI2)
	{
		// as in the sequential traversal: no mark needed
		const uint32 end = detail::state_of(m).darts->end_index();
		const AttributeArray<uint32>& key = detail::state_of(m).darts->key();
		parallel_for_chunks(end, PARALLEL_LINE_GRAIN, ChunkBody([&](uint32 b, uint32 e) {
								held_callable_t<FUNC> fc = f; // see held_callable_t
								for (uint32 i = b; i < e; ++i)
								{
									if (key[i] != INVALID_INDEX && represents_unindexed_edge(m, Dart(i)))
										fc(CELL(Dart(i)));
								}
							}));
	}
	else
		parallel_foreach_cell_by_darts<CELL>(m, f);
}

} // namespace detail

/// Calls f on every cell of the type of f's parameter (boundary cells
/// excluded), spread over thread_pool()->nb_workers() threads; returns when
/// all are done. f is called concurrently from several threads: it may write
/// to the cell it is given (its attribute values) and read anything, but must
/// synchronise other writes (or use per-thread slots indexed by
/// current_thread_index()). f must return void: early stop is not available.
/// Markers, local traversals and value() are safe inside f; topological
/// changes are not. With one worker (or when called from inside f) it runs
/// sequentially on the calling thread. Indexed orbits split their cell
/// container; other orbits split the darts (see
/// detail::parallel_foreach_cell_by_darts). O(cells / workers) when indexed,
/// O(darts / workers) otherwise. Works on maps and views.
template <typename MESH, typename FUNC>
void parallel_foreach_cell(const MESH& m, const FUNC& f)
{
	using CELL = func_parameter_type<FUNC>;
	static_assert(CellType<CELL>, "parallel_foreach_cell: the callable must take a cell (e.g. Vertex) by value");
	static_assert(std::is_void_v<func_result_type<FUNC>>,
				  "parallel_foreach_cell: the callable must return void (early stop is not available in parallel)");
	if constexpr (std::is_base_of_v<CMapBase, MESH>)
	{
		if (detail::run_sequentially())
			detail::foreach_cell_of_map<CELL>(m, f);
		else
			detail::parallel_foreach_cell_of_map<CELL>(m, f);
	}
	else
		m.template parallel_foreach_cell<CELL>(f);
}

} // namespace cgogn
