// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/functions/indexing.h>
#include <cgogn/core/functions/mesh_access.h>

#include <memory>
#include <string>

namespace cgogn
{

namespace detail
{
inline bool is_reserved_name(const std::string& name)
{
	return name.rfind("__", 0) == 0;
}
/// The value of new lines: zero for types with a static Zero() (Eigen vectors
/// and matrices, whose default constructor leaves them uninitialized: g++ -O3
/// then warns, -Werror fails), T() otherwise.
template <typename T>
T default_attribute_value()
{
	if constexpr (requires {
					  { T::Zero() } -> std::convertible_to<T>;
				  })
		return T::Zero();
	else
		return T();
}
} // namespace detail

/// Adds an attribute of type T on cells of type CELL. The first attribute of an
/// orbit indexes its cells (O(number of darts), once); afterwards O(number of
/// cells). Returns nullptr when an attribute of this name exists on this orbit
/// or when the name is reserved (names starting with "__" are the library's).
template <typename T, typename CELL, typename MESH>
std::shared_ptr<Attribute<T>> add_attribute(MESH& m, const std::string& name)
{
	static_assert(CellType<CELL>, "add_attribute<T, CELL>: CELL must be a cell type");
	auto& map = map_of(m);
	if (detail::is_reserved_name(name))
		return nullptr;
	if (container_of<CELL::ORBIT>(map).find(name) != nullptr)
		return nullptr;
	if (!is_indexed<CELL>(map))
		index_cells<CELL>(map);
	return container_of<CELL::ORBIT>(map).template add_attribute<T>(name, detail::default_attribute_value<T>());
}

/// The attribute of type T on CELL named `name`; nullptr when there is none or
/// when it has another type. O(number of attributes of the orbit).
template <typename T, typename CELL, typename MESH>
std::shared_ptr<Attribute<T>> get_attribute(const MESH& m, const std::string& name)
{
	static_assert(CellType<CELL>, "get_attribute<T, CELL>: CELL must be a cell type");
	if (detail::is_reserved_name(name))
		return nullptr;
	return container_of<CELL::ORBIT>(map_of(m)).template get_attribute<T>(name);
}

/// Removes an attribute from its map. Handles kept elsewhere stay usable as
/// plain arrays but no longer belong to the map. The explicit template
/// arguments of the API guide's `remove_attribute<T, CELL>(m, attr)` are accepted
/// and ignored. Returns false when attr is not an attribute of m.
template <typename... Ignored, typename MESH, typename A>
bool remove_attribute(MESH& m, const std::shared_ptr<A>& attr)
{
	static_assert(std::is_base_of_v<AttributeBase, A>);
	if (!attr || attr->container() == nullptr)
		return false;
	const auto& map = map_of(m);
	bool mine = attr->container() == map.darts_.get();
	for (const auto& c : map.cells_)
		mine = mine || attr->container() == c.get();
	return mine && attr->container()->remove_attribute(attr.get());
}

/// The value of attribute attr for cell c. O(1). Precondition: attr is an
/// attribute of c's orbit in m (checked in debug builds).
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE T& value(const MESH& m, Attribute<T>& attr, Cell<O> c)
{
	const auto& map = map_of(m);
	assert(attr.container() == &container_of<O>(map) && "attribute of another orbit or map");
	return attr[index_of(map, c)];
}
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE const T& value(const MESH& m, const Attribute<T>& attr, Cell<O> c)
{
	const auto& map = map_of(m);
	assert(attr.container() == &container_of<O>(map) && "attribute of another orbit or map");
	return attr[index_of(map, c)];
}
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE T& value(const MESH& m, const std::shared_ptr<Attribute<T>>& attr, Cell<O> c)
{
	return value<T>(m, *attr, c);
}
/// The same for a cell reported by a cached traversal: its stored line is
/// used directly (no lookup of the dart's index). O(1).
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE T& value([[maybe_unused]] const MESH& m, Attribute<T>& attr, LocatedCell<O> c)
{
	assert(attr.container() == &container_of<O>(map_of(m)) && "attribute of another orbit or map");
	assert(c.line == index_of(map_of(m), Cell<O>(c)) && "stale cell line");
	return attr[c.line];
}
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE const T& value([[maybe_unused]] const MESH& m, const Attribute<T>& attr, LocatedCell<O> c)
{
	assert(attr.container() == &container_of<O>(map_of(m)) && "attribute of another orbit or map");
	assert(c.line == index_of(map_of(m), Cell<O>(c)) && "stale cell line");
	return attr[c.line];
}
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE T& value(const MESH& m, const std::shared_ptr<Attribute<T>>& attr, LocatedCell<O> c)
{
	return value<T>(m, *attr, c);
}

} // namespace cgogn
