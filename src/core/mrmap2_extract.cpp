// SPDX-License-Identifier: MIT
#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/traversals/global.h>

#include "mrmap2_indexing.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn
{

namespace
{

/// Copies the attributes of the orbit of CELL at level l of s into the flat
/// map `flat`, whose dart i is the hierarchy's dart source[i].
template <typename CELL>
void copy_cell_attributes(const detail::MRState2& s, uint32 l, CMap2& flat, const std::vector<Dart>& source)
{
	constexpr Orbit O = CELL::ORBIT;
	constexpr uint32 slot = detail::mr_slot(O);
	if (s.cells[slot].index == nullptr)
		return;
	const AttributeContainer& from = *detail::state_of(s.map).cells[orbit_index(O)];
	std::vector<std::pair<const AttributeBase*, std::shared_ptr<AttributeBase>>> copies;
	for (const auto& a : from.attributes())
		if (a.get() != &from.key() && a->name().rfind("__", 0) != 0)
		{
			if (!is_indexed<CELL>(flat))
				index_cells<CELL>(flat);
			copies.emplace_back(a.get(), a->clone_empty(container_of<O>(flat)));
		}
	if (copies.empty())
		return;
	foreach_cell(flat, [&](CELL c) {
		const uint32 src = detail::mr_index_of(s, l, slot, source[c.dart.index]);
		const uint32 dst = index_of(flat, c);
		for (auto& [a, b] : copies)
			b->copy_line_from(dst, *a, src);
	});
}

} // namespace

CMap2 extract_level(const MRMap2& m, uint32 l)
{
	if (l > max_level(m))
		throw std::out_of_range("extract_level: level " + std::to_string(l) + " above the finest level " +
								std::to_string(max_level(m)));
	const detail::MRState2& s = detail::mr_state_of(m);
	CMap2 flat;
	// one flat dart per dart of the level, in the order of the finest map
	std::vector<uint32> target(detail::state_of(s.map).darts->end_index(), INVALID_INDEX);
	std::vector<Dart> source;
	source.reserve(nb_darts(level_view(m, l)));
	const auto level = s.level->view();
	foreach_dart(s.map, [&](Dart d) {
		if (level[d.index] > l)
			return;
		const Dart f = detail::add_dart(flat);
		target[d.index] = f.index;
		source.push_back(d);
	});
	for (uint32 i = 0; i < source.size(); ++i)
	{
		const Dart d = source[i];
		detail::set_phi1(flat, Dart(i), Dart(target[detail::mr_phi1(s, l, d).index]));
		detail::set_phi2(flat, Dart(i), Dart(target[detail::mr_phi2(s, l, d).index]));
		if (is_boundary(s.map, d))
			detail::set_boundary(flat, Dart(i), true);
	}
	// per-dart attributes, then those of the cells
	const AttributeContainer& darts = *detail::state_of(s.map).darts;
	for (const auto& a : darts.attributes())
	{
		if (a.get() == &darts.key() || a->name().rfind("__", 0) == 0)
			continue;
		auto b = a->clone_empty(*detail::state_of(flat).darts);
		for (uint32 i = 0; i < source.size(); ++i)
			b->copy_line_from(i, *a, source[i].index);
	}
	copy_cell_attributes<CMap2::Vertex>(s, l, flat, source);
	copy_cell_attributes<CMap2::Edge>(s, l, flat, source);
	copy_cell_attributes<CMap2::Face>(s, l, flat, source);
	copy_cell_attributes<CMap2::Volume>(s, l, flat, source);
	detail::release_idle_marks(flat);
	return flat;
}

} // namespace cgogn
