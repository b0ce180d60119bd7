// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/orbits.h>

#include <array>

namespace cgogn::detail
{

/// A new dart with the boundary mark of `like` (the face it joins). O(1).
inline Dart new_dart_like(GMap1& m, Dart like)
{
	const Dart d = add_dart(m);
	if (is_boundary(m, like))
		set_boundary(m, d, true);
	return d;
}

/// Links a and b by beta_i whatever they were linked to (the caller relinks
/// their former partners). O(1).
template <uint32 I, typename MAP>
void link_beta(MAP& m, Dart a, Dart b)
{
	set_beta<I>(m, a, b);
	set_beta<I>(m, b, a);
}

/// The darts of an edge of a 2-G-map: d, beta0(d), beta2(d), beta0(beta2(d)).
inline std::array<Dart, 4> edge_darts(const GMap2& m, Dart d)
{
	return {d, beta0(m, d), beta2(m, d), beta0(m, beta2(m, d))};
}

} // namespace cgogn::detail
