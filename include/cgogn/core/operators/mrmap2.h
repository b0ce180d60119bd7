// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mrmap2.h>

namespace cgogn
{

/// Adds a level above the finest one by refining every face of the finest
/// level with pattern r: every edge is cut at its middle, and every face is
/// cut as r says. The new darts get the new level, the pieces of a cut edge
/// keep its edge id, and a new inner edge takes the smallest id in {0, 1, 2}
/// that differs from the ids of the edges whose midpoints it joins. Attributes
/// of the finest map follow its operators (cut_edge, cut_face: their rules
/// apply). The current level becomes the new finest level. Throws
/// std::invalid_argument, leaving m unchanged, when r is a 3-D pattern, when r
/// is Triangular and a face is not a triangle, or when the finest level is not
/// regular (a face of a coarser level is not refined). O(number of darts).
void add_level(MRMap2& m, Refinement r);

/// Removes the finest level: every dart of that level goes, the faces and
/// edges of the level below come back (the inverse of add_level). The current
/// level is clamped to the new finest level. Throws std::invalid_argument when
/// m has no level above 0. O(number of darts).
void remove_finest_level(MRMap2& m);

// ---- adaptive refinement: cells of different levels side by side

/// The level at which edge e, read at the level of v, was made: the level of
/// the younger of its two darts. O(1 level step).
uint32 edge_level(const MRLevelView2& v, MRMap2::Edge e);
/// The level at which face f, read at the level of v, was made (the second
/// smallest level of its darts: a face keeps a dart older than it, and the
/// midpoints its neighbours cut into its edges are younger). O(codegree).
uint32 face_level(const MRLevelView2& v, MRMap2::Face f);
/// Whether edge e, read at the level l of v, is cut at level l + 1. O(1 level step).
bool edge_is_subdivided(const MRLevelView2& v, MRMap2::Edge e);
/// Whether face f, read at the level l of v, has children at level l + 1
/// (it can be subdivided only when it was made at level l). O(codegree).
bool face_is_subdivided(const MRLevelView2& v, MRMap2::Face f);

/// The same at the current level of m.
inline uint32 edge_level(const MRMap2& m, MRMap2::Edge e)
{
	return edge_level(detail::read_level(m), e);
}
/// The same at the current level of m.
inline uint32 face_level(const MRMap2& m, MRMap2::Face f)
{
	return face_level(detail::read_level(m), f);
}
/// The same at the current level of m.
inline bool edge_is_subdivided(const MRMap2& m, MRMap2::Edge e)
{
	return edge_is_subdivided(detail::read_level(m), e);
}
/// The same at the current level of m.
inline bool face_is_subdivided(const MRMap2& m, MRMap2::Face f)
{
	return face_is_subdivided(detail::read_level(m), f);
}

/// Subdivides face f, read at the current level of m, where it is a leaf (a
/// face without children; its level k = face_level(f)), with pattern r: its
/// edges are cut at level k + 1 (a midpoint a neighbour cut already is
/// reused), and it becomes 4 triangles (Triangular, Mixed on a triangle) or
/// one quad per edge (Quadrangular, Mixed on other faces). Level k + 1 is
/// created when k is the finest level. With `balance`, every neighbour across
/// an edge of f made before level k is subdivided first (recursively, with
/// Mixed when r is Triangular), so that adjacent leaves differ by at most
/// one level. Lines: as add_level, for the cells made (corners of f get a
/// line at level k + 1 when they have none). Throws std::invalid_argument,
/// leaving m unchanged, when r is a 3-D pattern, when r is Triangular and f
/// is not a triangle, or when f has children already. O(degree of f) plus
/// the balancing subdivisions.
void subdivide_face(MRMap2& m, MRMap2::Face f, Refinement r, bool balance = true);

/// Whether face f, read at the current level l of m, can be coarsened: it
/// was made at level l and has children at level l + 1, none of which has
/// children, and no edge of its children on its boundary is cut at level
/// l + 2 (a neighbour two levels finer would touch it). O(degree of f).
bool can_coarsen_face(const MRMap2& m, MRMap2::Face f);

/// Removes the children of face f (read at the current level): the inverse
/// of subdivide_face. The midpoints of its edges go too, unless the neighbour
/// across uses them. Lines of the children are released and f reads its own
/// again; a corner keeps its line of the children's level only while another
/// face of that level touches it. max_level drops while its level holds no
/// dart. Precondition: can_coarsen_face(m, f). O(degree of f).
void coarsen_face(MRMap2& m, MRMap2::Face f);

/// The mesh at level l of m as a flat CMap2, for a solver or a file: one
/// dart per dart of the level (in the order of the finest map), its phi1,
/// phi2 and boundary, and every attribute of m with its values at level l
/// (attributes of darts, vertices, edges, faces and components, with their
/// names and rules). Throws std::out_of_range when l > max_level(m).
/// O(number of darts of the level x cost of a level step + attributes x cells).
CMap2 extract_level(const MRMap2& m, uint32 l);

} // namespace cgogn
