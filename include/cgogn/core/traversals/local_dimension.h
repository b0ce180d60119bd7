// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/traversals/local_cell_set.h>

namespace cgogn
{

// Incidence and adjacency by dimension, for every map: the maps of any
// dimension (CMapN, GMapN) and those of dimension 1 to 3, whose cells of
// dimension J are cell_of_dimension_t<MAP, J>. One generic family; the maps
// of dimension 2 and 3 keep their tuned circulators (foreach_incident_edge,
// foreach_adjacent_vertex_through_edge, ...), which give the same cells.

/// Calls f on each J-cell incident to cell c (the J-cells that share a dart
/// with c: for J below c's dimension its faces, above it the cells it lies
/// in), each once, boundary cells excluded; f may return false to stop.
/// Cost: O(size of c's orbit) when the J-cells are indexed (a bit per cell
/// in the container), otherwise O(size of c's orbit + size of the J-cells met), each
/// walked once to mark its darts; marks are cleared in O(marks set) (pooled:
/// no allocation once warm).
template <uint32 J, typename MAP, Orbit O, typename FUNC>
requires std::derived_from<MAP, CMapBase>
void foreach_incident_cell(const MAP& m, Cell<O> c, const FUNC& f)
{
	using CJ = cell_of_dimension_t<MAP, J>;
	detail::LocalCellSet<MAP, CJ> met(m);
	foreach_dart_of_orbit(m, c, [&](Dart d) {
		const CJ x(d);
		return is_boundary_cell(m, x) || !met.insert(x) || call_and_continue(f, x);
	});
}

/// Calls f on each cell of c's type that shares a K-cell with c (c's
/// neighbours through K-cells: the 4-cells around a 4-cell through its
/// 3-cells, the vertices of a vertex's star through its edges or through
/// its D-cells, ...), each once, c excluded, boundary cells excluded (a
/// boundary K-cell links nothing); f may return false to stop.
/// Cost: the incidence of c with its K-cells, then of each K-cell with
/// their cells of c's type (see foreach_incident_cell). In a CMapN or GMapN
/// two cases take a shortcut with the same result: the D-cells through
/// their facets (the cell beyond each dart's facet, relation D away) and
/// the vertices through edges (the vertex at the other end of each dart's
/// edge), each O(size of c's orbit) when c's type is indexed, plus the size
/// of each neighbour otherwise (walked once to mark it).
template <uint32 K, typename MAP, Orbit O, typename FUNC>
requires std::derived_from<MAP, CMapBase>
void foreach_adjacent_cell(const MAP& m, Cell<O> c, const FUNC& f)
{
	using CI = Cell<O>;
	static_assert(!std::is_same_v<CI, cell_of_dimension_t<MAP, K>>, "adjacency through the cells themselves");
	detail::LocalCellSet<MAP, CI> met(m);
	if (!is_boundary_cell(m, c))
		met.insert(c);
	const auto report = [&](CI x) { return is_boundary_cell(m, x) || !met.insert(x) || call_and_continue(f, x); };
	if constexpr (is_nmap_v<MAP> && MAP::dimension >= 2 && std::is_same_v<CI, CellD<MAP::dimension>> &&
				  K + 1 == MAP::dimension)
	{
		// a facet has two sides, relation D apart: the D-cells beyond the
		// facets of c are those of relation D of c's darts
		foreach_dart_of_orbit(m, c, [&](Dart d) { return report(CI(detail::relation(m, MAP::dimension, d))); });
	}
	else if constexpr (is_nmap_v<MAP> && MAP::dimension >= 2 && std::is_same_v<CI, CellD<0>> && K == 1)
	{
		// every edge at c has a dart of c, whose other end is beta0 (a G-map)
		// or the start of phi1 (a combinatorial map: c's darts leave it)
		foreach_dart_of_orbit(m, c, [&](Dart d) {
			if constexpr (is_gmap_v<MAP>)
				return report(CI(beta0(m, d)));
			else
				return report(CI(phi1(m, d)));
		});
	}
	else
	{
		bool go_on = true;
		foreach_incident_cell<K>(m, c, [&](cell_of_dimension_t<MAP, K> k) {
			foreach_dart_of_orbit(m, k, [&](Dart d) {
				go_on = report(CI(d));
				return go_on;
			});
			return go_on;
		});
	}
}

} // namespace cgogn
