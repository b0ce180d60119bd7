// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/operators/gmap2.h>

#include <vector>

namespace cgogn
{

// Operators of 3-G-maps, with the names and contracts of the CMap3 ones
// (operators/cmap3.h): the map stays closed (the outside is made of boundary
// volumes) and, with set_indices (the default), every indexed orbit stays
// indexed: a split cell keeps its line on the part containing the given
// dart, new cells get new lines, removed cells release theirs, and cells the
// operator does not touch keep their lines. They work on orientable and
// non-orientable maps alike, and cost O(size of the cells they touch),
// whatever the size of the map (with connected components indexed, sewing
// two components walks the smaller one, as for the CMap3).
//
// A dart sits at one vertex of one edge of one face of one volume. Where the
// CMap3 speaks of "the origin of d", read "the vertex of d"; "the end of d"
// is the vertex of beta0(d).

// ---- cuts and merges

/// Inserts a vertex in the middle of edge e: beta0(x) of every dart x of the
/// edge at the vertex of e.dart moves to the new vertex, and a new pair of
/// darts takes its place at the other end. The half holding e.dart keeps the
/// edge's line; the new vertex and the other half get new lines; faces and
/// volumes keep theirs. Returns the new vertex; its dart lies in the face
/// and volume of e.dart, on the half that goes to the end of e.dart.
/// O(number of darts of e).
GMap3::Vertex cut_edge(GMap3& m, GMap3::Edge e, bool set_indices = true);

/// True when d and e are darts of one side of a face (one Face2 orbit) at two
/// distinct corners of it that no edge of the face joins. The face may lie on
/// the boundary of the mesh. O(degree of the face).
bool can_cut_face(const GMap3& m, Dart d, Dart e);
/// Cuts the face of d and e by a new edge between their vertices, on both of
/// its sides. The part containing d keeps the face's line; the other part and
/// the new edge get new lines; vertices and volumes keep theirs. Returns the
/// new edge; its dart lies at the vertex of d, in the part of d.
/// Precondition: can_cut_face(m, d, e). O(degree of the face).
GMap3::Edge cut_face(GMap3& m, Dart d, Dart e, bool set_indices = true);

/// True when edge e has exactly two incident faces, distinct, each of at least
/// 3 edges, so that it can be removed by merging them. O(1).
bool can_merge_incident_faces(const GMap3& m, GMap3::Edge e);
/// Removes edge e, merging its two incident faces into one, which keeps the
/// line of the face of e.dart; the other face's and the edge's lines are
/// released; vertices and volumes keep theirs. Returns the merged face.
/// Precondition: can_merge_incident_faces(m, e). O(1): the edge has 8 darts.
GMap3::Face merge_incident_faces(GMap3& m, GMap3::Edge e, bool set_indices = true);

/// True when `path` is a closed chain of at least 3 darts of one non-boundary
/// volume through distinct vertices of it, each dart starting, in that
/// volume, at the vertex where the previous one ends (the vertex of
/// beta0(previous)), on the same side of the chain: walking around that
/// vertex in the volume from beta0(previous) by beta1 then beta2 alternately,
/// the dart is met after a beta1 step, before its beta2 is. O(sum of the
/// degrees of the path's vertices in the volume).
bool can_cut_volume(const GMap3& m, const std::vector<Dart>& path);
/// Cuts the volume of `path` by a new face of path.size() edges inserted
/// along it. The part on the side of the path's darts keeps the volume's
/// line; the part on their beta2 side gets a new one. When the path does not
/// separate the volume (around a handle), it stays one volume, glued to
/// itself along the new face, and keeps its line. Vertices and edges keep
/// their lines; the new face gets a new one. Returns the new face; its dart
/// is beta2 of path[0]. Precondition: can_cut_volume(m, path).
/// O(size of the path).
GMap3::Face cut_volume(GMap3& m, const std::vector<Dart>& path, bool set_indices = true);

/// True when the face separates two distinct non-boundary volumes, is not
/// glued to itself along one of its edges, and no edge of f has a single
/// other face around it (the two volumes sharing that face too: removing f
/// would glue it to itself). O(degree of f + sizes of the faces beside f).
bool can_merge_incident_volumes(const GMap3& m, GMap3::Face f);
/// Removes face f, merging its two volumes into one, which keeps the line of
/// the volume of f.dart; the other volume's and the face's lines are
/// released; edges and vertices keep theirs. Returns the merged volume.
/// Precondition: can_merge_incident_volumes(m, f). O(degree of f).
GMap3::Volume merge_incident_volumes(GMap3& m, GMap3::Face f, bool set_indices = true);

// ---- sewing

/// True when f1.dart and f2.dart are non-boundary darts whose faces lie on
/// the boundary of the mesh (their beta3 side is a boundary volume), in
/// distinct faces of the same degree. O(degree).
bool can_sew_volumes(const GMap3& m, GMap3::Face f1, GMap3::Face f2);
/// Glues two volumes along boundary faces: the vertex of f1.dart meets the
/// vertex of f2.dart and the edge of f1.dart the edge of f2.dart, either way
/// round (beta3 joins the darts met walking both faces by beta0 and beta1 in
/// step). The boundary faces in between disappear; the cells brought
/// together merge and keep the lines of f1's side (the component of f1 when
/// two join), the others are released. Boundary darts beside the vanishing
/// faces are joined to the darts their edges lead to across them.
/// Precondition: can_sew_volumes(m, f1, f2). O(degree x sizes of the merged
/// cells); with connected components indexed and two components joined, plus
/// the size of the merged component.
void sew_volumes(GMap3& m, GMap3::Face f1, GMap3::Face f2, bool set_indices = true);

/// True when f separates two non-boundary volumes. O(1).
bool can_unsew_volumes(const GMap3& m, GMap3::Face f);
/// Separates the two volumes of face f: each side gets a boundary face.
/// f.dart's side keeps the face's line, the other side gets a new one. Edges
/// and vertices that no longer connect the two sides split in two (new lines
/// for the parts without f.dart); a connected component cut in two keeps its
/// line on the larger part. Volumes keep their lines. Precondition:
/// can_unsew_volumes(m, f). O(degree of f x degree of its edges); with
/// components indexed, plus the darts met while telling the sides apart.
void unsew_volumes(GMap3& m, GMap3::Face f, bool set_indices = true);

// ---- tetrahedral meshes

/// True when edge e of a tetrahedral region can be contracted, with the
/// conditions of the CMap3 can_collapse_edge (equal answers on the same
/// mesh): every volume around its ends is a tetrahedron with four distinct
/// corners, no two with the same corners; the link of each end is a sphere
/// or a disk; and the link condition holds. O(size of the stars of the two
/// ends).
bool can_collapse_edge(const GMap3& m, GMap3::Edge e);
/// Contracts edge e: the vertex of e.dart merges into the vertex of
/// beta0(e.dart), which keeps its line. Each triangle around e flattens, its
/// two other edges becoming one; each tetrahedron around e flattens, its two
/// other faces becoming one; the merged edge and face keep the lines of their
/// parts at the surviving vertex, the vanished cells release theirs, every
/// other cell keeps its line. Returns the surviving vertex.
/// Precondition: can_collapse_edge(m, e). O(size of the stars of the two
/// ends).
GMap3::Vertex collapse_edge(GMap3& m, GMap3::Edge e, bool set_indices = true);

} // namespace cgogn
