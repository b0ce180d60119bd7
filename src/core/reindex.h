// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/functions/indexing.h>
#include <cgogn/core/types/marker.h>

#include <algorithm>
#include <array>
#include <unordered_set>
#include <vector>

namespace cgogn::detail
{

/// Indexing of a region changed by an operator, for every indexed orbit at
/// once: record() the darts of the region before the change (their lines),
/// apply() the darts of the region after it (surviving and new darts, at least
/// one dart of every surviving cell). Each cell of the region then claims the
/// first unclaimed recorded line found on its darts (so a split cell keeps its
/// line on the part visited first, merged cells keep one line), cells without
/// one get a new line, boundary cells get none, and recorded lines left
/// unclaimed are released. O(size of the cells of the region).
template <typename MAP>
class RegionReindexer
{
public:
	void record(const MAP& m, const std::vector<Dart>& darts)
	{
		for (uint32 o = 0; o < NB_ORBITS; ++o)
			if (const AttributeArray<uint32>* idx = m.cell_index_[o])
				for (Dart d : darts)
					if (uint32 l = (*idx)[d.index]; l != INVALID_INDEX)
						old_[o].push_back(l);
	}

	void apply(MAP& m, const std::vector<Dart>& region)
	{
		[&]<typename... C>(std::tuple<C...>*) { (apply_orbit<C>(m, region), ...); }(
			static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
	}

private:
	template <typename CELL>
	void apply_orbit(MAP& m, const std::vector<Dart>& region)
	{
		constexpr Orbit O = CELL::ORBIT;
		if constexpr (O != Orbit::DART)
		{
			AttributeArray<uint32>* idx = m.cell_index_[orbit_index(O)];
			if (idx == nullptr)
				return;
			AttributeContainer& cells = *m.cells_[orbit_index(O)];
			std::unordered_set<uint32> claimed;
			DartMarkerStore<MAP> visited(m);
			for (Dart d : region)
			{
				if (visited.is_marked(d))
					continue;
				visited.mark_orbit(CELL(d));
				if (is_boundary_cell(m, CELL(d)))
				{
					foreach_dart_of_orbit(m, CELL(d), [&](Dart x) { (*idx)[x.index] = INVALID_INDEX; });
					continue;
				}
				uint32 line = INVALID_INDEX;
				foreach_dart_of_orbit(m, CELL(d), [&](Dart x) {
					const uint32 l = (*idx)[x.index];
					if (l != INVALID_INDEX && cells.is_live(l) && !claimed.count(l))
						line = l;
					return line == INVALID_INDEX;
				});
				if (line == INVALID_INDEX)
					line = cells.new_line(d.index);
				claimed.insert(line);
				write_index(m, CELL(d), line);
			}
			auto& olds = old_[orbit_index(O)];
			std::sort(olds.begin(), olds.end());
			olds.erase(std::unique(olds.begin(), olds.end()), olds.end());
			for (uint32 l : olds)
				if (!claimed.count(l) && cells.is_live(l))
					cells.release_line(l);
		}
	}

	std::array<std::vector<uint32>, NB_ORBITS> old_;
};

} // namespace cgogn::detail
