// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/functions/indexing.h>

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
			const Attribute<uint32>* idx = m.cell_index_[orbit_index(CELL::ORBIT)];
			if (idx == nullptr)
				return;
			for (Dart d : darts)
				if ((*idx)[d.index] == INVALID_INDEX && !is_boundary_cell(m, CELL(d)))
					new_index(m, CELL(d));
		}
	};
	[&]<typename... C>(std::tuple<C...>*) { (index_orbit(static_cast<C*>(nullptr)), ...); }(
		static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
}

} // namespace cgogn::detail
