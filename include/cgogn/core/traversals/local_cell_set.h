// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/detail/dart_buffer.h>
#include <cgogn/core/marking/marker.h>

#include <array>
#include <optional>

namespace cgogn::detail
{

/// The set of cells met by a local traversal, to report each once. With an
/// indexed orbit it keeps the first lines met in a small array (a star has
/// a few cells: no shared resource is touched), then marks one bit per cell
/// in the cell container; otherwise it marks the darts of each met cell.
/// Borrows pooled marks and buffers only when it marks: no allocation once
/// warm. Thread-safe to use from several threads at once.
template <typename MAP, typename CELL>
class LocalCellSet
{
public:
	explicit LocalCellSet(const MAP& m) : map_(m), indexed_(CELL::ORBIT != Orbit::DART && is_indexed<CELL>(m))
	{
		if (!indexed_)
			start_marking(*detail::state_of(m).darts);
	}
	~LocalCellSet()
	{
		if (mark_)
			for (Dart d : **marked_)
				(*mark_)->reset(d.index);
	}
	LocalCellSet(const LocalCellSet&) = delete;
	LocalCellSet& operator=(const LocalCellSet&) = delete;

	/// Adds c; true when it was not in the set.
	bool insert(CELL c)
	{
		if (indexed_)
		{
			const uint32 i = index_of(map_, c);
			if (!mark_)
			{
				for (uint32 k = 0; k < nb_few_; ++k)
					if (few_[k] == i)
						return false;
				if (nb_few_ < few_.size())
				{
					few_[nb_few_++] = i;
					return true;
				}
				start_marking(container_of<CELL::ORBIT>(map_));
				for (uint32 l : few_)
					mark_line(l);
			}
			if ((*mark_)->test(i))
				return false;
			mark_line(i);
			return true;
		}
		MarkAttribute& mark = **mark_;
		if (mark.test(c.dart.index))
			return false;
		std::vector<Dart>& marked = **marked_;
		foreach_dart_of_orbit(map_, c, [&](Dart d) {
			marked.push_back(d);
			mark.set(d.index);
		});
		return true;
	}

private:
	void start_marking(AttributeContainer& c)
	{
		mark_.emplace(c);
		marked_.emplace();
	}
	void mark_line(uint32 i)
	{
		(*marked_)->push_back(Dart(i)); // first: a set bit is always recorded (bad_alloc)
		(*mark_)->set(i);
	}

	const MAP& map_;
	bool indexed_;
	uint32 nb_few_ = 0;
	std::array<uint32, 16> few_{}; // the first lines met, while there are few
	std::optional<ReservedMark> mark_;
	std::optional<DartBuffer> marked_;
};

} // namespace cgogn::detail
