// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap2.h>

namespace cgogn
{

// Operators of 2-G-maps, with the names and contracts of the CMap2 ones
// (operators/cmap2.h): the map stays closed and, with set_indices (the
// default), every indexed orbit stays indexed (a split cell keeps its line
// on the part containing the given dart, new cells get new lines, removed
// cells release theirs). They work on orientable and non-orientable maps
// alike. Cost independent of the size of the map.

/// Inserts a vertex in the middle of edge e (its four darts, or two on the
/// boundary, each get a new neighbour by beta0). The half containing e.dart
/// keeps the edge's line. Returns the new vertex, whose dart lies in the
/// face of e.dart, on the half that does not contain e.dart. O(1).
GMap2::Vertex cut_edge(GMap2& m, GMap2::Edge e, bool set_indices = true);

/// True when v1.dart and v2.dart lie in the same non-boundary face, at two
/// vertices of it that are not joined by one of its edges (so that both parts
/// have at least 3 edges). O(degree of the face).
bool can_cut_face(const GMap2& m, GMap2::Vertex v1, GMap2::Vertex v2);

/// Cuts the face of v1.dart and v2.dart by a new edge between their
/// vertices. The part containing v1.dart keeps the face's line. Returns the
/// new edge, by its dart at the vertex of v1 in the part containing v1.dart.
/// Precondition: can_cut_face(m, v1, v2). O(degree of the face).
GMap2::Edge cut_face(GMap2& m, GMap2::Vertex v1, GMap2::Vertex v2, bool set_indices = true);

/// True when edge e separates two distinct non-boundary faces. O(degree).
bool can_merge_incident_faces(const GMap2& m, GMap2::Edge e);

/// Removes edge e, merging its two faces into one that keeps the line of the
/// face of e.dart. Returns the merged face. Precondition:
/// can_merge_incident_faces(m, e). O(degree of the faces).
GMap2::Face merge_incident_faces(GMap2& m, GMap2::Edge e, bool set_indices = true);

} // namespace cgogn
