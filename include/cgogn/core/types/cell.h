// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/types/dart.h>
#include <cgogn/core/types/orbit.h>

#include <functional>
#include <ostream>
#include <type_traits>

namespace cgogn
{

/// An orbit-typed dart: the cell of orbit O that contains `dart`. Any dart of
/// the orbit represents the same cell; compare cells with same_cell().
template <Orbit O>
struct Cell
{
	static constexpr Orbit ORBIT = O;

	Dart dart;

	constexpr Cell() = default;
	constexpr explicit Cell(Dart d) : dart(d)
	{
	}

	constexpr bool is_valid() const
	{
		return dart.is_valid();
	}

	/// Same representative dart (not the same cell: see same_cell()).
	friend constexpr bool operator==(Cell a, Cell b) = default;

	friend std::ostream& operator<<(std::ostream& out, Cell c)
	{
		return out << "Cell<" << orbit_name(O) << ">(" << c.dart.index << ")";
	}
};

template <typename T>
struct is_cell : std::false_type
{
};
template <Orbit O>
struct is_cell<Cell<O>> : std::true_type
{
};
template <typename T>
concept CellType = is_cell<std::remove_cvref_t<T>>::value;

} // namespace cgogn

template <cgogn::Orbit O>
struct std::hash<cgogn::Cell<O>>
{
	std::size_t operator()(cgogn::Cell<O> c) const noexcept
	{
		return std::hash<cgogn::Dart>{}(c.dart);
	}
};
