// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/operators/creation.h>
#include <cgogn/core/operators/dimension_guards.h>

namespace cgogn
{

// Operators of 1-maps. With set_indices = false they change the topology only:
// new darts get no index and lines of removed cells are not released (call
// index_cells and manage lines yourself). Attribute values are never touched.

/// Removes face f and its darts; releases its line. O(degree of f).
void remove_face(CMap1& m, CMap1::Face f, bool set_indices = true);

/// Inserts a new vertex after the vertex of e.dart, splitting edge e in two;
/// returns the new vertex (whose dart follows e.dart). O(1).
CMap1::Vertex cut_edge(CMap1& m, CMap1::Edge e, bool set_indices = true);

/// Removes edge e (the dart e.dart) from its face; returns the vertex that
/// followed it. Precondition: the face has at least 2 edges. O(degree).
CMap1::Vertex collapse_edge(CMap1& m, CMap1::Edge e, bool set_indices = true);

} // namespace cgogn
