// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_access.h>

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
					  {
						  T::Zero()
						  } -> std::convertible_to<T>;
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
/// The handle is a CellAttribute<T, CELL::ORBIT>: `(*attr)[c]` takes the cells
/// of that orbit; it converts to std::shared_ptr<mesh_traits<MESH>::Attribute<T>>.
/// The attribute's rule, what cells made by operators get, is its type's
/// default_rule(): Copy for integers and strings, Interpolate for linear
/// types, None for the rest (see attribute_rules.h to change it).
template <typename T, typename CELL, typename MESH>
std::shared_ptr<CellAttribute<T, CELL::ORBIT>> add_attribute(MESH& m, const std::string& name)
{
	static_assert(CellType<CELL>, "add_attribute<T, CELL>: CELL must be a cell type");
	auto& map = map_of(m);
	if (detail::is_reserved_name(name))
		return nullptr;
	if (container_of<CELL::ORBIT>(map).find(name) != nullptr)
		return nullptr;
	if (!is_indexed<CELL>(map))
		index_cells<CELL>(map);
	auto& container = container_of<CELL::ORBIT>(map);
	auto a =
		container.template add_attribute<T, CellAttribute<T, CELL::ORBIT>>(name, detail::default_attribute_value<T>());
	container.template set_default_rule<T>(*a);
	return a;
}

/// The attribute of type T on CELL named `name`; nullptr when there is none or
/// when it has another type. O(number of attributes of the orbit).
template <typename T, typename CELL, typename MESH>
std::shared_ptr<CellAttribute<T, CELL::ORBIT>> get_attribute(const MESH& m, const std::string& name)
{
	static_assert(CellType<CELL>, "get_attribute<T, CELL>: CELL must be a cell type");
	if (detail::is_reserved_name(name))
		return nullptr;
	auto a = container_of<CELL::ORBIT>(map_of(m)).template get_attribute<T>(name);
	// every attribute of a cell container was made by add_attribute<T, CELL>
	// (or cloned from one): its class is CellAttribute<T, CELL::ORBIT>
	assert((a == nullptr || dynamic_cast<CellAttribute<T, CELL::ORBIT>*>(a.get()) != nullptr));
	return std::static_pointer_cast<CellAttribute<T, CELL::ORBIT>>(a);
}

/// Removes an attribute from its map. Handles kept elsewhere stay usable as
/// plain arrays but no longer belong to the map. The explicit template
/// arguments of the CGoGN API guide's `remove_attribute<T, CELL>(m, attr)` are accepted
/// and ignored. Returns false when attr is not an attribute of m.
template <typename... Ignored, typename MESH, typename A>
bool remove_attribute(MESH& m, const std::shared_ptr<A>& attr)
{
	static_assert(std::is_base_of_v<AttributeBase, A>);
	if (!attr || attr->container() == nullptr)
		return false;
	const auto& map = map_of(m);
	bool mine = attr->container() == detail::state_of(map).darts.get();
	for (const auto& c : detail::state_of(map).cells)
		mine = mine || attr->container() == c.get();
	return mine && attr->container()->remove_attribute(attr.get());
}

namespace detail
{
/// value()'s result: read-only when the mesh is const.
template <typename MESH, typename T>
using value_ref_t = std::conditional_t<std::is_const_v<MESH>, const T&, T&>;
} // namespace detail

/// The value of attribute attr for cell c. O(1). Precondition: attr is an
/// attribute of c's orbit in m (checked in debug builds). The reference is
/// read-only when m is const. Same as `attr[c]`.
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE detail::value_ref_t<MESH, T> value(MESH& m, AttributeArray<T>& attr, Cell<O> c)
{
	const auto& map = map_of(m);
	assert(attr.container() == &container_of<O>(map) && "attribute of another orbit or map");
	return attr[index_of(map, c)];
}
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE const T& value(const MESH& m, const AttributeArray<T>& attr, Cell<O> c)
{
	const auto& map = map_of(m);
	assert(attr.container() == &container_of<O>(map) && "attribute of another orbit or map");
	return attr[index_of(map, c)];
}
/// The same for a cell reported by a cached traversal: its stored line is
/// used directly (no lookup of the dart's index). O(1).
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE detail::value_ref_t<MESH, T> value([[maybe_unused]] MESH& m, AttributeArray<T>& attr, LocatedCell<O> c)
{
	assert(attr.container() == &container_of<O>(map_of(m)) && "attribute of another orbit or map");
	assert(c.line == index_of(map_of(m), Cell<O>(c)) && "stale cell line");
	return attr[c.line];
}
template <typename T, typename MESH, Orbit O>
CGOGN_INLINE const T& value([[maybe_unused]] const MESH& m, const AttributeArray<T>& attr, LocatedCell<O> c)
{
	assert(attr.container() == &container_of<O>(map_of(m)) && "attribute of another orbit or map");
	assert(c.line == index_of(map_of(m), Cell<O>(c)) && "stale cell line");
	return attr[c.line];
}
/// The same through a handle (what add_attribute and get_attribute return).
/// T, when given (the CGoGN API guide's `value<double>(m, area, f)`), must be the
/// attribute's value type.
template <typename T = void, typename MESH, typename A, typename CELL>
requires std::derived_from<A, AttributeBase> && CellType<CELL> CGOGN_INLINE decltype(auto)
value(MESH& m, const std::shared_ptr<A>& attr, CELL c)
{
	using V = typename A::value_type;
	static_assert(std::is_void_v<T> || std::is_same_v<T, V>, "value<T>(m, attr, c): T is not the attribute's type");
	using Array = std::conditional_t<std::is_const_v<A>, const AttributeArray<V>, AttributeArray<V>>;
	return value<V>(m, static_cast<Array&>(*attr), c);
}

} // namespace cgogn
