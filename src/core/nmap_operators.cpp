// SPDX-License-Identifier: MIT
// The operators of the maps of any dimension. Removal and contraction follow
// Damiand and Lienhardt ("Removal and contraction for n-dimensional
// generalized maps", DGCI 2003): the darts of the cell go, and each dart whose
// relation I led into the cell is linked to the first dart outside it along
// beta_I (beta_{I+1} beta_I)^k (removal) or beta_I (beta_{I-1} beta_I)^k
// (contraction). In a combinatorial map the same walks read phi_I(phi_{I+1})
// and phi_I(phi_{I-1}) (phi_1 inverted), being the G-map's walks on the darts
// of one orientation; a vertex removal, which changes beta0, makes each dart
// ending at the vertex take over the relations of the dart that follows it.
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/operators/nmap.h>

#include "gmap_darts.h"
#include "nmap_darts.h"
#include "reindex.h"

#include <array>
#include <cassert>
#include <unordered_map>
#include <vector>

namespace cgogn
{

namespace
{

using namespace detail::nmap;

// Copies every line of `from` onto `to`: `to` takes the place of `from` in its cells.
void take_lines(CMapBase& m, Dart from, Dart to)
{
	for (AttributeArray<uint32>* idx : detail::state_of(m).cell_index)
		if (idx != nullptr)
			(*idx)[to.index] = (*idx)[from.index];
}

void drop_vertex_line(CMapBase& m, Dart d)
{
	if (AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(Orbit::CELL0)])
		(*idx)[d.index] = INVALID_INDEX;
}

template <typename MAP>
bool has_boundary_dart(const MAP& m, const std::vector<Dart>& darts)
{
	for (Dart d : darts)
		if (is_boundary(m, d))
			return true;
	return false;
}

// Whether relations a and b commute on every dart of c.
template <typename MAP>
bool commute_on(const MAP& m, const std::vector<Dart>& darts, int a, int b)
{
	for (Dart d : darts)
		if (rel(m, a, rel(m, b, d)) != rel(m, b, rel(m, a, d)))
			return false;
	return true;
}

// Links each x to its z by relation i (one side: each z is an x too, or
// relation i is a permutation), removes the darts C of the cell, and keeps
// the indexing of the cells of the x and z (a combinatorial vertex is where
// z starts: its cells change too).
template <typename MAP>
void relink_and_remove(MAP& m, uint32 i, const std::vector<Dart>& C, const std::vector<std::pair<Dart, Dart>>& links,
					   bool set_indices)
{
	std::vector<Dart> recorded = C;
	for (const auto& [x, z] : links)
		recorded.push_back(x);
	detail::RegionReindexer<MAP> reindexer;
	if (set_indices)
		reindexer.record(m, recorded);
	std::vector<Dart> region;
	for (const auto& [x, z] : links)
	{
		detail::set_relation(m, i, x, z);
		region.push_back(x);
		region.push_back(z);
	}
	remove_darts(m, C);
	if (set_indices)
		reindexer.apply(m, region);
}

} // namespace

// ---- insert a vertex in an edge

