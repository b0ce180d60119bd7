// SPDX-License-Identifier: MIT
// The typed part of the .cgmap reader and writer (see AttributeValues), for
// the TUs that instantiate it for a group of value types.
#pragma once

#include <cgogn/core/attributes/attributes.h>

#include "map_file_values.h"

#include <algorithm>
#include <bit>

namespace cgogn::io::detail
{

// Adds to `c` (the container of orbit o) an attribute of type T typed by o,
// with its type's default rule, as add_attribute<T, Cell<o>> would. One
// call through a table of the classes' factories, not a call per orbit
// (each of which would compile add_attribute for its class).
template <typename T>
std::shared_ptr<AttributeBase> add_attribute_of_orbit(AttributeContainer& c, Orbit o, const std::string& name,
													  const T& default_value)
{
	static constexpr std::array<AttributeContainer::Factory<T>, NB_ORBITS> factories =
		[]<std::size_t... I>(std::index_sequence<I...>)
	{
		return std::array<AttributeContainer::Factory<T>, NB_ORBITS>{
			cgogn::detail::cell_attribute_factory<T, Orbit(I)>()...};
	}
	(std::make_index_sequence<NB_ORBITS>{});
	if (orbit_index(o) >= NB_ORBITS || is_direct_orbit(o))
		return nullptr;
	std::shared_ptr<AttributeBase> a = c.add_attribute_made_by<T>(factories[orbit_index(o)], name, default_value);
	if (a)
		c.set_default_rule<T>(*a);
	return a;
}

template <typename T>
struct is_eigen_vector : std::false_type
{
};
template <int N>
struct is_eigen_vector<Eigen::Matrix<double, N, 1>> : std::true_type
{
};
template <typename T>
struct is_std_array : std::false_type
{
};
template <typename S, std::size_t K>
struct is_std_array<std::array<S, K>> : std::true_type
{
};

// Whether the values of T are, in memory, exactly their encoding in the
// file: then runs of lines are copied as they are, without a loop over the
// values (the difference between a save or a load at memory speed and one
// at a few hundred MB/s).
template <typename T>
constexpr bool is_bytes_as_encoded()
{
	if constexpr (std::endian::native != std::endian::little || std::is_same_v<T, bool>)
		return false;
	else if constexpr (std::is_arithmetic_v<T>)
		return true;
	else if constexpr (is_eigen_vector<T>::value)
		return sizeof(T) == sizeof(double) * std::size_t(T::RowsAtCompileTime);
	else if constexpr (is_std_array<T>::value)
		return std::is_arithmetic_v<typename T::value_type> && !std::is_same_v<typename T::value_type, bool> &&
			   sizeof(T) == sizeof(typename T::value_type) * std::tuple_size_v<T>;
	else
		return false;
}

template <typename T>
void write_values(ByteSink& out, const AttributeBase& base, uint32 end)
{
	const auto& a = static_cast<const AttributeArray<T>&>(base);
	put_string(out, ValueCodec<T>::name());
	uint64 payload = ValueCodec<T>::size(a.default_value());
	if constexpr (is_bytes_as_encoded<T>())
		payload += uint64(end) * sizeof(T);
	else
		for (uint32 i = 0; i < end; ++i)
			payload += ValueCodec<T>::size(a[i]);
	put_scalar<uint64>(out, payload);
	ValueCodec<T>::write(out, a.default_value());
	if constexpr (is_bytes_as_encoded<T>())
		for (uint32 i = 0; i < end;)
		{
			const uint32 run = std::min(a.run_end(i), end);
			out.append(reinterpret_cast<const char*>(&a[i]), std::size_t(run - i) * sizeof(T));
			i = run;
		}
	else
		for (uint32 i = 0; i < end; ++i)
			ValueCodec<T>::write(out, a[i]);
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
	if constexpr (is_bytes_as_encoded<T>())
	{
		r.in.check_count(r.end, sizeof(T), "attribute values");
		for (uint32 i = 0; i < r.end;)
		{
			const uint32 run = std::min(a.run_end(i), r.end);
			r.in.read_bytes(reinterpret_cast<char*>(&a[i]), std::size_t(run - i) * sizeof(T));
			i = run;
		}
	}
	else
		for (uint32 i = 0; i < r.end; ++i)
			a[i] = ValueCodec<T>::read(r.in);
}

template <typename... T>
typename AttributeValues<std::tuple<T...>>::Writer AttributeValues<std::tuple<T...>>::writer(const AttributeBase& a)
{
	Writer w = nullptr;
	(void)((a.type() == typeid(T) ? (w = &write_values<T>, true) : false) || ...);
	return w;
}

template <typename... T>
bool AttributeValues<std::tuple<T...>>::read(AttributeRead& r, std::string_view type)
{
	return ((type == ValueCodec<T>::name() ? (read_values<T>(r), true) : false) || ...);
}

} // namespace cgogn::io::detail
