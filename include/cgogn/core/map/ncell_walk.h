// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/betas.h>
#include <cgogn/core/marking/dart_marker.h>

#include <array>
#include <utility>

namespace cgogn::detail
{

/// The rest of the orbit of two involutions that is a path, not a cycle:
/// having met a fixed point going one way from d, walks the other way from d,
/// starting with `first`, then alternating. Returns false when f stopped.
template <typename FUNC, typename FIRST, typename SECOND>
bool walk_path_back(Dart d, const FUNC& f, const FIRST& first, const SECOND& second)
{
	Dart it = d;
	for (;;)
	{
		const Dart e(first[it.index]);
		if (e == it)
			return true;
		if (!call_and_continue(f, e))
			return false;
		const Dart g(second[e.index]);
		if (g == e)
			return true;
		if (!call_and_continue(f, g))
			return false;
		it = g;
	}
}

/// The generators of the I-cells of a D-dimensional map, as relation
/// numbers: in a G-map the beta_j, j != I (0 stands for beta0); in a
/// combinatorial map the phi_j, j != I, j >= 1, or for vertices (I = 0) the
/// phi1 o phi_j, j >= 2 (j then stands for phi_j followed by phi1).
template <bool GMAP, uint32 D, uint32 I>
constexpr std::array<uint32, GMAP ? D : D - 1> ncell_generators()
{
	std::array<uint32, GMAP ? D : D - 1> g{};
	uint32 k = 0;
	for (uint32 j = GMAP ? 0 : (I == 0 ? 2 : 1); j <= D; ++j)
		if (j != I)
			g[k++] = j;
	return g;
}

/// A relation read through a view held in a local (see LineStorage::View).
using RelationView = decltype(std::declval<const AttributeArray<uint32>&>().view());

/// One generator of the I-cells of a map of any dimension, read as a
/// relation view (see walk_path_back): the image of line i. Made once per
/// walk: it holds the views of the relations it reads.
template <typename MAP, uint32 I>
struct NCellStep
{
	RelationView rel;   ///< relation j (unused for beta0)
	RelationView phi1;  ///< phi1, for the vertices of a combinatorial map
	bool beta0 = false; ///< the generator is beta0 (d xor 1)

	NCellStep(const MapState& s, uint32 j)
		: rel(s.relations[j == 0 ? 0 : j - 1]->view()), phi1(s.relations[0]->view()), beta0(j == 0)
	{
	}

