// SPDX-License-Identifier: MIT
// The dart-level steps shared by the operators of the maps of any dimension
// (nmap_operators.cpp, nmap_sew.cpp, nmap_close.h): one relation by its number, new and
// removed darts for both models, and the relinking around a vanishing cell.
#pragma once

#include <cgogn/core/map/nmap.h>
#include <cgogn/core/marking/marker.h>

#include "gmap_darts.h"

#include <utility>
#include <vector>

namespace cgogn::detail::nmap
{

template <typename MAP>
constexpr bool G = is_gmap_v<MAP>;

// relation i of d: beta0 included in a G-map; phi1 for i = 1 and phi_-1 for
// i = -1 in a combinatorial map
template <typename MAP>
Dart rel(const MAP& m, int i, Dart d)
{
	if constexpr (G<MAP>)
	{
		if (i == 0)
			return Dart(d.index ^ 1u);
	}
	else if (i == -1)
		return phi_1(m, d);
	return relation(m, uint32(i), d);
}

// links a and b by relation i >= 2 (beta_i, i >= 1), both ways
template <typename MAP>
void link(MAP& m, uint32 i, Dart a, Dart b)
{
	set_relation(m, i, a, b);
	set_relation(m, i, b, a);
}

// A new dart (a pair of darts in a G-map), with the boundary mark or not.
template <typename MAP>
Dart new_dart(MAP& m, bool boundary)
{
	if constexpr (G<MAP>)
	{
		const Dart d = add_dart_pair(m);
		set_boundary(m, d, boundary);
		set_boundary(m, beta0(m, d), boundary);
		return d;
	}
	else
	{
		const Dart d = add_dart(m);
		set_boundary(m, d, boundary);
		return d;
	}
}

// A new dart (pair of darts in a G-map) with the boundary mark of `like`.
template <typename MAP>
Dart new_dart_like(MAP& m, Dart like)
{
	return new_dart(m, is_boundary(m, like));
}

template <typename MAP>
void remove_darts(MAP& m, const std::vector<Dart>& darts)
{
	if constexpr (G<MAP>)
		remove_dart_pairs(m, darts);
	else
		for (Dart d : darts)
			remove_dart(m, d);
}

// Each dart x outside the cell C (marked in in_c) whose relation i leads
// into it (phi1 leads into it from phi_1 of a dart of C), with the first
// dart z outside C from rel_i(x) on along `next`: x's new relation i.
template <typename MAP, typename NEXT>
std::vector<std::pair<Dart, Dart>> links_around(const MAP& m, uint32 i, const std::vector<Dart>& C,
												const DartMarkerStore<MAP>& in_c, const NEXT& next)
{
	std::vector<std::pair<Dart, Dart>> links;
	for (Dart d : C)
	{
		const Dart x = rel(m, !G<MAP> && i == 1 ? -1 : int(i), d);
		if (in_c.is_marked(x))
			continue;
		Dart z = rel(m, int(i), x);
		while (in_c.is_marked(z))
			z = next(z);
		links.emplace_back(x, z);
	}
	return links;
}

// The dart of the boundary cells beside x's (D - 2)-cell, found by turning
// around that cell from x, away from x's facet, through the inner D-cells
// (relation D - 1 in a cell, relation D across a facet) until relation D
// leads out of them. Precondition: x's facet has a boundary side (relation
// D of x is a boundary dart). O(number of D-cells around the (D - 2)-cell).
template <typename MAP>
Dart boundary_beside(const MAP& m, Dart x)
{
	constexpr int D = int(MAP::dimension);
	Dart e = rel(m, D - 1, x);
	while (!is_boundary(m, rel(m, D, e)))
		e = rel(m, D - 1, rel(m, D, e));
	return rel(m, D, e);
}

} // namespace cgogn::detail::nmap
