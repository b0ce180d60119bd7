// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/ncell_walk.h>
#include <cgogn/core/marking/dart_marker.h>

#include <array>
#include <limits>
#include <utility>

namespace cgogn::detail
{

/// The dimension of the cells of type CELL in MAP (CELL is
/// cell_of_dimension_t<MAP, I>) other than OTHER, or no value when CELL is
/// none of them (a sub-cell such as the vertex of one volume). OTHER tells
/// the vertices from the edges of a CMap1, both single darts.
template <typename MAP, typename CELL, uint32 OTHER>
constexpr uint32 dimension_of_cell()
{
	return []<std::size_t... I>(std::index_sequence<I...>)
	{
		uint32 r = std::numeric_limits<uint32>::max();
		((r = r > I && I != OTHER && std::is_same_v<CELL, cell_of_dimension_t<MAP, I>> ? uint32(I) : r), ...);
		return r;
	}
	(std::make_index_sequence<MAP::dimension + 1>{});
}

/// One generator of the incidences of I-cells with J-cells: relation
/// `first` (0 is beta0), then relation `then` when it is not 0.
struct IncidenceGenerator
{
	uint32 first = 0;
	uint32 then = 0;
};

/// The generators of the incidences of the I-cells with the J-cells (I != J)
/// of a D-dimensional map: the relations shared by both orbits, whose
/// orbits split an I-cell into its incidences with J-cells (its corners with
/// faces, its sides with facets, ...).
/// - In a G-map, the beta_k, k != I, J.
/// - In a combinatorial map without vertices (I, J >= 1), the phi_k, k >= 1,
///   k != I, J.
/// - Between the vertices and the J-cells, J >= 2, the phi1 o phi_k, k >= 2,
///   k != J: those that keep both the vertex and the J-cell.
/// - Between the vertices and the edges, the phi2 o phi_k, k >= 3: a dart
///   and phi2 of it lie on the same edge but leave its two ends, so the ones
///   that leave the same end are those of an even number of phi_k, k >= 2.
/// None at all (each dart its own incidence) between the vertices, edges and
/// faces of a combinatorial 2-map.
template <bool GMAP, uint32 D, uint32 I, uint32 J>
constexpr auto incidence_generators()
{
	static_assert(I != J && I <= D && J <= D);
	constexpr uint32 lo = I < J ? I : J, hi = I < J ? J : I;
	std::array<IncidenceGenerator, GMAP ? D - 1 : (D >= 2 ? D - 2 : 0)> g{};
	uint32 n = 0;
	if constexpr (GMAP)
	{
		for (uint32 k = 0; k <= D; ++k)
			if (k != I && k != J)
				g[n++] = {k, 0};
	}
	else if constexpr (lo >= 1)
	{
		for (uint32 k = 1; k <= D; ++k)
			if (k != I && k != J)
				g[n++] = {k, 0};
	}
	else if constexpr (hi >= 2)
	{
		for (uint32 k = 2; k <= D; ++k)
			if (k != hi)
				g[n++] = {k, 1};
	}
	else
	{
		for (uint32 k = 3; k <= D; ++k)
			g[n++] = {k, 2};
	}
	return g;
}

/// One incidence generator read through relation views (see NCellStep):
/// the image of line i.
struct IncidenceStep
{
	RelationView first;
	RelationView then;
	bool beta0 = false;
	bool composed = false;

	IncidenceStep(const MapState& s, IncidenceGenerator g)
		: first(s.relations[g.first == 0 ? 0 : g.first - 1]->view()),
		  then(s.relations[g.then == 0 ? 0 : g.then - 1]->view()), beta0(g.first == 0), composed(g.then != 0)
	{
	}

	CGOGN_INLINE uint32 operator[](uint32 i) const
	{
		const uint32 x = beta0 ? i ^ 1u : first[i];
		return composed ? then[x] : x;
	}
};

/// The generator that, with those of the incidences of the I-cells with
/// the J-cells, generates the I-cells: it leads from an incidence to the
/// next one around the I-cell. beta_J in a G-map, phi_J between cells of
/// dimension 1 and more; around a vertex phi1 o phi_J (phi1 o phi2 for the
/// edges); around the vertices of a cell phi1 (phi2 for an edge).
template <bool GMAP, uint32 I, uint32 J>
constexpr IncidenceGenerator incidence_crossing()
{
	if constexpr (GMAP || (I >= 1 && J >= 1))
		return {J, 0};
	else if constexpr (I == 0)
		return J >= 2 ? IncidenceGenerator{J, 1} : IncidenceGenerator{2, 1};
	else
		return I >= 2 ? IncidenceGenerator{1, 0} : IncidenceGenerator{2, 0};
}

/// The incidences of the I-cells of MAP with its J-cells.
template <typename MAP, uint32 I, uint32 J>
struct Incidences
{
	static constexpr auto generators = incidence_generators<is_gmap_v<MAP>, MAP::dimension, I, J>();
	/// Whether each dart is an incidence of its own (no generator).
	static constexpr bool single_darts = generators.size() == 0;

	/// The steps of the generators, made once per traversal.
	static auto steps(const MapState& s)
	{
		return [&]<std::size_t... K>(std::index_sequence<K...>)
		{
			return std::array<IncidenceStep, generators.size()>{IncidenceStep(s, generators[K])...};
		}
		(std::make_index_sequence<generators.size()>{});
	}
};

/// Marks the darts of the incidence of d (the orbit of the generators of
/// `steps`) in `marked`, d unmarked. O(size of the incidence); the work list
/// is the marker's record of the darts it marked.
template <typename MARKER, std::size_t N>
void mark_incidence(MARKER& marked, const std::array<IncidenceStep, N>& steps, Dart d)
{
	if constexpr (N == 1)
	{
		// a permutation (phi1, phi1 o phi_k, ...) or an involution: a cycle
		Dart x = d;
		do
		{
			marked.mark(x);
			x = Dart(steps[0][x.index]);
		} while (x != d);
	}
	else
	{
		const std::vector<Dart>& darts = marked.marked_darts();
		std::size_t i = darts.size();
		marked.mark(d);
		for (; i < darts.size(); ++i)
		{
			const Dart x = darts[i];
			for (const IncidenceStep& next : steps)
				marked.mark(Dart(next[x.index]));
		}
	}
}

/// Calls f(d) on one dart d of each incidence of the I-cell of `start` with
/// J-cells, that of `start` first (start itself), then the others in the
/// order met by crossing from one to the next (see incidence_crossing); f
/// may return false to stop. Returns false when f stopped. Each dart of the
/// I-cell is marked once (pooled marks: no allocation once warm).
template <uint32 I, uint32 J, typename MAP, typename FUNC>
bool foreach_incidence_dart(const MAP& m, Dart start, const FUNC& f)
{
	using Incidences = detail::Incidences<MAP, I, J>;
	static_assert(!Incidences::single_darts, "each dart is an incidence: walk the darts");
	const MapState& s = state_of(m);
	const auto steps = Incidences::steps(s);
	const IncidenceStep crossing(s, incidence_crossing<is_gmap_v<MAP>, I, J>());
	DartMarkerStore<MAP> met(m);
	const std::vector<Dart>& darts = met.marked_darts();
	mark_incidence(met, steps, start);
	if (!f(start))
		return false;
	for (std::size_t i = 0; i < darts.size(); ++i)
	{
		const Dart next(crossing[darts[i].index]);
		if (!met.is_marked(next))
		{
			mark_incidence(met, steps, next);
			if (!f(next))
				return false;
		}
	}
	return true;
}

} // namespace cgogn::detail
