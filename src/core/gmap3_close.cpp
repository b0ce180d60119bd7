// SPDX-License-Identifier: MIT
// Closing a 3-G-map: the boundary volumes that mirror its free faces.
#include "gmap3_close.h"

#include <cgogn/core/map/betas.h>

#include "gmap_darts.h"
#include "index_lines.h"

#include <cassert>

namespace cgogn::detail
{

void close_beta3_holes(GMap3& m, const std::vector<Dart>& darts, std::vector<Dart>& created)
{
	const std::size_t first = created.size();
	// 1. a boundary mirror for every free dart, pair by pair (free darts come
	// in whole faces: the pair of a free dart is free)
	for (Dart d : darts)
	{
		if (beta3(m, d) != d)
			continue;
		assert(beta3(m, beta0(m, d)) == beta0(m, d));
		const Dart p = add_dart_pair(m);
		for (const auto& [x, b] : {std::pair{d, p}, std::pair{beta0(m, d), beta0(m, p)}})
		{
			set_boundary(m, b, true);
			copy_dart_index<Orbit::BETA1_BETA2_BETA3>(m, b, x);
			copy_dart_index<Orbit::BETA0_BETA2_BETA3>(m, b, x);
			copy_dart_index<Orbit::BETA0_BETA1_BETA3>(m, b, x);
			copy_dart_index<Orbit::BETA0_BETA1_BETA2_BETA3>(m, b, x);
			link_beta<3>(m, x, b);
			created.push_back(b);
		}
	}
	// 2. the faces of the boundary mirror the free faces; around each edge, a
	// boundary dart is glued to the first boundary dart met by turning from
	// its own free dart through the inner volumes
	for (std::size_t i = first; i < created.size(); ++i)
	{
		const Dart b = created[i];
		const Dart d = beta3(m, b);
		assert(beta3(m, beta1(m, d)) != beta1(m, d));
		if (beta1(m, b) == b)
			link_beta<1>(m, b, beta3(m, beta1(m, d)));
		if (beta2(m, b) != b)
			continue;
		Dart e = beta2(m, d);
		while (beta3(m, e) != e && !is_boundary(m, beta3(m, e)))
			e = beta2(m, beta3(m, e));
		assert(beta3(m, e) != e); // free darts come in whole faces: all mirrored above
		// a new boundary dart, or an older one, which leaves its former
		// neighbour (that one meets a new dart from the other side)
		link_beta<2>(m, b, beta3(m, e));
	}
}

} // namespace cgogn::detail
