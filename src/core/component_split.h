// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/marking/marker.h>

#include <array>
#include <cstdint>
#include <vector>

namespace cgogn::detail
{

/// Number of darts the reindexing of operators has visited in this thread
/// since the last reset: lets tests assert that an operator's reindexing stays
/// within the cells it touched. Not a timing; one increment per visited dart.
std::uint64_t reindexed_dart_count();
void reset_reindexed_dart_count();
void count_reindexed_darts(std::uint64_t n);

/// The darts joined to d by phi1, phi2 (and phi3), or by beta0, beta1, beta2
/// (and beta3) in a G-map, by every relation in the maps of any dimension:
/// walking them from a dart visits its connected component.
template <typename MAP>
std::array<Dart, MAP::dimension + (is_gmap_v<MAP> ? 1 : 0)> linked_darts(const MAP& m, Dart d)
{
	if constexpr (is_nmap_v<MAP>)
	{
		std::array<Dart, MAP::dimension + (is_gmap_v<MAP> ? 1 : 0)> r;
		uint32 k = 0;
		if constexpr (is_gmap_v<MAP>)
			r[k++] = Dart(d.index ^ 1u);
		for (uint32 i = 1; i <= MAP::dimension; ++i)
			r[k++] = relation(m, i, d);
		return r;
	}
	else if constexpr (is_gmap_v<MAP> && MAP::dimension >= 3)
		return {beta0(m, d), beta1(m, d), beta2(m, d), beta3(m, d)};
	else if constexpr (is_gmap_v<MAP> && MAP::dimension == 2)
		return {beta0(m, d), beta1(m, d), beta2(m, d)};
	else if constexpr (is_gmap_v<MAP>)
		return {beta0(m, d), beta1(m, d)};
	else if constexpr (MAP::dimension >= 3)
		return {phi1(m, d), phi2(m, d), phi3(m, d)};
	else
		return {phi1(m, d), phi2(m, d)};
}

/// What walking from a and b at once found (detached_part).
struct PartSearch
{
	bool apart = false; // the walks did not meet: a and b are no longer connected
	int ended = 0;      // when apart, the side whose walk ended: 0 for a, 1 for b
	/// When apart, the whole component of the side that ended; otherwise the
	/// darts walked from a, all in b's component.
	std::vector<Dart> darts;
};

/// Whether an edit has cut a and b apart, found by walking both components at
/// once, one dart each in turn, until the walks meet or one of them ends (it
/// has then met its whole component). O(darts met before the walks meet or
/// the smaller component ends), never the whole mesh unless the parts are
/// joined only far away.
template <typename MAP>
PartSearch detached_part(const MAP& m, Dart a, Dart b)
{
	if (a == b)
		return {false, 0, {a}};
	DartMarkerStore<MAP> seen_a(m), seen_b(m);
	std::vector<Dart> walk_a{a}, walk_b{b};
	std::size_t next_a = 0, next_b = 0;
	seen_a.mark(a);
	seen_b.mark(b);
	// one step of a walk: false when it met the other walk
	const auto step = [&](std::vector<Dart>& walk, std::size_t& next, DartMarkerStore<MAP>& mine,
						  const DartMarkerStore<MAP>& other) {
		for (Dart x : linked_darts(m, walk[next++]))
		{
			if (other.is_marked(x))
				return false;
			if (!mine.is_marked(x))
			{
				mine.mark(x);
				walk.push_back(x);
			}
		}
		return true;
	};
	PartSearch result;
	for (;;)
	{
		if (next_a == walk_a.size())
		{
			result = {true, 0, std::move(walk_a)};
			break;
		}
		if (!step(walk_a, next_a, seen_a, seen_b))
			break;
		if (next_b == walk_b.size())
		{
			result = {true, 1, std::move(walk_b)};
			break;
		}
		if (!step(walk_b, next_b, seen_b, seen_a))
			break;
	}
	if (!result.apart)
		result.darts = std::move(walk_a);
	count_reindexed_darts(seen_a.marked_darts().size() + seen_b.marked_darts().size());
	return result;
}

/// Component lines after an edit that may have cut the component of line
/// `line` into parts, each holding at least one dart of `seeds` (live darts).
/// Precondition: every dart of those parts carries `line`. The part that no
/// walk ended in (the larger one, when two parts are compared) keeps `line`;
/// every other part, walked whole by detached_part, gets a new line. A seed
/// met by an earlier walk is not searched again. O(seeds x parts x the cost
/// of detached_part).
template <typename CELL, typename MAP>
void split_component_lines(MAP& m, uint32 line, const std::vector<Dart>& seeds)
{
	constexpr Orbit O = CELL::ORBIT;
	struct Part
	{
		Dart seed;
		std::vector<Dart> darts; // its whole component, when a walk ended in it
		bool walked = false;
	};
	std::vector<Part> parts;
	DartMarkerStore<MAP> placed(m); // darts known to lie in one of the parts
	const auto place = [&](const std::vector<Dart>& darts) {
		for (Dart d : darts)
			placed.mark(d);
	};
	for (Dart s : seeds)
	{
		if (placed.is_marked(s))
			continue;
		Part candidate{s, {}, false};
		bool known = false;
		for (Part& p : parts)
		{
			PartSearch found = detached_part(m, s, p.seed);
			if (!found.apart)
			{
				place(found.darts);
				known = true;
				break;
			}
			Part& ended = found.ended == 0 ? candidate : p;
			if (!ended.walked)
			{
				place(found.darts);
				ended.darts = std::move(found.darts);
				ended.walked = true;
			}
		}
		if (!known)
		{
			placed.mark(s);
			parts.push_back(std::move(candidate));
		}
	}
	if (parts.empty())
		return;
	std::size_t keeper = 0;
	for (std::size_t i = 0; i < parts.size(); ++i)
		if (!parts[i].walked)
			keeper = i;
	AttributeContainer& cells = *detail::state_of(m).cells[orbit_index(O)];
	AttributeArray<uint32>& idx = *detail::state_of(m).cell_index[orbit_index(O)];
	cells.key()[line] = parts[keeper].seed.index;
	for (std::size_t i = 0; i < parts.size(); ++i)
		if (i != keeper)
		{
			const uint32 l = cells.new_line(parts[i].seed.index);
			for (Dart d : parts[i].darts)
				idx[d.index] = l;
			detail::inherit_line<O>(m, l, line); // a part of the component that came apart
		}
}

/// Writes line `to` on the darts that carry line `from` and are reached from
/// `start` through such darts: after a sew joined two components, the part
/// that carried `from` takes the other's line. Precondition: `start` carries
/// `from`. O(size of that part).
template <typename CELL, typename MAP>
void relabel_part(MAP& m, Dart start, uint32 from, uint32 to)
{
	AttributeArray<uint32>& idx = *detail::state_of(m).cell_index[orbit_index(CELL::ORBIT)];
	std::vector<Dart> pending{start};
	idx[start.index] = to;
	std::uint64_t walked = 1;
	while (!pending.empty())
	{
		const Dart d = pending.back();
		pending.pop_back();
		for (Dart x : linked_darts(m, d))
			if (idx[x.index] == from)
			{
				idx[x.index] = to;
				pending.push_back(x);
				++walked;
			}
	}
	count_reindexed_darts(walked);
}

} // namespace cgogn::detail