template <typename MAP>
requires is_nmap_v<MAP> CellD<0> insert_vertex_in_edge(MAP& m, CellD<1> e, bool set_indices)
{
	constexpr uint32 D = MAP::dimension;
	detail::RegionReindexer<MAP> reindexer;
	if constexpr (!G<MAP>)
	{
		const std::vector<Dart> E = detail::orbit_darts(m, e);
		if (set_indices)
			reindexer.record(m, E);
		std::unordered_map<uint32, Dart> n;
		std::vector<std::array<Dart, D + 1>> old(E.size());
		for (std::size_t k = 0; k < E.size(); ++k)
		{
			n[E[k].index] = new_dart_like(m, E[k]);
			for (uint32 j = 2; j <= D; ++j)
				old[k][j] = rel(m, int(j), E[k]);
		}
		std::vector<Dart> region = E;
		for (std::size_t k = 0; k < E.size(); ++k)
		{
			const Dart d = E[k], nd = n[d.index];
			detail::set_relation(m, 1, nd, phi1(m, d));
			detail::set_relation(m, 1, d, nd);
			for (uint32 j = 2; j <= D; ++j)
			{
				detail::set_relation(m, j, d, n[old[k][j].index]);
				detail::set_relation(m, j, nd, old[k][j]);
			}
			region.push_back(nd);
		}
		if (set_indices)
			reindexer.apply(m, region);
		// rules: the new vertex (new darts only) between the two ends; each
		// half of the edge holds old and new darts, and the reindexing gives
		// the half that lost the line the edge's values
		const Dart nd = n[e.dart.index];
		if (set_indices && detail::has_rules(m))
			detail::inherit_midpoint<CellD<0>::ORBIT>(m, nd, e.dart, phi1(m, nd));
		return CellD<0>(nd);
	}
	else
	{
		// the darts of the edge at its end B (beta0 of e.dart's end and its
		// images by beta2 ... betaD) move to the new vertex; a new pair (p, q)
		// follows each of them, p at the new vertex, q at B in its place
		std::vector<Dart> Y;
		std::unordered_map<uint32, uint32> rank;
		Y.push_back(beta0(m, e.dart));
		rank[Y[0].index] = 0;
		for (std::size_t k = 0; k < Y.size(); ++k)
			for (uint32 j = 2; j <= D; ++j)
			{
				const Dart y = rel(m, int(j), Y[k]);
				if (rank.emplace(y.index, uint32(Y.size())).second)
					Y.push_back(y);
			}
		std::vector<Dart> region;
		for (Dart y : Y)
		{
			region.push_back(y);
			region.push_back(beta0(m, y));
		}
		if (set_indices)
			reindexer.record(m, region);
		std::vector<Dart> P(Y.size());
		std::vector<std::array<Dart, D + 1>> old(Y.size());
		for (std::size_t k = 0; k < Y.size(); ++k)
		{
			P[k] = new_dart_like(m, Y[k]);
			for (uint32 j = 1; j <= D; ++j)
				old[k][j] = rel(m, int(j), Y[k]);
		}
		auto q_of = [&](Dart y) { return beta0(m, P[rank.at(y.index)]); };
		for (std::size_t k = 0; k < Y.size(); ++k)
		{
			const Dart y = Y[k], p = P[k], q = beta0(m, p);
			if (set_indices)
			{
				take_lines(m, y, q);
				drop_vertex_line(m, y);
			}
			const Dart z = old[k][1];
			link(m, 1, q, rank.count(z.index) ? q_of(z) : z);
			link(m, 1, y, p);
			for (uint32 j = 2; j <= D; ++j)
			{
				const uint32 l = rank.at(old[k][j].index);
				detail::set_relation(m, j, p, P[l]);
				detail::set_relation(m, j, q, beta0(m, P[l]));
			}
			region.push_back(p);
			region.push_back(q);
		}
		if (set_indices)
			reindexer.apply(m, region);
		// rules: the new vertex between e's end (A) and the far end (B, where
		// the q darts stand)
		if (set_indices && detail::has_rules(m))
			detail::inherit_midpoint<CellD<0>::ORBIT>(m, Y[0], e.dart, beta0(m, P[0]));
		return CellD<0>(Y[0]);
	}
}

// ---- insert an edge in a face

namespace
{

// The side (phi1 cycle, or beta0 beta1 cycle) of d, as darts.
template <typename MAP>
std::vector<Dart> side_of(const MAP& m, Dart d)
{
	if constexpr (G<MAP>)
		return detail::orbit_darts(m, Cell<Orbit::BETA0_BETA1>(d));
	else
	{
		std::vector<Dart> v;
		Dart it = d;
		do
		{
			v.push_back(it);
			it = phi1(m, it);
		} while (it != d);
		return v;
	}
}

} // namespace

template <typename MAP>
requires is_nmap_v<MAP>
bool can_insert_edge_in_face(const MAP& m, Dart d1, Dart d2)
{
	if constexpr (MAP::dimension < 2)
		return false;
	else
	{
		if (!is_dart_valid(m, d1) || !is_dart_valid(m, d2) || d1 == d2)
			return false;
		if (MAP::dimension == 2 && is_boundary(m, d1))
			return false;
		if constexpr (G<MAP>)
			if (d2 == beta1(m, d1))
				return false; // the same corner
		for (Dart x : side_of(m, d1))
			if (x == d2)
				return true;
		return false;
	}
}

