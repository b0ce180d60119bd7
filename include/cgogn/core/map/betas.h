// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/darts.h>

namespace cgogn
{

// The involutions of the generalized maps. beta0 is not stored: darts are
// allocated in pairs (2k, 2k + 1), the two ends of an edge in one face, which
// stay each other's beta0 for their whole life (see detail::add_dart_pair).
// A new pair is a fixed point of every other beta_i until sewn; builders and
// operators leave no fixed point in a finished map (holes are closed by
// boundary faces, as in the CMaps).

/// The dart at the other end of the same edge, in the same face: the other
/// dart of d's pair. O(1), no memory access.
CGOGN_INLINE Dart beta0(const GMap1&, Dart d)
{
	return Dart(d.index ^ 1u);
}

/// The dart of the other edge at the same vertex, in the same face. O(1).
CGOGN_INLINE Dart beta1(const GMap1& m, Dart d)
{
	return Dart((*detail::state_of(m).beta[1])[d.index]);
}

/// The dart of the adjacent face at the same vertex of the same edge. O(1).
CGOGN_INLINE Dart beta2(const GMap2& m, Dart d)
{
	return Dart((*detail::state_of(m).beta[2])[d.index]);
}

/// The dart of the adjacent volume at the same vertex, edge and face. O(1).
CGOGN_INLINE Dart beta3(const GMap3& m, Dart d)
{
	return Dart((*detail::state_of(m).beta[3])[d.index]);
}

/// beta0 of a G-map of any dimension: the other dart of d's pair. O(1).
template <uint32 D>
CGOGN_INLINE Dart beta0(const GMapN<D>&, Dart d)
{
	return Dart(d.index ^ 1u);
}

/// beta1 of a G-map of any dimension. O(1).
template <uint32 D>
CGOGN_INLINE Dart beta1(const GMapN<D>& m, Dart d)
{
	return Dart((*detail::state_of(m).beta[1])[d.index]);
}

/// beta2 of a G-map of any dimension (D >= 2). O(1).
template <uint32 D>
requires(D >= 2) CGOGN_INLINE Dart beta2(const GMapN<D>& m, Dart d)
{
	return Dart((*detail::state_of(m).beta[2])[d.index]);
}

/// beta3 of a G-map of any dimension (D >= 3). O(1).
template <uint32 D>
requires(D >= 3) CGOGN_INLINE Dart beta3(const GMapN<D>& m, Dart d)
{
	return Dart((*detail::state_of(m).beta[3])[d.index]);
}

/// Composition of involutions applied left to right: beta<0, 2>(m, d) is
/// beta2(m, beta0(m, d)). O(number of relations).
template <int... N, typename MAP>
Dart beta(const MAP& m, Dart d)
{
	static_assert(((N >= 0 && N <= int(MAP::dimension)) && ...), "beta<...>: relation not available in this map");
	auto apply = [&](int n) {
		if (n == 0)
			d = beta0(m, d);
		else if (n == 1)
			d = beta1(m, d);
		else if (n == 2)
		{
			if constexpr (MAP::dimension >= 2)
				d = beta2(m, d);
		}
		else if (n == 3)
		{
			if constexpr (MAP::dimension >= 3)
				d = beta3(m, d);
		}
		else
			d = Dart((*detail::state_of(m).beta[n])[d.index]);
	};
	(apply(N), ...);
	return d;
}

namespace detail
{

/// Sets beta_i(d) = e (one side only), for i >= 1 (beta0 is fixed by the
/// allocation of the darts). Every change of a relation drops the quick
/// incidence caches (see drop_incidence_caches).
template <uint32 I, typename MAP>
requires is_gmap_v<MAP> &&(I >= 1 && I <= MAP::dimension) inline void set_beta(MAP& m, Dart d, Dart e)
{
	drop_incidence_caches(m);
	(*detail::state_of(m).beta[I])[d.index] = e.index;
}

} // namespace detail

/// Links d and e by beta_i (i >= 1); both must be beta_i fixed points. Low
/// level: the map is not closed while fixed points remain (builders use it).
template <uint32 I, typename MAP>
requires is_gmap_v<MAP> &&(I >= 1 && I <= MAP::dimension) void beta_sew(MAP& m, Dart d, Dart e)
{
	assert(beta<int(I)>(m, d) == d && beta<int(I)>(m, e) == e);
	detail::set_beta<I>(m, d, e);
	detail::set_beta<I>(m, e, d);
}

/// Unlinks d and beta_i(d) (i >= 1), leaving two fixed points. Low level.
template <uint32 I, typename MAP>
requires is_gmap_v<MAP> &&(I >= 1 && I <= MAP::dimension) void beta_unsew(MAP& m, Dart d)
{
	const Dart e = beta<int(I)>(m, d);
	detail::set_beta<I>(m, d, d);
	detail::set_beta<I>(m, e, e);
}

} // namespace cgogn
