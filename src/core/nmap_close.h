// SPDX-License-Identifier: MIT
// Closing a map of any dimension: the free facets get boundary D-cells.
#pragma once

#include <cgogn/core/map/betas.h>

#include "nmap_darts.h"

#include <vector>

namespace cgogn::detail
{

/// Sews a boundary dart to every dart of g that beta_D leaves fixed, so
/// that g is closed: the boundary darts of a free facet mirror it (beta_i,
/// i <= D - 2, as the facet's), and beta_{D-1} joins them to the boundary
/// darts of the next free facet around their common (D - 2)-cell, found by
/// turning around it through the cells of g (beta_{D-1} then beta_D). In a
/// 1-G-map, whose free darts are the ends of paths, each path gets one
/// boundary edge from one end to the other. O(number of darts of g, and of
/// the cells around the (D - 2)-cells of the free facets).
template <uint32 D>
void close_free_facets(GMapN<D>& g)
{
	std::vector<Dart> free;
	foreach_dart(g, [&](Dart d) {
		if (relation(g, D, d) == d)
			free.push_back(d);
	});
	auto sew = [&](Dart a, Dart b, uint32 i) {
		set_relation(g, i, a, b);
		set_relation(g, i, b, a);
	};
	auto new_boundary_pair = [&] { return nmap::new_dart(g, true); };
	if constexpr (D == 1)
	{
		for (Dart d : free)
		{
			if (beta1(g, d) != d)
				continue; // the other end of a path closed already
			Dart e = beta0(g, d);
			while (beta1(g, e) != e)
				e = beta0(g, beta1(g, e));
			const Dart b = new_boundary_pair();
			sew(d, b, 1);
			sew(e, beta0(g, b), 1);
		}
	}
	else
	{
		// beta0 lies in a facet: a free facet's darts are free by pairs
		for (Dart d : free)
			if (d.index % 2 == 0)
			{
				const Dart b = new_boundary_pair();
				sew(d, b, D);
				sew(beta0(g, d), beta0(g, b), D);
			}
		for (Dart d : free)
		{
			const Dart b = relation(g, D, d);
			for (uint32 i = 1; i + 2 <= D; ++i)
				set_relation(g, i, b, relation(g, D, relation(g, i, d)));
			set_relation(g, D - 1, b, nmap::boundary_beside(g, d));
		}
	}
}

} // namespace cgogn::detail
