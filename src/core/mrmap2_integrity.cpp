// SPDX-License-Identifier: MIT
#include <cgogn/core/properties/integrity.h>

#include "mrmap2_indexing.h"

#include <optional>
#include <string>
#include <vector>

namespace cgogn
{

namespace
{

/// Checks a multiresolution 2-map with walks that give up instead of looping
/// when the labels are broken.
class MRChecker
{
public:
	MRChecker(const detail::MRState2& s, IntegrityReport& r)
		: s_(s), report_(r), limit_(detail::state_of(s.map).darts->end_index() + 1)
	{
	}

	void add(IntegrityError::Kind k, uint32 dart, const std::string& what)
	{
		++report_.nb_errors;
		if (report_.errors.size() >= 1000)
			return;
		std::string msg = what;
		if (dart != INVALID_INDEX)
			msg += " (dart " + std::to_string(dart) + ")";
		report_.errors.push_back({k, Orbit::DART, dart, INVALID_INDEX, msg});
	}

	/// The per-level counts and the edge ids.
	void check_labels()
	{
		const uint32 nb_levels = uint32(s_.darts_per_level.size());
		std::vector<uint32> count(nb_levels, 0);
		foreach_dart(s_.map, [&](Dart d) {
			const uint32 l = level(d);
			if (l >= nb_levels)
				add(IntegrityError::Kind::LevelCountWrong, d.index,
					"dart of level " + std::to_string(l) + " above the finest level");
			else
				++count[l];
			const uint8 id = (*s_.edge_id)[d.index];
			if (id > 2)
				add(IntegrityError::Kind::EdgeIdWrong, d.index, "edge id " + std::to_string(id) + " above 2");
			else if (id != (*s_.edge_id)[cgogn::phi2(s_.map, d).index])
				add(IntegrityError::Kind::EdgeIdWrong, d.index, "the two darts of an edge have different edge ids");
		});
		for (uint32 l = 0; l < nb_levels; ++l)
			if (count[l] != s_.darts_per_level[l])
				add(IntegrityError::Kind::LevelCountWrong, INVALID_INDEX,
					"level " + std::to_string(l) + " counts " + std::to_string(s_.darts_per_level[l]) +
						" darts, holds " + std::to_string(count[l]));
	}

	/// The relations at level l.
	void check_level(uint32 l)
	{
		const std::string at = " at level " + std::to_string(l);
		std::vector<uint8> hit(detail::state_of(s_.map).darts->end_index(), 0);
		foreach_dart(s_.map, [&](Dart d) {
			if (level(d) > l)
				return;
			const std::optional<Dart> p = phi1(l, d);
			if (!p || level(*p) > l)
			{
				add(IntegrityError::Kind::LevelRelationBroken, d.index, "phi1 leaves the level" + at);
				return;
			}
			if (hit[p->index]++)
				add(IntegrityError::Kind::Phi1NotPermutation, p->index, "two darts have this phi1" + at);
			if (phi_1(l, *p) != d)
				add(IntegrityError::Kind::LevelRelationBroken, d.index, "phi_1 is not the inverse of phi1" + at);
			if (is_boundary(s_.map, *p) != is_boundary(s_.map, d))
				add(IntegrityError::Kind::BoundaryMarkNotConstant, d.index,
					"boundary mark not constant on a face" + at);
			if (!is_boundary(s_.map, d) && phi1(l, *p) == d)
				add(IntegrityError::Kind::ShortFace, d.index, "face of fewer than 3 edges" + at);
			const std::optional<Dart> t = phi2(l, d);
			if (!t || level(*t) > l)
			{
				add(IntegrityError::Kind::LevelRelationBroken, d.index, "phi2 leaves the level" + at);
				return;
			}
			if (*t == d)
				add(IntegrityError::Kind::PhiFixedPoint, d.index, "phi2 fixed point" + at);
			else if (phi2(l, *t) != d)
				add(IntegrityError::Kind::PhiNotInvolution, d.index, "phi2 not an involution" + at);
			if (is_boundary(s_.map, d) && is_boundary(s_.map, *t))
				add(IntegrityError::Kind::BoundaryLinked, d.index, "phi2 links two boundary darts" + at);
		});
	}

