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

/// True when edge e can be contracted without breaking the manifold: e is not
/// a loop (its ends are distinct vertices), the link
/// condition (the vertices adjacent to both ends are exactly the opposite
/// vertices of the triangles incident to e, counting the outside of a
/// boundary as a vertex), its edge part for the outside (no vertex is joined
/// to both ends by boundary edges), the two incident faces are distinct with
/// at least 3 edges, and two incident triangles do not have the same opposite
/// vertex.
/// Pure topology. O(degree of the two vertices).
bool can_collapse_edge(const CMap2& m, CMap2::Edge e);

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
/// Precondition: can_collapse_edge(m, e).
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
bool can_flip_edge(const CMap2& m, CMap2::Edge e);

/// Rotates edge e forward inside its two faces: each end moves to the next
/// vertex of its face (in a triangle pair: the classic flip). Faces keep
/// their lines. Precondition: can_flip_edge(m, e). O(degree of the faces).
void flip_edge(CMap2& m, CMap2::Edge e, bool set_indices = true);

/// True when edge e can be flipped back: the conditions of can_flip_edge on
/// the faces and end vertices, and the new edge's ends (the origins of
/// phi_1(e.dart) and phi_1(phi2(e.dart)), not the forward flip's unless both
/// faces are triangles) distinct and not already adjacent. Same cost as
/// can_flip_edge.
bool can_flip_back_edge(const CMap2& m, CMap2::Edge e);

/// The inverse of flip_edge: each end moves to the previous vertex of its
/// face. Faces keep their lines. Precondition: can_flip_back_edge(m, e).
/// O(degree of the faces).
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
/// pairwise distinct and have at least 3 edges, and the merged face would have
/// at least 3 edges (two triangles around a vertex of degree 2 would make a
/// face of 2). O(sum of the degrees of the faces).
bool can_merge_incident_faces(const CMap2& m, CMap2::Vertex v);

/// Removes vertex v and its edges, merging its incident faces into one (the
/// inverse of triangulate_face). Returns the merged face, which keeps the line
/// of the face of v.dart. Precondition: can_merge_incident_faces(m, v).
/// O(sum of the degrees of the faces).
CMap2::Face merge_incident_faces(CMap2& m, CMap2::Vertex v, bool set_indices = true);

/// True when v has degree 2, its two edges are distinct and no face is left
/// with fewer than 3 edges: its two faces have at least 4 edges, or 5 when
/// they are one face (v on a path dangling inside it, which loses 2 edges).
/// O(degree of the smaller face).
bool can_merge_incident_edges(const CMap2& m, CMap2::Vertex v);

/// Removes vertex v of degree 2, merging its two edges into one (the inverse
/// of cut_edge). Lines: the merged edge keeps the line of the edge that does
/// not contain v.dart, the other edge's line and v's are released; faces and
/// the component keep theirs. Incidence caches are dropped. Returns the merged
/// edge. Precondition: can_merge_incident_edges(m, v). O(degree of the faces).
CMap2::Edge merge_incident_edges(CMap2& m, CMap2::Vertex v, bool set_indices = true);

/// True when d1 and d2 are distinct darts of one vertex, not both boundary
/// darts (the new edge of split_vertex lies in their faces: two boundary
/// faces would put the boundary on both its sides). O(degree).
bool can_split_vertex(const CMap2& m, Dart d1, Dart d2);

/// Splits the vertex of d1 and d2 by a new edge: the darts from d1 up to (not
/// including) d2 in the vertex's cyclic order go to a new vertex, which gets
/// a new line; the old vertex keeps its line on the part holding d2. The new
/// edge lies in the faces of d1 and d2 and gets a new line; faces and the
/// component keep theirs. Incidence caches are dropped. Returns the new edge,
/// its dart going from the old vertex to the new one.
/// Precondition: can_split_vertex(m, d1, d2). O(degree).
CMap2::Edge split_vertex(CMap2& m, Dart d1, Dart d2, bool set_indices = true);

/// Splits face f into a fan of triangles around a new vertex (one triangle per
/// edge); the triangle on f.dart keeps the face's line. Returns the new vertex.
/// Precondition: f is not a boundary face. O(degree of f).
CMap2::Vertex triangulate_face(CMap2& m, CMap2::Face f, bool set_indices = true);

/// Removes face f, which becomes part of the boundary: edges whose other side
/// is already boundary disappear, as do vertices left without edges and the
/// connected component if nothing remains of it. Lines: f's line is released,
/// as are the lines of the edges and vertices that disappear; a vertex or a
/// component that comes apart (at a pinched vertex) keeps its line on one
/// part, the other parts get new lines (when components are indexed, the
/// part kept is the one not walked whole: see below). Incidence caches are
/// dropped. Precondition: f is not a boundary face. O(degree of f x degree);
/// with components indexed, plus the darts met while telling the parts apart
/// (a few around f when they are still connected there, else the smaller
/// parts, walked whole).
void remove_face(CMap2& m, CMap2::Face f, bool set_indices = true);

