// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/indexing.h>

#include <tuple>
#include <vector>

namespace cgogn::detail
{

/// Gives a new line, in every indexed orbit of the map, to each real cell made
/// only of new darts (darts whose index is still INVALID_INDEX). Operators call
/// it for the darts they create. O(number of darts given x indexed orbits).
template <typename MAP>
void index_new_darts(MAP& m, const std::vector<Dart>& darts)
{
	auto index_orbit = [&]<typename CELL>(CELL*) {
		if constexpr (CELL::ORBIT != Orbit::DART)
		{
			const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(CELL::ORBIT)];
			if (idx == nullptr)
				return;
			for (Dart d : darts)
				if ((*idx)[d.index] == INVALID_INDEX && !is_boundary_cell(m, CELL(d)))
					new_index(m, CELL(d));
		}
	};
	[&]<typename... C>(std::tuple<C...>*) {
		(index_orbit(static_cast<C*>(nullptr)), ...);
	}(static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
}

} // namespace cgogn::detail

namespace cgogn::detail
{

/// The index of d's cell of orbit O, or INVALID_INDEX when O is not indexed.
template <Orbit O>
uint32 index_or_invalid(const CMapBase& m, Dart d)
{
	const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(O)];
	return idx ? (*idx)[d.index] : INVALID_INDEX;
}

/// Gives dart dst the index of dart src in orbit O (when O is indexed).
template <Orbit O>
void copy_dart_index(CMapBase& m, Dart dst, Dart src)
{
	if (AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(O)])
		(*idx)[dst.index] = (*idx)[src.index];
}

/// Sets the index of dart d in orbit O (when O is indexed).
template <Orbit O>
void set_dart_index(CMapBase& m, Dart d, uint32 i)
{
	if (AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(O)])
		(*idx)[d.index] = i;
}

/// Merges two cells of orbit O that became one: the line of `keep` is written
/// on all darts of the merged cell (which contains `keep`), the other line is
/// released. No-op when O is not indexed or both lines are the same.
template <typename MAP, Orbit O>
void merge_cell_indices(MAP& m, Cell<O> merged, uint32 keep, uint32 other)
{
	if (detail::state_of(m).cell_index[orbit_index(O)] == nullptr)
		return;
	if (keep == INVALID_INDEX)
		std::swap(keep, other);
	if (keep == INVALID_INDEX)
		return;
	write_index(m, merged, keep);
	if (other != INVALID_INDEX && other != keep)
		detail::state_of(m).cells[orbit_index(O)]->release_line(other);
}

} // namespace cgogn::detail
