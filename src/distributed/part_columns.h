// SPDX-License-Identifier: MIT
// The attributes a part message carries (columns of values by line) and the
// names of those it does not, shared by distribute() and the distributed
// refinements.
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/indexing.h>

#include "distribute_common.h"
#include "part_message.h"

#include <cstring>
#include <string>
#include <vector>

namespace cgogn::dist::detail
{

/// Names the user attributes of the cells of type CELL ("edge attribute
/// 'crease'") in names. O(attributes).
template <typename CELL, typename MAP>
void name_attributes_of(const MAP& m, std::vector<std::string>& names, const char* cells)
{
	if (!is_indexed<CELL>(m))
		return;
	const AttributeContainer& c = container_of<CELL::ORBIT>(m);
	for (const auto& a : c.attributes())
		if (a.get() != &c.key() && !cgogn::detail::is_reserved_name(a->name()))
			names.push_back(std::string(cells) + " attribute '" + a->name() + "'");
}

/// Adds to msg the values on `lines` of the container's attributes of a
/// carried type, except `skip`; names the others in msg.not_carried
/// ("volume attribute 'x' (of a type not carried)"). O(attributes x lines).
inline void add_columns(PartMessage& msg, const AttributeContainer& c, const std::vector<uint32>& lines,
						uint8 of_top_cells, const char* cells, const std::string& skip = {})
{
	for (const auto& a : c.attributes())
	{
		if (a.get() == &c.key() || cgogn::detail::is_reserved_name(a->name()) || a->name() == skip)
			continue;
		const int type = carried_type_of(*a);
		if (type < 0)
		{
			msg.not_carried.push_back(std::string(cells) + " attribute '" + a->name() + "' (of a type not carried)");
			continue;
		}
		PartMessage::Column& col = msg.columns.emplace_back();
		col.name = a->name();
		col.of_top_cells = of_top_cells;
		col.type = uint8(type);
		visit_carried_type(col.type, [&]<typename T>() {
			const auto& values = static_cast<const AttributeArray<T>&>(*a);
			col.values.resize(lines.size() * sizeof(T));
			for (std::size_t i = 0; i < lines.size(); ++i)
				std::memcpy(col.values.data() + i * sizeof(T), &values[lines[i]], sizeof(T));
		});
	}
}

} // namespace cgogn::dist::detail
