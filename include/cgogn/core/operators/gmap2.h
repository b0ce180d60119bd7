// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap2.h>
#include <cgogn/core/operators/gmap1.h>

#include <vector>

namespace cgogn
{

// Operators of 2-G-maps, with the names and contracts of the CMap2 ones
// (operators/cmap2.h): the map stays closed and, with set_indices (the
// default), every indexed orbit stays indexed (a split cell keeps its line
// on the part containing the given dart, new cells get new lines, removed
// cells release theirs). They work on orientable and non-orientable maps
// alike. Costs are independent of the size of the map, except where said
// (close, and sew / unsew with components indexed).
// Darts are named as in the README's G-map section: a dart sits at one
// vertex of one edge of one face, and its edge "goes" from that vertex to
// the one of beta0(dart); the operators that need a direction (flip) take
// it from the given dart.

// ---- edges

/// Inserts a vertex in the middle of edge e: beta0 of each dart of e at the
/// vertex of e.dart moves to the new vertex, and a new pair of darts takes
/// its place at the other end (see docs/gmaps.md, the model). The half
/// containing e.dart keeps the edge's line. Returns the new vertex, whose dart lies in the
/// face of e.dart, on the half that does not contain e.dart. O(1).
GMap2::Vertex cut_edge(GMap2& m, GMap2::Edge e, bool set_indices = true);

/// True when edge e can be contracted without breaking the manifold, with
/// the conditions of the CMap2 can_collapse_edge: e is not a loop, its two
/// faces are distinct with at least 3 edges, two incident triangles do not
/// have the same opposite vertex, two boundary vertices are not pinched
/// together, and the link condition holds (the outside of a boundary
/// counting as a vertex). O(sum of the degrees of the two ends and of their
/// neighbours), with dart marks.
bool can_collapse_edge(const GMap2& m, GMap2::Edge e);

/// Contracts edge e: the vertex of e.dart disappears, the other end survives
/// with its line. Incident faces reduced to 2 edges are removed, their two
/// edges becoming one, which keeps the line of the edge at the surviving
/// vertex. Returns the surviving vertex. Precondition: can_collapse_edge(m,
/// e). O(degree of the two vertices + degree of the faces around them).
GMap2::Vertex collapse_edge(GMap2& m, GMap2::Edge e, bool set_indices = true);

/// True when edge e can be flipped: both sides are distinct non-boundary
/// faces with at least 3 edges, both end vertices have degree >= 3, and the
/// new ends (see flip_edge) are distinct and not already adjacent.
/// O(degree of the new ends).
bool can_flip_edge(const GMap2& m, GMap2::Edge e);

/// Rotates edge e inside its two faces, in the direction of e.dart: the end
/// of beta0(e.dart) moves to the next vertex of e.dart's face, the end of
/// e.dart to the next vertex of the other face (in a triangle pair: the
/// classic flip). e.dart stays in its face, now at the new end that came
/// from the other face. Faces and vertices keep their lines.
/// Precondition: can_flip_edge(m, e). O(1).
void flip_edge(GMap2& m, GMap2::Edge e, bool set_indices = true);

/// True when edge e can be flipped back: can_flip_edge of the edge seen from
/// beta0(e.dart) (the opposite direction). Same cost.
bool can_flip_back_edge(const GMap2& m, GMap2::Edge e);

/// The inverse of flip_edge(m, e): flip_edge of the edge seen from
/// beta0(e.dart). Precondition: can_flip_back_edge(m, e). O(1).
void flip_back_edge(GMap2& m, GMap2::Edge e, bool set_indices = true);

// ---- faces

/// Creates an isolated polygon of n edges (2n darts), closed by a boundary
/// face, and returns the (non-boundary) face. With set_indices, its cells get
/// new lines. Precondition: n >= 1 (1 or 2 edges are the degenerate faces of
/// the CMap2 add_face). O(n).
GMap2::Face add_face(GMap2& m, uint32 n, bool set_indices = true);

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

/// Splits face f into a fan of triangles around a new vertex (one triangle
/// per edge); the triangle on f.dart keeps the face's line. Returns the new
/// vertex. Precondition: f is not a boundary face. O(sum of the degrees of
/// the vertices of f).
GMap2::Vertex triangulate_face(GMap2& m, GMap2::Face f, bool set_indices = true);

// ---- holes and boundary

/// Closes the hole along d, a beta2 fixed point left by low-level sewing
/// (beta_sew), with a new face: boundary by default, else a real face with
/// a new line. Returns it. The new darts take the vertex, edge and component
/// lines of their beta2 neighbours. O(size of the hole x degree of its
/// vertices).
GMap2::Face close_hole(GMap2& m, Dart d, bool mark_boundary = true, bool set_indices = true);

/// Closes every hole left by low-level sewing (beta2 fixed points) with
/// boundary faces; returns how many. O(number of darts).
uint32 close(GMap2& m, bool set_indices = true);

/// True when d is a boundary dart of a hole of at least 3 edges. O(1).
bool can_fill_hole_with_face(const GMap2& m, Dart d);

/// Turns the boundary face of d into a real face with a new line and returns
/// it. Precondition: can_fill_hole_with_face(m, d). O(size of the hole).
GMap2::Face fill_hole_with_face(GMap2& m, Dart d, bool set_indices = true);

/// True when e1.dart and e2.dart are non-boundary darts of distinct edges
/// that both border a boundary face. O(1).
bool can_sew_faces(const GMap2& m, GMap2::Edge e1, GMap2::Edge e2);

/// Glues two boundary edges: e1.dart and e2.dart become beta2 of each other
/// (so do their beta0), the vertex of e1.dart meeting the vertex of e2.dart.
/// Unlike the CMap2 sew_faces, either way round is allowed: a twisted sew
/// makes a surface non-orientable. The boundary darts of both edges are
/// removed and the boundary faces they were in merge or split. Lines: e1's
/// edge line is kept, e2's released; merged vertices keep the line of
/// e1.dart's side; merged components keep e1's line; a vertex that comes
/// apart at a pinched vertex keeps its line on the part of e1.dart, a
/// component that comes apart on its larger part, the others get new ones.
/// Precondition: can_sew_faces(m, e1, e2). O(degree of the end vertices);
/// with components indexed, plus the size of the merged component when two
/// components merge (walked whole), or of the smaller part when one comes
/// apart.
void sew_faces(GMap2& m, GMap2::Edge e1, GMap2::Edge e2, bool set_indices = true);

/// True when e is an interior edge that is not a loop at a boundary vertex.
/// O(degree of its ends).
bool can_unsew_faces(const GMap2& m, GMap2::Edge e);

/// Cuts an interior edge into two boundary edges (the inverse of sew_faces):
/// end vertices already on the boundary split in two, the part of e.dart
/// keeping the line. The side of e.dart keeps the edge's line, the other
/// gets a new one; a component cut in two keeps its line on the larger
/// part, the smaller one gets a new line. Precondition: can_unsew_faces(m,
/// e). O(degree of its ends); with components indexed, plus the darts met
/// while telling the parts apart.
void unsew_faces(GMap2& m, GMap2::Edge e, bool set_indices = true);

} // namespace cgogn
