// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/marking/marker.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_gmap3.h>

namespace cgogn
{

// Properties of the cells of a GMap2 (as properties.h gives them for CMap2),
// and orientability.

/// Number of edges incident to v. O(degree): each edge has two darts at v
/// (one per side, a boundary side included).
inline uint32 degree(const GMap2& m, GMap2::Vertex v)
{
	return nb_darts_of_orbit(m, v) / 2;
}
/// Number of faces incident to e (1 or 2, boundary faces excluded). O(1).
inline uint32 degree(const GMap2& m, GMap2::Edge e)
{
	return uint32(!is_boundary(m, e.dart)) + uint32(!is_boundary(m, beta2(m, e.dart)));
}
/// Number of edges of face f. O(codegree).
inline uint32 codegree(const GMap2& m, GMap2::Face f)
{
	return nb_darts_of_orbit(m, f) / 2;
}

/// Number of edges incident to v in a 3-G-map. O(size of the vertex orbit).
inline uint32 degree(const GMap3& m, GMap3::Vertex v)
{
	uint32 n = 0;
	foreach_incident_edge(m, v, [&](GMap3::Edge) { ++n; });
	return n;
}
/// Number of faces incident to e in a 3-G-map. O(degree): each face has four
/// darts in the edge (two ends, two sides).
inline uint32 degree(const GMap3& m, GMap3::Edge e)
{
	return nb_darts_of_orbit(m, e) / 4;
}
/// Number of non-boundary volumes incident to f (1 or 2). O(1).
inline uint32 degree(const GMap3& m, GMap3::Face f)
{
	return uint32(!is_boundary(m, f.dart)) + uint32(!is_boundary(m, beta3(m, f.dart)));
}
/// Number of edges of face f of a 3-G-map. O(codegree).
inline uint32 codegree(const GMap3& m, GMap3::Face f)
{
	return codegree(static_cast<const GMap2&>(m), GMap2::Face(f.dart));
}
/// Number of faces of volume w. O(number of darts of w).
inline uint32 codegree(const GMap3& m, GMap3::Volume w)
{
	uint32 n = 0;
	foreach_incident_face(m, w, [&](GMap3::Face) { ++n; });
	return n;
}

/// True when vertex v touches a boundary face. O(1) on a map without
/// boundary, else O(degree).
inline bool is_incident_to_boundary(const GMap2& m, GMap2::Vertex v)
{
	if (!has_boundary(m))
		return false;
	bool b = false;
	foreach_dart_of_orbit(m, v, [&](Dart d) { return !(b = is_boundary(m, d)); });
	return b;
}
/// True when edge e borders a boundary face. O(1).
inline bool is_incident_to_boundary(const GMap2& m, GMap2::Edge e)
{
	return is_boundary(m, e.dart) || is_boundary(m, beta2(m, e.dart));
}

/// True when face f of a 3-G-map is on the boundary (one side is a boundary
/// volume). O(1).
inline bool is_incident_to_boundary(const GMap3& m, GMap3::Face f)
{
	return is_boundary(m, f.dart) || is_boundary(m, beta3(m, f.dart));
}

/// Number of connected components. O(number of darts).
inline uint32 nb_connected_components(const GMap2& m)
{
	return nb_cells<GMap2::Volume>(m);
}
/// Number of connected components of a 3-G-map. O(number of darts).
inline uint32 nb_connected_components(const GMap3& m)
{
	return nb_cells<GMap3::CC>(m);
}

namespace detail
{

/// The paper's two-colouring of a G-map: marks in `black` the darts of one
/// colour, the first dart met of each connected component black, so that
/// every beta_i joins two colours. The components coloured are those of the
/// darts of `starts` (by default, every dart; then each component starts at
/// its smallest dart). Returns false, with the colouring left unfinished,
/// when some beta_i joins two darts of one colour (the map is not
/// orientable). O(number of darts of those components).
template <typename MAP, typename STARTS>
requires is_gmap_v<MAP>
bool two_colour_from(const MAP& m, DartMarker<MAP>& black, const STARTS& starts)
{
	DartMarker<MAP> seen(m);
	std::vector<Dart> work;
	bool ok = true;
	starts([&](Dart start) {
		if (seen.is_marked(start))
			return true;
		seen.mark(start);
		black.mark(start);
		work.assign(1, start);
		while (!work.empty() && ok)
		{
			const Dart d = work.back();
			work.pop_back();
			const bool d_black = black.is_marked(d);
			for (uint32 i = 0; i <= MAP::dimension; ++i)
			{
				const Dart e = i == 0 ? beta0(m, d) : Dart((*detail::state_of(m).beta[i])[d.index]);
				if (e == d)
					continue; // a free dart of an unfinished map: no constraint
				if (!seen.is_marked(e))
				{
					seen.mark(e);
					if (!d_black)
						black.mark(e);
					work.push_back(e);
				}
				else if (black.is_marked(e) == d_black)
					ok = false;
			}
		}
		return ok;
	});
	return ok;
}

/// two_colour_from every dart of m.
template <typename MAP>
requires is_gmap_v<MAP>
bool two_colour(const MAP& m, DartMarker<MAP>& black)
{
	return two_colour_from(m, black, [&](const auto& f) { foreach_dart(m, f); });
}

} // namespace detail

/// Whether every connected component of m can be oriented: the paper's
/// two-colouring, each component's darts coloured so that every beta_i joins
/// two darts of different colours (a CMap2 is then the darts of one colour).
/// A boundary face is a face like the others: a Möbius strip stays
/// non-orientable once closed. O(number of darts).
template <typename MAP>
requires is_gmap_v<MAP>
bool is_orientable(const MAP& m)
{
	DartMarker<MAP> black(m);
	return detail::two_colour(m, black);
}

} // namespace cgogn
