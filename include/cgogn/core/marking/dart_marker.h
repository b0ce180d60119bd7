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
	explicit ScopedDartMark(const CMapBase& m) : mark_(*detail::darts_of(m))
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
	using MapType = typename mesh_traits<MESH>::MapType;

	explicit DartMarker(const MESH& m) : map_(map_of(m)), mark_(map_)
	{
	}

	void mark(Dart d)
	{
		mark_->set(d.index);
	}
	void unmark(Dart d)
	{
		mark_->reset(d.index);
	}
	bool is_marked(Dart d) const
	{
		return mark_->test(d.index);
	}
	template <Orbit O>
	void mark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->set(d.index); });
	}
	template <Orbit O>
	void unmark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { mark_->reset(d.index); });
	}
	void unmark_all()
	{
		mark_->clear_all();
	}

protected:
	const MapType& map_;
	detail::ScopedDartMark mark_; // cleared and given back with the marker; not copyable
};

/// A DartMarker that also records the marked darts, so that clearing is
/// O(number of marked darts). unmark(d) is O(number of marked darts).
template <typename MESH>
class DartMarkerStore
{
public:
	using MapType = typename mesh_traits<MESH>::MapType;

	explicit DartMarkerStore(const MESH& m) : map_(map_of(m)), mark_(*detail::darts_of(map_))
	{
	}
	~DartMarkerStore()
	{
		unmark_all();
	}

	void mark(Dart d)
	{
		if (!mark_->test(d.index))
		{
			marked_->push_back(d); // first: a set bit is always recorded (bad_alloc)
			mark_->set(d.index);
		}
	}
	void unmark(Dart d)
	{
		if (mark_->test(d.index))
		{
			mark_->reset(d.index);
			marked_->erase(std::find(marked_->begin(), marked_->end(), d));
		}
	}
	bool is_marked(Dart d) const
	{
		return mark_->test(d.index);
	}
	template <Orbit O>
	void mark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { mark(d); });
	}
	template <Orbit O>
	void unmark_orbit(Cell<O> c)
	{
		foreach_dart_of_orbit(map_, c, [&](Dart d) { unmark(d); });
	}
	void unmark_all()
	{
		for (Dart d : *marked_)
			mark_->reset(d.index);
		marked_->clear();
	}
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
