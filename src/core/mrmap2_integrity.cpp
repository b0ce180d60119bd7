// SPDX-License-Identifier: MIT
#include <cgogn/core/properties/integrity.h>

#include "mr_line_checks.h"

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

	/// No boundary face has a line at level l.
	void check_boundary_faces(uint32 l)
	{
		const detail::MRCellIndex& ci = s_.cells[detail::MRDim<detail::MRState2>::face_slot];
		foreach_dart(s_.map, [&](Dart d) {
			if (level(d) <= l && is_boundary(s_.map, d) && (*ci.index)[d.index] != INVALID_INDEX)
				add(IntegrityError::Kind::BoundaryCellIndexed, d.index,
					"boundary face with a line at level " + std::to_string(l));
		});
	}

private:
	uint32 level(Dart d) const
	{
		return (*s_.level)[d.index];
	}
	bool finest(uint32 l) const
	{
		return detail::mr_is_finest(s_, l);
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
	const detail::MRReport add = [&](IntegrityError::Kind k, uint32 d, const std::string& what) { c.add(k, d, what); };
	for (uint32 slot = 0; slot < 4; ++slot)
	{
		if (s.cells[slot].index == nullptr || !detail::mr_check_chains(s, slot, add))
			continue;
		for (uint32 l = first; l <= last; ++l)
		{
			detail::mr_check_lines(s, slot, l, add);
			if (slot == detail::MRDim<detail::MRState2>::face_slot)
				c.check_boundary_faces(l);
		}
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
