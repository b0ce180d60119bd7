// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/map/orbits.h>

#include <array>
#include <unordered_map>
#include <vector>

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

/// The darts of cell c, in the order of its walk. O(size of the cell).
template <typename MAP, typename CELL>
std::vector<Dart> orbit_darts(const MAP& m, CELL c)
{
	std::vector<Dart> darts;
	foreach_dart_of_orbit(m, c, [&](Dart x) { darts.push_back(x); });
	return darts;
}

/// Inserts a vertex in the middle of an edge given by all its darts (its
/// BETA0_BETA2(_BETA3) orbit): each dart x gets a new dart n(x) as its beta0,
/// at the new vertex, with beta1(n(x)) = n(beta0(x)) and beta_i(n(x)) =
/// n(beta_i(x)) for i >= 2. Returns the new darts, in the order of `edge`.
/// O(size of the edge).
template <typename MAP>
std::vector<Dart> insert_vertex_in_edge(MAP& m, const std::vector<Dart>& edge)
{
	std::unordered_map<uint32, Dart> made;
	std::vector<Dart> added, ends;
	for (Dart x : edge)
	{
		added.push_back(new_dart_like(m, x));
		made.emplace(x.index, added.back());
		ends.push_back(beta0(m, x));
	}
	for (std::size_t i = 0; i < edge.size(); ++i)
	{
		const Dart x = edge[i], n = added[i];
		link_beta<0>(m, x, n);
		set_beta<1>(m, n, made.at(ends[i].index));
		set_beta<2>(m, n, made.at(beta2(m, x).index));
		if constexpr (MAP::dimension >= 3)
			set_beta<3>(m, n, made.at(beta3(m, x).index));
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
