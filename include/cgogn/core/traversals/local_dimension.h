// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/detail/incidence_lookup.h>
#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/traversals/incidence_classes.h>
#include <cgogn/core/traversals/local_cell_set.h>

namespace cgogn
{

// Incidence and adjacency by dimension, for every map: the maps of any
// dimension (CMapN, GMapN) and those of dimension 1 to 3, whose cells of
// dimension J are cell_of_dimension_t<MAP, J>. One generic family; the maps
// of dimension 2 and 3 keep their tuned circulators (foreach_incident_edge,
// foreach_adjacent_vertex_through_edge, ...), which give the same cells.
//
// Each function reports each cell once, or, given `each_incidence`, once
// per incidence: the incidences of an I-cell with its J-cells split its
// darts by the relations both orbits share (see detail::incidence_generators):
// the corners of a face, the sides of a facet, one dart per corner around
// a vertex of a surface. On a manifold mesh every cell meets another at most
// once, and both give the same cells; where a face passes twice by a vertex
// (or an edge is a loop), each_incidence reports it twice, as the tuned
// circulators of the surfaces do, and costs no deduplication.

namespace detail
{

/// The two shortcuts of foreach_adjacent_cell, in both its forms.
/// A dart of the vertex at the other end of d's edge, in a map of dimension
/// 2 or more: beta0 in a G-map, phi2 in a combinatorial map (d leaves its
/// vertex, phi2(d) the other end; the walk around a vertex has just read it,
/// where phi1(d) would be one more load). O(1).
template <typename MAP>
CGOGN_INLINE Dart far_end_of_edge(const MAP& m, Dart d)
{
	if constexpr (is_gmap_v<MAP>)
		return beta0(m, d);
	else
		return phi2(m, d);
}
/// The dart facing d across its facet, in the D-cell on the other side:
/// relation D (a facet has two sides). O(1).
template <typename MAP>
CGOGN_INLINE Dart across_facet(const MAP& m, Dart d)
{
	return relation(m, MAP::dimension, d);
}

} // namespace detail

/// Selects the traversals that report a cell once per incidence.
struct EachIncidence
{
};
/// See EachIncidence.
inline constexpr EachIncidence each_incidence{};

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
		// the D-cells beyond the facets of c are across c's darts
		foreach_dart_of_orbit(m, c, [&](Dart d) { return report(CI(detail::across_facet(m, d))); });
	else if constexpr (is_nmap_v<MAP> && MAP::dimension >= 2 && std::is_same_v<CI, CellD<0>> && K == 1)
		// every edge at c has a dart of c
		foreach_dart_of_orbit(m, c, [&](Dart d) { return report(CI(detail::far_end_of_edge(m, d))); });
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

/// Calls f on the J-cell of each incidence of cell c with J-cells (see
/// EachIncidence), boundary cells excluded, the J-cell of c.dart first; f
/// may return false to stop. c is a cell of a dimension of the map
/// (cell_of_dimension_t), J another one.
/// Cost: O(size of c's orbit), without any mark, where each dart is its own
/// incidence (the vertices, edges and faces of a combinatorial 2-map);
/// otherwise c is walked incidence by incidence, each dart marked once
/// (pooled marks: no allocation once warm).
template <uint32 J, typename MAP, Orbit O, typename FUNC>
requires std::derived_from<MAP, CMapBase>
void foreach_incident_cell(const MAP& m, Cell<O> c, const FUNC& f, EachIncidence)
{
	constexpr uint32 I = detail::dimension_of_cell<MAP, Cell<O>, J>();
	static_assert(I <= MAP::dimension, "c is not a cell of one of the map's dimensions other than J");
	using CJ = cell_of_dimension_t<MAP, J>;
	using Incidences = detail::Incidences<MAP, I, J>;
	if constexpr (Incidences::single_darts)
	{
		// only the D-cells can be boundary cells, and only in a map with a boundary
		if (J < MAP::dimension || !has_boundary(m))
			detail::report_with_lines<CJ>(
				m, [&](const auto& report) { foreach_dart_of_orbit(m, c, report); }, f);
		else
			detail::report_with_lines<CJ>(
				m,
				[&](const auto& report) {
					foreach_dart_of_orbit(m, c, [&](Dart d) { return is_boundary_cell(m, CJ(d)) || report(d); });
				},
				f);
	}
	else
		detail::foreach_incidence_dart<I, J>(
			m, c.dart, [&](Dart d) { return is_boundary_cell(m, CJ(d)) || call_and_continue(f, CJ(d)); });
}

/// Calls f on the cells of c's type met through each incidence of c with
/// K-cells (see EachIncidence): for each K-cell k at c, once per incidence
/// of k with cells of c's type other than the one c meets k by, boundary
/// cells excluded; c itself when a K-cell meets it twice (the far end of a
/// loop edge). f may return false to stop. On a manifold mesh, the cells of
/// foreach_adjacent_cell<K>, each once per K-cell it shares with c (once
/// through edges or facets). c is a cell of a dimension of the map, K
/// another one.
/// Cost: the incidences of c with K-cells (see above), then each K-cell met
/// is walked, its incidences with cells of c's type marked as in
/// foreach_incident_cell. Two cases take a shortcut, with no walk of the
/// K-cells: the D-cells through their facets (relation D of each side) and
/// the vertices through edges (the other end of each dart's edge), each
/// O(size of c's orbit) without any mark in a combinatorial 2-map.
template <uint32 K, typename MAP, Orbit O, typename FUNC>
requires std::derived_from<MAP, CMapBase>
void foreach_adjacent_cell(const MAP& m, Cell<O> c, const FUNC& f, EachIncidence)
{
	using CI = Cell<O>;
	using CK = cell_of_dimension_t<MAP, K>;
	constexpr uint32 I = detail::dimension_of_cell<MAP, CI, K>();
	constexpr uint32 D = MAP::dimension;
	static_assert(!std::is_same_v<CI, CK>, "adjacency through the cells themselves");
	static_assert(I <= D, "c is not a cell of one of the map's dimensions");
	const auto report = [&](CI x) { return is_boundary_cell(m, x) || call_and_continue(f, x); };
	if constexpr (D >= 2 && I == D && K + 1 == D)
		foreach_incident_cell<K>(
			m, c, [&](CK k) { return report(CI(detail::across_facet(m, k.dart))); }, each_incidence);
	else if constexpr (D >= 2 && I == 0 && K == 1)
		foreach_incident_cell<K>(
			m, c, [&](CK k) { return report(CI(detail::far_end_of_edge(m, k.dart))); }, each_incidence);
	else
	{
		foreach_incident_cell<K>(
			m, c,
			[&](CK k) {
				// k's incidences with cells of c's type but the one of c's dart
				if constexpr (detail::Incidences<MAP, K, I>::single_darts)
					return foreach_dart_of_orbit(m, k, [&](Dart x) { return x == k.dart || report(CI(x)); });
				else
					return detail::foreach_incidence_dart<K, I>(m, k.dart,
																[&](Dart x) { return x == k.dart || report(CI(x)); });
			},
			each_incidence);
	}
}

} // namespace cgogn
