// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_access.h>

#include <concepts>
#include <functional>
#include <tuple>
#include <vector>

namespace cgogn
{

/// A view on a mesh (CellFilter, CellCache): usable as a mesh by traversals
/// and generic algorithms; it reads the map it looks at and never owns it.
/// A view declares `using MeshViewTag = void;`, `mesh()` (the viewed mesh)
/// and `accepts(c)` (whether a cell of any type belongs to the view).
template <typename V>
concept MeshView = requires(const V& v)
{
	typename V::MeshViewTag;
	v.mesh();
};

/// The map under a view (and under views of views). O(depth of nesting).
template <MeshView V>
const typename mesh_traits<V>::MapType& map_of(const V& v)
{
	return map_of(v.mesh());
}

/// The index of c in the map under the view (see index_of on maps). O(1).
template <MeshView V, Orbit O>
uint32 index_of(const V& v, Cell<O> c)
{
	return index_of(map_of(v), c);
}

/// Whether the orbit of CELL is indexed in the map under the view. O(1).
template <typename CELL, MeshView V>
bool is_indexed(const V& v)
{
	return is_indexed<CELL>(map_of(v));
}

namespace detail
{
/// std::tuple<W<C>...> for a tuple of cell types std::tuple<C...>.
template <typename TUPLE, template <typename> class W>
struct per_cell_type;
template <typename... C, template <typename> class W>
struct per_cell_type<std::tuple<C...>, W>
{
	using type = std::tuple<W<C>...>;
};
template <typename CELL>
using CellPredicate = std::function<bool(CELL)>;
template <typename CELL>
using CellVector = std::vector<CELL>;
} // namespace detail

} // namespace cgogn
