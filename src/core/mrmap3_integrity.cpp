// SPDX-License-Identifier: MIT
// check_integrity of a multiresolution 3-map.
#include <cgogn/core/properties/integrity.h>
#include <cgogn/core/traversals/local_mrmap3.h>

#include "mr_line_checks.h"

#include <optional>
#include <string>
#include <vector>

namespace cgogn
{

namespace
{

/// Checks a multiresolution 3-map with walks that give up instead of looping
/// when the labels are broken.
class MR3Checker
{
public:
	MR3Checker(const detail::MRState3& s, IntegrityReport& r)
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

	/// The per-level counts, and the ids constant on the finest edges and faces.
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
			if ((*s_.edge_id)[d.index] != (*s_.edge_id)[cgogn::phi2(s_.map, d).index] ||
				(*s_.edge_id)[d.index] != (*s_.edge_id)[cgogn::phi3(s_.map, d).index])
				add(IntegrityError::Kind::EdgeIdWrong, d.index, "the darts of an edge have different edge ids");
			if ((*s_.face_id)[d.index] != (*s_.face_id)[cgogn::phi1(s_.map, d).index] ||
				(*s_.face_id)[d.index] != (*s_.face_id)[cgogn::phi3(s_.map, d).index])
				add(IntegrityError::Kind::FaceIdWrong, d.index, "the darts of a face have different face ids");
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
		const auto in_level = [&](const std::optional<Dart>& x) { return x && level(*x) <= l; };
		foreach_dart(s_.map, [&](Dart d) {
			if (level(d) > l)
				return;
			const std::optional<Dart> p = phi1(l, d);
			if (!in_level(p))
			{
				add(IntegrityError::Kind::LevelRelationBroken, d.index, "phi1 leaves the level" + at);
				return;
			}
			if (hit[p->index]++)
				add(IntegrityError::Kind::Phi1NotPermutation, p->index, "two darts have this phi1" + at);
			if (phi_1(l, *p) != d)
				add(IntegrityError::Kind::LevelRelationBroken, d.index, "phi_1 is not the inverse of phi1" + at);
			const std::optional<Dart> t = phi2(l, d), u = phi3(l, d);
			if (!in_level(t) || !in_level(u))
			{
				add(IntegrityError::Kind::LevelRelationBroken, d.index, "phi2 or phi3 leaves the level" + at);
				return;
			}
			if (is_boundary(s_.map, *p) != is_boundary(s_.map, d) || is_boundary(s_.map, *t) != is_boundary(s_.map, d))
				add(IntegrityError::Kind::BoundaryMarkNotConstant, d.index,
					"boundary mark not constant on a volume" + at);
			if (*t == d || *u == d)
				add(IntegrityError::Kind::PhiFixedPoint, d.index, "phi2 or phi3 fixed point" + at);
			else if (phi2(l, *t) != d || phi3(l, *u) != d)
				add(IntegrityError::Kind::PhiNotInvolution, d.index, "phi2 or phi3 not an involution" + at);
			else if (const std::optional<Dart> w = phi1(l, *u), x = w ? phi3(l, *w) : std::nullopt;
					 !x || phi1(l, *x) != std::optional<Dart>(d))
				add(IntegrityError::Kind::PhiNotInvolution, d.index, "phi3 o phi1 not an involution" + at);
			if (is_boundary(s_.map, d) && is_boundary(s_.map, *u))
				add(IntegrityError::Kind::BoundaryLinked, d.index, "phi3 links two boundary darts" + at);
		});
	}

private:
	uint32 level(Dart d) const
	{
		return (*s_.level)[d.index];
	}

	/// The level relations, giving up after more steps than there are darts.
	std::optional<Dart> phi1(uint32 l, Dart d) const
	{
		return valid(detail::mr_phi1(s_, l, d, detail::MRStepLimit{limit_}));
	}
	std::optional<Dart> phi_1(uint32 l, Dart d) const
	{
		return valid(detail::mr_phi_1(s_, l, d, detail::MRStepLimit{limit_}));
	}
	std::optional<Dart> phi2(uint32 l, Dart d) const
	{
		const Dart x = detail::mr_last_piece(s_, l, d, detail::MRStepLimit{limit_});
		return x.is_valid() ? std::optional<Dart>(cgogn::phi2(s_.map, x)) : std::nullopt;
	}
	std::optional<Dart> phi3(uint32 l, Dart d) const
	{
		const Dart x = detail::mr_last_piece(s_, l, d, detail::MRStepLimit{limit_});
		return x.is_valid() ? std::optional<Dart>(cgogn::phi3(s_.map, x)) : std::nullopt;
	}
	static std::optional<Dart> valid(Dart d)
	{
		return d.is_valid() ? std::optional<Dart>(d) : std::nullopt;
	}

	const detail::MRState3& s_;
	IntegrityReport& report_;
	uint32 limit_;
};

IntegrityReport check_levels(const detail::MRState3& s, uint32 first, uint32 last)
{
	IntegrityReport r = check_integrity(s.map);
	if (!r.ok())
		return r; // the level walks assume a sound finest map
	MR3Checker c(s, r);
	c.check_labels();
	if (!r.ok())
		return r;
	for (uint32 l = first; l <= last; ++l)
		c.check_level(l);
	if (!r.ok())
		return r; // the lines are read through the level relations
	const detail::MRReport add = [&](IntegrityError::Kind k, uint32 d, const std::string& what) { c.add(k, d, what); };
	for (uint32 slot = 0; slot < s.cells.size(); ++slot)
	{
		if (s.cells[slot].index == nullptr || !detail::mr_check_chains(s, slot, add))
			continue;
		for (uint32 l = first; l <= last; ++l)
			detail::mr_check_lines(s, slot, l, add);
	}
	return r;
}

} // namespace

IntegrityReport check_integrity(const MRMap3& m)
{
	return check_levels(detail::mr_state_of(m), 0, max_level(m));
}

IntegrityReport check_integrity(const MRLevelView3& v)
{
	return check_levels(v.state(), v.level(), v.level());
}

} // namespace cgogn
