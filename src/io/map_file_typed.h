// SPDX-License-Identifier: MIT
// The typed part of the .cgmap reader and writer (see AttributeValues), for
// the TUs that instantiate it for a group of value types.
#pragma once

#include <cgogn/core/attributes/attributes.h>

#include "map_file_values.h"

namespace cgogn::io::detail
{

// Adds to `c` (the container of orbit o) an attribute of type T typed by o,
// as add_attribute<T, Cell<o>> would.
template <typename T>
std::shared_ptr<AttributeBase> add_attribute_of_orbit(AttributeContainer& c, Orbit o, const std::string& name,
													  const T& default_value)
{
	std::shared_ptr<AttributeBase> a;
	[&]<std::size_t... I>(std::index_sequence<I...>)
	{
		(
			[&] {
				constexpr Orbit X = Orbit(I);
				if constexpr (!is_direct_orbit(X))
					if (o == X)
						a = c.add_attribute<T, CellAttribute<T, X>>(name, default_value);
			}(),
			...);
	}
	(std::make_index_sequence<uint32(Orbit::NB_ORBITS)>{});
	return a;
}

template <typename T>
void write_values(std::string& out, const AttributeArray<T>& a, uint32 end)
{
	put_string(out, ValueCodec<T>::name());
	const std::size_t size_at = out.size();
	put_scalar<uint64>(out, 0); // the payload's size, known once written
	ValueCodec<T>::write(out, a.default_value());
	for (uint32 i = 0; i < end; ++i)
		ValueCodec<T>::write(out, a[i]);
	std::string size;
	put_scalar<uint64>(size, out.size() - size_at - sizeof(uint64));
	out.replace(size_at, sizeof(uint64), size);
}

template <typename T>
void read_values(AttributeRead& r)
{
	const T default_value = ValueCodec<T>::read(r.in);
	if (r.found == nullptr)
		r.found = add_attribute_of_orbit<T>(r.container, r.orbit, r.name, default_value);
	else if (r.found->type() != typeid(T))
		r.in.fail("attribute '" + r.name + "' is of type " + ValueCodec<T>::name() +
				  " in the file, but the map's own attribute of that name is not");
	auto& a = static_cast<AttributeArray<T>&>(*r.found);
	for (uint32 i = 0; i < r.end; ++i)
		a[i] = ValueCodec<T>::read(r.in);
}

template <typename... T>
bool AttributeValues<std::tuple<T...>>::write(std::string& out, const AttributeBase& a, uint32 end)
{
	return (
		(a.type() == typeid(T) ? (write_values(out, static_cast<const AttributeArray<T>&>(a), end), true) : false) ||
		...);
}

template <typename... T>
bool AttributeValues<std::tuple<T...>>::read(AttributeRead& r, std::string_view type)
{
	return ((type == ValueCodec<T>::name() ? (read_values<T>(r), true) : false) || ...);
}

} // namespace cgogn::io::detail
