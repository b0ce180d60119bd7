// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/orbits.h>

namespace cgogn
{

/// The container that holds the attributes of cells of orbit O (the dart
/// container for DART).
template <Orbit O>
AttributeContainer& container_of(const CMapBase& m)
{
	if constexpr (O == Orbit::DART)
		return *detail::state_of(m).darts;
	else
		return *detail::state_of(m).cells[orbit_index(O)];
}

/// True when cells of this orbit have indices (created by the first attribute
/// of the orbit, or by index_cells). Darts are always indexed. O(1).
template <typename CELL>
bool is_indexed(const CMapBase& m)
{
	if constexpr (CELL::ORBIT == Orbit::DART || is_direct_orbit(CELL::ORBIT))
		return true;
	else
		return detail::state_of(m).cell_index[orbit_index(CELL::ORBIT)] != nullptr;
}

/// The index of cell c in its orbit's container: the line of its attribute
/// values. INVALID_INDEX for boundary cells and cells created with
/// set_indices = false. Precondition: the orbit is indexed. O(1).
template <Orbit O>
CGOGN_INLINE uint32 index_of(const CMapBase& m, Cell<O> c)
{
	if constexpr (O == Orbit::DART || is_direct_orbit(O))
		return c.dart.index;
	else
	{
		assert(detail::state_of(m).cell_index[orbit_index(O)] != nullptr);
		return (*detail::state_of(m).cell_index[orbit_index(O)])[c.dart.index];
	}
}

/// The line of a cell reported by a cached traversal (stored in the cache). O(1).
template <Orbit O>
CGOGN_INLINE uint32 index_of(const CMapBase&, LocatedCell<O> c)
{
	return c.line;
}

namespace detail
{

/// Writes index i on every dart of c and makes c.dart the representative of
/// line i. Does not release the previous line.
template <typename MAP, Orbit O>
void write_index(MAP& m, Cell<O> c, uint32 i)
{
	AttributeArray<uint32>& idx = *detail::state_of(m).cell_index[orbit_index(O)];
	foreach_dart_of_orbit(m, c, [&](Dart d) { idx[d.index] = i; });
	if (i != INVALID_INDEX)
		detail::state_of(m).cells[orbit_index(O)]->key()[i] = c.dart.index;
}

/// A new line for cell c, written on all its darts. Returns it.
template <typename MAP, Orbit O>
uint32 new_index(MAP& m, Cell<O> c)
{
	uint32 i = detail::state_of(m).cells[orbit_index(O)]->new_line(c.dart.index);
	write_index(m, c, i);
	return i;
}

/// Indexes c with a new line when its orbit is indexed (used by the operators).
template <typename MAP, Orbit O>
void index_new_cell(MAP& m, Cell<O> c)
{
	if (detail::state_of(m).cell_index[orbit_index(O)] != nullptr)
		new_index(m, c);
}

/// Writes line i on the darts of c when its orbit is indexed and makes c.dart
/// its representative (used by the operators for cells that keep their index).
template <typename MAP, Orbit O>
void reindex_cell(MAP& m, Cell<O> c, uint32 i)
{
	if (detail::state_of(m).cell_index[orbit_index(O)] != nullptr && i != INVALID_INDEX)
		write_index(m, c, i);
}

/// Releases line i of orbit O when the orbit is indexed and i is valid.
template <Orbit O>
void release_index(CMapBase& m, uint32 i)
{
	if (detail::state_of(m).cell_index[orbit_index(O)] != nullptr && i != INVALID_INDEX)
		detail::state_of(m).cells[orbit_index(O)]->release_line(i);
}

/// Makes d the representative of its (indexed) cell of orbit O: operators
/// call it when the previous representative dart is about to disappear.
template <Orbit O>
void set_representative(CMapBase& m, Dart d)
{
	if (const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(O)])
	{
		uint32 i = (*idx)[d.index];
		if (i != INVALID_INDEX)
			detail::state_of(m).cells[orbit_index(O)]->key()[i] = d.index;
	}
}

/// The index attribute of orbit o (the dart attribute holding each dart's
/// line), created and handed to the orbit's container when o is not indexed
/// yet: its darts then hold INVALID_INDEX. O(1).
inline AttributeArray<uint32>& index_attribute(CMapBase& m, Orbit o)
{
	AttributeArray<uint32>*& idx = state_of(m).cell_index[orbit_index(o)];
	if (idx == nullptr)
	{
		idx = state_of(m).darts->add_attribute<uint32>("__index_" + std::string(orbit_name(o)), INVALID_INDEX).get();
		state_of(m).cells[orbit_index(o)]->set_cell_index(idx);
	}
	return *idx;
}

} // namespace detail

/// Assigns cell c to line i of its orbit's container: every dart of c gets
/// index i and the cell becomes the owner of the line. A line belongs to one
/// cell only, so the cell's previous line is released; line i must be live and
/// not owned by another cell (or be the cell's own line). O(size of the orbit).
template <typename MAP, Orbit O>
requires std::derived_from<MAP, CMapBase>
void set_index(MAP& m, Cell<O> c, uint32 i)
{
	static_assert(O != Orbit::DART, "darts are their own index");
	assert(is_indexed<Cell<O>>(m));
	AttributeContainer& cont = *detail::state_of(m).cells[orbit_index(O)];
	assert(cont.is_live(i));
	const uint32 old = index_of(m, c);
	if (old == i)
		return;
	detail::drop_incidence_caches(m); // their stored lines would be stale
	detail::write_index(m, c, i);
	if (old != INVALID_INDEX)
		cont.release_line(old);
}

/// Gives an index to every real cell of orbit O that has none, creating the
/// orbit's index attribute if needed. Called by add_attribute; call it after
/// operators used with set_indices = false. O(number of darts).
template <typename CELL, typename MAP>
requires std::derived_from<MAP, CMapBase>
void index_cells(MAP& m)
{
	constexpr Orbit O = CELL::ORBIT;
	if constexpr (O == Orbit::DART || is_direct_orbit(O))
		return;
	else
	{
		AttributeArray<uint32>* idx = &detail::index_attribute(m, O);
		foreach_dart(m, [&](Dart d) {
			if ((*idx)[d.index] == INVALID_INDEX && !is_boundary_cell(m, CELL(d)))
				detail::new_index(m, CELL(d));
		});
	}
}

} // namespace cgogn
