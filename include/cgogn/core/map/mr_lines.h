// SPDX-License-Identifier: MIT
// The lines of the cells of a multiresolution map, shared by every
// dimension (see detail::MRCellIndex).
#pragma once

#include <cgogn/core/map/mr_common.h>
#include <cgogn/core/map/mrmap2.h>

#include <array>

namespace cgogn::detail
{

/// What the code shared by the multiresolution maps of every dimension needs
/// to know of the 2-D one: its types and the orbits of its cell slots.
template <>
struct MRDim<MRState2>
{
	using Map = MRMap2;        ///< The multiresolution map.
	using View = MRLevelView2; ///< Its level views.
	using Flat = CMap2;        ///< Its finest map.
	/// The orbits of the slots of MRState2::cells.
	static constexpr std::array<Orbit, 4> orbits{Orbit::PHI21, Orbit::PHI2, Orbit::PHI1, Orbit::PHI1_PHI2};
	static constexpr uint32 vertex_slot = 0;    ///< The slot of the vertices.
	static constexpr uint32 edge_slot = 1;      ///< The slot of the edges.
	static constexpr uint32 face_slot = 2;      ///< The slot of the faces.
	static constexpr uint32 component_slot = 3; ///< The slot of the connected components.
	/// The slot of orbit o (4 for an orbit without one).
	static constexpr uint32 slot(Orbit o)
	{
		return mr_slot(o);
	}
};

/// The line at level l below the finest of the cell whose finest line is i
/// (not INVALID_INDEX): followed down the versions. Out of line, so that the
/// finest level's reads (see mr_line_of) keep their registers. O(levels - l).
template <typename S>
[[gnu::noinline, gnu::cold]] uint32 mr_line_below(const S& s, uint32 l, uint32 slot, uint32 i)
{
	const MRCellIndex& ci = s.cells[slot];
	const auto level = ci.level->view();
	const auto down = ci.down->view();
	while (level[i] > l)
		i = down[i];
	return i;
}

/// The line of the cell in slot `slot` holding dart d at level l: the line of
/// d's finest cell, followed down to the level. INVALID_INDEX for a cell
/// without a line (a boundary cell). O(1) at the finest level, O(levels - l)
/// below.
template <typename S>
CGOGN_INLINE uint32 mr_line_of(const S& s, uint32 l, uint32 slot, Dart d)
{
	const uint32 i = (*s.cells[slot].index)[d.index];
	if (mr_is_finest(s, l) || i == INVALID_INDEX) [[likely]]
		return i;
	return mr_line_below(s, l, slot, i);
}

/// The container of the cells of slot `slot` in the finest map. O(1).
template <typename S>
AttributeContainer& mr_slot_container(const S& s, uint32 slot)
{
	return *state_of(s.map).cells[orbit_index(MRDim<S>::orbits[slot])];
}

/// Calls f(line) on every line of slot `slot` that holds at level l, for
/// lines [b, e) of the container; f may return false to stop.
template <typename S, typename FUNC>
void mr_foreach_line_holding(const S& s, uint32 slot, uint32 l, uint32 b, uint32 e, const FUNC& f)
{
	const auto key = mr_slot_container(s, slot).key().view();
	const auto level = s.cells[slot].level->view();
	const auto replaced = s.cells[slot].replaced->view();
	for (uint32 i = b; i < e; ++i)
		if (key[i] != INVALID_INDEX && level[i] <= l && replaced[i] > l && !call_and_continue(f, i))
			return;
}

/// Calls f on the darts of the cell of d in slot `slot` at level l.
template <typename S, typename FUNC>
void mr_foreach_dart_of_cell(const S& s, uint32 slot, uint32 l, Dart d, const FUNC& f)
{
	using D = MRDim<S>;
	const typename D::View v(s, l);
	[&]<std::size_t... I>(std::index_sequence<I...>)
	{
		(void)((slot == I ? (foreach_dart_of_orbit(v, Cell<D::orbits[I]>(d), f), true) : false) || ...);
	}
	(std::make_index_sequence<D::orbits.size()>{});
}

} // namespace cgogn::detail
