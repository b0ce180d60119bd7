// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/incidence_graph.h>
#include <cgogn/core/properties/integrity.h>

namespace cgogn
{

/// Number of edges of vertex v; 0 for a vertex without edge. O(degree of v).
uint32 degree(const IncidenceGraph& ig, IncidenceGraph::Vertex v);

/// Number of faces on edge e: 0 for a wire, 1 on a border, 2 inside a
/// manifold surface, 3 or more where the complex branches. O(degree of e).
uint32 degree(const IncidenceGraph& ig, IncidenceGraph::Edge e);

/// Number of edges (and of vertices) of face f. O(size of f).
uint32 codegree(const IncidenceGraph& ig, IncidenceGraph::Face f);

/// True when edge e has at most two faces. O(degree of e).
bool is_manifold_edge(const IncidenceGraph& ig, IncidenceGraph::Edge e);

/// True when the faces around v form one fan, as around a vertex of a
/// manifold surface (a disc inside, a half-disc on a border): every edge of
/// v has one or two faces, and going from face to face across the edges of
/// v reaches them all. A vertex without edge, or with an edge without face
/// (a wire), is not manifold. O(sum of the degrees of v's edges).
bool is_manifold_vertex(const IncidenceGraph& ig, IncidenceGraph::Vertex v);

/// Number of connected components (through edges; a vertex without edge is
/// one). O(vertices + edges).
uint32 nb_connected_components(const IncidenceGraph& ig);

/// V - E + F. O(1) when faces are indexed, O(uses) otherwise.
int64 euler_characteristic(const IncidenceGraph& ig);

/// Number of edges with three faces or more. O(uses + edges).
uint32 nb_non_manifold_edges(const IncidenceGraph& ig);

/// Number of vertices that are not manifold (is_manifold_vertex), vertices
/// without edge included. O(uses + edges + vertices).
uint32 nb_non_manifold_vertices(const IncidenceGraph& ig);

} // namespace cgogn
