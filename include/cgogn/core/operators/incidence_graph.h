// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/incidence_graph.h>

#include <span>

namespace cgogn
{

// Operators of incidence graphs. Each keeps the complex valid
// (check_integrity): edges join two different vertices, faces are simple
// cycles of at least 3 edges. Vertices and edges are records, always
// indexed: a new one gets a new line (its attributes at their default
// values), a removed one releases its line, a surviving one keeps it.
// Faces are indexed when their orbit is (a face attribute exists), and the
// operators keep those lines as the maps' operators do. Costs count the
// records touched; walks around a vertex or an edge are O(its degree), as
// the rings are singly linked (see IncidenceGraph).

/// A new vertex, without edge. O(1).
IncidenceGraph::Vertex add_vertex(IncidenceGraph& ig);

/// Whether an edge can join v0 and v1: two different live vertices. O(1).
bool can_add_edge(const IncidenceGraph& ig, IncidenceGraph::Vertex v0, IncidenceGraph::Vertex v1);

/// A new edge from v0 to v1 (its first and second vertex), without face.
/// Another edge may already join them (parallel edges are allowed; see
/// find_edge). Throws TopologyError, changing nothing, when !can_add_edge.
/// O(1).
IncidenceGraph::Edge add_edge(IncidenceGraph& ig, IncidenceGraph::Vertex v0, IncidenceGraph::Vertex v1);

/// An edge joining v0 and v1 (either direction), or an invalid edge when
/// there is none. O(degree of v0).
IncidenceGraph::Edge find_edge(const IncidenceGraph& ig, IncidenceGraph::Vertex v0, IncidenceGraph::Vertex v1);

/// Whether `edges`, in any order, form one simple cycle of at least 3
/// distinct live edges: each vertex met is the end of exactly two of them,
/// and they are connected. O(k^2) for k edges.
bool can_add_face(const IncidenceGraph& ig, std::span<const IncidenceGraph::Edge> edges);

/// A new face bounded by `edges`, given in any order. The face runs along
/// its cycle starting with edges[0], toward the vertex edges[0] shares with
/// edges[1] when they share one (so edges given in cycle order give the face
/// that order and orientation), from edges[0]'s first vertex otherwise.
/// Throws TopologyError, changing nothing, when !can_add_face. O(k^2) for k
/// edges, plus O(1) per edge.
IncidenceGraph::Face add_face(IncidenceGraph& ig, std::span<const IncidenceGraph::Edge> edges);

/// A new face through `vertices` in this order (at least 3, all different),
/// using the edge that joins two consecutive ones when there is one
/// (find_edge) and adding it otherwise. Throws TopologyError, changing
/// nothing, when fewer than 3 vertices are given, one repeats or one is not
/// live. O(sum of the degrees of the vertices).
IncidenceGraph::Face add_face_through_vertices(IncidenceGraph& ig, std::span<const IncidenceGraph::Vertex> vertices);

/// Removes face f; its edges and vertices stay. O(size of f x degrees of
/// its edges).
void remove_face(IncidenceGraph& ig, IncidenceGraph::Face f);

/// Removes edge e and every face on it; its vertices stay (possibly
/// without edge). O(sizes of the removed faces x degrees of their edges).
void remove_edge(IncidenceGraph& ig, IncidenceGraph::Edge e);

/// Removes vertex v, its edges and their faces. O(what remove_edge costs
/// for each edge of v).
void remove_vertex(IncidenceGraph& ig, IncidenceGraph::Vertex v);

/// Splits edge e by a new vertex w: e keeps its line and first vertex and
/// now ends at w, a new edge runs from w to e's former second vertex, and
/// every face on e gets the new edge beside it. Returns w. O(degree of e +
/// degree of e's second vertex).
IncidenceGraph::Vertex cut_edge(IncidenceGraph& ig, IncidenceGraph::Edge e);

/// Whether face f can be cut between v0 and v1: both are vertices of f and
/// they are not consecutive in it (each part keeps at least 3 edges).
/// O(size of f).
bool can_cut_face(const IncidenceGraph& ig, IncidenceGraph::Face f, IncidenceGraph::Vertex v0,
				  IncidenceGraph::Vertex v1);

/// Cuts face f in two along an edge from v0 to v1: the edge that joins them
/// already when there is one (find_edge), a new one otherwise. The part
/// that starts at v0 keeps f's line (when faces are indexed), the other gets
/// a new one. Returns the edge. Throws TopologyError, changing nothing, when
/// !can_cut_face. O(size of f + degree of v0).
IncidenceGraph::Edge cut_face(IncidenceGraph& ig, IncidenceGraph::Face f, IncidenceGraph::Vertex v0,
							  IncidenceGraph::Vertex v1);

/// The face that can be cut between v0 and v1 (can_cut_face), when exactly
/// one face around v0 can; an invalid face otherwise (none, or several: say
/// which with the overloads taking the face). O(sum of the sizes of the
/// faces around v0).
IncidenceGraph::Face face_to_cut(const IncidenceGraph& ig, IncidenceGraph::Vertex v0, IncidenceGraph::Vertex v1);

/// Whether face_to_cut(ig, v0, v1) finds a face. O(as face_to_cut).
bool can_cut_face(const IncidenceGraph& ig, IncidenceGraph::Vertex v0, IncidenceGraph::Vertex v1);

/// Cuts the face that v0 and v1 share, not as consecutive vertices (see
/// face_to_cut), along an edge from v0 to v1, as cut_face(ig, f, v0, v1).
/// Throws TopologyError, changing nothing, when no face or several faces
/// qualify. O(as face_to_cut + size of the face).
IncidenceGraph::Edge cut_face(IncidenceGraph& ig, IncidenceGraph::Vertex v0, IncidenceGraph::Vertex v1);

/// Whether edge e can be collapsed: no face other than e's own holds both
/// of its vertices (it would be pinched into a non-simple cycle), and no
/// other edge joining them has a face. O(sum of the sizes of the faces
/// around e's first vertex).
bool can_collapse_edge(const IncidenceGraph& ig, IncidenceGraph::Edge e);

/// Collapses edge e: its second vertex is merged into its first, which keeps
/// its line (and values; the other vertex's are dropped, set the survivor's
/// after the call, e.g. the midpoint). The faces on e lose it; those left
/// with 2 edges are removed. Edges that now join the same two vertices are
/// merged into one, which keeps the line of the one met first around the
/// survivor (its faces gather on it); an edge that joined e's two vertices
/// is removed. Returns the surviving vertex. Throws TopologyError, changing
/// nothing, when !can_collapse_edge. O(sizes of the faces around e's
/// vertices + their degrees, with a sort of the survivor's edges).
IncidenceGraph::Vertex collapse_edge(IncidenceGraph& ig, IncidenceGraph::Edge e);

} // namespace cgogn
