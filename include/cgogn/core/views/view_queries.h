// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/properties.h>
#include <cgogn/core/views/mesh_view.h>

namespace cgogn
{

// Topological queries on views: a view hides cells from traversals, never
// from the topology, so these answer for the map under the view (degree
// counts every incident cell, accepted by a filter or not). They let generic
// code written for maps take a view. Costs are those of the map's functions.

template <MeshView V>
Dart phi1(const V& v, Dart d)
{
	return phi1(map_of(v), d);
}
template <MeshView V>
Dart phi_1(const V& v, Dart d)
{
	return phi_1(map_of(v), d);
}
template <MeshView V>
Dart phi2(const V& v, Dart d)
{
	return phi2(map_of(v), d);
}
template <MeshView V>
Dart phi3(const V& v, Dart d)
{
	return phi3(map_of(v), d);
}
/// phi<1, 2>(view, d) as on the map (see phi on maps).
template <int... N, MeshView V>
Dart phi(const V& v, Dart d)
{
	return phi<N...>(map_of(v), d);
}
template <MeshView V>
bool is_boundary(const V& v, Dart d)
{
	return is_boundary(map_of(v), d);
}
template <MeshView V, CellType CELL>
uint32 degree(const V& v, CELL c)
{
	return degree(map_of(v), c);
}
template <MeshView V, CellType CELL>
uint32 codegree(const V& v, CELL c)
{
	return codegree(map_of(v), c);
}
template <MeshView V, CellType CELL>
bool is_incident_to_boundary(const V& v, CELL c)
{
	return is_incident_to_boundary(map_of(v), c);
}
template <MeshView V, Orbit O>
bool same_cell(const V& v, Cell<O> c1, Cell<O> c2)
{
	return same_cell(map_of(v), c1, c2);
}

} // namespace cgogn