	/// The chains of lines of an indexed slot: each line refines a live line
	/// of a lower level (so that reading a line at a level ends). Returns
	/// false when one does not.
	bool check_chains(uint32 slot)
	{
		const detail::MRCellIndex& ci = s_.cells[slot];
		const AttributeContainer& c = container(slot);
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
					"line " + std::to_string(i) + " of orbit " + std::string(orbit_name(detail::MR2_ORBITS[slot])) +
						" refines a line that is free, not coarser, or not replaced by then");
			}
		}
		return ok;
	}

	/// The lines of an indexed slot at level l.
	void check_lines(uint32 slot, uint32 l)
	{
		const std::string at = std::string(" of orbit ") + std::string(orbit_name(detail::MR2_ORBITS[slot])) +
							   " at level " + std::to_string(l);
		const detail::MRCellIndex& ci = s_.cells[slot];
		const AttributeContainer& c = container(slot);
		const auto key = c.key().view();
		std::vector<uint8> used(c.end_index(), 0);
		uint32 nb_cells = 0;
		detail::mr_foreach_cell_by_darts(s_, slot, l, [&](Dart d) {
			++nb_cells;
			const uint32 i = index_of(slot, l, d);
			if (i == INVALID_INDEX || i >= c.end_index() || key[i] == INVALID_INDEX)
			{
				add(IntegrityError::Kind::MissingIndex, d.index, "cell without a live line" + at);
				return;
			}
			if ((*ci.level)[i] > l || (*ci.replaced)[i] <= l)
				add(IntegrityError::Kind::LevelLineWrong, d.index, "line " + std::to_string(i) + " does not hold" + at);
			bool representative = false;
			detail::mr_foreach_dart_of_slot(s_, slot, l, d, [&](Dart x) {
				representative = representative || x.index == key[i];
				if (index_of(slot, l, x) != i)
					add(IntegrityError::Kind::IndexNotConstant, x.index,
						"two darts of a cell read different lines" + at);
			});
			if (!representative)
				add(IntegrityError::Kind::BadRepresentative, d.index,
					"the representative of line " + std::to_string(i) + " is not a dart of its cell" + at);
			if (used[i]++ == 1)
				add(IntegrityError::Kind::IndexShared, d.index, "line " + std::to_string(i) + " shared" + at);
		});
		uint32 nb_lines = 0;
		detail::mr_foreach_line_at_level(s_, slot, l, 0, c.end_index(), [&](uint32) { ++nb_lines; });
		if (nb_lines != nb_cells)
			add(IntegrityError::Kind::LevelLineWrong, INVALID_INDEX,
				std::to_string(nb_lines) + " lines hold for " + std::to_string(nb_cells) + " cells" + at);
		if (slot == 2)
			foreach_dart(s_.map, [&](Dart d) {
				if (level(d) <= l && is_boundary(s_.map, d) && (*ci.index)[d.index] != INVALID_INDEX)
					add(IntegrityError::Kind::BoundaryCellIndexed, d.index, "boundary face with a line" + at);
			});
	}

private:
	const AttributeContainer& container(uint32 slot) const
	{
		return *detail::state_of(s_.map).cells[orbit_index(detail::MR2_ORBITS[slot])];
	}
	uint32 level(Dart d) const
	{
		return (*s_.level)[d.index];
	}
	bool finest(uint32 l) const
	{
		return detail::mr_is_finest(s_, l);
	}
	/// detail::mr_index_of following live lines only (their chains were
	/// checked: each link leads to a coarser live line), so that a dart
	/// holding a free or missing line (a broken file) ends the walk:
	/// INVALID_INDEX then.
	uint32 index_of(uint32 slot, uint32 l, Dart d) const
	{
		const detail::MRCellIndex& ci = s_.cells[slot];
		const AttributeContainer& c = container(slot);
		const uint32 end = c.end_index();
		uint32 i = (*ci.index)[d.index];
		while (i < end && c.key()[i] != INVALID_INDEX && !finest(l) && (*ci.level)[i] > l)
			i = (*ci.down)[i];
		return i < end && c.key()[i] != INVALID_INDEX ? i : INVALID_INDEX;
	}

	/// mr_phi1 and mr_phi_1 giving up after more steps than there are darts.
	std::optional<Dart> phi1(uint32 l, Dart d) const
	{
		const Dart r = detail::mr_phi1(s_, l, d, detail::MRStepLimit{limit_});
		return r.is_valid() ? std::optional<Dart>(r) : std::nullopt;
	}
	std::optional<Dart> phi_1(uint32 l, Dart d) const
	{
		const Dart r = detail::mr_phi_1(s_, l, d, detail::MRStepLimit{limit_});
		return r.is_valid() ? std::optional<Dart>(r) : std::nullopt;
	}
	std::optional<Dart> phi2(uint32 l, Dart d) const
	{
		if (finest(l))
			return cgogn::phi2(s_.map, d);
		const std::optional<Dart> p = phi1(l, d);
		if (!p)
			return std::nullopt;
		return cgogn::phi2(s_.map, cgogn::phi_1(s_.map, *p));
	}

	const detail::MRState2& s_;
	IntegrityReport& report_;
	uint32 limit_;
};

IntegrityReport check_levels(const detail::MRState2& s, uint32 first, uint32 last)
{
	IntegrityReport r = check_integrity(s.map);
	if (!r.ok())
		return r; // the level walks assume a sound finest map
	MRChecker c(s, r);
	c.check_labels();
	if (!r.ok())
		return r;
	for (uint32 l = first; l <= last; ++l)
		c.check_level(l);
	if (!r.ok())
		return r; // the lines are read through the level relations
	for (uint32 slot = 0; slot < 4; ++slot)
	{
		if (s.cells[slot].index == nullptr || !c.check_chains(slot))
			continue;
		for (uint32 l = first; l <= last; ++l)
			c.check_lines(slot, l);
	}
	return r;
}

} // namespace

IntegrityReport check_integrity(const MRMap2& m)
{
	return check_levels(detail::mr_state_of(m), 0, max_level(m));
}

IntegrityReport check_integrity(const MRLevelView2& v)
{
	return check_levels(v.state(), v.level(), v.level());
}

} // namespace cgogn