template <typename MAP>
requires is_nmap_v<MAP> CellD<1> insert_edge_in_face(MAP& m, Dart d1, Dart d2, bool set_indices)
{
	constexpr uint32 D = MAP::dimension;
	static_assert(D >= 2, "insert_edge_in_face: a map of dimension 1 has no face");
	assert(can_insert_edge_in_face(m, d1, d2));
	// the sides of the face, each with its two corners (C-map: the darts
	// leaving the two vertices; G-map: the first dart met at each vertex
	// walking the half of the side that starts at d1's edge)
	struct Side
	{
		Dart a, b;
	};
	std::vector<Side> sides;
	std::unordered_map<uint32, uint32> side_of_dart;
	std::vector<Dart> region;
	auto add_side = [&](Dart a, Dart b) {
		const uint32 k = uint32(sides.size());
		sides.push_back({a, b});
		for (Dart x : side_of(m, a))
		{
			side_of_dart[x.index] = k;
			region.push_back(x);
		}
	};
	if constexpr (G<MAP>)
	{
		// the dart at d2's corner that ends the walk beta0, beta1, ... from d1
		Dart t = beta0(m, d1);
		while (t != d2 && t != beta1(m, d2))
			t = beta0(m, beta1(m, t));
		add_side(d1, t);
	}
	else
		add_side(d1, d2);
	for (std::size_t k = 0; k < sides.size(); ++k)
		for (uint32 j = 3; j <= D; ++j)
		{
			const Dart a = rel(m, int(j), sides[k].a);
			if (side_of_dart.count(a.index))
				continue;
			if constexpr (G<MAP>)
				add_side(a, rel(m, int(j), sides[k].b));
			else
				add_side(phi1(m, a), phi1(m, rel(m, int(j), sides[k].b)));
		}
	detail::RegionReindexer<MAP> reindexer;
	if (set_indices)
		reindexer.record(m, region);
	// n and mm: the new edge in the half of a side that holds a, in the other
	std::vector<Dart> n(sides.size()), mm(sides.size());
	std::vector<std::array<Dart, 2>> before(sides.size());
	for (std::size_t k = 0; k < sides.size(); ++k)
	{
		n[k] = new_dart_like(m, sides[k].a);
		mm[k] = new_dart_like(m, sides[k].a);
		if constexpr (G<MAP>)
			before[k] = {beta1(m, sides[k].a), beta1(m, sides[k].b)};
		else
			before[k] = {phi_1(m, sides[k].a), phi_1(m, sides[k].b)};
	}
	for (std::size_t k = 0; k < sides.size(); ++k)
	{
		const Dart a = sides[k].a, b = sides[k].b;
		if constexpr (G<MAP>)
		{
			// n[k] at a's vertex, beta0(n[k]) at b's; mm[k] the same on the other half
			link(m, 1, a, n[k]);
			link(m, 1, b, beta0(m, n[k]));
			link(m, 1, before[k][0], mm[k]);
			link(m, 1, before[k][1], beta0(m, mm[k]));
			link(m, 2, n[k], mm[k]);
			link(m, 2, beta0(m, n[k]), beta0(m, mm[k]));
			for (uint32 j = 3; j <= D; ++j)
			{
				const uint32 l = side_of_dart.at(rel(m, int(j), a).index);
				detail::set_relation(m, j, n[k], n[l]);
				detail::set_relation(m, j, beta0(m, n[k]), beta0(m, n[l]));
				detail::set_relation(m, j, mm[k], mm[l]);
				detail::set_relation(m, j, beta0(m, mm[k]), beta0(m, mm[l]));
			}
		}
		else
		{
			// n[k] from a's vertex to b's, before b; mm[k] back, before a
			detail::set_relation(m, 1, before[k][0], n[k]);
			detail::set_relation(m, 1, n[k], b);
			detail::set_relation(m, 1, before[k][1], mm[k]);
			detail::set_relation(m, 1, mm[k], a);
			link(m, 2, n[k], mm[k]);
			for (uint32 j = 3; j <= D; ++j)
			{
				const uint32 l = side_of_dart.at(rel(m, int(j), a).index);
				detail::set_relation(m, j, n[k], mm[l]);
				detail::set_relation(m, j, mm[k], n[l]);
			}
		}
		region.push_back(n[k]);
		region.push_back(mm[k]);
		if constexpr (G<MAP>)
		{
			region.push_back(beta0(m, n[k]));
			region.push_back(beta0(m, mm[k]));
		}
	}
	if (set_indices)
		reindexer.apply(m, region);
	return CellD<1>(n[0]);
}

