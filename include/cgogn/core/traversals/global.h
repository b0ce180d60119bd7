// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_access.h>
#include <cgogn/core/marking/marker.h>

#include <optional>

namespace cgogn
{

namespace detail
{

/// The cell given to a foreach_cell callable: with its line when the
/// callable takes a LocatedCell (INVALID_INDEX when the orbit is not indexed).
template <typename CELL>
constexpr CELL reported_cell(Dart d, uint32 line = INVALID_INDEX)
{
	if constexpr (std::is_same_v<CELL, LocatedCell<CELL::ORBIT>>)
		return CELL(d, line);
	else
		return CELL(d);
}

/// Whether live dart d represents its edge in the traversals of a map whose
/// edges have no index: d is not a boundary dart and is the smaller dart of
/// the edge, or its only non-boundary one. No mark needed.
template <typename MAP>
bool represents_unindexed_edge(const MAP& m, Dart d)
{
	if (is_boundary(m, d))
		return false;
	const Dart e = phi2(m, d);
	return d.index < e.index || is_boundary(m, e);
}

/// The same for a 2-G-map's edge, whose (up to) four darts are d, beta0(d),
/// beta2(d) and beta0(beta2(d)): d is its smallest non-boundary dart.
template <typename MAP>
bool represents_unindexed_gmap_edge(const MAP& m, Dart d)
{
	// beta0(d) is usually d's neighbour line: the cheapest test first
	if (beta0(m, d).index < d.index || is_boundary(m, d))
		return false;
	const Dart d2 = beta2(m, d);
	if (is_boundary(m, d2))
		return true;
	return d.index < d2.index && d.index < beta0(m, d2).index;
}

/// Says which darts of a map without an index for the orbit O start a new
/// cell: the walk of foreach_cell_of_map when the cells have no container to
/// walk. Asked in increasing dart order, it reports each cell from its
/// smallest dart not passed over (see passed_over_by_traversals), and marks the cells it reported in one dart
/// mark (none for edges); floods share one work list.
template <Orbit O, typename MAP>
class UnindexedCellStarts
{
	// The cells of the maps of any dimension: a pair (an edge of a 2-map, ...)
	// needs no mark, a cycle is walked, the others flooded.
	static constexpr bool pair = [] {
		if constexpr (is_dimension_orbit(O))
			return ncell_is_pair<MAP, dimension_of_orbit(O)>();
		else
			return false;
	}();
	static constexpr bool flooded = [] {
		if constexpr (is_dimension_orbit(O))
			return ncell_is_flooded<MAP, dimension_of_orbit(O)>();
		else
			return orbit_is_flooded(O);
	}();

public:
	explicit UnindexedCellStarts(const MAP& m) : m_(m)
	{
		if constexpr (O != Orbit::PHI2 && O != Orbit::BETA0_BETA2 && O != Orbit::ALPHA0 && !pair)
			mark_.emplace(m);
		if constexpr (flooded)
			work_.emplace();
	}

