// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mrmap2.h>

namespace cgogn
{

/// The subdivision pattern of a new level.
enum class Refinement
{
	Triangular,   ///< 2-D: every triangle into 4 triangles (edge midpoints joined).
	Quadrangular, ///< 2-D: every k-gon into k quads (edge midpoints joined to a face centre).
	Mixed,        ///< 2-D: triangles as Triangular, the other faces as Quadrangular.
	Hexahedral,   ///< 3-D: every hexahedron into 8.
	TetraOcta,    ///< 3-D: a tetrahedron into 4 tetrahedra and an octahedron, an octahedron into 6 and 8.
};

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

/// The mesh at level l of m as a flat CMap2, for a solver or a file: one
/// dart per dart of the level (in the order of the finest map), its phi1,
/// phi2 and boundary, and every attribute of m with its values at level l
/// (attributes of darts, vertices, edges, faces and components, with their
/// names and rules). Throws std::out_of_range when l > max_level(m).
/// O(number of darts of the level x cost of a level step + attributes x cells).
CMap2 extract_level(const MRMap2& m, uint32 l);

} // namespace cgogn