// ---- removal

template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&(I < MAP::dimension) bool can_remove_cell(const MAP& m, CellD<I> c)
{
	constexpr uint32 D = MAP::dimension;
	if (!is_dart_valid(m, c.dart))
		return false;
	const std::vector<Dart> C = detail::orbit_darts(m, c);
	// a (D-1)-cell on the boundary would merge a D-cell with the outside
	if (I == D - 1 && has_boundary_dart(m, C))
		return false;
	if constexpr (I + 2 <= D)
	{
		if constexpr (I == 0 && !G<MAP>)
		{
			// beta1 beta2 = beta2 beta1, read on the darts of one orientation
			for (Dart d : C)
				if (phi1(m, phi2(m, d)) != phi2(m, phi_1(m, d)))
					return false;
		}
		else if (!commute_on(m, C, int(I) + 1, int(I) + 2))
			return false;
	}
	{
		// two distinct (I + 1)-cells on its sides (for a vertex, two edges:
		// not the end of a dangling edge)
		const Dart d = c.dart;
		const Dart other = rel(m, I == 0 ? (G<MAP> ? 1 : -1) : int(I) + 1, d);
		if (same_orbit(m, CellD<I + 1>(d), CellD<I + 1>(other)))
			return false;
	}
	if constexpr (I == 0)
	{
		// no edge from the vertex to itself
		DartMarkerStore<MAP> in_c(m);
		for (Dart d : C)
			in_c.mark(d);
		for (Dart d : C)
			if (in_c.is_marked(rel(m, G<MAP> ? 0 : 1, d)))
				return false;
		if constexpr (D == 1 && !G<MAP>)
			return phi_1(m, c.dart) != c.dart;
	}
	return true;
}

template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&(I < MAP::dimension) void remove_cell(MAP& m, CellD<I> c, bool set_indices)
{
	constexpr uint32 D = MAP::dimension;
	assert((can_remove_cell<I>(m, c)));
	const std::vector<Dart> C = detail::orbit_darts(m, c);
	DartMarkerStore<MAP> in_c(m);
	for (Dart d : C)
		in_c.mark(d);
	detail::RegionReindexer<MAP> reindexer;
	std::vector<Dart> region; // the darts that stay and change
	if constexpr (I == 0)
	{
		if constexpr (G<MAP>)
		{
			// each corner {p, beta1(p)} of the vertex: the pair of the smaller
			// dart, a, stays and takes the place of y, the far end of the
			// other dart's edge, whose pair goes
			std::unordered_map<uint32, Dart> absorber_of; // y -> a
			std::vector<std::pair<Dart, Dart>> absorbs;   // (a, y)
			for (Dart p : C)
			{
				const Dart q = beta1(m, p);
				if (p.index > q.index)
					continue;
				absorbs.emplace_back(p, beta0(m, q));
			}
			for (const auto& [a, y] : absorbs)
				absorber_of[y.index] = a;
			auto R = [&](Dart t) {
				const auto it = absorber_of.find(t.index);
				return it == absorber_of.end() ? t : it->second;
			};
			std::vector<Dart> recorded = C;
			for (const auto& [a, y] : absorbs)
			{
				recorded.push_back(y);
				recorded.push_back(beta0(m, a));
			}
			if (set_indices)
				reindexer.record(m, recorded);
			std::vector<std::array<Dart, D + 1>> next(absorbs.size());
			for (std::size_t k = 0; k < absorbs.size(); ++k)
				for (uint32 j = 1; j <= D; ++j)
					next[k][j] = R(rel(m, int(j), absorbs[k].second));
			std::vector<Dart> gone;
			for (std::size_t k = 0; k < absorbs.size(); ++k)
			{
				const auto [a, y] = absorbs[k];
				if (set_indices)
					take_lines(m, y, a);
				for (uint32 j = 1; j <= D; ++j)
					link(m, j, a, next[k][j]);
				region.push_back(a);
				region.push_back(beta0(m, a));
				gone.push_back(y);
				gone.push_back(beta0(m, y));
			}
			remove_darts(m, gone);
		}
		else
		{
			// each dart c ending at the vertex takes the relations of the dart y after it
			std::vector<std::pair<Dart, Dart>> absorbs; // (c, y)
			for (Dart y : C)
				absorbs.emplace_back(phi_1(m, y), y);
			std::vector<Dart> recorded = C;
			for (const auto& [x, y] : absorbs)
				recorded.push_back(x);
			if (set_indices)
				reindexer.record(m, recorded);
			std::vector<std::array<Dart, D + 1>> next(absorbs.size());
			for (std::size_t k = 0; k < absorbs.size(); ++k)
				for (uint32 j = 1; j <= D; ++j)
					next[k][j] = rel(m, int(j), absorbs[k].second);
			for (std::size_t k = 0; k < absorbs.size(); ++k)
			{
				for (uint32 j = 1; j <= D; ++j)
				{
					detail::set_relation(m, j, absorbs[k].first, next[k][j]);
					region.push_back(next[k][j]);
				}
				region.push_back(absorbs[k].first);
			}
			remove_darts(m, C);
		}
	}
	else
	{
		// each dart x outside c whose relation I enters c: linked to the first
		// dart outside c along rel_I (rel_{I+1} rel_I)^k
		const auto links = links_around(m, I, C, in_c, [&](Dart z) { return rel(m, int(I), rel(m, int(I) + 1, z)); });
		relink_and_remove(m, I, C, links, set_indices);
		return;
	}
	if (set_indices)
		reindexer.apply(m, region);
}

