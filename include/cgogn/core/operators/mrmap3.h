// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mrmap3.h>

namespace cgogn
{

/// Adds a level above the finest one by refining every volume of the finest
/// level with pattern r. Hexahedral: every edge is cut at its middle, every
/// face into quads around a centre, every hexahedron into 8 around a centre
/// by 12 inner quads. TetraOcta: every edge is cut at its middle, every
/// triangle into 4, every tetrahedron into 4 tetrahedra at its corners and
/// an octahedron, every octahedron into 6 octahedra at its corners and 8
/// tetrahedra at its faces around a new centre (the inner faces are the 24
/// triangles of the 4 hexagons through its centre parallel to its faces; an
/// inner edge of a triangle takes an edge id different from both edges whose
/// midpoints it joins). The new darts get the new level; the pieces of a cut
/// edge (face) keep its edge (face) id; a new inner edge of a face takes an
/// edge id different from the edges whose midpoints it leaves, and a new
/// inner face the smallest face id not used around its edges (see MRState3).
/// The cells of the new level get lines by the rules of the attributes (see
/// mrmap3_attributes.h); the children of a face or a volume without a dart of
/// their parent (a middle triangle, a middle octahedron, a face tetrahedron)
/// refine their parent's line as the others do. The current level becomes the
/// new finest level. Throws std::invalid_argument, leaving m unchanged, when r
/// is a 2-D pattern, or a volume of the finest level is not a hexahedron (6
/// quads, 3 edges at each corner) for Hexahedral, neither a tetrahedron nor an
/// octahedron (8 triangles, 4 edges at each corner) for TetraOcta. O(number
/// of darts).
void add_level(MRMap3& m, Refinement r);

/// Removes the finest level: every dart of that level goes, and the darts
/// left get back the relations of the level below (the inverse of
/// add_level). The current level is clamped to the new finest level. Throws
/// std::invalid_argument when m has no level above 0. O(number of darts x
/// cost of a level step).
void remove_finest_level(MRMap3& m);

// ---- adaptive refinement: hexahedra of different levels side by side

/// The level at which edge e, read at the level of v, was made: the level of
/// the younger of its darts at its two ends. O(1 level step).
uint32 edge_level(const MRLevelView3& v, MRMap3::Edge e);
/// The level at which face f, read at the level of v, was made (the second
/// smallest level of the darts of one of its sides). O(codegree).
uint32 face_level(const MRLevelView3& v, MRMap3::Face f);
/// The level at which volume w, read at the level of v, was made: the
/// smallest level of its darts but those at the corner of its oldest dart (a
/// child keeps the darts of its parent at one corner). O(number of darts of
/// w).
uint32 volume_level(const MRLevelView3& v, MRMap3::Volume w);
/// Whether edge e, read at the level l of v, is cut at level l + 1. O(1
/// level step).
bool edge_is_subdivided(const MRLevelView3& v, MRMap3::Edge e);
/// Whether face f, read at the level l of v, has children at level l + 1.
/// O(codegree).
bool face_is_subdivided(const MRLevelView3& v, MRMap3::Face f);
/// Whether volume w, read at the level l of v, has children at level l + 1
/// (it can be subdivided only when it was made at level l). O(number of
/// darts of w).
bool volume_is_subdivided(const MRLevelView3& v, MRMap3::Volume w);

/// The same at the current level of m.
inline uint32 edge_level(const MRMap3& m, MRMap3::Edge e)
{
	return edge_level(detail::read_level(m), e);
}
/// The same at the current level of m.
inline uint32 face_level(const MRMap3& m, MRMap3::Face f)
{
	return face_level(detail::read_level(m), f);
}
/// The same at the current level of m.
inline uint32 volume_level(const MRMap3& m, MRMap3::Volume w)
{
	return volume_level(detail::read_level(m), w);
}
/// The same at the current level of m.
inline bool edge_is_subdivided(const MRMap3& m, MRMap3::Edge e)
{
	return edge_is_subdivided(detail::read_level(m), e);
}
/// The same at the current level of m.
inline bool face_is_subdivided(const MRMap3& m, MRMap3::Face f)
{
	return face_is_subdivided(detail::read_level(m), f);
}
/// The same at the current level of m.
inline bool volume_is_subdivided(const MRMap3& m, MRMap3::Volume w)
{
	return volume_is_subdivided(detail::read_level(m), w);
}

/// Subdivides hexahedron w, read at the current level of m, where it is a
/// leaf (a volume without children; its level k = volume_level(w)), into 8
/// hexahedra of level k + 1: its edges are cut at their middle and its faces
/// into 4 quads around their centre (a cut or a face that a neighbour made
/// already is reused), and 12 inner quads meet at its centre. Level k + 1 is
/// created when k is the finest level. With `balance`, every volume sharing
/// an edge (or a face) with w and made before level k is subdivided first,
/// recursively, so that leaves sharing an edge differ by at most one level.
/// Lines: as add_level, for the cells made (corners of w get a line at
/// level k + 1 when they have none); new vertices get the attributes' rules
/// from the corners of the edge, face or hexahedron they are the middle of.
/// Throws std::invalid_argument, leaving m unchanged, when w is a boundary
/// volume, is not a hexahedron at its level, has children already, or when
/// its surface holds cuts finer than level k + 1 (a neighbour two levels
/// finer, after subdivisions without balance). O(1) plus the balancing
/// subdivisions.
void subdivide_volume(MRMap3& m, MRMap3::Volume w, bool balance = true);

/// Whether volume w, read at the current level l of m, can be coarsened: it
/// was made at level l and has 8 children at level l + 1, none of which has
/// children, and no cut of level l + 2 lies on their surface (a leaf two
/// levels finer would share an edge with w). O(size of the children).
bool can_coarsen_volume(const MRMap3& m, MRMap3::Volume w);

/// Removes the children of volume w (read at the current level): the inverse
/// of subdivide_volume. Its inner faces, edges and centre go; so do the
/// quads of a face of w and the midpoints of an edge of w that no other
/// subdivided volume uses. The lines of what goes are released, and w, its
/// faces and edges read their own lines again; a corner keeps its line of
/// level l + 1 while a volume of that level touches it. max_level drops
/// while its level holds no dart. Precondition: can_coarsen_volume(m, w).
/// O(size of the children + degrees of w's edges).
void coarsen_volume(MRMap3& m, MRMap3::Volume w);

/// The mesh of level l as a flat CMap3: one dart per dart of the level (in
/// the order of the finest map), with the relations of the level, the
/// boundary marks, the per-dart attributes and the attributes of the cells
/// with their values at level l. Throws std::out_of_range when
/// l > max_level(m). O(number of darts of the finest map x cost of a level
/// step).
CMap3 extract_level(const MRMap3& m, uint32 l);

} // namespace cgogn
