// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/detail/dart_buffer.h>
#include <cgogn/core/marking/marker.h>

namespace cgogn::detail
{

/// The set of cells met by a local traversal, to report each once. With an
/// indexed orbit it marks one bit per cell in the cell container; otherwise it
/// marks the darts of each met cell. Borrows pooled marks and buffers: no
/// allocation once warm. Thread-safe to use from several threads at once.
template <typename MAP, typename CELL>
class LocalCellSet
{
public:
	explicit LocalCellSet(const MAP& m)
		: map_(m), indexed_(CELL::ORBIT != Orbit::DART && is_indexed<CELL>(m)),
		  mark_(indexed_ ? container_of<CELL::ORBIT>(m) : *detail::state_of(m).darts)
	{
	}
	~LocalCellSet()
	{
		for (Dart d : *marked_)
			mark_->reset(d.index);
	}

	/// Adds c; true when it was not in the set.
	bool insert(CELL c)
	{
		if (indexed_)
		{
			const uint32 i = index_of(map_, c);
			if (mark_->test(i))
				return false;
			marked_->push_back(Dart(i)); // first: a set bit is always recorded (bad_alloc)
			mark_->set(i);
			return true;
		}
		if (mark_->test(c.dart.index))
			return false;
		foreach_dart_of_orbit(map_, c, [&](Dart d) {
			marked_->push_back(d);
			mark_->set(d.index);
		});
		return true;
	}

private:
	const MAP& map_;
	bool indexed_;
	ReservedMark mark_; // not copyable: neither is the set
	DartBuffer marked_;
};

} // namespace cgogn::detail