// ---- contraction

template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&(I >= 1 && I <= MAP::dimension) bool can_contract_cell(const MAP& m, CellD<I> c)
{
	if (!is_dart_valid(m, c.dart))
		return false;
	const std::vector<Dart> C = detail::orbit_darts(m, c);
	if (I == MAP::dimension && has_boundary_dart(m, C))
		return false;
	if constexpr (I >= 2)
	{
		// phi_{I-1} and phi_{I-2} commute (phi1 is read as beta1 o beta0:
		// for I = 2 the faces are digons, for I = 3 phi2 phi_-1 = phi1 phi2)
		if constexpr (G<MAP>)
		{
			if (!commute_on(m, C, int(I) - 1, int(I) - 2))
				return false;
		}
		else if constexpr (I == 2)
		{
			for (Dart d : C)
				if (phi1(m, phi1(m, d)) != d)
					return false;
		}
		else if constexpr (I == 3)
		{
			for (Dart d : C)
				if (phi2(m, phi_1(m, d)) != phi1(m, phi2(m, d)))
					return false;
		}
		else if (!commute_on(m, C, int(I) - 1, int(I) - 2))
			return false;
	}
	if constexpr (I >= 2)
	{
		// two distinct (I - 1)-cells to merge (not a face of one edge)
		const Dart other = rel(m, I == 2 && !G<MAP> ? -1 : int(I) - 1, c.dart);
		if (same_orbit(m, CellD<I - 1>(c.dart), CellD<I - 1>(other)))
			return false;
	}
	if constexpr (I == 1)
	{
		// two distinct vertices
		const Dart other = rel(m, G<MAP> ? 0 : 1, c.dart);
		if (same_orbit(m, CellD<0>(c.dart), CellD<0>(other)))
			return false;
	}
	if constexpr (I == MAP::dimension)
	{
		// the cells around are glued to each other: never two boundary cells
		DartMarkerStore<MAP> in_c(m);
		for (Dart d : C)
			in_c.mark(d);
		for (Dart d : C)
		{
			const Dart x = rel(m, int(I), d);
			if (!is_boundary(m, x))
				continue;
			Dart z = rel(m, int(I), x);
			while (in_c.is_marked(z))
				z = rel(m, int(I), rel(m, I == 2 && !G<MAP> ? -1 : int(I) - 1, z));
			if (is_boundary(m, z))
				return false;
		}
	}
	return true;
}

