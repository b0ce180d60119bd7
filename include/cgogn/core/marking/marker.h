// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_access.h>
#include <cgogn/core/marking/dart_marker.h>

#include <algorithm>
#include <vector>

namespace cgogn
{

/// Marks cells of type CELL. When the orbit is indexed, a bit per cell in the
/// cell container is used (mark/is_marked O(1)); otherwise the darts of the
/// cell are marked (mark O(size of the orbit), is_marked O(1)). Cleared on
/// destruction; unmark_all is O(number of cells / 64) or O(darts / 64).
template <typename MESH, typename CELL>
class CellMarker
{
	static_assert(CellType<CELL>);

public:
	using MapType = typename mesh_traits<MESH>::MapType; ///< The map under MESH (MESH itself for a map).

	/// A marker of the cells of m (a map or a view: the cells of the map under
	/// it), with no cell marked. Whether the orbit is indexed is read here, and
	/// the marker keeps the bits it chose then (cell bits or dart bits) for its
	/// whole life. O(1) once the pool is warm.
	explicit CellMarker(const MESH& m)
		: map_(map_of(m)), indexed_(CELL::ORBIT != Orbit::DART && is_indexed<CELL>(map_)),
		  mark_(indexed_ ? container_of<CELL::ORBIT>(map_) : *detail::state_of(map_).darts)
	{
	}
	~CellMarker()
	{
		mark_->clear_all();
	}

	/// Marks c. O(1) when the orbit is indexed, else O(size of the orbit).
	void mark(CELL c)
	{
		if (indexed_)
			mark_->set(index_of(map_, c));
		else
		{
			if constexpr (!is_direct_orbit(CELL::ORBIT)) // records are always indexed
				foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->set(d.index); });
		}
	}
	/// Unmarks c. O(1) when the orbit is indexed, else O(size of the orbit).
	void unmark(CELL c)
	{
		if (indexed_)
			mark_->reset(index_of(map_, c));
		else
		{
			if constexpr (!is_direct_orbit(CELL::ORBIT)) // records are always indexed
				foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->reset(d.index); });
		}
	}
	/// Whether c is marked, through any of its darts. O(1).
	bool is_marked(CELL c) const
	{
		return mark_->test(indexed_ ? index_of(map_, c) : c.dart.index);
	}
	/// Unmarks every cell. O(cells / 64) when the orbit is indexed, else
	/// O(darts / 64).
	void unmark_all()
	{
		mark_->clear_all();
	}

protected:
	const MapType& map_; ///< The map whose cells are marked.
	/// Whether the marks are bits of the cell container (one per cell) rather
	/// than of the dart container (one per dart of each marked cell).
	bool indexed_;
	ReservedMark mark_; ///< The reserved bits; not copyable: neither is the marker.
};

/// A CellMarker that records the marked cells: unmark_all is O(number of
/// marked cells), unmark(c) O(number of marked cells). Best when few cells are
/// marked and the marker is cleared often.
template <typename MESH, typename CELL>
class CellMarkerStore
{
	static_assert(CellType<CELL>);

public:
	using MapType = typename mesh_traits<MESH>::MapType; ///< The map under MESH (MESH itself for a map).

	/// A marker of the cells of m, with no cell marked; as CellMarker's.
	explicit CellMarkerStore(const MESH& m)
		: map_(map_of(m)), indexed_(CELL::ORBIT != Orbit::DART && is_indexed<CELL>(map_)),
		  mark_(indexed_ ? container_of<CELL::ORBIT>(map_) : *detail::state_of(map_).darts)
	{
	}
	~CellMarkerStore()
	{
		unmark_all();
	}

	/// Marks c and records it, unless it is marked already. O(1) amortized when
	/// the orbit is indexed, else O(size of the orbit).
	void mark(CELL c)
	{
		if (is_marked(c))
			return;
		set(c, true);
		marked_.push_back(c);
	}
	/// Unmarks c and removes it from the record: O(number of marked cells)
	/// when the orbit is indexed; else each recorded cell is compared with
	/// same_cell(), O(marked cells x size of the orbit). O(1) when c is not
	/// marked.
	void unmark(CELL c)
	{
		if (!is_marked(c))
			return;
		set(c, false);
		auto it = std::find_if(marked_.begin(), marked_.end(), [&](CELL x) { return is_same(x, c); });
		if (it != marked_.end())
			marked_.erase(it);
	}
	/// Whether c is marked, through any of its darts. O(1).
	bool is_marked(CELL c) const
	{
		return mark_->test(indexed_ ? index_of(map_, c) : c.dart.index);
	}
	/// Unmarks every marked cell. O(number of marked cells) when the orbit is
	/// indexed, else O(their darts).
	void unmark_all()
	{
		for (CELL c : marked_)
			set(c, false);
		marked_.clear();
	}
	/// The marked cells, each once, in the order they were first marked (with
	/// the dart they were marked through).
	const std::vector<CELL>& marked_cells() const
	{
		return marked_;
	}

private:
	void set(CELL c, bool b)
	{
		if (indexed_)
			mark_->set_value(index_of(map_, c), b);
		else
		{
			if constexpr (!is_direct_orbit(CELL::ORBIT)) // records are always indexed
				foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->set_value(d.index, b); });
		}
	}
	bool is_same(CELL a, CELL b) const
	{
		return indexed_ ? index_of(map_, a) == index_of(map_, b) : same_cell(map_, a, b);
	}

	const MapType& map_;
	bool indexed_;
	ReservedMark mark_; // not copyable: neither is the marker
	std::vector<CELL> marked_;
};

} // namespace cgogn
