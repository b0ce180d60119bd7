// SPDX-License-Identifier: MIT
#include <cgogn/core/build/nmap_boundary.h>
#include <cgogn/core/map/indexing.h>

#include "attribute_copy.h"

#include <vector>

namespace cgogn
{

namespace
{

template <typename TARGET, typename SOURCE>
TARGET boundary_of(const SOURCE& m)
{
	TARGET t;
	std::vector<uint32> a(detail::state_of(m).darts->end_index(), INVALID_INDEX);
	foreach_dart(m, [&](Dart d) {
		if (!is_boundary(m, d))
			return;
		if constexpr (is_gmap_v<SOURCE>)
		{
			if (d.index % 2 == 0)
			{
				a[d.index] = detail::add_dart_pair(t).index;
				a[d.index + 1] = a[d.index] + 1;
			}
		}
		else
			a[d.index] = detail::add_dart(t).index;
	});
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			for (uint32 i = 1; i < SOURCE::dimension; ++i)
				detail::set_relation(t, i, Dart(a[d.index]), Dart(a[detail::relation(m, i, d).index]));
	});
	const AttributeArray<uint32>* source_index = detail::state_of(m).cell_index[orbit_index(Orbit::CELL0)];
	if (source_index == nullptr)
		return t;
	// the vertices of t, each with the line of the vertex of m it lies on
	index_cells<CellD<0>>(t);
	const AttributeContainer& from = *detail::state_of(m).cells[orbit_index(Orbit::CELL0)];
	AttributeContainer& to = *detail::state_of(t).cells[orbit_index(Orbit::CELL0)];
	std::vector<std::vector<uint32>> lines_of(from.end_index());
	std::vector<uint32> dart_of(detail::state_of(t).darts->end_index());
	foreach_dart(m, [&](Dart d) {
		if (a[d.index] != INVALID_INDEX)
			dart_of[a[d.index]] = d.index;
	});
	for (uint32 l = 0; l < to.end_index(); ++l)
		if (to.is_live(l))
			lines_of[(*source_index)[dart_of[to.key()[l]]]].push_back(l);
	detail::copy_attributes(from, to, [&](uint32 i, const auto& put) {
		for (uint32 l : lines_of[i])
			put(l);
	});
	return t;
}

} // namespace

template <uint32 D>
requires(D >= 2) CMapN<D - 1> extract_boundary(const CMapN<D>& m)
{
	return boundary_of<CMapN<D - 1>>(m);
}

template <uint32 D>
requires(D >= 2) GMapN<D - 1> extract_boundary(const GMapN<D>& m)
{
	return boundary_of<GMapN<D - 1>>(m);
}

#define CGOGN_NMAP_BOUNDARY(D)                                                                                         \
	template CMapN<D - 1> extract_boundary(const CMapN<D>&);                                                           \
	template GMapN<D - 1> extract_boundary(const GMapN<D>&);
CGOGN_NMAP_BOUNDARY(2)
CGOGN_NMAP_BOUNDARY(3)
CGOGN_NMAP_BOUNDARY(4)
CGOGN_NMAP_BOUNDARY(5)
CGOGN_NMAP_BOUNDARY(6)
CGOGN_NMAP_BOUNDARY(7)
#undef CGOGN_NMAP_BOUNDARY

} // namespace cgogn
