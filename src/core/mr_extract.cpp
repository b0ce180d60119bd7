// SPDX-License-Identifier: MIT
// extract_level of the multiresolution maps of every dimension: the mesh of
// one level as a flat map, with its attributes' values at that level.
#include <cgogn/core/map/mrmap2_attributes.h>
#include <cgogn/core/map/mrmap3_attributes.h>
#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/operators/mrmap3.h>

#include "mr_indexing.h"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace cgogn
{

namespace
{

template <typename M>
auto extract(const M& m, uint32 l)
{
	if (l > max_level(m))
		throw std::out_of_range("extract_level: level " + std::to_string(l) + " above the finest level " +
								std::to_string(max_level(m)));
	const auto& s = detail::mr_state_of(m);
	using S = std::remove_cvref_t<decltype(s)>;
	typename detail::MRDim<S>::Flat flat;
	// one flat dart per dart of the level, in the order of the finest map
	std::vector<uint32> target(detail::state_of(s.map).darts->end_index(), INVALID_INDEX);
	std::vector<Dart> source;
	source.reserve(nb_darts(level_view(m, l)));
	const auto level = s.level->view();
	foreach_dart(s.map, [&](Dart d) {
		if (level[d.index] > l)
			return;
		target[d.index] = detail::add_dart(flat).index;
		source.push_back(d);
	});
	for (uint32 i = 0; i < source.size(); ++i)
	{
		const Dart d = source[i];
		detail::set_phi1(flat, Dart(i), Dart(target[detail::mr_phi1(s, l, d).index]));
		detail::set_phi2(flat, Dart(i), Dart(target[detail::mr_phi2(s, l, d).index]));
		if constexpr (std::is_same_v<S, detail::MRState3>)
			detail::set_phi3(flat, Dart(i), Dart(target[detail::mr_phi3(s, l, d).index]));
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
	for (uint32 slot = 0; slot < s.cells.size(); ++slot)
		detail::mr_copy_cell_attributes(s, slot, l, flat, source);
	detail::release_idle_marks(flat);
	return flat;
}

} // namespace

CMap2 extract_level(const MRMap2& m, uint32 l)
{
	return extract(m, l);
}

CMap3 extract_level(const MRMap3& m, uint32 l)
{
	return extract(m, l);
}

} // namespace cgogn
