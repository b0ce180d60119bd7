// SPDX-License-Identifier: MIT
// check_integrity of the lines of a multiresolution map (see
// detail::MRCellIndex), for the maps of every dimension.
#pragma once

#include <cgogn/core/properties/integrity.h>

#include "mr_indexing.h"

#include <string>
#include <vector>

namespace cgogn::detail
{

/// Reports an error: kind, dart (INVALID_INDEX: none) and message.
using MRReport = std::function<void(IntegrityError::Kind, uint32, const std::string&)>;

/// mr_line_of following live lines only (the chains are checked first: each
/// link leads to a coarser live line), so that a dart holding a free or
/// missing line (a broken file) ends the walk: INVALID_INDEX then.
template <typename S>
uint32 mr_checked_line_of(const S& s, uint32 slot, uint32 l, Dart d)
{
	const MRCellIndex& ci = s.cells[slot];
	const AttributeContainer& c = mr_slot_container(s, slot);
	const uint32 end = c.end_index();
	uint32 i = (*ci.index)[d.index];
	while (i < end && c.key()[i] != INVALID_INDEX && !mr_is_finest(s, l) && (*ci.level)[i] > l)
		i = (*ci.down)[i];
	return i < end && c.key()[i] != INVALID_INDEX ? i : INVALID_INDEX;
}

/// The chains of lines of an indexed slot: each line refines a live line of
/// a lower level (so that reading a line at a level ends). Returns false
/// when one does not.
template <typename S>
bool mr_check_chains(const S& s, uint32 slot, const MRReport& add)
{
	const MRCellIndex& ci = s.cells[slot];
	const AttributeContainer& c = mr_slot_container(s, slot);
	const auto key = c.key().view();
	bool ok = true;
	for (uint32 i = 0, end = c.end_index(); i < end; ++i)
	{
		const uint32 down = (*ci.down)[i];
		if (key[i] == INVALID_INDEX || down == INVALID_INDEX)
			continue;
		if (down >= end || key[down] == INVALID_INDEX || (*ci.level)[down] >= (*ci.level)[i] ||
			(*ci.replaced)[down] > (*ci.level)[i])
		{
			ok = false;
			add(IntegrityError::Kind::LevelLineWrong, INVALID_INDEX,
				"line " + std::to_string(i) + " of orbit " + std::string(orbit_name(MRDim<S>::orbits[slot])) +
					" refines a line that is free, not coarser, or not replaced by then");
		}
	}
	return ok;
}

/// The lines of an indexed slot at level l: every cell reads one live line
/// that holds at l from all its darts, whose representative is one of them,
/// no two cells share a line, and as many lines hold as there are cells.
template <typename S>
void mr_check_lines(const S& s, uint32 slot, uint32 l, const MRReport& add)
{
	const std::string at =
		std::string(" of orbit ") + std::string(orbit_name(MRDim<S>::orbits[slot])) + " at level " + std::to_string(l);
	const MRCellIndex& ci = s.cells[slot];
	const AttributeContainer& c = mr_slot_container(s, slot);
	const auto key = c.key().view();
	std::vector<uint8> used(c.end_index(), 0);
	uint32 nb_cells = 0;
	mr_foreach_cell_of_slot(s, slot, l, [&](Dart d) {
		++nb_cells;
		const uint32 i = mr_checked_line_of(s, slot, l, d);
		if (i == INVALID_INDEX)
		{
			add(IntegrityError::Kind::MissingIndex, d.index, "cell without a live line" + at);
			return;
		}
		if ((*ci.level)[i] > l || (*ci.replaced)[i] <= l)
			add(IntegrityError::Kind::LevelLineWrong, d.index, "line " + std::to_string(i) + " does not hold" + at);
		bool representative = false;
		mr_foreach_dart_of_cell(s, slot, l, d, [&](Dart x) {
			representative = representative || x.index == key[i];
			if (mr_checked_line_of(s, slot, l, x) != i)
				add(IntegrityError::Kind::IndexNotConstant, x.index, "two darts of a cell read different lines" + at);
		});
		if (!representative)
			add(IntegrityError::Kind::BadRepresentative, d.index,
				"the representative of line " + std::to_string(i) + " is not a dart of its cell" + at);
		if (used[i]++ == 1)
			add(IntegrityError::Kind::IndexShared, d.index, "line " + std::to_string(i) + " shared" + at);
	});
	uint32 nb_lines = 0;
	mr_foreach_line_holding(s, slot, l, 0, c.end_index(), [&](uint32) { ++nb_lines; });
	if (nb_lines != nb_cells)
		add(IntegrityError::Kind::LevelLineWrong, INVALID_INDEX,
			std::to_string(nb_lines) + " lines hold for " + std::to_string(nb_cells) + " cells" + at);
}

} // namespace cgogn::detail
