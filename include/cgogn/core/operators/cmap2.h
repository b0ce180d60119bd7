// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/operators/creation.h>
#include <cgogn/core/operators/dimension_guards.h>

#include <vector>

namespace cgogn
{

// Operators of 2-maps. Each keeps the map closed and, with set_indices (the
// default), every indexed orbit correctly indexed: new cells get new lines,
// a split cell keeps its line on the part containing the given dart, merged
// cells keep the line of the surviving cell, removed cells release theirs,
// and representative darts stay valid. Attribute values are never touched
// (positions are the caller's job). With set_indices = false only the
// topology changes: new darts have no index and no line is released.
// Preconditions that a user can violate have a `can_*` predicate and are
// asserted in debug builds.

// ---- edges

/// Inserts a vertex in the middle of edge e. The half containing e.dart keeps
/// the edge's line; the other half gets a new one. Returns the new vertex,
/// whose dart goes from it to the end of e.dart. O(1).
CMap2::Vertex cut_edge(CMap2& m, CMap2::Edge e, bool set_indices = true);

/// True when edge e can be contracted without breaking the manifold: the link
/// condition (the vertices adjacent to both ends are exactly the opposite
/// vertices of the triangles incident to e, counting the outside of a
/// boundary as a vertex), the two incident faces are distinct with at least 3
/// edges, and two incident triangles do not have the same opposite vertex.
/// Pure topology. O(degree of the two vertices).
bool edge_can_collapse(const CMap2& m, CMap2::Edge e);

/// Contracts edge e: the origin of e.dart disappears, the other end survives
/// with its line. Incident triangles degenerate and are removed: their two
/// other edges merge into the one whose lower dart is lower, which survives
/// whole (both darts, its line) while the other edge's darts and line go;
/// the face next to the triangle that receives a dart of it keeps the lower
/// of its line and the triangle's. Older darts and lines thus survive: the
/// collapse of a vertex added by triangulate_face in a triangle gives back
/// exactly the darts, relations and lines the split found. Dart handles to
/// the edges around the vanished triangles may be invalidated (check with
/// is_dart_valid). Returns the surviving vertex.
/// Precondition: edge_can_collapse(m, e).
/// O(degree of the two vertices + degree of the faces around the triangles).
CMap2::Vertex collapse_edge(CMap2& m, CMap2::Edge e, bool set_indices = true);

/// True when edge e can be flipped: both sides are non-boundary faces with at
/// least 3 edges, distinct, both end vertices have degree >= 3, and the new
/// edge's end vertices are distinct and not already adjacent. When vertices
/// are indexed, the lines of one new end's neighbours are compared with the
/// other end's: O(degree of that end); darts left without a line by an
/// operator called with set_indices = false make it fall back to the
/// topology, lines changed behind the library's back are caught by an
/// assertion in debug builds. Otherwise O(degree of both new ends) with a
/// dart mark.
bool edge_can_flip(const CMap2& m, CMap2::Edge e);

/// Rotates edge e forward inside its two faces: each end moves to the next
/// vertex of its face (in a triangle pair: the classic flip). Faces keep
/// their lines. Precondition: edge_can_flip(m, e). O(degree of the faces).
void flip_edge(CMap2& m, CMap2::Edge e, bool set_indices = true);

/// The inverse of flip_edge: each end moves to the previous vertex of its
/// face. Same preconditions. O(degree of the faces).
void flip_back_edge(CMap2& m, CMap2::Edge e, bool set_indices = true);

// ---- faces

/// True when v1.dart and v2.dart are distinct, non-consecutive darts of the
/// same non-boundary face (so that both parts have at least 3 edges).
/// O(degree of the face).
bool can_cut_face(const CMap2& m, CMap2::Vertex v1, CMap2::Vertex v2);

/// Cuts the face of v1.dart and v2.dart by a new edge between their origins.
/// The part containing v1.dart keeps the face's line. Returns the new edge,
/// whose dart goes from the origin of v1.dart to the origin of v2.dart and
/// lies in the new face. Precondition: can_cut_face(m, v1, v2). O(degree).
CMap2::Edge cut_face(CMap2& m, CMap2::Vertex v1, CMap2::Vertex v2, bool set_indices = true);

/// True when edge e separates two distinct non-boundary faces. O(degree).
bool can_merge_incident_faces(const CMap2& m, CMap2::Edge e);

/// Removes edge e, merging its two faces into one that keeps the line of the
/// face of e.dart. Returns the merged face. Precondition:
/// can_merge_incident_faces(m, e). O(degree of the faces).
CMap2::Face merge_incident_faces(CMap2& m, CMap2::Edge e, bool set_indices = true);

/// True when v is an interior vertex of degree >= 2 whose incident faces are
/// pairwise distinct and have at least 3 edges. O(degree).
bool can_merge_incident_faces(const CMap2& m, CMap2::Vertex v);

/// Removes vertex v and its edges, merging its incident faces into one (the
/// inverse of triangulate_face). Returns the merged face, which keeps the line
/// of the face of v.dart. Precondition: can_merge_incident_faces(m, v).
/// O(sum of the degrees of the faces).
CMap2::Face merge_incident_faces(CMap2& m, CMap2::Vertex v, bool set_indices = true);

/// True when v has degree 2, its two edges are distinct and its two faces have
/// at least 4 edges (so that no face is left with fewer than 3). O(1).
bool can_merge_incident_edges(const CMap2& m, CMap2::Vertex v);

/// Removes vertex v of degree 2, merging its two edges into one (the inverse
/// of cut_edge); the merged edge keeps the line of the edge of
/// phi2(v.dart)... i.e. of the edge that does not contain v.dart. Returns it.
/// Precondition: can_merge_incident_edges(m, v). O(degree of the faces).
CMap2::Edge merge_incident_edges(CMap2& m, CMap2::Vertex v, bool set_indices = true);

/// Splits the vertex of d1 and d2 (two distinct darts of one vertex) by a new
/// edge: the darts from d1 up to (not including) d2 in the vertex's cyclic
/// order go to a new vertex. The new edge lies in the faces of d1 and d2.
/// Returns it, its dart going from the old vertex to the new one. O(degree).
CMap2::Edge split_vertex(CMap2& m, Dart d1, Dart d2, bool set_indices = true);

/// Splits face f into a fan of triangles around a new vertex (one triangle per
/// edge); the triangle on f.dart keeps the face's line. Returns the new vertex.
/// Precondition: f is not a boundary face. O(degree of f).
CMap2::Vertex triangulate_face(CMap2& m, CMap2::Face f, bool set_indices = true);

/// Removes face f, which becomes part of the boundary: edges whose other side
/// is already boundary disappear, as do vertices left without edges and the
/// connected component if nothing remains of it. O(degree of f x degree).
void remove_face(CMap2& m, CMap2::Face f, bool set_indices = true);

// ---- holes and boundary

/// Closes the hole along d, a phi2 fixed point left by low-level sewing, with a
/// new face (boundary by default, else a real face); returns it. O(size of the hole).
CMap2::Face close_hole(CMap2& m, Dart d, bool mark_boundary = true, bool set_indices = true);

/// Closes every hole left by low-level sewing (phi2 fixed points) with
/// boundary faces; returns how many. O(number of darts).
uint32 close(CMap2& m, bool set_indices = true);

/// Turns the boundary face of dart d into a real face (fills the hole with one
/// polygon) and returns it. Precondition: is_boundary(m, d). O(size of the hole).
CMap2::Face fill_hole(CMap2& m, Dart d, bool set_indices = true);

/// True when e1.dart and e2.dart are non-boundary darts whose phi2 are
/// boundary darts, of distinct edges. O(1).
bool can_sew_faces(const CMap2& m, CMap2::Edge e1, CMap2::Edge e2);

/// Glues two boundary edges: e1.dart and e2.dart become phi2 of each other
/// (their boundary darts are removed). Vertices brought together merge,
/// keeping the lines of e1's end vertices; e1's edge line is kept. O(degree).
/// Precondition: can_sew_faces(m, e1, e2).
void sew_faces(CMap2& m, CMap2::Edge e1, CMap2::Edge e2, bool set_indices = true);

/// Cuts an interior edge into two boundary edges (the inverse of sew_faces):
/// end vertices already on the boundary split in two. e.dart keeps the edge's
/// line. Precondition: !is_incident_to_boundary(m, e). O(degree).
void unsew_faces(CMap2& m, CMap2::Edge e, bool set_indices = true);

// ---- volumes (closed surfaces)

/// A closed pyramid surface: an n-gon base and n triangles. Returns it. O(n).
CMap2::Volume add_pyramid(CMap2& m, uint32 n, bool set_indices = true);
/// A closed prism surface: two n-gons and n quads. Returns it. O(n).
CMap2::Volume add_prism(CMap2& m, uint32 n, bool set_indices = true);
/// A closed tetrahedron surface (pyramid on a triangle). O(1).
CMap2::Volume add_tetra(CMap2& m, bool set_indices = true);
/// A closed hexahedron surface (prism on a quad). O(1).
CMap2::Volume add_hexa(CMap2& m, bool set_indices = true);

/// Removes a connected component and releases the lines of all its cells.
/// O(size of the component).
void remove_volume(CMap2& m, CMap2::Volume w);

/// Reverses the orientation of every face of the map (phi1 becomes phi_1);
/// vertex indices move with the darts' origins. O(number of darts).
void reverse_orientation(CMap2& m);

/// Copies every cell of `other` into m (appending, other is unchanged), with
/// the values of every attribute of other: attributes of the same name and
/// type in m receive them, missing ones are created. Returns, for each dart
/// of other, its copy in m (indexed by dart index; invalid for free lines).
/// O(size of other).
std::vector<Dart> merge(CMap2& m, const CMap2& other);

} // namespace cgogn
