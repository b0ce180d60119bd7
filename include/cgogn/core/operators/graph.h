// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/graph.h>

namespace cgogn
{

// Operators of graphs. Each keeps the graph valid (check_integrity) and costs
// O(1) unless stated: alpha_1 is stored, so no walk around a vertex is needed
// to insert or remove a half-edge. With set_indices = false they change the
// topology only: new cells get no index, the lines of removed cells are not
// released and merged vertices keep their own lines (call index_cells and
// manage the lines yourself). Attribute values are never touched: a new
// cell holds its attributes' default values, a cell that survives keeps its
// line (so its values).

/// A new isolated vertex: one dart, degree 0, no edge.
Graph::Vertex add_vertex(Graph& g, bool set_indices = true);

/// Removes vertex v together with its edges (a self-loop once); the other
/// ends of those edges stay, with a lower degree (an end left without edges
/// becomes an isolated vertex). O(degree of v).
void remove_vertex(Graph& g, Graph::Vertex v, bool set_indices = true);

/// A new edge from v1 to v2 (a self-loop when v1 and v2 are the same
/// vertex: its degree grows by 2), inserted after v1.dart around v1 and
/// after v2.dart around v2. Returns the edge, whose dart is at v1. O(1)
/// when vertices are indexed, O(degree of v1) otherwise (to tell whether v1
/// and v2 are one vertex).
Graph::Edge connect_vertices(Graph& g, Graph::Vertex v1, Graph::Vertex v2, bool set_indices = true);

/// Removes edge e; its ends stay (an end left without edges becomes an
/// isolated vertex, keeping its line).
void disconnect_vertices(Graph& g, Graph::Edge e, bool set_indices = true);

/// Whether v1 and v2 can be merged: they are two different vertices.
/// O(degree of v1) when vertices are not indexed.
bool can_merge_vertices(const Graph& g, Graph::Vertex v1, Graph::Vertex v2);

/// Merges v2 into v1: the edges of v2 come after v1.dart around v1, v1's
/// line is kept and v2's released (an edge between them becomes a
/// self-loop). Returns the merged vertex; v1 unchanged when v1 and v2 are
/// one vertex. O(degree of the merged vertex) when vertices are indexed
/// (its darts get v1's line), O(degree of v1) otherwise (the test of one
/// vertex).
Graph::Vertex merge_vertices(Graph& g, Graph::Vertex v1, Graph::Vertex v2, bool set_indices = true);

/// Splits edge e by a new vertex of degree 2. The part at e.dart keeps e's
/// line; the other part is a new edge. Returns the new vertex.
Graph::Vertex cut_edge(Graph& g, Graph::Edge e, bool set_indices = true);

/// Whether edge e can be collapsed: it is not a self-loop. O(degree of the
/// vertex of e.dart) when vertices are not indexed.
bool can_collapse_edge(const Graph& g, Graph::Edge e);

/// Removes edge e and merges its two ends into one vertex, which keeps the
/// line of the vertex of e.dart (the other end's is released): the other
/// end's attribute values are dropped, set them after the call (e.g. the
/// midpoint). Two ends of degree 1 leave an isolated vertex. Returns the
/// merged vertex. Throws TopologyError (nothing changed) for a self-loop
/// (see can_collapse_edge). O(degree of the merged vertex) when vertices
/// are indexed, O(degree of e's vertex) otherwise (the test of a self-loop).
Graph::Vertex collapse_edge(Graph& g, Graph::Edge e, bool set_indices = true);

} // namespace cgogn
