// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>

#include <vector>

namespace cgogn
{

// Operators of 3-maps. Each keeps the map closed (the outside is made of
// boundary volumes) and, with set_indices (the default), every indexed orbit
// correctly indexed: cells of the changed region claim back their lines (a
// split cell keeps its line on the part containing the given dart; a split
// connected component, on its larger part), new cells get new lines, lines of
// vanished cells are released. Attribute values are never touched. With
// set_indices = false only the topology changes. The reindexing walks the
// cells the operator touched, never the boundary volume beside them, nor the
// connected component unless it comes apart or two of them merge. Cells the
// operator does not touch keep their lines. Every operator drops the map's
// incidence caches (any change of a relation, a boundary mark or the set of
// darts does). Each operator below says which lines survive and which cells
// are new.
//
// A pinched edge is an edge whose volumes form several fans joined through
// the boundary (remove_volume leaves them); a pinched vertex, likewise.

// ---- creation

/// A tetrahedron (with its boundary volume), a new connected component whose
/// cells all get new lines. Returns it. O(1).
CMap3::Volume add_tetra(CMap3& m, bool set_indices = true);
/// A pyramid on an n-gon (n >= 3), with its boundary volume. O(n).
CMap3::Volume add_pyramid(CMap3& m, uint32 n, bool set_indices = true);
/// A prism on an n-gon (n >= 3), with its boundary volume. O(n).
CMap3::Volume add_prism(CMap3& m, uint32 n, bool set_indices = true);
/// A hexahedron (prism on a quad), with its boundary volume. O(1).
CMap3::Volume add_hexa(CMap3& m, bool set_indices = true);

/// Closes every hole left by low-level phi3 sewing (phi3 fixed points) with
/// boundary faces, sewn into boundary volumes; returns the number of boundary
/// volumes they belong to. The faces closed keep their lines. O(darts).
uint32 close(CMap3& m, bool set_indices = true);

/// Closes the hole of d (a phi3 fixed point): the free faces connected to it
/// around edges get boundary faces; returns the boundary volume. O(hole size).
CMap3::Volume close_hole(CMap3& m, Dart d, bool set_indices = true);

/// True when f1 and f2 are boundary faces (their phi3 side is boundary) of the
/// same degree, in distinct faces. O(degree).
bool can_sew_volumes(const CMap3& m, CMap3::Face f1, CMap3::Face f2);
/// Glues two volumes along boundary faces: phi3(f1.dart) becomes f2.dart (f2
/// is walked in the opposite direction). The boundary faces in between
/// disappear; the cells brought together merge and keep the lines of f1's
/// side (its face, edges and vertices; the component of f1 when two join),
/// the others are released. Boundary darts beside the vanishing faces are
/// joined to the darts their edges lead to across them; where that was the
/// only link between two parts of a pinched edge, the edge (and the
/// component) comes apart as unsew_volumes describes. Precondition:
/// can_sew_volumes(m, f1, f2). O(degree x sizes of the merged cells); with
/// connected components indexed and two components joined, plus the size of
/// the merged component (walked to give it one line).
void sew_volumes(CMap3& m, CMap3::Face f1, CMap3::Face f2, bool set_indices = true);

/// Separates the two volumes of face f: f.dart's side keeps the face's line,
/// the other side gets a new one; each side gets a boundary face. Edges and
/// vertices that no longer connect the two sides split in two (new lines for
/// the parts without f.dart). At a pinched edge the fan of the cut face splits
/// into edges of their own and the other fans stay one edge. A connected
/// component cut in two keeps its line on the larger part, the smaller gets a
/// new one. Volumes keep their lines. Precondition: f is an
/// inner face (both sides non-boundary). O(degree of f x size of the cells
/// around it); with components indexed, plus the darts met while telling the
/// sides apart (a few when they still meet around f, else the smaller part).
void unsew_volumes(CMap3& m, CMap3::Face f, bool set_indices = true);

/// Removes volume w: its faces shared with other volumes become boundary and
/// keep their lines, the rest disappears with the cells left without darts
/// (their lines released); every other cell keeps its line. A connected
/// component that comes apart keeps its line on one part (the larger when
/// two are compared), the others get new lines. O(size of w); with components
/// indexed, plus the darts met while telling the parts apart (a few when they
/// still meet around w, else the smaller parts, walked whole).
void remove_volume(CMap3& m, CMap3::Volume w, bool set_indices = true);

// ---- cuts and merges

/// Inserts a vertex in the middle of edge e (in every face around it). The
/// half holding e.dart keeps the edge's line; the new vertex and the other
/// half get new lines; faces and volumes keep theirs. Returns the new vertex
/// (its dart goes from it to the end of e.dart). O(degree of e).
CMap3::Vertex cut_edge(CMap3& m, CMap3::Edge e, bool set_indices = true);

/// True when d and e are distinct, non-consecutive darts of one face of a
/// volume (the face may be on the boundary of the mesh). O(degree).
bool can_cut_face(const CMap3& m, Dart d, Dart e);
/// Cuts the face of d and e by a new edge between their origins (on both
/// sides of the face). The part containing d keeps the face's line; the other
/// part and the new edge get new lines; vertices and volumes keep theirs.
/// Returns the new edge (its dart goes from the origin of d to the origin of
/// e). O(degree of the face).
CMap3::Edge cut_face(CMap3& m, Dart d, Dart e, bool set_indices = true);

/// True when `path` is a closed chain of at least 3 darts of one non-boundary
/// volume (each dart starts, in that volume, at the vertex where the previous
/// one ends) through distinct vertices of the volume. O(sum of the degrees of
/// those vertices in the volume).
bool can_cut_volume(const CMap3& m, const std::vector<Dart>& path);
/// Cuts the volume of the darts of `path` by a new face of path.size() edges,
/// inserted along the path. The part on the path side keeps the volume's line,
/// the part on the phi2 side gets a new one; a path around one face makes a
/// volume of two faces. When the path does not separate the volume (around a
/// handle), the volume stays one, glued to itself along the new face, and keeps
/// its line. Vertices and edges keep their lines; the new face gets a new one.
/// Returns the new face (its dart is phi2 of path[0]). Precondition:
/// can_cut_volume(m, path). O(size of the path).
CMap3::Face cut_volume(CMap3& m, const std::vector<Dart>& path, bool set_indices = true);

/// True when the face separates two distinct non-boundary volumes and is not
/// glued to itself along one of its edges. O(degree of f squared).
bool can_merge_incident_volumes(const CMap3& m, CMap3::Face f);
/// Removes face f, merging its two volumes into one, which keeps the line of
/// the volume of f.dart; the other volume's and the face's lines are
/// released; edges and vertices keep theirs. Returns it. O(degree of f).
CMap3::Volume merge_incident_volumes(CMap3& m, CMap3::Face f, bool set_indices = true);

/// True when edge e has exactly two incident faces, distinct, each of at least
/// 3 edges, so that it can be removed by merging them. O(degree of the faces).
bool can_merge_incident_faces(const CMap3& m, CMap3::Edge e);
/// Removes edge e, merging its two incident faces into one, which keeps the
/// line of the face of e.dart; the other face's and the edge's lines are
/// released; vertices and volumes keep theirs. Returns it. O(degree of e).
CMap3::Face merge_incident_faces(CMap3& m, CMap3::Edge e, bool set_indices = true);

// ---- tetrahedral meshes

/// Splits tetrahedron w into 4 tetrahedra around a new vertex (1-to-4).
/// Returns the new vertex; its dart goes from the new vertex to the origin of
/// w.dart, in the new tet that holds w.dart (which keeps w's volume line; the
/// other cells of w keep theirs, see the note at the top). Throws
/// TopologyError (map unchanged) when w is not a tetrahedron or is a boundary
/// volume. O(1): 36 new darts, no allocation beyond the containers' growth.
CMap3::Vertex split_tetra(CMap3& m, CMap3::Volume w, bool set_indices = true);

/// True when edge e of a tetrahedral region can be contracted: every volume
/// around its ends is a tetrahedron with four distinct corner vertices, no two
/// of them with the same corners and no two faces at an end with the same
/// corners (the two sides of an unsewn face); the link of each end is a sphere
/// or a disk (no pinched vertex or edge); and the link condition holds (the
/// common vertices, edges and triangles of the links of its two ends are
/// exactly those of the link of e, the outside counting as a vertex). Pure
/// topology. O(size of the stars of the two ends).
bool can_collapse_edge(const CMap3& m, CMap3::Edge e);
/// Contracts edge e: the origin of e.dart disappears, the other end survives
/// with its line; the tetrahedra around e vanish, the others around the
/// removed vertex are rebuilt on the survivor with new volume, inner face and
/// inner edge lines (the replaced ones are released); the faces, edges and
/// vertices around the star keep theirs. Returns the surviving vertex.
/// Precondition: can_collapse_edge(m, e). O(size of the star of the origin).
CMap3::Vertex collapse_edge(CMap3& m, CMap3::Edge e, bool set_indices = true);

/// True when the face between two tetrahedra can be flipped 2-3: both sides
/// are tetrahedra (not boundary), their five corners are distinct vertices and
/// their apexes are not already joined by an edge. O(size of the five vertices).
bool can_flip_face(const CMap3& m, CMap3::Face f);
/// 2-3 flip: the two tetrahedra of face f become three around the edge joining
/// their apexes. The new tets, faces and edge inside get new lines and the
/// replaced ones are released; vertices and the six outer faces (with their
/// edges) keep theirs. Returns the new edge. Precondition: can_flip_face(m, f).
CMap3::Edge flip_face(CMap3& m, CMap3::Face f, bool set_indices = true);

/// True when edge e is an interior edge of 3 or 4 tetrahedra that can be
/// flipped: its ends and the vertices around it are distinct, and 3-2 (its 3
/// surrounding vertices do not form a face already) or 4-4 (the diagonal
/// through the origin of the edge's ring is not an edge already).
bool can_flip_edge(const CMap3& m, CMap3::Edge e);
/// 3-2 flip (degree 3: the three tetrahedra become two on the surrounding
/// triangle) or 4-4 flip (degree 4: the four tetrahedra become four around the
/// diagonal of the surrounding quad that starts at the third vertex of the
/// face of e.dart). As for flip_face, the cells inside get new lines and the
/// replaced ones are released; the vertices and the outer faces keep theirs.
/// Returns a dart of the new face (3-2) or of the new edge (4-4).
/// Precondition: can_flip_edge(m, e). O(1).
Dart flip_edge(CMap3& m, CMap3::Edge e, bool set_indices = true);

// ---- former names, kept for one release

/// \deprecated Use can_collapse_edge.
[[deprecated("use can_collapse_edge")]] inline bool edge_can_collapse(const CMap3& m, CMap3::Edge e)
{
	return can_collapse_edge(m, e);
}
/// \deprecated Use can_flip_face.
[[deprecated("use can_flip_face")]] inline bool face_can_flip(const CMap3& m, CMap3::Face f)
{
	return can_flip_face(m, f);
}
/// \deprecated Use can_flip_edge.
[[deprecated("use can_flip_edge")]] inline bool edge_can_flip(const CMap3& m, CMap3::Edge e)
{
	return can_flip_edge(m, e);
}

} // namespace cgogn
