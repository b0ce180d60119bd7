// SPDX-License-Identifier: MIT
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/modeling/adaptive_hexahedra.h>

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

namespace cgogn::modeling
{

uint32 refine_hexahedra(MRMap3& m, AttributeArray<Vec3>& position,
						const std::function<bool(const MRMap3&, MRMap3::Volume)>& refine, uint32 max_level)
{
	AttributeContainer* vertices = position.container();
	if (vertices != &detail::mr3_container<Orbit::PHI21_PHI31>(detail::mr_state_of(m)))
		throw std::invalid_argument("refine_hexahedra: the position is not a vertex attribute of the map");
	const uint32 initial_level = current_level(m);
	const AttributeRule rule = position.rule();
	// the hexahedral scheme's points are the means of the corners
	vertices->set_rule(position, AttributeRule::Interpolate);
	const auto leaves = [&] { return nb_cells<MRMap3::Volume>(level_view(m, cgogn::max_level(m))); };
	const uint32 leaves_before = leaves();
	try
	{
		for (;;)
		{
			set_current_level(m, cgogn::max_level(m));
			std::vector<std::pair<uint32, MRMap3::Volume>> selected; // with their levels
			foreach_cell(m, [&](MRMap3::Volume w) {
				const uint32 k = volume_level(m, w);
				if (k < max_level && refine(m, w))
					selected.emplace_back(k, w);
			});
			if (selected.empty())
				break;
			for (const auto& [k, w] : selected)
			{
				// a balancing subdivision may have refined it already
				set_current_level(m, k);
				if (!volume_is_subdivided(m, w))
					subdivide_volume(m, w);
			}
		}
	}
	catch (...)
	{
		vertices->set_rule(position, rule);
		set_current_level(m, std::min(initial_level, cgogn::max_level(m)));
		throw;
	}
	vertices->set_rule(position, rule);
	set_current_level(m, initial_level);
	// each subdivision turns a leaf into 8
	return (leaves() - leaves_before) / 7;
}

} // namespace cgogn::modeling