template <uint32 I, typename MAP>
requires is_nmap_v<MAP> &&(I >= 1 && I <= MAP::dimension) void contract_cell(MAP& m, CellD<I> c, bool set_indices)
{
	assert((can_contract_cell<I>(m, c)));
	const std::vector<Dart> C = detail::orbit_darts(m, c);
	DartMarkerStore<MAP> in_c(m);
	for (Dart d : C)
		in_c.mark(d);
	// each dart x outside c whose relation I enters c: linked to the first dart
	// outside c along rel_I (rel_{I-1} rel_I)^k, phi1 inverted in a
	// combinatorial map (around an edge: the next dart of the face)
	const int before = !G<MAP> && I == 2 ? -1 : int(I) - 1;
	const auto links = links_around(
		m, I, C, in_c, [&](Dart z) { return !G<MAP> && I == 1 ? rel(m, 1, z) : rel(m, int(I), rel(m, before, z)); });
	relink_and_remove(m, I, C, links, set_indices);
}

// ---- instances

#define CGOGN_NMAP_REMOVE(MAP, I)                                                                                      \
	template bool can_remove_cell<I, MAP>(const MAP&, CellD<I>);                                                       \
	template void remove_cell<I, MAP>(MAP&, CellD<I>, bool);
#define CGOGN_NMAP_CONTRACT(MAP, I)                                                                                    \
	template bool can_contract_cell<I, MAP>(const MAP&, CellD<I>);                                                     \
	template void contract_cell<I, MAP>(MAP&, CellD<I>, bool);
#define CGOGN_NMAP_OPERATORS(MAP)                                                                                      \
	template CellD<0> insert_vertex_in_edge(MAP&, CellD<1>, bool);                                                     \
	template bool can_insert_edge_in_face(const MAP&, Dart, Dart);
