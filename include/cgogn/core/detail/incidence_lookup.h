// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/indexing.h>

namespace cgogn::detail
{

/// Key of the relation FROM -> TO (through THROUGH for adjacencies; void for
/// incidences) in a map's incidence tables.
template <typename FROM, typename TO, typename THROUGH>
constexpr uint32 incidence_key()
{
	constexpr uint32 N = NB_ORBITS + 1;
	uint32 through = NB_ORBITS;
	if constexpr (!std::is_void_v<THROUGH>)
		through = orbit_index(THROUGH::ORBIT);
	const uint32 key = (orbit_index(FROM::ORBIT) * N + orbit_index(TO::ORBIT)) * N + through;
	static_assert(N * N * NB_ORBITS == NB_INCIDENCE_KEYS);
	return key;
}

/// Depth of "compute without caches" requests on this thread (builders and
/// check_integrity set it to get the relation from the darts).
inline thread_local uint32 incidence_cache_bypass = 0;

/// While alive, local traversals on this thread ignore incidence caches.
struct IncidenceCacheBypass
{
	IncidenceCacheBypass()
	{
		++incidence_cache_bypass;
	}
	~IncidenceCacheBypass()
	{
		--incidence_cache_bypass;
	}
	IncidenceCacheBypass(const IncidenceCacheBypass&) = delete;
	IncidenceCacheBypass& operator=(const IncidenceCacheBypass&) = delete;
};

/// The table of relation `key` in m, nullptr when absent or bypassed.
inline const IncidenceTable* find_incidence_table(const CMapBase& m, uint32 key)
{
	if (incidence_cache_bypass != 0)
		return nullptr;
	return detail::state_of(m).incidence_tables.find(key);
}

/// Whether callable FUNC takes exactly the plain cell type TO (not a
/// LocatedCell, not `auto`): it never reads a neighbour's line, so the
/// traversals need not look for lines at all.
template <typename FUNC, typename TO>
constexpr bool takes_plain_cell()
{
	if constexpr (requires { &std::remove_cvref_t<FUNC>::operator(); })
		return std::is_same_v<func_parameter_type<FUNC>, TO>;
	else
		return false;
}

/// The hook of the local traversals: when m holds a cache of FROM -> TO
/// (through THROUGH) that covers c, calls f on the cached neighbours (f may
/// stop by returning false) and returns true; otherwise returns false and the
/// caller traverses the darts. The neighbours are given as LocatedCell (cell
/// and line) when the table holds their lines, which converts to TO for a
/// callable taking TO. One test of a null pointer when no cache is enabled,
/// one array read to find the table otherwise.
template <typename TO, typename THROUGH, typename FROM, typename FUNC>
CGOGN_INLINE bool foreach_cached(const CMapBase& m, FROM c, const FUNC& f)
{
	if (detail::state_of(m).incidence_tables.empty())
		return false;
	const IncidenceTable* t = find_incidence_table(m, incidence_key<FROM, TO, THROUGH>());
	if (t == nullptr)
		return false;
	uint32 r;
	if constexpr (requires { c.line; })
		r = c.line != INVALID_INDEX ? c.line : index_of(m, Cell<FROM::ORBIT>(c));
	else
		r = index_of(m, c);
	if (r >= t->nb_rows)
		return false; // a cell created after the cache was built (or r == INVALID_INDEX)
	const uint32 b = t->offsets[r], e = t->offsets[r + 1];
	const Dart* targets = t->targets.data();
	if (!takes_plain_cell<FUNC, TO>() && !t->target_lines.empty())
	{
		const uint32* lines = t->target_lines.data();
		for (uint32 i = b; i < e; ++i)
			if (!call_and_continue(f, LocatedCell<TO::ORBIT>(targets[i], lines[i])))
				break;
	}
	else
		for (uint32 i = b; i < e; ++i)
			if (!call_and_continue(f, TO(targets[i])))
				break;
	return true;
}

/// What report_with_lines gives a walk when f takes the lines: report(e)
/// reads e's line and calls f. A 2-D vertex walk given it directly (see
/// foreach_dart_of_orbit) also calls prefetch_line(e) with e = phi2(d) before
/// it reads phi1(e), the next dart it reports: that dart is in e's face, so
/// its line is usually in the cache line of e's, and its miss overlaps the
/// phi1(e) one instead of following it.
template <typename TO, typename FUNC, typename VIEW>
struct LineReport
{
	const FUNC& f;
	VIEW line_of;
	CGOGN_INLINE bool operator()(Dart e) const
	{
		return call_and_continue(f, LocatedCell<TO::ORBIT>(e, line_of[e.index]));
	}
	CGOGN_INLINE void prefetch_line(uint32 e) const
	{
		CGOGN_PREFETCH(&line_of[e]);
	}
};

/// The uncached form of the hook: `walk(report)` calls report(Dart e) on the
/// darts of the neighbours, and f receives each as a LocatedCell<TO> (the
/// cell and its line) when TO's orbit is indexed, as TO otherwise. The line is
/// read here through a view of the index held in a local (LineStorage::View),
/// so a callable taking `auto` reads its attributes with value(m, attr, c)
/// without the index lookup, whose storage the compiler would otherwise load
/// again at every neighbour; a callable taking TO drops the line and the
/// compiler the read.
template <typename TO, typename WALK, typename FUNC>
CGOGN_INLINE void report_with_lines(const CMapBase& m, const WALK& walk, const FUNC& f)
{
	const AttributeArray<uint32>* index = detail::state_of(m).cell_index[orbit_index(TO::ORBIT)];
	if (takes_plain_cell<FUNC, TO>() || index == nullptr)
	{
		walk([&](Dart e) { return call_and_continue(f, TO(e)); });
		return;
	}
	walk(LineReport<TO, FUNC, decltype(index->view())>{f, index->view()});
}

} // namespace cgogn::detail
