// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/dart.h>
#include <cgogn/core/map/orbit.h>

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
	static constexpr Orbit ORBIT = O; ///< The orbit of the cell type.

	Dart dart; ///< A dart of the orbit, representing the cell; invalid by default.

	constexpr Cell() = default;
	/// The cell of orbit O that contains d.
	constexpr explicit Cell(Dart d) : dart(d)
	{
	}

	/// Whether the representative dart is valid (not whether it is a live dart
	/// of some map: see is_dart_valid()). O(1).
	constexpr bool is_valid() const
	{
		return dart.is_valid();
	}

	/// Same representative dart (not the same cell: see same_cell()).
	friend constexpr bool operator==(Cell a, Cell b) = default;

	/// Prints the orbit and the dart index, e.g. `Cell<PHI21>(12)`.
	friend std::ostream& operator<<(std::ostream& out, Cell c)
	{
		return out << "Cell<" << orbit_name(O) << ">(" << c.dart.index << ")";
	}
};

/// A cell as reported by a quick (cached) local traversal: the cell and its
/// line in the orbit's container, read from the incidence cache. It converts
/// to Cell<O> (a callable taking `Vertex` gets the plain cell); a callable
/// taking `auto` keeps the line, and value() then reads the attribute at that
/// line without looking up the dart's index (the dependent, usually
/// cache-missing load that separates a dart-based traversal from flat arrays).
/// Valid while the cache is, i.e. until the next change of the map.
template <Orbit O>
struct LocatedCell : Cell<O>
{
	uint32 line = INVALID_INDEX; ///< The cell's line in the container of orbit O.

	constexpr LocatedCell() = default;
	/// The cell of orbit O that contains d, at line l of the orbit's container.
	constexpr LocatedCell(Dart d, uint32 l) : Cell<O>(d), line(l)
	{
	}
};

/// `Located<Vertex>`: the located form of a cell type, e.g. the parameter of
/// a foreach_cell callable that wants each cell with its line.
template <typename CELL>
using Located = LocatedCell<CELL::ORBIT>;

/// The cell parameter of the local traversals: a cell, plus its line when the
/// caller has it (a LocatedCell from foreach_cell or from a cached
/// traversal), so that a cached traversal finds its row without reading the
/// dart's index. Built implicitly from either; behaves as the cell.
template <typename CELL>
struct CellParam : CELL
{
	uint32 line = INVALID_INDEX; ///< INVALID_INDEX: unknown, looked up when needed

	/// A cell whose line is unknown.
	constexpr CellParam(CELL c) : CELL(c)
	{
	}
	/// A cell with its line.
	constexpr CellParam(LocatedCell<CELL::ORBIT> c) : CELL(c), line(c.line)
	{
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
template <Orbit O>
struct is_cell<LocatedCell<O>> : std::true_type
{
};
template <typename T>
concept CellType = is_cell<std::remove_cvref_t<T>>::value;

} // namespace cgogn

/// Hashes a cell by its representative dart, as operator== compares them: two
/// darts of the same cell are two different keys.
template <cgogn::Orbit O>
struct std::hash<cgogn::Cell<O>>
{
	/// The hash of c's dart.
	std::size_t operator()(cgogn::Cell<O> c) const noexcept
	{
		return std::hash<cgogn::Dart>{}(c.dart);
	}
};