	/// Whether live dart d is the first dart met of its cell (the cell is then
	/// marked as met); false for boundary darts.
	bool starts_cell(Dart d)
	{
		if constexpr (O == Orbit::PHI2)
			return represents_unindexed_edge(m_, d);
		else if constexpr (O == Orbit::BETA0_BETA2)
			return represents_unindexed_gmap_edge(m_, d);
		else if constexpr (O == Orbit::ALPHA0)
		{
			// a graph edge from its smaller half-edge; an isolated vertex has none
			const Dart e = alpha0(m_, d);
			return d.index < e.index;
		}
		else if constexpr (pair)
		{
			// the smaller dart of the pair
			const Dart e(ncell_steps<MAP, dimension_of_orbit(O)>(state_of(m_))[0][d.index]);
			return d.index <= e.index && !passed_over_by_traversals<O>(m_, d);
		}
		else
		{
			MarkAttribute& mark = **mark_;
			if (passed_over_by_traversals<O>(m_, d) || mark.test(d.index))
				return false;
			if constexpr (flooded)
				flood_orbit_keep_marks<O>(m_, d, mark, **work_, [](Dart) {});
			else
				foreach_dart_of_orbit(m_, Cell<O>(d), [&](Dart x) { mark.set(x.index); });
			return true;
		}
	}

private:
	const MAP& m_;
	std::optional<ScopedDartMark> mark_;
	std::optional<DartBuffer> work_;
};

/// Visits every real cell of type CELL of map m (see foreach_cell).
template <typename CELL, typename MAP, typename FUNC>
void foreach_cell_of_map(const MAP& m, const FUNC& func)
{
	// f's captures in registers across the loop (see held_callable_t)
	held_callable_t<FUNC> f = func;
	constexpr Orbit O = CELL::ORBIT;
	if constexpr (is_direct_orbit(O))
	{
		// a record's line is the cell itself
		const AttributeContainer& c = *detail::state_of(m).cells[orbit_index(O)];
		const auto key = c.key().view();
		for (uint32 i = 0, end = c.end_index(); i < end; ++i)
			if (key[i] != INVALID_INDEX && !call_and_continue(f, reported_cell<CELL>(Dart(i), i)))
				return;
	}
	else if constexpr (O == Orbit::DART)
	{
		// a dart's line is its index
		foreach_dart(
			m, [&](Dart d) { return is_boundary(m, d) || call_and_continue(f, reported_cell<CELL>(d, d.index)); });
	}
	else
	{
		// One loop, and f called at one place in it, whether the cells come from
		// their container (one representative dart per live line) or from a
		// scan of the darts: the compilers inline a callable called from one
		// site whatever its size, while from two (one per way of finding the
		// cells) they often keep it out of line, and each cell then pays a call
		// and reloads everything f captured.
		const bool indexed = is_indexed<CELL>(m);
		const AttributeContainer& walked =
			indexed ? *detail::state_of(m).cells[orbit_index(O)] : *detail::state_of(m).darts;
		std::optional<UnindexedCellStarts<O, MAP>> starts;
		if (!indexed)
			starts.emplace(m);
		// the keys through a view held in a local: the compiler would otherwise
		// reload the storage's base and bound at each line
		const auto key = walked.key().view();
		for (uint32 i = 0, end = walked.end_index(); i < end; ++i)
		{
			const uint32 k = key[i]; // a cell's dart, or a dart's phi1: INVALID_INDEX on free lines
			if (k == INVALID_INDEX)
				continue;
			Dart d(k);
			uint32 line = i;
			if (!indexed)
			{
				d = Dart(i);
				line = INVALID_INDEX;
				if (!starts->starts_cell(d))
					continue;
			}
			if (!call_and_continue(f, reported_cell<CELL>(d, line)))
				return;
		}
	}
}

} // namespace detail

/// Calls f on every cell of the type of f's parameter (e.g. `[](Vertex v)`),
/// boundary cells excluded. f may return false to stop. O(number of cells)
/// when the orbit is indexed (the cell container is walked), O(number of
/// darts) otherwise. No assumption can be made on the dart representing each
/// cell. Works on maps and on views (CellFilter, CellCache). On a map, a
/// callable taking `Located<Vertex>` (LocatedCell) gets each cell with its
/// line: value() and the cached local traversals then skip the dart -> index
/// lookup (the quick mode's fastest form).
template <typename MESH, typename FUNC>
void foreach_cell(const MESH& m, const FUNC& f)
{
	using CELL = func_parameter_type<FUNC>;
	static_assert(CellType<CELL>, "foreach_cell: the callable must take a cell (e.g. Vertex) by value");
	if constexpr (std::is_base_of_v<CMapBase, MESH>)
		detail::foreach_cell_of_map<CELL>(m, f);
	else
		m.template foreach_cell<CELL>(f);
}

/// Number of cells of type CELL (boundary cells excluded). O(1) when the orbit
/// is indexed, O(number of darts) otherwise.
template <typename CELL, typename MESH>
uint32 nb_cells(const MESH& m)
{
	if constexpr (std::is_base_of_v<CMapBase, MESH>)
	{
		if constexpr (CELL::ORBIT != Orbit::DART)
			if (is_indexed<CELL>(m))
				return detail::state_of(m).cells[orbit_index(CELL::ORBIT)]->nb_lines();
	}
	uint32 n = 0;
	foreach_cell(m, [&](CELL) { ++n; });
	return n;
}

} // namespace cgogn