#define CGOGN_NMAP_FACE_OPERATORS(MAP) template CellD<1> insert_edge_in_face(MAP&, Dart, Dart, bool);
CGOGN_NMAP_OPERATORS(CMapN<1>)
CGOGN_NMAP_OPERATORS(CMapN<2>)
CGOGN_NMAP_OPERATORS(CMapN<3>)
CGOGN_NMAP_OPERATORS(CMapN<4>)
CGOGN_NMAP_OPERATORS(CMapN<5>)
CGOGN_NMAP_OPERATORS(CMapN<6>)
CGOGN_NMAP_OPERATORS(CMapN<7>)
CGOGN_NMAP_OPERATORS(GMapN<1>)
CGOGN_NMAP_OPERATORS(GMapN<2>)
CGOGN_NMAP_OPERATORS(GMapN<3>)
CGOGN_NMAP_OPERATORS(GMapN<4>)
CGOGN_NMAP_OPERATORS(GMapN<5>)
CGOGN_NMAP_OPERATORS(GMapN<6>)
CGOGN_NMAP_OPERATORS(GMapN<7>)
CGOGN_NMAP_FACE_OPERATORS(CMapN<2>)
CGOGN_NMAP_FACE_OPERATORS(CMapN<3>)
CGOGN_NMAP_FACE_OPERATORS(CMapN<4>)
CGOGN_NMAP_FACE_OPERATORS(CMapN<5>)
CGOGN_NMAP_FACE_OPERATORS(CMapN<6>)
CGOGN_NMAP_FACE_OPERATORS(CMapN<7>)
CGOGN_NMAP_FACE_OPERATORS(GMapN<2>)
CGOGN_NMAP_FACE_OPERATORS(GMapN<3>)
CGOGN_NMAP_FACE_OPERATORS(GMapN<4>)
CGOGN_NMAP_FACE_OPERATORS(GMapN<5>)
CGOGN_NMAP_FACE_OPERATORS(GMapN<6>)
CGOGN_NMAP_FACE_OPERATORS(GMapN<7>)
CGOGN_NMAP_REMOVE(CMapN<1>, 0)
CGOGN_NMAP_CONTRACT(CMapN<1>, 1)
CGOGN_NMAP_REMOVE(CMapN<2>, 0)
CGOGN_NMAP_REMOVE(CMapN<2>, 1)
CGOGN_NMAP_CONTRACT(CMapN<2>, 1)
CGOGN_NMAP_CONTRACT(CMapN<2>, 2)
CGOGN_NMAP_REMOVE(CMapN<3>, 0)
CGOGN_NMAP_REMOVE(CMapN<3>, 1)
CGOGN_NMAP_REMOVE(CMapN<3>, 2)
CGOGN_NMAP_CONTRACT(CMapN<3>, 1)
CGOGN_NMAP_CONTRACT(CMapN<3>, 2)
CGOGN_NMAP_CONTRACT(CMapN<3>, 3)
CGOGN_NMAP_REMOVE(CMapN<4>, 0)
CGOGN_NMAP_REMOVE(CMapN<4>, 1)
CGOGN_NMAP_REMOVE(CMapN<4>, 2)
CGOGN_NMAP_REMOVE(CMapN<4>, 3)
CGOGN_NMAP_CONTRACT(CMapN<4>, 1)
CGOGN_NMAP_CONTRACT(CMapN<4>, 2)
CGOGN_NMAP_CONTRACT(CMapN<4>, 3)
CGOGN_NMAP_CONTRACT(CMapN<4>, 4)
CGOGN_NMAP_REMOVE(CMapN<5>, 0)
CGOGN_NMAP_REMOVE(CMapN<5>, 1)
CGOGN_NMAP_REMOVE(CMapN<5>, 2)
CGOGN_NMAP_REMOVE(CMapN<5>, 3)
CGOGN_NMAP_REMOVE(CMapN<5>, 4)
CGOGN_NMAP_CONTRACT(CMapN<5>, 1)
CGOGN_NMAP_CONTRACT(CMapN<5>, 2)
CGOGN_NMAP_CONTRACT(CMapN<5>, 3)
CGOGN_NMAP_CONTRACT(CMapN<5>, 4)
CGOGN_NMAP_CONTRACT(CMapN<5>, 5)
CGOGN_NMAP_REMOVE(CMapN<6>, 0)
CGOGN_NMAP_REMOVE(CMapN<6>, 1)
CGOGN_NMAP_REMOVE(CMapN<6>, 2)
CGOGN_NMAP_REMOVE(CMapN<6>, 3)
CGOGN_NMAP_REMOVE(CMapN<6>, 4)
CGOGN_NMAP_REMOVE(CMapN<6>, 5)
CGOGN_NMAP_CONTRACT(CMapN<6>, 1)
CGOGN_NMAP_CONTRACT(CMapN<6>, 2)
CGOGN_NMAP_CONTRACT(CMapN<6>, 3)
CGOGN_NMAP_CONTRACT(CMapN<6>, 4)
CGOGN_NMAP_CONTRACT(CMapN<6>, 5)
CGOGN_NMAP_CONTRACT(CMapN<6>, 6)
CGOGN_NMAP_REMOVE(CMapN<7>, 0)
CGOGN_NMAP_REMOVE(CMapN<7>, 1)
CGOGN_NMAP_REMOVE(CMapN<7>, 2)
CGOGN_NMAP_REMOVE(CMapN<7>, 3)
CGOGN_NMAP_REMOVE(CMapN<7>, 4)
CGOGN_NMAP_REMOVE(CMapN<7>, 5)
CGOGN_NMAP_REMOVE(CMapN<7>, 6)
CGOGN_NMAP_CONTRACT(CMapN<7>, 1)
CGOGN_NMAP_CONTRACT(CMapN<7>, 2)
CGOGN_NMAP_CONTRACT(CMapN<7>, 3)
CGOGN_NMAP_CONTRACT(CMapN<7>, 4)
CGOGN_NMAP_CONTRACT(CMapN<7>, 5)
CGOGN_NMAP_CONTRACT(CMapN<7>, 6)
CGOGN_NMAP_CONTRACT(CMapN<7>, 7)
CGOGN_NMAP_REMOVE(GMapN<1>, 0)
CGOGN_NMAP_CONTRACT(GMapN<1>, 1)
CGOGN_NMAP_REMOVE(GMapN<2>, 0)
CGOGN_NMAP_REMOVE(GMapN<2>, 1)
CGOGN_NMAP_CONTRACT(GMapN<2>, 1)
CGOGN_NMAP_CONTRACT(GMapN<2>, 2)
CGOGN_NMAP_REMOVE(GMapN<3>, 0)
CGOGN_NMAP_REMOVE(GMapN<3>, 1)
CGOGN_NMAP_REMOVE(GMapN<3>, 2)
CGOGN_NMAP_CONTRACT(GMapN<3>, 1)
CGOGN_NMAP_CONTRACT(GMapN<3>, 2)
CGOGN_NMAP_CONTRACT(GMapN<3>, 3)
CGOGN_NMAP_REMOVE(GMapN<4>, 0)
CGOGN_NMAP_REMOVE(GMapN<4>, 1)
CGOGN_NMAP_REMOVE(GMapN<4>, 2)
CGOGN_NMAP_REMOVE(GMapN<4>, 3)
CGOGN_NMAP_CONTRACT(GMapN<4>, 1)
CGOGN_NMAP_CONTRACT(GMapN<4>, 2)
CGOGN_NMAP_CONTRACT(GMapN<4>, 3)
CGOGN_NMAP_CONTRACT(GMapN<4>, 4)
CGOGN_NMAP_REMOVE(GMapN<5>, 0)
CGOGN_NMAP_REMOVE(GMapN<5>, 1)
CGOGN_NMAP_REMOVE(GMapN<5>, 2)
CGOGN_NMAP_REMOVE(GMapN<5>, 3)
CGOGN_NMAP_REMOVE(GMapN<5>, 4)
CGOGN_NMAP_CONTRACT(GMapN<5>, 1)
CGOGN_NMAP_CONTRACT(GMapN<5>, 2)
CGOGN_NMAP_CONTRACT(GMapN<5>, 3)
CGOGN_NMAP_CONTRACT(GMapN<5>, 4)
CGOGN_NMAP_CONTRACT(GMapN<5>, 5)
CGOGN_NMAP_REMOVE(GMapN<6>, 0)
CGOGN_NMAP_REMOVE(GMapN<6>, 1)
CGOGN_NMAP_REMOVE(GMapN<6>, 2)
CGOGN_NMAP_REMOVE(GMapN<6>, 3)
CGOGN_NMAP_REMOVE(GMapN<6>, 4)
CGOGN_NMAP_REMOVE(GMapN<6>, 5)
CGOGN_NMAP_CONTRACT(GMapN<6>, 1)
CGOGN_NMAP_CONTRACT(GMapN<6>, 2)
CGOGN_NMAP_CONTRACT(GMapN<6>, 3)
CGOGN_NMAP_CONTRACT(GMapN<6>, 4)
CGOGN_NMAP_CONTRACT(GMapN<6>, 5)
CGOGN_NMAP_CONTRACT(GMapN<6>, 6)
CGOGN_NMAP_REMOVE(GMapN<7>, 0)
CGOGN_NMAP_REMOVE(GMapN<7>, 1)
CGOGN_NMAP_REMOVE(GMapN<7>, 2)
CGOGN_NMAP_REMOVE(GMapN<7>, 3)
CGOGN_NMAP_REMOVE(GMapN<7>, 4)
CGOGN_NMAP_REMOVE(GMapN<7>, 5)
CGOGN_NMAP_REMOVE(GMapN<7>, 6)
CGOGN_NMAP_CONTRACT(GMapN<7>, 1)
CGOGN_NMAP_CONTRACT(GMapN<7>, 2)
CGOGN_NMAP_CONTRACT(GMapN<7>, 3)
CGOGN_NMAP_CONTRACT(GMapN<7>, 4)
CGOGN_NMAP_CONTRACT(GMapN<7>, 5)
CGOGN_NMAP_CONTRACT(GMapN<7>, 6)
CGOGN_NMAP_CONTRACT(GMapN<7>, 7)
#undef CGOGN_NMAP_OPERATORS
#undef CGOGN_NMAP_REMOVE
#undef CGOGN_NMAP_CONTRACT
#undef CGOGN_NMAP_FACE_OPERATORS

} // namespace cgogn
