// SPDX-License-Identifier: MIT
// Copying attribute values between two maps' containers (merge of 2-maps,
// conversions between CMap2 and GMap2).
#pragma once

#include <cgogn/core/attributes/attribute_container.h>

namespace cgogn::detail
{

/// Copies the user attributes of `from` (not its key, not the "__" ones) into
/// `to`, creating those `to` lacks (typed by `to`'s orbit, see clone_empty);
/// an attribute of the same name and another type in `to` is left alone.
/// lines_of(i, put) calls put(line) on each line of `to` that takes the
/// values of live line i of `from`. O(lines x attributes).
template <typename LINES>
void copy_attributes(const AttributeContainer& from, AttributeContainer& to, const LINES& lines_of)
{
	for (const auto& a : from.attributes())
	{
		if (a.get() == &from.key() || a->name().rfind("__", 0) == 0)
			continue;
		auto target = to.find(a->name());
		if (target && target->type() != a->type())
			continue;
		if (!target)
			target = a->clone_empty(to);
		for (uint32 i = 0; i < from.end_index(); ++i)
			if (from.is_live(i))
				lines_of(i, [&](uint32 line) { target->copy_line_from(line, *a, i); });
	}
}

} // namespace cgogn::detail