// ---- holes and boundary

/// Closes the hole along d, a phi2 fixed point left by low-level sewing, with a
/// new face (boundary by default, else a real face); returns it. O(size of the hole).
CMap2::Face close_hole(CMap2& m, Dart d, bool mark_boundary = true, bool set_indices = true);

/// Closes every hole left by low-level sewing (phi2 fixed points) with
/// boundary faces; returns how many. O(number of darts).
uint32 close(CMap2& m, bool set_indices = true);

/// True when d is a boundary dart of a hole of at least 3 edges (a hole of 1
/// or 2 edges would become a face of 1 or 2 edges; sew its edges instead).
/// O(1).
bool can_fill_hole_with_face(const CMap2& m, Dart d);

/// Turns the boundary face of dart d into a real face (fills the hole with one
/// polygon) and returns it. The face gets a new line; no other line changes.
/// Incidence caches are dropped. Precondition: can_fill_hole_with_face(m, d).
/// O(size of the hole).
CMap2::Face fill_hole_with_face(CMap2& m, Dart d, bool set_indices = true);

/// True when e1.dart and e2.dart are non-boundary darts whose phi2 are
/// boundary darts, of distinct edges. O(1).
bool can_sew_faces(const CMap2& m, CMap2::Edge e1, CMap2::Edge e2);

/// Glues two boundary edges: e1.dart and e2.dart become phi2 of each other
/// (their boundary darts are removed, the boundary faces they were in merge or
/// split). Lines: e1's edge line is kept, e2's released. Vertices brought
/// together merge: the vertex of e1.dart keeps the line of the origin of
/// e1.dart, the vertex of e2.dart the line of the end of e1.dart (the other
/// end's line is released). At a pinched vertex the sew can instead cut a
/// vertex in two: the part without those darts keeps another line of the
/// vertex or gets a new one. Sewing two components keeps e1's component line
/// and releases e2's (e2's component is walked to take e1's line); a
/// component held together only through a pinched vertex can fall apart: one
/// part keeps the line, the others, walked whole, get new ones. Incidence
/// caches are dropped. O(degree of the end vertices) (the boundary faces,
/// holes as long as a border, are not walked); with components indexed,
/// plus the size of e2's component when two components merge, and the darts
/// met while telling parts apart.
/// Precondition: can_sew_faces(m, e1, e2).
void sew_faces(CMap2& m, CMap2::Edge e1, CMap2::Edge e2, bool set_indices = true);

/// True when e is an interior edge (no boundary on either side) that is not a
/// loop at a boundary vertex: there, both new boundary edges would enter the
/// same boundary corner. O(degree of its ends).
bool can_unsew_faces(const CMap2& m, CMap2::Edge e);

/// Cuts an interior edge into two boundary edges (the inverse of sew_faces):
/// end vertices already on the boundary split in two, the part without
/// e.dart (resp. its phi2) getting a new line. e.dart keeps the edge's line,
/// the other side gets a new one. A component cut in two keeps its line on
/// the larger part; the smaller one gets a new line. Incidence caches are
/// dropped. Precondition: can_unsew_faces(m, e). O(degree); with components
/// indexed, plus the darts met by walking both sides at once until they
/// meet (a few, around e's ends) or until the smaller part ends.
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
/// type in m receive them, missing ones are created; an orbit indexed in other
/// and not in m becomes indexed in m (its cells get lines). Returns, for each dart
/// of other, its copy in m (indexed by dart index; invalid for free lines).
/// O(size of other).
std::vector<Dart> merge(CMap2& m, const CMap2& other);

// ---- former names, kept for one release

/// \deprecated Use can_collapse_edge.
[[deprecated("use can_collapse_edge")]] inline bool edge_can_collapse(const CMap2& m, CMap2::Edge e)
{
	return can_collapse_edge(m, e);
}
/// \deprecated Use can_flip_edge.
[[deprecated("use can_flip_edge")]] inline bool edge_can_flip(const CMap2& m, CMap2::Edge e)
{
	return can_flip_edge(m, e);
}
/// \deprecated Use can_flip_back_edge.
[[deprecated("use can_flip_back_edge")]] inline bool edge_can_flip_back(const CMap2& m, CMap2::Edge e)
{
	return can_flip_back_edge(m, e);
}
/// \deprecated Use can_fill_hole_with_face.
[[deprecated("use can_fill_hole_with_face")]] inline bool can_fill_hole(const CMap2& m, Dart d)
{
	return can_fill_hole_with_face(m, d);
}
/// \deprecated Use fill_hole_with_face (modeling::fill_hole is the geometric hole filling).
[[deprecated("use fill_hole_with_face")]] inline CMap2::Face fill_hole(CMap2& m, Dart d, bool set_indices = true)
{
	return fill_hole_with_face(m, d, set_indices);
}

} // namespace cgogn
