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
	using MapType = typename mesh_traits<MESH>::MapType;

	explicit CellMarker(const MESH& m)
		: map_(map_of(m)), indexed_(CELL::ORBIT != Orbit::DART && is_indexed<CELL>(map_)),
		  mark_(indexed_ ? container_of<CELL::ORBIT>(map_) : *detail::darts_of(map_))
	{
	}
	~CellMarker()
	{
		mark_->clear_all();
	}

	void mark(CELL c)
	{
		if (indexed_)
			mark_->set(index_of(map_, c));
		else
			foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->set(d.index); });
	}
	void unmark(CELL c)
	{
		if (indexed_)
			mark_->reset(index_of(map_, c));
		else
			foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->reset(d.index); });
	}
	bool is_marked(CELL c) const
	{
		return mark_->test(indexed_ ? index_of(map_, c) : c.dart.index);
	}
	void unmark_all()
	{
		mark_->clear_all();
	}

protected:
	const MapType& map_;
	bool indexed_;
	ReservedMark mark_; // not copyable: neither is the marker
};

/// A CellMarker that records the marked cells: unmark_all is O(number of
/// marked cells), unmark(c) O(number of marked cells). Best when few cells are
/// marked and the marker is cleared often.
template <typename MESH, typename CELL>
class CellMarkerStore
{
	static_assert(CellType<CELL>);

public:
	using MapType = typename mesh_traits<MESH>::MapType;

	explicit CellMarkerStore(const MESH& m)
		: map_(map_of(m)), indexed_(CELL::ORBIT != Orbit::DART && is_indexed<CELL>(map_)),
		  mark_(indexed_ ? container_of<CELL::ORBIT>(map_) : *detail::darts_of(map_))
	{
	}
	~CellMarkerStore()
	{
		unmark_all();
	}

	void mark(CELL c)
	{
		if (is_marked(c))
			return;
		set(c, true);
		marked_.push_back(c);
	}
	void unmark(CELL c)
	{
		if (!is_marked(c))
			return;
		set(c, false);
		auto it = std::find_if(marked_.begin(), marked_.end(), [&](CELL x) { return is_same(x, c); });
		if (it != marked_.end())
			marked_.erase(it);
	}
	bool is_marked(CELL c) const
	{
		return mark_->test(indexed_ ? index_of(map_, c) : c.dart.index);
	}
	void unmark_all()
	{
		for (CELL c : marked_)
			set(c, false);
		marked_.clear();
	}
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
			foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->set_value(d.index, b); });
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
