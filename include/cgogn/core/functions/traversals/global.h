// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/functions/indexing.h>
#include <cgogn/core/functions/mesh_access.h>
#include <cgogn/core/types/marker.h>

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

/// Visits every real cell of type CELL of map m (see foreach_cell).
template <typename CELL, typename MAP, typename FUNC>
void foreach_cell_of_map(const MAP& m, const FUNC& f)
{
	constexpr Orbit O = CELL::ORBIT;
	if constexpr (O == Orbit::DART)
	{
		// a dart's line is its index
		foreach_dart(m, [&](Dart d) { return is_boundary(m, d) || call_and_continue(f, reported_cell<CELL>(d, d.index)); });
	}
	else
	{
		if (is_indexed<CELL>(m))
		{
			// walk the cell container: one representative dart per live line
			// the keys through a view held in a local: the compiler would otherwise
			// reload the storage's base and bound at each line (f, when it is not
			// inlined, might change them as far as the compiler knows)
			const auto rep = m.cells_[orbit_index(O)]->key().view();
			for (uint32 i = 0, end = m.cells_[orbit_index(O)]->end_index(); i < end; ++i)
			{
				const uint32 d = rep[i];
				if (d == INVALID_INDEX)
					continue;
				if (!call_and_continue(f, reported_cell<CELL>(Dart(d), i)))
					return;
			}
		}
		else if constexpr (O == Orbit::PHI2)
		{
			// an edge is visited from its smaller dart, or from its only non-boundary one
			foreach_dart(m, [&](Dart d) {
				if (is_boundary(m, d))
					return true;
				const Dart e = phi2(m, d);
				if (d.index < e.index || is_boundary(m, e))
					return call_and_continue(f, reported_cell<CELL>(d));
				return true;
			});
		}
		else if constexpr (orbit_is_flooded(O))
		{
			// one mark for the whole traversal, also used by the floods (a cell
			// is flooded once, from its first dart met, the smallest non-boundary one)
			ScopedDartMark mark(m);
			DartBuffer buffer;
			foreach_dart(m, [&](Dart d) {
				if (is_boundary(m, d) || (*mark).test(d.index))
					return true;
				flood_orbit_keep_marks<O>(m, d, *mark, *buffer, [](Dart) {});
				return call_and_continue(f, reported_cell<CELL>(d));
			});
		}
		else
		{
			DartMarker<MAP> dm(m);
			foreach_dart(m, [&](Dart d) {
				if (is_boundary(m, d) || dm.is_marked(d))
					return true;
				dm.mark_orbit(Cell<O>(d));
				return call_and_continue(f, reported_cell<CELL>(d));
			});
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
				return m.cells_[orbit_index(CELL::ORBIT)]->nb_lines();
	}
	uint32 n = 0;
	foreach_cell(m, [&](CELL) { ++n; });
	return n;
}

} // namespace cgogn
