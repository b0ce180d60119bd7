// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/orbits.h>

#include <algorithm>
#include <array>
#include <cassert>
#include <unordered_map>
#include <vector>

namespace cgogn::detail
{

/// A new pair of darts (an edge side, see add_dart_pair) with the boundary
/// mark of `like` (the face it joins). Returns its first dart. O(1).
template <typename MAP>
requires is_gmap_v<MAP> Dart new_dart_pair_like(MAP& m, Dart like)
{
	const Dart d = add_dart_pair(m);
	if (is_boundary(m, like))
	{
		set_boundary(m, d, true);
		set_boundary(m, beta0(m, d), true);
	}
	return d;
}

/// Removes darts listed with their pairs (every dart's beta0 is listed too:
/// whole edges, faces or volumes), each pair once. O(number of darts).
template <typename MAP>
requires is_gmap_v<MAP>
void remove_dart_pairs(MAP& m, const std::vector<Dart>& darts)
{
	for (Dart x : darts)
		if (x.index % 2 == 0)
		{
			assert(std::find(darts.begin(), darts.end(), beta0(m, x)) != darts.end());
			remove_dart_pair(m, x);
		}
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

/// The darts of cell c, in the order of its walk. O(size of the cell).
template <typename MAP, typename CELL>
std::vector<Dart> orbit_darts(const MAP& m, CELL c)
{
	std::vector<Dart> darts;
	foreach_dart_of_orbit(m, c, [&](Dart x) { darts.push_back(x); });
	return darts;
}

/// Gives q the lines that b has in the cells that do not contain beta0
/// (vertices, and the vertices of a face or a volume), where q takes b's
/// place; b, which moves to a new vertex, gets no line there (as a new dart).
/// A cell represented by b is represented by q. O(number of orbits).
inline void move_vertex_lines(GMap1& m, Dart b, Dart q)
{
	MapState& s = state_of(m);
	for (uint32 o = 0; o < NB_ORBITS; ++o)
	{
		AttributeArray<uint32>* idx = s.cell_index[o];
		if (idx == nullptr || Orbit(o) == Orbit::DART || orbit_uses_beta(Orbit(o), 0))
			continue;
		const uint32 line = (*idx)[b.index];
		(*idx)[q.index] = line;
		(*idx)[b.index] = INVALID_INDEX;
		if (line != INVALID_INDEX && s.cells[o]->key()[line] == b.index)
			s.cells[o]->key()[line] = q.index;
	}
}

/// Inserts a vertex in the middle of the edge of d, from d's vertex A to the
/// other end B. Every dart x of the edge at A (d and its images by beta2,
/// beta3) keeps its pair: beta0(x) moves from B to the new vertex, and a new
/// pair (p, q) follows it, p at the new vertex (beta1(p) = beta0(x)), q at B
/// in the place beta0(x) left (its relations and its vertex lines, see
/// move_vertex_lines). Returns p, q for each such x, d's first: p is in the
/// face of d, on the half that does not hold d. O(size of the edge).
template <typename MAP>
std::vector<Dart> insert_vertex_in_edge(MAP& m, Dart d)
{
	std::vector<Dart> at_a{d};
	for (std::size_t i = 0; i < at_a.size(); ++i)
	{
		const auto visit = [&](Dart y) {
			if (std::find(at_a.begin(), at_a.end(), y) == at_a.end())
				at_a.push_back(y);
		};
		if constexpr (MAP::dimension >= 2)
			visit(beta2(m, at_a[i]));
		if constexpr (MAP::dimension >= 3)
			visit(beta3(m, at_a[i]));
	}
	// the new pair of each pair of the edge (a pair's index is d.index / 2)
	std::unordered_map<uint32, Dart> new_pair;
	std::vector<Dart> added;
	for (Dart x : at_a)
	{
		const Dart p = new_dart_pair_like(m, x);
		new_pair.emplace(x.index / 2, p);
		added.insert(added.end(), {p, beta0(m, p)});
	}
	const auto p_of = [&](Dart y) { return new_pair.at(y.index / 2); };
	for (Dart x : at_a)
	{
		const Dart b = beta0(m, x), p = p_of(x), q = beta0(m, p);
		if (const Dart b1 = beta1(m, b); b1 != b)
			link_beta<1>(m, q, b1);
		link_beta<1>(m, b, p);
		// beta_i(b) (i >= 2) is at the new vertex too, in the pair of beta_i(x)
		if constexpr (MAP::dimension >= 2)
		{
			const Dart p2 = p_of(beta2(m, b));
			set_beta<2>(m, p, p2);
			set_beta<2>(m, q, beta0(m, p2));
		}
		if constexpr (MAP::dimension >= 3)
		{
			const Dart p3 = p_of(beta3(m, b));
			set_beta<3>(m, p, p3);
			set_beta<3>(m, q, beta0(m, p3));
		}
		move_vertex_lines(m, b, q);
	}
	return added;
}

/// The new darts of split_face_side: p and p0 in the part of d (at the vertex
/// of d and of the other corner), q and q0 in the other part.
struct FaceSideCut
{
	Dart p, p0, q, q0;
};

/// True when d and e lie at two distinct corners of one face side (beta0,
/// beta1) that no edge of the face joins. O(degree of the face).
bool corners_can_be_joined(const GMap2& m, Dart d, Dart e);

/// Cuts the face side (beta0, beta1 orbit) of d and e by a new edge between
/// the corners of d and e: four new darts, with d's boundary mark, joined by
/// beta0, beta1 and beta2 to the face and to each other (beta3 is left to
/// the caller). Precondition: corners_can_be_joined(m, d, e). O(degree).
FaceSideCut split_face_side(GMap2& m, Dart d, Dart e);

} // namespace cgogn::detail
