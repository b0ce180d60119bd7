// SPDX-License-Identifier: MIT
#pragma once

// Quick checks of the invariants of a combinatorial map: whether they hold,
// yes or no, without naming what is wrong, and in parallel on a large map.
// check_integrity runs them first and runs its detailed checks, which are
// sequential and say what is wrong, only where a quick one fails. Why: every
// load validates the map it builds, and on a map of 10^6 faces the
// sequential checks were half of the time of loading a .cgmap file.

#include <cgogn/core/map/orbits.h>
#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/parallel.h>

#include <atomic>
#include <vector>

namespace cgogn::detail
{

/// Fewer items than this are checked on the calling thread: the threads
/// would cost more than they save.
inline constexpr uint32 PARALLEL_CHECK_MIN_ITEMS = 1u << 16;
inline constexpr uint32 PARALLEL_CHECK_GRAIN = 1u << 14;

/// Whether body(b, e) returns true for every chunk [b, e) of [0, n). The
/// chunks run in parallel when n is large; once one fails, the others that
/// have not started are skipped. body must be safe to run concurrently on
/// disjoint chunks.
template <typename BODY>
bool all_chunks_hold(uint32 n, const BODY& body)
{
	if (n < PARALLEL_CHECK_MIN_ITEMS || run_sequentially())
		return body(0u, n);
	std::atomic<bool> ok{true};
	parallel_for_chunks(n, PARALLEL_CHECK_GRAIN, ChunkBody([&](uint32 b, uint32 e) {
							if (ok.load(std::memory_order_relaxed) && !body(b, e))
								ok.store(false, std::memory_order_relaxed);
						}));
	return ok.load();
}

/// Whether phi1 is injective on the live darts, so a permutation: no two
/// darts have the same phi1. Precondition: every phi1 of a live dart is a
/// live dart. Each worker takes a range of the darts and reads the phi1 of
/// every dart, recording the ones that fall in its range (no two workers
/// write the same byte, nothing atomic). O(darts) per worker.
template <typename MAP>
bool phi1_is_injective(const MAP& m)
{
	const AttributeContainer& darts = *state_of(m).darts;
	const uint32 end = darts.end_index();
	const auto key = darts.key().view();
	const auto phi1 = state_of(m).relations[0]->view();
	const uint32 nb_parts = end < PARALLEL_CHECK_MIN_ITEMS || run_sequentially() ? 1u : thread_pool()->nb_workers();
	std::vector<uint8> hit(end, 0);
	std::atomic<bool> ok{true};
	const auto check_part = [&](uint32 first_part, uint32 last_part) {
		for (uint32 p = first_part; p < last_part; ++p)
		{
			const uint32 lo = uint32(uint64(end) * p / nb_parts);
			const uint32 width = uint32(uint64(end) * (p + 1) / nb_parts) - lo;
			for (uint32 i = 0; i < end; ++i)
			{
				if (key[i] == INVALID_INDEX)
					continue;
				const uint32 t = phi1[i];
				if (t - lo < width) // t in [lo, lo + width), one compare
				{
					if (hit[t] != 0)
					{
						ok.store(false, std::memory_order_relaxed);
						return;
					}
					hit[t] = 1;
				}
			}
		}
	};
	if (nb_parts == 1)
		check_part(0, 1);
	else
		parallel_for_chunks(nb_parts, 1, ChunkBody(check_part));
	return ok.load();
}

/// phi_n of d in a CMap2 or CMap3 (phi2, phi3): the relation across which a
/// boundary dart must never face another. O(1).
template <typename MAP>
Dart last_phi(const MAP& m, Dart d)
{
	if constexpr (MAP::dimension == 2)
		return phi2(m, d);
	else
		return phi3(m, d);
}

/// Whether the relations of a CMap1, CMap2 or CMap3 hold (see
/// check_phi_relations in integrity.cpp for the list). O(darts), in parallel.
template <typename MAP>
bool phi_relations_hold(const MAP& m)
{
	const auto& st = state_of(m);
	const uint32 end = st.darts->end_index();
	const auto key = st.darts->key().view();
	const auto live = [&](uint32 i) { return i < end && key[i] != INVALID_INDEX; };
	using View = decltype(st.relations[0]->view());
	std::vector<View> relation; // phi1, phi2 ... phi_dimension
	for (const AttributeArray<uint32>* r : st.relations)
		relation.push_back(r->view());
	const bool relations_hold = all_chunks_hold(end, [&](uint32 b, uint32 e) {
		for (uint32 i = b; i < e; ++i)
		{
			if (key[i] == INVALID_INDEX)
				continue;
			if (!live(relation[0][i]))
				return false;
			for (std::size_t r = 1; r < relation.size(); ++r)
			{
				const uint32 j = relation[r][i];
				if (j == i || !live(j) || relation[r][j] != i)
					return false;
			}
		}
		return true;
	});
	if (!relations_hold || !phi1_is_injective(m))
		return false;
	if constexpr (MAP::dimension >= 2)
	{
		std::atomic<uint64> marked{0};
		const bool boundary_holds = all_chunks_hold(end, [&](uint32 b, uint32 e) {
			uint64 marked_here = 0;
			for (uint32 i = b; i < e; ++i)
			{
				if (key[i] == INVALID_INDEX)
					continue;
				const Dart d(i);
				if constexpr (MAP::dimension == 3)
					if (phi3(m, phi1(m, phi3(m, phi1(m, d)))) != d)
						return false;
				const bool boundary = is_boundary(m, d);
				marked_here += boundary;
				if (boundary && is_boundary(m, last_phi(m, d)))
					return false;
				if (is_boundary(m, phi1(m, d)) != boundary)
					return false;
				if constexpr (MAP::dimension == 3)
					if (is_boundary(m, phi2(m, d)) != boundary)
						return false;
				if (!boundary && phi1(m, phi1(m, d)) == d)
					return false;
			}
			marked.fetch_add(marked_here, std::memory_order_relaxed);
			return true;
		});
		return boundary_holds && marked.load() == st.nb_boundary_darts;
	}
	return true;
}

/// Whether the indexing of orbit O holds, in two linear passes: every dart
/// of a non-boundary cell has a live line and every boundary one none, and
/// the walk of the orbit of each line's representative meets only darts of
/// that line, as many in all as there are indexed darts. The walks are then
/// disjoint and cover every indexed dart: each cell has one line, constant on
/// its darts, and no two cells share a line. About half the cost of checking
/// each dart's neighbours as well. Both passes run in parallel, the walks
/// only for the orbits walked without a mark (see orbit_is_cyclic).
/// Precondition: the relations hold.
template <Orbit O, typename MAP>
bool orbit_indexing_holds(const MAP& m, const AttributeArray<uint32>& idx, const AttributeContainer& cells)
{
	const AttributeContainer& darts = *state_of(m).darts;
	const auto key = darts.key().view();
	const auto cells_key = cells.key().view();
	const uint32 cells_end = cells.end_index();
	std::atomic<uint64> indexed{0};
	const bool lines_hold = all_chunks_hold(darts.end_index(), [&](uint32 b, uint32 e) {
		uint64 indexed_here = 0;
		for (uint32 k = b; k < e; ++k)
		{
			if (key[k] == INVALID_INDEX)
				continue;
			const uint32 i = idx[k];
			if (is_boundary_cell(m, Cell<O>(Dart(k))))
			{
				if (i != INVALID_INDEX)
					return false;
			}
			else
			{
				if (i >= cells_end || cells_key[i] == INVALID_INDEX)
					return false;
				++indexed_here;
			}
		}
		indexed.fetch_add(indexed_here, std::memory_order_relaxed);
		return true;
	});
	if (!lines_hold)
		return false;
	std::atomic<uint64> walked{0};
	const auto representative = cells.key().view(); // INVALID_INDEX on a free line
	const auto walks_hold = [&](uint32 b, uint32 e) {
		uint64 walked_here = 0;
		bool ok = true;
		for (uint32 i = b; ok && i < e; ++i)
		{
			const Dart rep(representative[i]);
			if (!rep.is_valid())
				continue;
			if (!is_dart_valid(m, rep) || idx[rep.index] != i)
				return false;
			foreach_dart_of_orbit(m, Cell<O>(rep), [&](Dart x) {
				++walked_here;
				ok = idx[x.index] == i;
				return ok;
			});
		}
		walked.fetch_add(walked_here, std::memory_order_relaxed);
		return ok;
	};
	bool walks_ok;
	if constexpr (orbit_is_cyclic(O))
		walks_ok = all_chunks_hold(cells.end_index(), walks_hold);
	else
		walks_ok = walks_hold(0u, cells.end_index()); // the walk takes a mark of the map
	return walks_ok && walked.load() == indexed.load();
}

} // namespace cgogn::detail
