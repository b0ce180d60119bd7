// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <functional>
#include <ostream>

namespace cgogn
{

/// A dart: the index of a line of the dart container of a map.
/// A default-constructed dart is invalid.
struct Dart
{
	uint32 index = INVALID_INDEX;

	constexpr Dart() = default;
	constexpr explicit Dart(uint32 i) : index(i)
	{
	}

	constexpr bool is_valid() const
	{
		return index != INVALID_INDEX;
	}

	friend constexpr bool operator==(Dart a, Dart b) = default;
	friend constexpr auto operator<=>(Dart a, Dart b) = default;

	friend std::ostream& operator<<(std::ostream& out, Dart d)
	{
		if (d.is_valid())
			return out << "Dart(" << d.index << ")";
		return out << "Dart(invalid)";
	}
};

} // namespace cgogn

template <>
struct std::hash<cgogn::Dart>
{
	std::size_t operator()(cgogn::Dart d) const noexcept
	{
		return std::hash<cgogn::uint32>{}(d.index);
	}
};
