// SPDX-License-Identifier: MIT
#pragma once

// The dart markers on their own, below orbits.h: the floods of
// foreach_dart_of_orbit use DartMarkerStore as their mark and work list, the
// whole-map floods a ScopedDartMark (a DartMarker's raw mark).
// mark_orbit and unmark_orbit find foreach_dart_of_orbit when instantiated.

#include <cgogn/core/detail/dart_buffer.h>
#include <cgogn/core/map/mesh_access.h>

#include <algorithm>
#include <vector>

namespace cgogn
{

namespace detail
{

/// A dart mark reserved from the map's pool for the life of a scope, cleared
/// (O(darts / 64)) and given back at its end, exceptions included. The raw
/// mark of a DartMarker, for the floods that take a MarkAttribute.
class ScopedDartMark
{
public:
	explicit ScopedDartMark(const CMapBase& m) : mark_(*detail::state_of(m).darts)
	{
	}
	~ScopedDartMark()
	{
		mark_->clear_all();
	}

	MarkAttribute& operator*() const
	{
		return *mark_;
	}
	MarkAttribute* operator->() const
	{
		return &*mark_;
	}

private:
	ReservedMark mark_;
};

} // namespace detail

/// Marks darts with a bit reserved from the map's pool; the bits are cleared
/// and the reservation given back when the marker dies. Any number of markers
/// may be alive at once. Clearing (unmark_all, destruction) is O(number of
/// darts / 64); use DartMarkerStore when few darts are marked.
template <typename MESH>
class DartMarker
{
public:
	using MapType = typename mesh_traits<MESH>::MapType; ///< The map under MESH (MESH itself for a map).

	/// A marker of the darts of m (a map or a view: the darts of the map under
	/// it), with no dart marked. O(1) once the pool is warm; the first use of a
	/// pool slot allocates its bits, O(darts / 64).
	explicit DartMarker(const MESH& m) : map_(map_of(m)), mark_(map_)
	{
	}

	/// Marks d. O(1).
	void mark(Dart d)
	{
		mark_->set(d.index);
	}
	/// Unmarks d. O(1).
	void unmark(Dart d)
	{
		mark_->reset(d.index);
	}
	/// Whether d is marked. O(1).
	bool is_marked(Dart d) const
	{
		return mark_->test(d.index);
	}
	/// Marks every dart of cell c. O(size of the orbit).
	template <Orbit O>
	void mark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->set(d.index); });
	}
	/// Unmarks every dart of cell c. O(size of the orbit).
	template <Orbit O>
	void unmark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->reset(d.index); });
	}
	/// Unmarks every dart. O(darts / 64).
	void unmark_all()
	{
		mark_->clear_all();
	}

protected:
	const MapType& map_;          ///< The map whose darts are marked.
	detail::ScopedDartMark mark_; ///< The reserved bits: cleared and given back with the marker; not copyable.
};

/// A DartMarker that also records the marked darts, so that clearing is
/// O(number of marked darts). unmark(d) is O(number of marked darts).
template <typename MESH>
class DartMarkerStore
{
public:
	using MapType = typename mesh_traits<MESH>::MapType; ///< The map under MESH (MESH itself for a map).

	/// A marker of the darts of m (a map or a view: the darts of the map under
	/// it), with no dart marked. O(1) once the pools are warm.
	explicit DartMarkerStore(const MESH& m) : map_(map_of(m)), mark_(*detail::state_of(map_).darts)
	{
	}
	~DartMarkerStore()
	{
		unmark_all();
	}

	/// Marks d and records it, unless it is marked already. O(1) amortized.
	void mark(Dart d)
	{
		if (!mark_->test(d.index))
		{
			marked_->push_back(d); // first: a set bit is always recorded (bad_alloc)
			mark_->set(d.index);
		}
	}
	/// Unmarks d and removes it from the record. O(number of marked darts)
	/// when d is marked, O(1) otherwise.
	void unmark(Dart d)
	{
		if (mark_->test(d.index))
		{
			mark_->reset(d.index);
			marked_->erase(std::find(marked_->begin(), marked_->end(), d));
		}
	}
	/// Whether d is marked. O(1).
	bool is_marked(Dart d) const
	{
		return mark_->test(d.index);
	}
	/// Marks every dart of cell c. O(size of the orbit).
	template <Orbit O>
	void mark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { mark(d); });
	}
	/// Unmarks every dart of cell c. O(size of the orbit x number of marked
	/// darts): each unmark searches the record.
	template <Orbit O>
	void unmark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { unmark(d); });
	}
	/// Unmarks every marked dart. O(number of marked darts).
	void unmark_all()
	{
		for (Dart d : *marked_)
			mark_->reset(d.index);
		marked_->clear();
	}
	/// The marked darts, in the order they were first marked (an unmark
	/// removes its dart and keeps the order of the others).
	const std::vector<Dart>& marked_darts() const
	{
		return *marked_;
	}

private:
	const MapType& map_;
	ReservedMark mark_; // not copyable: neither is the marker
	// borrowed from a per-thread pool: no allocation once warm
	mutable detail::DartBuffer marked_;
};

} // namespace cgogn
