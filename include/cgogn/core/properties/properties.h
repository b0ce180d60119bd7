// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/dimension_properties.h>
#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/traversals/local_cmap3.h>

namespace cgogn
{

// ---- degree: number of incident cells of the next dimension (non-boundary)
//
// degree and codegree exist for every cell type of CMap2 (Vertex, Edge, Face,
// Volume) and CMap3 (Vertex, Edge, Face, Volume), so that generic code can ask
// them of any cell; the face of a 1-map has its codegree. On a 3-map the
// cells of its volumes' 2-maps (Vertex2 = CMap2::Vertex, Edge2 = CMap2::Edge,
// CMap2::Face) get the CMap2 answers, counted within their volume.

/// Number of edges incident to v. O(degree).
inline uint32 degree(const CMap2& m, CMap2::Vertex v)
{
	return nb_darts_of_orbit(m, v);
}
/// Number of non-boundary faces incident to e (1 or 2). O(1).
inline uint32 degree(const CMap2& m, CMap2::Edge e)
{
	return uint32(!is_boundary(m, e.dart)) + uint32(!is_boundary(m, phi2(m, e.dart)));
}
/// Number of edges incident to v. O(size of the vertex orbit).
inline uint32 degree(const CMap3& m, CMap3::Vertex v)
{
	uint32 n = 0;
	foreach_incident_edge(m, v, [&](CMap3::Edge) { ++n; });
	return n;
}
/// Number of faces incident to e. O(degree).
inline uint32 degree(const CMap3& m, CMap3::Edge e)
{
	uint32 n = 0;
	foreach_incident_face(m, e, [&](CMap3::Face) { ++n; });
	return n;
}
/// Number of non-boundary volumes incident to f (1 or 2). O(1).
inline uint32 degree(const CMap3& m, CMap3::Face f)
{
	return uint32(!is_boundary(m, f.dart)) + uint32(!is_boundary(m, phi3(m, f.dart)));
}
/// 1: a face of a 2-map lies in one volume (its connected component). O(1).
inline uint32 degree(const CMap2&, CMap2::Face)
{
	return 1;
}
/// 0: no cell of a 2-map has a higher dimension than its volumes. O(1).
inline uint32 degree(const CMap2&, CMap2::Volume)
{
	return 0;
}
/// 0: no cell of a 3-map has a higher dimension than its volumes. O(1).
inline uint32 degree(const CMap3&, CMap3::Volume)
{
	return 0;
}

// ---- codegree: number of incident cells of the previous dimension

/// Number of vertices (= edges) of a face. O(codegree).
inline uint32 codegree(const CMap1& m, CMap1::Face f)
{
	return nb_darts_of_orbit(m, f);
}
/// 2: the vertices of an edge.
inline uint32 codegree(const CMap2&, CMap2::Edge)
{
	return 2;
}
/// Number of edges of face f. O(codegree).
inline uint32 codegree(const CMap3& m, CMap3::Face f)
{
	return codegree(static_cast<const CMap1&>(m), CMap1::Face(f.dart));
}
/// Number of faces of volume w. O(number of darts of w).
inline uint32 codegree(const CMap3& m, CMap3::Volume w)
{
	uint32 n = 0;
	foreach_incident_face(m, w, [&](CMap3::Face) { ++n; });
	return n;
}
/// Number of faces of volume w (a connected component of the 2-map).
/// O(number of darts of w).
inline uint32 codegree(const CMap2& m, CMap2::Volume w)
{
	uint32 n = 0;
	foreach_incident_face(m, w, [&](CMap2::Face) { ++n; });
	return n;
}
/// 2: the vertices of an edge.
inline uint32 codegree(const CMap3&, CMap3::Edge)
{
	return 2;
}
/// 0: a vertex has no incident cell of a lower dimension. O(1).
inline uint32 codegree(const CMap2&, CMap2::Vertex)
{
	return 0;
}
/// 0: a vertex has no incident cell of a lower dimension. O(1).
inline uint32 codegree(const CMap3&, CMap3::Vertex)
{
	return 0;
}

// ---- boundary

/// True when vertex v touches a boundary face. O(1) on a map without
/// boundary, else O(degree).
inline bool is_incident_to_boundary(const CMap2& m, CMap2::Vertex v)
{
	if (!has_boundary(m))
		return false;
	bool b = false;
	foreach_dart_of_orbit(m, v, [&](Dart d) { return !(b = is_boundary(m, d)); });
	return b;
}
/// True when edge e borders a boundary face. O(1).
inline bool is_incident_to_boundary(const CMap2& m, CMap2::Edge e)
{
	return is_boundary(m, e.dart) || is_boundary(m, phi2(m, e.dart));
}
/// True when face f has an edge on the boundary. O(codegree).
inline bool is_incident_to_boundary(const CMap2& m, CMap2::Face f)
{
	bool b = false;
	foreach_dart_of_orbit(m, f, [&](Dart d) { return !(b = is_boundary(m, phi2(m, d))); });
	return b;
}
/// True when vertex v touches a boundary volume. O(1) on a map without
/// boundary, else O(size of the vertex orbit).
inline bool is_incident_to_boundary(const CMap3& m, CMap3::Vertex v)
{
	if (!has_boundary(m))
		return false;
	bool b = false;
	foreach_dart_of_orbit(m, v, [&](Dart d) { return !(b = is_boundary(m, d)); });
	return b;
}
/// True when edge e touches a boundary volume. O(degree).
inline bool is_incident_to_boundary(const CMap3& m, CMap3::Edge e)
{
	bool b = false;
	foreach_dart_of_orbit(m, e, [&](Dart d) { return !(b = is_boundary(m, d)); });
	return b;
}
/// True when face f is on the boundary (one side is a boundary volume). O(1).
inline bool is_incident_to_boundary(const CMap3& m, CMap3::Face f)
{
	return is_boundary(m, f.dart) || is_boundary(m, phi3(m, f.dart));
}
/// True when volume w has a face on the boundary. O(number of darts of w).
inline bool is_incident_to_boundary(const CMap3& m, CMap3::Volume w)
{
	bool b = false;
	foreach_dart_of_orbit(m, w, [&](Dart d) { return !(b = is_boundary(m, phi3(m, d))); });
	return b;
}

// ---- global

/// Number of connected components. O(number of darts).
inline uint32 nb_connected_components(const CMap2& m)
{
	return nb_cells<CMap2::Volume>(m);
}
inline uint32 nb_connected_components(const CMap3& m)
{
	return nb_cells<CMap3::CC>(m);
}

/// Number of boundary components (boundary faces of a 2-map or 2-G-map,
/// boundary volumes of a 3-map or 3-G-map). O(number of darts).
template <typename MAP>
requires std::derived_from<MAP, CMapBase> uint32 nb_boundary_components(const MAP& m)
{
	using Top = std::conditional_t<
		is_gmap_v<MAP>,
		std::conditional_t<MAP::dimension == 3, Cell<Orbit::BETA0_BETA1_BETA2>, Cell<Orbit::BETA0_BETA1>>,
		std::conditional_t<MAP::dimension == 3, Cell<Orbit::PHI1_PHI2>, Cell<Orbit::PHI1>>>;
	DartMarker<MAP> dm(m);
	uint32 n = 0;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d) && !dm.is_marked(d))
		{
			dm.mark_orbit(Top(d));
			++n;
		}
	});
	return n;
}

} // namespace cgogn
