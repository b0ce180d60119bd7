// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/marking/marker.h>

#include "component_split.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_set>
#include <vector>

namespace cgogn::detail
{

// The parts of RegionReindexer that depend neither on the map nor on the
// orbit, compiled once (reindex.cpp) rather than in every (map, orbit) pair:
/// Sorts `lines`, drops their repeats and those no longer live in `cells`.
void keep_live_lines_once(std::vector<uint32>& lines, const AttributeContainer& cells);
/// Releases the lines of `olds` that are not in `claimed`.
void release_unclaimed_lines(AttributeContainer& cells, const std::vector<uint32>& olds,
							 const std::unordered_set<uint32>& claimed);

/// Indexing of a region changed by an operator, for every indexed orbit at
/// once: record() the darts of the region before the change (their lines),
/// apply() the darts of the region after it (surviving and new darts, at least
/// one dart of every surviving cell, and every dart that became a boundary
/// dart). Each cell of the region then claims the first unclaimed recorded line
/// found on its darts (so a split cell keeps its line on the part visited first,
/// merged cells keep one line), cells without one get a new line, and recorded
/// lines left unclaimed are released.
///
/// Two kinds of cells are never walked, since they can be as large as the mesh:
/// - boundary cells (the boundary "volume" of a 3-map is the whole boundary
///   surface): the region's darts in them get no index, which is all a dart
///   entering the boundary needs;
/// - connected components, when the region lies in one recorded component:
///   the component keeps its line, written on the region's darts. When the
///   operator may cut it (components_may_split()), the region's darts are
///   searched for parts that no longer meet (split_component_lines): a part
///   cut off is walked whole and gets a new line.
/// Cost: O(size of the region's cells), plus the size of the smaller parts of
/// a component that comes apart, or of components that merge (walked whole).
template <typename MAP>
class RegionReindexer
{
public:
	void record(const MAP& m, const std::vector<Dart>& darts)
	{
		for (uint32 o = 0; o < NB_ORBITS; ++o)
			if (const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[o])
				for (Dart d : darts)
					if (uint32 l = (*idx)[d.index]; l != INVALID_INDEX)
						old_[o].push_back(l);
	}

	/// For operators that can disconnect a component (unsew, remove a volume).
	void components_may_split()
	{
		components_may_split_ = true;
	}

	void apply(MAP& m, const std::vector<Dart>& region)
	{
		[&]<typename... C>(std::tuple<C...>*) {
			(apply_orbit<C>(m, region), ...);
		}(static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
	}

private:
	template <typename CELL>
	void apply_orbit(MAP& m, const std::vector<Dart>& region)
	{
		constexpr Orbit O = CELL::ORBIT;
		if constexpr (O != Orbit::DART)
		{
			AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(O)];
			if (idx == nullptr)
				return;
			AttributeContainer& cells = *detail::state_of(m).cells[orbit_index(O)];
			auto& olds = old_[orbit_index(O)];
			keep_live_lines_once(olds, cells);
			// connected components of a 3-map or a G-map: never walked whole
			// (BETA0_BETA1_BETA2 is the component of a 2-G-map, a volume of a 3-G-map)
			constexpr bool component = O == Orbit::PHI1_PHI2_PHI3 || O == Orbit::BETA0_BETA1_BETA2_BETA3 ||
									   (O == Orbit::BETA0_BETA1_BETA2 && MAP::dimension == 2);
			if (component && olds.size() == 1 && !region.empty())
			{
				for (Dart d : region)
					(*idx)[d.index] = olds.front();
				cells.key()[olds.front()] = region.front().index;
				count_reindexed_darts(region.size());
				if (components_may_split_)
					split_component_lines<CELL>(m, olds.front(), region);
				return;
			}
			std::unordered_set<uint32> claimed;
			DartMarkerStore<MAP> visited(m);
			std::uint64_t walked = 0;
			for (Dart d : region)
			{
				++walked;
				if (is_boundary_cell(m, CELL(d)))
				{
					(*idx)[d.index] = INVALID_INDEX;
					continue;
				}
				if (visited.is_marked(d))
					continue;
				uint32 line = INVALID_INDEX, seen = INVALID_INDEX;
				foreach_dart_of_orbit(m, CELL(d), [&](Dart x) {
					walked += 2; // write_index walks the cell again
					visited.mark(x);
					const uint32 l = (*idx)[x.index];
					if (seen == INVALID_INDEX && l != INVALID_INDEX && cells.is_live(l))
						seen = l;
					if (line == INVALID_INDEX && l != INVALID_INDEX && cells.is_live(l) && !claimed.count(l))
						line = l;
				});
				if (line == INVALID_INDEX)
				{
					// a part of a cell that came apart (its line went to another
					// part) gets its rules' values from that line; a cell of new
					// darts only is the operator's to fill
					line = cells.new_line(d.index);
					detail::inherit_line<O>(m, line, seen);
				}
				claimed.insert(line);
				write_index(m, CELL(d), line);
			}
			count_reindexed_darts(walked);
			release_unclaimed_lines(cells, olds, claimed);
		}
	}

	std::array<std::vector<uint32>, NB_ORBITS> old_;
	bool components_may_split_ = false;
};

} // namespace cgogn::detail