	CGOGN_INLINE uint32 operator[](uint32 i) const
	{
		if constexpr (is_gmap_v<MAP>)
			return beta0 ? i ^ 1u : rel[i];
		else if constexpr (I == 0)
			return phi1[rel[i]];
		else
			return rel[i];
	}
};

/// The steps of the generators of the I-cells of MAP (see ncell_generators).
template <typename MAP, uint32 I>
auto ncell_steps(const MapState& s)
{
	constexpr auto gens = ncell_generators<is_gmap_v<MAP>, MAP::dimension, I>();
	return [&]<std::size_t... K>(std::index_sequence<K...>)
	{
		return std::array<NCellStep<MAP, I>, gens.size()>{NCellStep<MAP, I>(s, gens[K])...};
	}
	(std::make_index_sequence<gens.size()>{});
}

/// Whether the I-cells of MAP are pairs of darts exchanged by one
/// involution (the edges of a 2-map, the vertices and edges of a 1-G-map).
template <typename MAP, uint32 I>
constexpr bool ncell_is_pair()
{
	constexpr auto gens = ncell_generators<is_gmap_v<MAP>, MAP::dimension, I>();
	return gens.size() == 1 && (is_gmap_v<MAP> || (I != 0 && gens[0] != 1));
}

/// Whether the I-cells of a combinatorial MAP are two phi1 cycles exchanged
/// by an involution phi_j, j >= 3 (the faces of a 3-map): phi1 o phi_j is
/// an involution, so phi_j maps the cycle of d onto the reversed cycle of
/// phi_j(d).
template <typename MAP, uint32 I>
constexpr bool ncell_is_two_cycles()
{
	constexpr auto gens = ncell_generators<is_gmap_v<MAP>, MAP::dimension, I>();
	if constexpr (gens.size() == 2 && !is_gmap_v<MAP> && I != 0)
		return gens[0] == 1 && gens[1] >= 3;
	else
		return false;
}

/// Whether foreach_dart_of_ncell floods the I-cells of MAP (with a mark and
/// a work list) rather than walking them as a cycle, a pair or two cycles.
template <typename MAP, uint32 I>
constexpr bool ncell_is_flooded()
{
	constexpr auto gens = ncell_generators<is_gmap_v<MAP>, MAP::dimension, I>();
	return gens.size() > 2 ||
		   (gens.size() == 2 && !is_gmap_v<MAP> && (I == 0 || gens[0] == 1) && !ncell_is_two_cycles<MAP, I>());
}

/// Calls f on each dart of the I-cell of d in a CMapN or GMapN (see
/// foreach_dart_of_orbit); f may return false to stop. Returns false when
/// stopped. O(size of the cell). The orbit of one generator is walked as a
/// cycle (phi1 in a face of a 2-map, phi1 o phi2 around its vertex) or a pair
/// (an involution); that of two involutions (edges of a 3-map, every cell of
/// a 2-G-map) as one cycle alternating them, or a path in a map not closed
/// yet; that of phi1 and phi_j, j >= 3 (faces of a 3-map) as two phi1
/// cycles; the others are flooded with a pooled mark (no allocation once warm).
template <uint32 I, typename MAP, typename FUNC>
bool foreach_dart_of_ncell(const MAP& m, Dart d, const FUNC& f)
{
	constexpr bool G = is_gmap_v<MAP>;
	constexpr auto gens = ncell_generators<G, MAP::dimension, I>();
	const auto steps = ncell_steps<MAP, I>(state_of(m));
	if constexpr (gens.size() == 0)
		return call_and_continue(f, d);
	else if constexpr (gens.size() == 1)
	{
		const NCellStep<MAP, I>& next = steps[0];
		if constexpr (!G && (I == 0 || gens[0] == 1))
		{
			// a permutation: phi1 or phi1 o phi2
			Dart it = d;
			do
			{
				if (!call_and_continue(f, it))
					return false;
				it = Dart(next[it.index]);
			} while (it != d);
			return true;
		}
		else
		{
			const Dart e(next[d.index]);
			return call_and_continue(f, d) && (e == d || call_and_continue(f, e));
		}
	}
	else if constexpr (ncell_is_two_cycles<MAP, I>())
	{
		// the phi1 cycle of d, then that of phi_j(d) unless it is the same
		const NCellStep<MAP, I>&next = steps[0], &across = steps[1];
		const Dart e(across[d.index]);
		bool e_met = false;
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			e_met |= it == e;
			it = Dart(next[it.index]);
		} while (it != d);
		if (e_met)
			return true;
		it = e;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = Dart(next[it.index]);
		} while (it != e);
		return true;
	}
	else if constexpr (!ncell_is_flooded<MAP, I>())
	{
		// two involutions a and b: d, a(d), b(a(d)), ... (see walk_path_back)
		const NCellStep<MAP, I>&a = steps[0], &b = steps[1];
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			const Dart e(a[it.index]);
			if (e == it)
				return walk_path_back(d, f, b, a);
			if (!call_and_continue(f, e))
				return false;
			it = Dart(b[e.index]);
			if (it == e)
				return walk_path_back(d, f, b, a);
		} while (it != d);
		return true;
	}
	else
	{
		DartMarkerStore<MAP> seen(m);
		const std::vector<Dart>& darts = seen.marked_darts();
		seen.mark(d);
		for (std::size_t i = 0; i < darts.size(); ++i)
		{
			const Dart x = darts[i];
			if (!call_and_continue(f, x))
				return false;
			for (const NCellStep<MAP, I>& next : steps)
				seen.mark(Dart(next[x.index]));
		}
		return true;
	}
}

} // namespace cgogn::detail
