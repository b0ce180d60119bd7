// SPDX-License-Identifier: MIT
// What the root and the ranks of distribute() share: the attribute types it
// carries.
#pragma once

#include <cgogn/core/attributes/attribute.h>
#include <cgogn/distributed/distributed_map.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <limits>
#include <tuple>
#include <type_traits>

namespace cgogn::dist::detail
{

constexpr uint64 NO_GID = std::numeric_limits<uint64>::max();

template <typename MAP>
using Top = typename DistributedMap<MAP>::TopCell;

// The attribute types distribute() carries to the ranks, by index.
using CarriedTypes =
	std::tuple<double, float, int8, uint8, std::int16_t, uint16, int32, uint32, int64, uint64, Vec2, Vec3, Vec4>;

// Calls f.template operator()<T>() with the carried type of index i.
template <typename F, std::size_t I = 0>
void visit_carried_type(uint8 i, const F& f)
{
	if constexpr (I < std::tuple_size_v<CarriedTypes>)
	{
		if (i == I)
			f.template operator()<std::tuple_element_t<I, CarriedTypes>>();
		else
			visit_carried_type<F, I + 1>(i, f);
	}
}

// The index of type T among the carried types.
template <typename T, std::size_t I = 0>
constexpr uint8 carried_type_index()
{
	static_assert(I < std::tuple_size_v<CarriedTypes>, "not a carried type");
	if constexpr (std::is_same_v<T, std::tuple_element_t<I, CarriedTypes>>)
		return uint8(I);
	else
		return carried_type_index<T, I + 1>();
}

// The index of a's type among the carried types; -1 when it is not carried.
inline int carried_type_of(const AttributeBase& a)
{
	int found = -1;
	for (uint8 i = 0; i < std::tuple_size_v<CarriedTypes>; ++i)
		visit_carried_type(i, [&]<typename T>() {
			if (a.type() == typeid(T))
				found = i;
		});
	return found;
}

} // namespace cgogn::dist::detail
