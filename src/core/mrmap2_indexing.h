// SPDX-License-Identifier: MIT
// The lines of the cells of a multiresolution 2-map (see detail::MRCellIndex).
#pragma once

#include <cgogn/core/map/mrmap2_attributes.h>
#include <cgogn/core/traversals/local_mrmap2.h>

#include <functional>

namespace cgogn::detail
{

/// The cells of a slot at level l, found from the darts (not from the
/// lines): f(first dart) once per real cell. O(number of darts of level <= l
/// x cost of a level step).
void mr_foreach_cell_by_darts(const MRState2& s, uint32 slot, uint32 l, const std::function<void(Dart)>& f);

/// Calls f on the darts of the cell of d in slot `slot` at level l.
template <typename FUNC>
void mr_foreach_dart_of_slot(const MRState2& s, uint32 slot, uint32 l, Dart d, const FUNC& f)
{
	const MRLevelView2 v(s, l);
	switch (slot)
	{
	case 0:
		foreach_dart_of_orbit(v, MRMap2::Vertex(d), f);
		break;
	case 1:
		foreach_dart_of_orbit(v, MRMap2::Edge(d), f);
		break;
	case 2:
		foreach_dart_of_orbit(v, MRMap2::Face(d), f);
		break;
	default:
		foreach_dart_of_orbit(v, MRMap2::Volume(d), f);
	}
}

/// A new line of slot `slot` at level l, with representative dart
/// `representative`, refining line `down` (INVALID_INDEX: none), whose values
/// it copies; `down` is then replaced from level l on. O(attributes).
uint32 mr_new_line(MRState2& s, uint32 slot, uint32 l, Dart representative, uint32 down);

/// The vertex lines of level l - 1 the attribute rules of new vertex v of
/// level l start from: the ends of the edge of level l - 1 it cuts, or the
/// corners of the face of level l - 1 it centres. Empty when it is neither.
std::vector<uint32> mr_vertex_parents(const MRState2& s, uint32 l, Dart v);

/// Adds the per-line attributes of a slot (down, level, replaced) to its
/// container. O(capacity of the container).
void mr_add_line_attributes(MRState2& s, uint32 slot);

/// Gives lines to the cells of a slot at level l, the levels below being
/// indexed: a vertex gets a new line refining its line below (a copy of its
/// values) or, when new, a line filled by the attribute rules; an edge or a
/// face that is the same cell as below keeps its line, another one gets a new
/// line refining its parent's (a copy of its values), or none when it has no
/// parent. Writes each cell's line on its darts of level <= l.
/// O(number of darts of level <= l x cost of a level step).
void mr_index_level(MRState2& s, uint32 slot, uint32 l);

/// Undoes mr_index_level for the finest level l, whose darts are gone:
/// the darts left get back their lines of level l - 1, the lines of level
/// l are released. O(number of darts + number of lines).
void mr_unindex_level(MRState2& s, uint32 slot, uint32 l);

} // namespace cgogn::detail
