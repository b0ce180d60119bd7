// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mesh_traits.h>

namespace cgogn
{

/// The map underlying a mesh: the map itself, or the map a view
/// (CellFilter, CellCache) looks at. Views add their own overloads.
template <typename MAP>
requires std::derived_from<MAP, CMapBase>
const MAP& map_of(const MAP& m)
{
	return m;
}
template <typename MAP>
requires std::derived_from<MAP, CMapBase> MAP& map_of(MAP& m)
{
	return m;
}

} // namespace cgogn
