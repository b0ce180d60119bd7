// SPDX-License-Identifier: MIT
// The lines of the cells of a multiresolution map at every level (see
// detail::MRCellIndex), for the maps of every dimension (instantiated in
// mr_indexing.cpp).
#pragma once

#include <cgogn/core/map/mr_lines.h>
#include <cgogn/core/traversals/local_mrmap2.h>
#include <cgogn/core/traversals/local_mrmap3.h>

#include <functional>
#include <vector>

namespace cgogn::detail
{

/// The level at which dart d was made. O(1).
template <typename S>
uint32 mr_dart_level(const S& s, Dart d)
{
	return (*s.level)[d.index];
}
/// Whether the cells of slot `slot` have lines. O(1).
template <typename S>
bool mr_indexed(const S& s, uint32 slot)
{
	return s.cells[slot].index != nullptr;
}
/// The per-dart line index of slot `slot` (which must be indexed). O(1).
template <typename S>
AttributeArray<uint32>& mr_index(S& s, uint32 slot)
{
	return *s.cells[slot].index;
}

/// The cells of a slot at level l, found from the darts (not from the
/// lines): f(first dart) once per cell, boundary cells skipped. O(number of
/// darts of level <= l x cost of a level step).
template <typename S>
void mr_foreach_cell_of_slot(const S& s, uint32 slot, uint32 l, const std::function<void(Dart)>& f);

/// A new line of slot `slot` at level l, with representative dart
/// `representative`, refining line `down` (INVALID_INDEX: none), whose values
/// it copies; `down` is then replaced from level l on. O(attributes).
template <typename S>
uint32 mr_add_line(S& s, uint32 slot, uint32 l, Dart representative, uint32 down);

/// Adds the per-line attributes of a slot (down, level, replaced) to its
/// container. O(capacity of the container).
template <typename S>
void mr_add_slot_attributes(S& s, uint32 slot);

/// Gives lines to the cells of a slot at level l, the levels below being
/// indexed: a vertex gets a new line refining its line below (a copy of its
/// values) or, when new, a line filled by the attribute rules from the
/// vertices it is the middle of; an edge, face or volume that is the same
/// cell as below keeps its line, another one gets a new line refining its
/// parent's (a copy of its values), or none when it has no parent. Writes
/// each cell's line on its darts of level <= l. O(number of darts of level
/// <= l x cost of a level step).
template <typename S>
void mr_index_cells_at(S& s, uint32 slot, uint32 l);

/// Undoes mr_index_cells_at for the finest level l, whose darts are gone:
/// the darts left get back their lines of level l - 1, the lines of level
/// l are released. O(number of darts + number of lines).
template <typename S>
void mr_unindex_cells_at(S& s, uint32 slot, uint32 l);

/// Gives lines to the cells of orbit o, which has none yet, at every level:
/// a per-dart line attribute, the per-line attributes, the lines of level
/// 0 up. O(number of darts x levels x cost of a level step).
template <typename S>
void mr_index_new_orbit(S& s, Orbit o);

/// Takes over the indexing of the orbits the finest map indexes (at
/// construction): their lines become level-0 lines, and the finest map's
/// own indexing of them is switched off. O(number of orbits).
template <typename S>
void mr_take_over_indexing(S& s);

/// Writes line i on the darts of the finest map's cell of d in slot `slot`
/// (the cell as the finest map has it). O(size of the cell).
template <typename S>
void mr_write_line(S& s, uint32 slot, Dart d, uint32 i);

/// Gives vertex x a line at level l when it reads a coarser one there: the
/// new line sits in its chain between the coarser and the finer lines, with
/// a copy of the values it read. O(levels + attributes).
template <typename S>
void mr_ensure_vertex_line(S& s, Dart x, uint32 l);

/// Takes the line of level l out of the chain of vertex x, if it has one
/// above a coarser line (the inverse of mr_ensure_vertex_line).
/// O(levels + degree of x).
template <typename S>
void mr_drop_vertex_line(S& s, Dart x, uint32 l);

/// The vertex lines of level l - 1 the attribute rules of new vertex v of
/// level l start from: the corners of the cell of level l - 1 it is the
/// middle of (an edge, a face; a volume in 3-D). Empty when it is none of
/// these.
std::vector<uint32> mr_vertex_parents(const MRState2& s, uint32 l, Dart v);
std::vector<uint32> mr_vertex_parents(const MRState3& s, uint32 l, Dart v);

/// Copies the attributes of the cells of orbit slot `slot` at level l of s
/// into the flat map `flat`, whose dart i is the hierarchy's dart
/// source[i]. O(number of cells x attributes).
template <typename S>
void mr_copy_cell_attributes(const S& s, uint32 slot, uint32 l, typename MRDim<S>::Flat& flat,
							 const std::vector<Dart>& source);

} // namespace cgogn::detail
