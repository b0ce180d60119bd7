// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap1.h>
#include <cgogn/core/operators/dimension_guards.h>

namespace cgogn
{

// Operators of 1-G-maps (polygons), with the names and contracts of the
// CMap1 ones (operators/cmap1.h). With set_indices (the default) every
// indexed orbit stays indexed.

/// Creates an isolated polygon of n edges (2n darts) and returns it. With
/// set_indices, its cells get new lines. Precondition: n >= 1. O(n).
GMap1::Face add_face(GMap1& m, uint32 n, bool set_indices = true);

/// Inserts a vertex in the middle of edge e; the half containing e.dart
/// keeps the edge's line. Returns the new vertex, by its dart on the half
/// that does not contain e.dart. O(1).
GMap1::Vertex cut_edge(GMap1& m, GMap1::Edge e, bool set_indices = true);

/// Removes edge e from its polygon: the vertex of e.dart disappears, the
/// other end survives with its line and is returned. Precondition: the
/// polygon has at least 2 edges. O(1).
GMap1::Vertex collapse_edge(GMap1& m, GMap1::Edge e, bool set_indices = true);

} // namespace cgogn
