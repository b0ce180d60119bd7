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
	uint32 index = INVALID_INDEX; ///< The dart's line in the dart container; INVALID_INDEX for an invalid dart.

	constexpr Dart() = default;
	/// The dart of line i.
	constexpr explicit Dart(uint32 i) : index(i)
	{
	}

	/// Whether the index is not INVALID_INDEX (not whether the dart is live in
	/// some map: see is_dart_valid()). O(1).
	constexpr bool is_valid() const
	{
		return index != INVALID_INDEX;
	}

	/// Same index.
	friend constexpr bool operator==(Dart a, Dart b) = default;
	/// Orders darts by index (for sorting and ordered containers).
	friend constexpr auto operator<=>(Dart a, Dart b) = default;

	/// Prints `Dart(index)`, or `Dart(invalid)`.
	friend std::ostream& operator<<(std::ostream& out, Dart d)
	{
		if (d.is_valid())
			return out << "Dart(" << d.index << ")";
		return out << "Dart(invalid)";
	}
};

} // namespace cgogn

/// Hashes a dart by its index, for unordered containers of darts.
template <>
struct std::hash<cgogn::Dart>
{
	/// The hash of d's index.
	std::size_t operator()(cgogn::Dart d) const noexcept
	{
		return std::hash<cgogn::uint32>{}(d.index);
	}
};
