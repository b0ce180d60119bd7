// SPDX-License-Identifier: MIT
// The lines of the cells of a multiresolution 2-map at every level (see
// detail::MRCellIndex).
#include "mrmap2_indexing.h"

#include <cgogn/core/traversals/local_mrmap2.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace cgogn::detail
{

namespace
{

/// Copies the values of line src to line dst in every attribute of the
/// container but the key and the library's own.
void copy_values(AttributeContainer& c, uint32 dst, uint32 src)
{
	for (const auto& a : c.attributes())
		if (a.get() != &c.key() && a->name().rfind("__", 0) != 0)
			a->copy_line(dst, src);
}

} // namespace

void mr_foreach_cell_by_darts(const MRState2& s, uint32 slot, uint32 l, const std::function<void(Dart)>& f)
{
	const MRLevelView2 v(s, l);
	const auto level = s.level->view();
	if (slot == 3)
	{
		DartMarkerStore<CMap2> seen(s.map);
		foreach_dart(s.map, [&](Dart d) {
			if (level[d.index] > l || is_boundary(s.map, d) || seen.is_marked(d))
				return;
			foreach_dart_of_orbit(v, MRMap2::Volume(d), [&](Dart x) { seen.mark(x); });
			f(d);
		});
		return;
	}
	foreach_dart(s.map, [&](Dart d) {
		if (level[d.index] > l || is_boundary(s.map, d))
			return;
		const bool reports = slot == 0   ? mr_reports_cell<MRMap2::Vertex>(v, d)
							 : slot == 1 ? mr_reports_cell<MRMap2::Edge>(v, d)
										 : mr_reports_cell<MRMap2::Face>(v, d);
		if (reports)
			f(d);
	});
}

namespace
{

/// For a face of level l without a dart of level l - 1 (the middle triangle
/// of a triangle cut in 4): a dart of level l - 1 of a face that shares its
/// parent, reached across the new edges of level l. INVALID when none.
Dart old_dart_of_sibling(const MRState2& s, uint32 l, Dart d)
{
	const auto level = s.level->view();
	std::vector<Dart> work{d};
	DartMarkerStore<CMap2> seen(s.map);
	seen.mark(d);
	for (std::size_t i = 0; i < work.size() && i < 64; ++i)
	{
		Dart found;
		mr_foreach_dart_of_slot(s, 2, l, work[i], [&](Dart x) {
			if (level[x.index] < l)
			{
				found = x;
				return false;
			}
			const Dart y = mr_phi2(s, l, x);
			if (!is_boundary(s.map, y) && level[y.index] == l && !seen.is_marked(y))
			{
				seen.mark(y);
				work.push_back(y);
			}
			return true;
		});
		if (found.is_valid())
			return found;
	}
	return Dart();
}

} // namespace

std::vector<uint32> mr_vertex_parents(const MRState2& s, uint32 l, Dart v)
{
	std::vector<uint32> parents;
	const auto [origin, d] = mr_vertex_origin(s, l, v);
	if (origin == MRVertexOrigin::Midpoint)
		parents = {mr_index_of(s, l - 1, 0, d), mr_index_of(s, l - 1, 0, mr_phi2(s, l - 1, d))};
	else if (origin == MRVertexOrigin::Centre)
		mr_foreach_dart_of_slot(s, 2, l - 1, d, [&](Dart x) { parents.push_back(mr_index_of(s, l - 1, 0, x)); });
	return parents;
}

uint32 mr_new_line(MRState2& s, uint32 slot, uint32 l, Dart representative, uint32 down)
{
	MRCellIndex& ci = s.cells[slot];
	AttributeContainer& c = *state_of(s.map).cells[orbit_index(MR2_ORBITS[slot])];
	const uint32 i = c.new_line(representative.index);
	(*ci.down)[i] = down;
	(*ci.level)[i] = uint8(l);
	(*ci.replaced)[i] = MR_NOT_REPLACED;
	if (down != INVALID_INDEX)
	{
		(*ci.replaced)[down] = uint8(l);
		copy_values(c, i, down);
	}
	return i;
}

void mr_add_line_attributes(MRState2& s, uint32 slot)
{
	MRCellIndex& ci = s.cells[slot];
	AttributeContainer& c = *state_of(s.map).cells[orbit_index(MR2_ORBITS[slot])];
	ci.down = c.add_attribute<uint32>("__mr_down", INVALID_INDEX);
	ci.level = c.add_attribute<uint8>("__mr_level", 0);
	ci.replaced = c.add_attribute<uint8>("__mr_replaced", MR_NOT_REPLACED);
}

void mr_index_level(MRState2& s, uint32 slot, uint32 l)
{
	AttributeContainer& c = *state_of(s.map).cells[orbit_index(MR2_ORBITS[slot])];
	AttributeArray<uint32>& index = *s.cells[slot].index;
	const auto level = s.level->view();
	// the cells first: writing lines while finding cells would change what
	// the next cells read
	std::vector<Dart> cells;
	mr_foreach_cell_by_darts(s, slot, l, [&](Dart d) { cells.push_back(d); });
	std::vector<double> weights;
	for (Dart d : cells)
	{
		// a dart of the cell that the level below has, and whether the cell
		// is the same there
		Dart old;
		uint32 nb_old = 0;
		mr_foreach_dart_of_slot(s, slot, l, d, [&](Dart x) {
			if (l > 0 && level[x.index] < l)
			{
				++nb_old;
				if (!old.is_valid())
					old = x;
			}
		});
		uint32 line = INVALID_INDEX;
		if (l == 0)
			line = mr_new_line(s, slot, 0, d, INVALID_INDEX);
		else if (slot == 0)
		{
			// a vertex gets a line at every level
			if (old.is_valid())
				line = mr_new_line(s, slot, l, old, mr_index_of(s, l - 1, 0, old));
			else
			{
				line = mr_new_line(s, slot, l, d, INVALID_INDEX);
				if (c.has_rules())
				{
					const std::vector<uint32> parents = mr_vertex_parents(s, l, d);
					weights.assign(parents.size(), parents.empty() ? 0.0 : 1.0 / double(parents.size()));
					if (!parents.empty())
						c.apply_rules(line, parents, weights);
				}
			}
		}
		else
		{
			if (slot == 2 && !old.is_valid())
				old = old_dart_of_sibling(s, l, d);
			const uint32 below = old.is_valid() ? mr_index_of(s, l - 1, slot, old) : INVALID_INDEX;
			uint32 nb_below = 0;
			if (old.is_valid())
				mr_foreach_dart_of_slot(s, slot, l - 1, old, [&](Dart) { ++nb_below; });
			// the same cell as below: all its darts of the level below are in it,
			// and (for an edge) it has no new dart
			const bool same = slot == 3 || (old.is_valid() && nb_old == nb_below && (slot != 1 || nb_old == 2));
			if (same)
				line = below;
			else
				line = mr_new_line(s, slot, l, d, below);
		}
		mr_foreach_dart_of_slot(s, slot, l, d, [&](Dart x) { index[x.index] = line; });
	}
}

void mr_unindex_level(MRState2& s, uint32 slot, uint32 l)
{
	MRCellIndex& ci = s.cells[slot];
	AttributeContainer& c = *state_of(s.map).cells[orbit_index(MR2_ORBITS[slot])];
	foreach_dart(s.map, [&](Dart d) {
		const uint32 i = (*ci.index)[d.index];
		if (i != INVALID_INDEX && (*ci.level)[i] == l)
			(*ci.index)[d.index] = (*ci.down)[i];
	});
	const auto key = c.key().view();
	for (uint32 i = 0, end = c.end_index(); i < end; ++i)
	{
		if (key[i] == INVALID_INDEX)
			continue;
		if ((*ci.level)[i] == l)
			c.release_line(i);
		else if ((*ci.replaced)[i] == l)
			(*ci.replaced)[i] = MR_NOT_REPLACED;
	}
}

} // namespace cgogn::detail

namespace cgogn
{

void detail::mr_index_orbit(MRMap2& m, Orbit o)
{
	MRState2& s = mr_state_of(m);
	const uint32 slot = mr_slot(o);
	AttributeContainer& darts = *state_of(s.map).darts;
	auto index = darts.add_attribute<uint32>("__mr_index_" + std::string(orbit_name(o)), INVALID_INDEX);
	s.cells[slot].index = index.get();
	state_of(s.map).cells[orbit_index(o)]->set_cell_index(index.get());
	mr_add_line_attributes(s, slot);
	for (uint32 l = 0; l <= max_level(m); ++l)
		mr_index_level(s, slot, l);
}

} // namespace cgogn
