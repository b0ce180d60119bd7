// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/marking/dart_marker.h>
#include <cgogn/core/traversals/global.h>

#include <vector>

namespace cgogn
{

// Counts by dimension, for every map: the maps of any dimension (CMapN,
// GMapN) and those of dimension 1 to 3, whose cells of dimension I are
// cell_of_dimension_t<MAP, I>.

/// Number of I-cells (boundary cells excluded): `nb_cells<2>(m)` counts the
/// faces of any map. O(1) when the orbit is indexed, O(number of darts)
/// otherwise (see nb_cells<CELL>).
template <uint32 I, typename MESH>
uint32 nb_cells(const MESH& m)
{
	return nb_cells<cell_of_dimension_t<typename mesh_traits<MESH>::MapType, I>>(m);
}

/// The f-vector of the mesh: the number of cells of each dimension 0 ... D,
/// boundary cells excluded. O(D) when every orbit is indexed, O(D x number
/// of darts) otherwise.
template <typename MESH>
std::vector<uint32> f_vector(const MESH& m)
{
	constexpr uint32 D = mesh_traits<MESH>::dimension;
	std::vector<uint32> f(D + 1);
	[&]<std::size_t... I>(std::index_sequence<I...>)
	{
		((f[I] = nb_cells<uint32(I)>(m)), ...);
	}
	(std::make_index_sequence<D + 1>{});
	return f;
}

/// The Euler characteristic of the mesh: the alternating sum of its
/// f-vector, V - E + F - W + ..., counting only real cells (boundary cells
/// excluded: a disk gives 1, a D-ball 1, the boundary of a D-ball
/// 1 + (-1)^(D - 1)). O(D) for the indexed orbits, O(number of darts) for
/// each other one.
template <typename MESH>
int64 euler_characteristic(const MESH& m)
{
	int64 chi = 0, sign = 1;
	for (uint32 n : f_vector(m))
	{
		chi += sign * int64(n);
		sign = -sign;
	}
	return chi;
}

/// Number of connected components of a map of any dimension that hold a
/// real (non-boundary) dart: the darts reached from one another through
/// every relation. O(number of darts).
template <typename MAP>
requires is_nmap_v<MAP> uint32 nb_connected_components(const MAP& m)
{
	DartMarker<MAP> seen(m);
	std::vector<Dart> work;
	uint32 n = 0;
	foreach_dart(m, [&](Dart start) {
		if (seen.is_marked(start))
			return;
		bool real = false;
		seen.mark(start);
		work.assign(1, start);
		while (!work.empty())
		{
			const Dart d = work.back();
			work.pop_back();
			real = real || !is_boundary(m, d);
			auto visit = [&](Dart e) {
				if (!seen.is_marked(e))
				{
					seen.mark(e);
					work.push_back(e);
				}
			};
			if constexpr (is_gmap_v<MAP>)
				visit(beta0(m, d));
			for (uint32 i = 1; i <= MAP::dimension; ++i)
				visit(detail::relation(m, i, d));
		}
		n += real;
	});
	return n;
}

/// True when cell c of a map of any dimension touches a boundary D-cell
/// (one of its darts is a boundary dart or is glued by the last relation to
/// one). O(1) on a map without boundary, else O(size of the cell).
template <typename MAP, Orbit O>
requires is_nmap_v<MAP>
bool is_incident_to_boundary(const MAP& m, Cell<O> c)
{
	if (!has_boundary(m))
		return false;
	bool b = false;
	foreach_dart_of_orbit(m, c, [&](Dart d) {
		b = is_boundary(m, d) || is_boundary(m, detail::relation(m, MAP::dimension, d));
		return !b;
	});
	return b;
}

} // namespace cgogn
