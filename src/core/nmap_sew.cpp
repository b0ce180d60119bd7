// SPDX-License-Identifier: MIT
// Sewing two D-cells of a map of any dimension along boundary facets, and
// unsewing them. A facet ((D - 1)-cell) has one side in each D-cell around
// it: the darts of the facet in that cell, the orbit of beta_0 ... beta_{D-2}
// (phi_1 ... phi_{D-2} in a combinatorial map). Sewing links two sides by
// beta_D (phi_D) and takes the boundary sides that faced them out of the
// boundary cells; unsewing gives each side a new boundary side, glued into
// the boundary cells around it.
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/operators/nmap.h>

#include "nmap_darts.h"
#include "reindex.h"

#include <cassert>
#include <unordered_map>
#include <utility>
#include <vector>

namespace cgogn
{

namespace
{

using namespace detail::nmap;

// The inverse of phi1 on the faces met, each face walked once: phi_1 of a
// CMapN walks the whole face, which would make a side's matching quadratic.
class Phi1Inverse
{
public:
	template <uint32 D>
	Dart operator()(const CMapN<D>& m, Dart d)
	{
		if (auto it = prev_.find(d.index); it != prev_.end())
			return Dart(it->second);
		Dart it = d;
		do
		{
			const Dart n = phi1(m, it);
			prev_[n.index] = it.index;
			it = n;
		} while (it != d);
		return Dart(prev_.at(d.index));
	}

private:
	std::unordered_map<uint32, uint32> prev_;
};

// The side of d's facet in d's D-cell, matched dart for dart with the side
// of e's facet in e's D-cell when the two are isomorphic with d facing e:
// beta_i(x) faces beta_i(y) for i <= D - 2 in a G-map; in a combinatorial
// map, phi1(x) faces phi_1(y) (the sides face each other, so one is walked
// backwards) and phi_i(x) faces phi_i(y) for 2 <= i <= D - 2. Empty when
// they are not isomorphic. With e = d, the side of d with itself.
// O(size of the sides and of their faces).
template <typename MAP>
std::vector<std::pair<Dart, Dart>> facing_sides(const MAP& m, Dart d, Dart e)
{
	constexpr uint32 D = MAP::dimension;
	std::unordered_map<uint32, uint32> facing, faced_by;
	std::vector<std::pair<Dart, Dart>> pairs{{d, e}};
	facing[d.index] = e.index;
	faced_by[e.index] = d.index;
	Phi1Inverse phi_1_of;
	// false when a and b contradict the pairs already met
	auto face = [&](Dart a, Dart b) {
		const auto [it, fresh] = facing.emplace(a.index, b.index);
		if (!fresh)
			return it->second == b.index;
		if (!faced_by.emplace(b.index, a.index).second)
			return false;
		pairs.emplace_back(a, b);
		return true;
	};
	for (std::size_t k = 0; k < pairs.size(); ++k)
	{
		const auto [x, y] = pairs[k];
		bool consistent = true;
		if constexpr (G<MAP>)
		{
			for (uint32 i = 0; i + 2 <= D && consistent; ++i)
				consistent = face(rel(m, int(i), x), rel(m, int(i), y));
		}
		else if constexpr (D >= 3)
		{
			consistent = face(phi1(m, x), e == d ? phi1(m, y) : phi_1_of(m, y));
			for (uint32 i = 2; i + 2 <= D && consistent; ++i)
				consistent = face(rel(m, int(i), x), rel(m, int(i), y));
		}
		if (!consistent)
			return {};
	}
	return pairs;
}

// The darts of d's side of its facet. O(size of the side).
template <typename MAP>
std::vector<Dart> facet_side(const MAP& m, Dart d)
{
	std::vector<Dart> side;
	for (const auto& [x, y] : facing_sides(m, d, d))
		side.push_back(x);
	return side;
}

// In a 2-map the boundary darts beside a new boundary edge b are the ones
// before and after it in its boundary face: turning around the vertex at
// each end of b's inner dart x (phi2 phi_1 one way, phi2 phi1 the other)
// until a boundary dart. O(degree of the two vertices).
template <typename MAP>
std::pair<Dart, Dart> boundary_around(const MAP& m, Dart x)
{
	Dart e = x, next;
	while (!is_boundary(m, next = phi2(m, phi_1(m, e))))
		e = next;
	Dart f = x, prev;
	while (!is_boundary(m, prev = phi2(m, phi1(m, f))))
		f = prev;
	return {prev, next};
}

} // namespace

template <typename MAP>
requires is_nmap_v<MAP> &&
	(MAP::dimension >= 2) bool can_sew_facets(const MAP& m, CellD<MAP::dimension - 1> f1, CellD<MAP::dimension - 1> f2)
{
	constexpr uint32 D = MAP::dimension;
	const Dart d1 = f1.dart, d2 = f2.dart;
	if (!is_dart_valid(m, d1) || !is_dart_valid(m, d2) || is_boundary(m, d1) || is_boundary(m, d2))
		return false;
	if (!is_boundary(m, rel(m, int(D), d1)) || !is_boundary(m, rel(m, int(D), d2)))
		return false;
	const std::vector<std::pair<Dart, Dart>> pairs = facing_sides(m, d1, d2);
	if (pairs.empty())
		return false;
	// two distinct facets: the sides are disjoint orbits
	for (const auto& [x, y] : pairs)
		if (x == d2)
			return false;
	return true;
}

template <typename MAP>
requires is_nmap_v<MAP> &&(MAP::dimension >= 2) void sew_facets(MAP& m, CellD<MAP::dimension - 1> f1,
																CellD<MAP::dimension - 1> f2, bool set_indices)
{
	constexpr uint32 D = MAP::dimension;
	assert(can_sew_facets(m, f1, f2));
	const std::vector<std::pair<Dart, Dart>> pairs = facing_sides(m, f1.dart, f2.dart);
	// the boundary sides in between vanish; each boundary dart of one faces
	// the matching boundary dart of the other
	std::vector<Dart> vanishing;
	std::unordered_map<uint32, Dart> across;
	for (const auto& [x, y] : pairs)
	{
		const Dart bx = rel(m, int(D), x), by = rel(m, int(D), y);
		vanishing.push_back(bx);
		vanishing.push_back(by);
		across[bx.index] = by;
		across[by.index] = bx;
	}
	DartMarkerStore<MAP> in_c(m);
	for (Dart b : vanishing)
		in_c.mark(b);
	// A boundary dart beside the vanishing sides (relation D - 1 leads into
	// them) meets the dart its (D - 2)-cell leads to across them: from the
	// vanishing dart, go to the one facing it and take its relation D - 1,
	// again while that vanishes (a boundary side folded onto the other one).
	const auto links =
		links_around(m, D - 1, vanishing, in_c, [&](Dart t) { return rel(m, int(D - 1), across.at(t.index)); });
	std::vector<Dart> region;
	for (const auto& [x, y] : pairs)
	{
		region.push_back(x);
		region.push_back(y);
	}
	detail::RegionReindexer<MAP> reindexer;
	// the vanishing boundary sides may have been the only link between parts
	// of a cell that touches the boundary twice
	reindexer.components_may_split();
	if (set_indices)
	{
		std::vector<Dart> recorded = region;
		recorded.insert(recorded.end(), vanishing.begin(), vanishing.end());
		reindexer.record(m, recorded);
	}
	for (const auto& [x, z] : links)
	{
		detail::set_relation(m, D - 1, x, z);
		region.push_back(x);
		region.push_back(z);
	}
	remove_darts(m, vanishing);
	for (const auto& [x, y] : pairs)
		link(m, D, x, y);
	if (set_indices)
		reindexer.apply(m, region);
}

template <typename MAP>
requires is_nmap_v<MAP> &&(MAP::dimension >= 2) bool can_unsew_facets(const MAP& m, CellD<MAP::dimension - 1> f)
{
	return is_dart_valid(m, f.dart) && !is_boundary(m, f.dart) && !is_boundary(m, rel(m, int(MAP::dimension), f.dart));
}

template <typename MAP>
requires is_nmap_v<MAP> &&(MAP::dimension >= 2) void unsew_facets(MAP& m, CellD<MAP::dimension - 1> f, bool set_indices)
{
	constexpr uint32 D = MAP::dimension;
	assert(can_unsew_facets(m, f));
	// both sides of the facet, each dart with the dart facing it
	std::vector<Dart> inner = facet_side(m, f.dart);
	const std::size_t half = inner.size();
	for (std::size_t k = 0; k < half; ++k)
		inner.push_back(rel(m, int(D), inner[k]));
	detail::RegionReindexer<MAP> reindexer;
	reindexer.components_may_split();
	if (set_indices)
		reindexer.record(m, inner);
	// every inner dart faces a new boundary dart
	std::vector<Dart> made(inner.size());
	std::unordered_map<uint32, Dart> made_for;
	for (std::size_t k = 0; k < inner.size(); ++k)
	{
		const Dart x = inner[k];
		if constexpr (G<MAP>)
		{
			// one pair for the two darts of x's pair (x and beta0(x) are both inner)
			if (const auto it = made_for.find(beta0(m, x).index); it != made_for.end())
				made[k] = beta0(m, it->second);
			else
				made[k] = new_dart(m, true);
		}
		else
			made[k] = new_dart(m, true);
		made_for[x.index] = made[k];
	}
	for (std::size_t k = 0; k < inner.size(); ++k)
		link(m, D, inner[k], made[k]);
	// the boundary sides mirror the inner ones (phi1 backwards)
	for (std::size_t k = 0; k < inner.size(); ++k)
	{
		const Dart x = inner[k], b = made[k];
		if constexpr (G<MAP>)
		{
			for (uint32 i = 1; i + 2 <= D; ++i)
				detail::set_relation(m, i, b, made_for.at(rel(m, int(i), x).index));
		}
		else if constexpr (D >= 3)
		{
			detail::set_relation(m, 1, made_for.at(phi1(m, x).index), b);
			for (uint32 i = 2; i + 2 <= D; ++i)
				detail::set_relation(m, i, b, made_for.at(rel(m, int(i), x).index));
		}
	}
	// relation D - 1 of the new boundary darts: the boundary beside each
	// (D - 2)-cell of the facet, found before any of it is relinked; a dart
	// of a boundary cell that was there before leaves its former neighbour,
	// which is reached from the other side of the facet
	std::vector<Dart> region = inner;
	region.insert(region.end(), made.begin(), made.end());
	if constexpr (!G<MAP> && D == 2)
	{
		std::vector<std::pair<Dart, Dart>> around(inner.size());
		for (std::size_t k = 0; k < inner.size(); ++k)
			around[k] = boundary_around(m, inner[k]);
		for (std::size_t k = 0; k < inner.size(); ++k)
		{
			const auto [prev, next] = around[k];
			detail::set_relation(m, 1, made[k], next);
			detail::set_relation(m, 1, prev, made[k]);
			region.push_back(prev);
			region.push_back(next);
		}
	}
	else
	{
		std::vector<Dart> beside(inner.size());
		for (std::size_t k = 0; k < inner.size(); ++k)
			beside[k] = boundary_beside(m, inner[k]);
		for (std::size_t k = 0; k < inner.size(); ++k)
		{
			link(m, D - 1, made[k], beside[k]);
			region.push_back(beside[k]);
		}
	}
	if (set_indices)
		reindexer.apply(m, region);
}

// ---- instances

#define CGOGN_NMAP_SEW(MAP)                                                                                            \
	template bool can_sew_facets(const MAP&, CellD<MAP::dimension - 1>, CellD<MAP::dimension - 1>);                    \
	template void sew_facets(MAP&, CellD<MAP::dimension - 1>, CellD<MAP::dimension - 1>, bool);                        \
	template bool can_unsew_facets(const MAP&, CellD<MAP::dimension - 1>);                                             \
	template void unsew_facets(MAP&, CellD<MAP::dimension - 1>, bool);
CGOGN_NMAP_SEW(CMapN<2>)
CGOGN_NMAP_SEW(CMapN<3>)
CGOGN_NMAP_SEW(CMapN<4>)
CGOGN_NMAP_SEW(CMapN<5>)
CGOGN_NMAP_SEW(CMapN<6>)
CGOGN_NMAP_SEW(CMapN<7>)
CGOGN_NMAP_SEW(GMapN<2>)
CGOGN_NMAP_SEW(GMapN<3>)
CGOGN_NMAP_SEW(GMapN<4>)
CGOGN_NMAP_SEW(GMapN<5>)
CGOGN_NMAP_SEW(GMapN<6>)
CGOGN_NMAP_SEW(GMapN<7>)
#undef CGOGN_NMAP_SEW

} // namespace cgogn
