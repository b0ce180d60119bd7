// SPDX-License-Identifier: MIT
// Between the two models of maps: CMap2 <-> GMap2, CMap3 <-> GMap3, with
// every attribute.
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/utils/error.h>

#include "attribute_copy.h"

#include <array>
#include <string>
#include <utility>

namespace cgogn
{

namespace
{

// The cells of orbit TO's counterpart in the source (see surface_counterpart),
// copied into the target map: each live line of the source becomes a new line
// of the target, written on the target cell of its representative dart
// (dart_of gives it), and its values copied.
template <Orbit TO, Orbit FROM = surface_counterpart(TO), typename TARGET, typename SOURCE, typename DART_OF>
void copy_orbit(TARGET& target, const SOURCE& source, const DART_OF& dart_of)
{
	const AttributeContainer& fc = *detail::state_of(source).cells[orbit_index(FROM)];
	if (detail::state_of(source).cell_index[orbit_index(FROM)] == nullptr)
		return;
	detail::index_attribute(target, TO);
	AttributeContainer& tc = *detail::state_of(target).cells[orbit_index(TO)];
	std::vector<uint32> line(fc.end_index(), INVALID_INDEX);
	for (uint32 i = 0; i < fc.end_index(); ++i)
		if (fc.is_live(i))
		{
			const Dart d = dart_of(Dart(fc.key()[i]));
			line[i] = tc.new_line(d.index);
			detail::write_index(target, Cell<TO>(d), line[i]);
		}
	detail::copy_attributes(fc, tc, [&](uint32 i, const auto& put) { put(line[i]); });
}

} // namespace

namespace
{

// The G-map of a combinatorial map: each dart d of m becomes A(d) = 2k at
// its origin and B(d) = 2k + 1 at its end, a pair (beta0); beta1 joins
// the end of d to the origin of phi1(d), beta_i (i >= 2) the origin of d to
// the end of phi_i(d), which goes the other way.
template <typename GMAP, typename CMAP>
GMAP gmap_of(const CMAP& m)
{
	GMAP g;
	const AttributeContainer& darts = *detail::state_of(m).darts;
	std::vector<uint32> a(darts.end_index(), INVALID_INDEX);
	foreach_dart(m, [&](Dart d) { a[d.index] = detail::add_dart_pair(g).index; });
	auto A = [&](Dart d) { return Dart(a[d.index]); };
	auto B = [&](Dart d) { return Dart(a[d.index] + 1); };
	foreach_dart(m, [&](Dart d) {
		detail::set_relation(g, 1, B(d), A(phi1(m, d)));
		detail::set_relation(g, 1, A(phi1(m, d)), B(d));
		for (uint32 i = 2; i <= CMAP::dimension; ++i)
		{
			const Dart e = detail::relation(m, i, d);
			detail::set_relation(g, i, A(d), B(e));
			detail::set_relation(g, i, B(e), A(d));
		}
		if (is_boundary(m, d))
		{
			detail::set_boundary(g, A(d), true);
			detail::set_boundary(g, B(d), true);
		}
	});
	detail::copy_attributes(darts, *detail::state_of(g).darts, [&](uint32 i, const auto& put) {
		put(a[i]);
		put(a[i] + 1);
	});
	if constexpr (is_nmap_v<CMAP>)
	{
		[&]<std::size_t... K>(std::index_sequence<K...>)
		{
			(copy_orbit<cell_orbit(K)>(g, m, A), ...);
		}
		(std::make_index_sequence<CMAP::dimension + 1>{});
	}
	else
	{
		copy_orbit<Orbit::BETA1_BETA2>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA2>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA1>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA1_BETA2>(g, m, A);
	}
	if constexpr (!is_nmap_v<CMAP> && CMAP::dimension >= 3)
	{
		copy_orbit<Orbit::BETA1_BETA2_BETA3>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA2_BETA3>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA1_BETA3>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA1_BETA2_BETA3>(g, m, A);
	}
	detail::release_idle_marks(g);
	return g;
}

} // namespace

namespace detail
{

// The combinatorial map of an orientable G-map, added to m: the darts of one
// colour class, phi1 = beta1 o beta0 and phi_i = beta0 o beta_i (i >= 2).
// c[d] is the dart of m made from dart d of g (INVALID_INDEX for the others).
template <typename CMAP, typename GMAP>
void cmap_into(const GMAP& g, CMAP& m, const char* name, std::vector<uint32>& c)
{
	// the kept darts: in each component, the colour class of its smallest dart
	DartMarker<GMAP> kept(g);
	if (!detail::two_colour(g, kept))
		throw TopologyError(std::string(name) +
							": the G-map is not orientable (a Möbius strip, a Klein bottle, ...): no combinatorial "
							"map can hold it");
	const AttributeContainer& darts = *detail::state_of(g).darts;
	c.assign(darts.end_index(), INVALID_INDEX);
	foreach_dart(g, [&](Dart d) {
		if (kept.is_marked(d))
			c[d.index] = detail::add_dart(m).index;
	});
	auto C = [&](Dart d) { return Dart(c[d.index]); };
	foreach_dart(g, [&](Dart d) {
		if (!kept.is_marked(d))
			return;
		detail::set_relation(m, 1, C(d), C(beta1(g, beta0(g, d))));
		for (uint32 i = 2; i <= CMAP::dimension; ++i)
			detail::set_relation(m, i, C(d), C(beta0(g, detail::relation(g, i, d))));
		if (is_boundary(g, d))
			detail::set_boundary(m, C(d), true);
	});
	detail::copy_attributes(darts, *detail::state_of(m).darts, [&](uint32 i, const auto& put) {
		if (c[i] != INVALID_INDEX)
			put(c[i]);
	});
	// a cell's kept dart: the representative, or its beta1 (vertices) or beta0
	// neighbour (the other cells), which lies in the same cell
	auto kept_in = [&](bool vertex) {
		return [&, vertex](Dart d) { return C(kept.is_marked(d) ? d : vertex ? beta1(g, d) : beta0(g, d)); };
	};
	if constexpr (is_nmap_v<CMAP>)
	{
		[&]<std::size_t... K>(std::index_sequence<K...>)
		{
			(copy_orbit<cell_orbit(K)>(m, g, kept_in(K == 0)), ...);
		}
		(std::make_index_sequence<CMAP::dimension + 1>{});
	}
	else
	{
		copy_orbit<Orbit::PHI21>(m, g, kept_in(true));
		copy_orbit<Orbit::PHI2>(m, g, kept_in(false));
		copy_orbit<Orbit::PHI1>(m, g, kept_in(false));
		copy_orbit<Orbit::PHI1_PHI2>(m, g, kept_in(false));
	}
	if constexpr (!is_nmap_v<CMAP> && CMAP::dimension >= 3)
	{
		copy_orbit<Orbit::PHI21_PHI31>(m, g, kept_in(true));
		copy_orbit<Orbit::PHI2_PHI3>(m, g, kept_in(false));
		copy_orbit<Orbit::PHI1_PHI3>(m, g, kept_in(false));
		copy_orbit<Orbit::PHI1_PHI2_PHI3>(m, g, kept_in(false));
	}
	detail::release_idle_marks(m);
}

} // namespace detail

namespace
{

template <typename CMAP, typename GMAP>
CMAP cmap_of(const GMAP& g, const char* name)
{
	CMAP m;
	std::vector<uint32> c;
	detail::cmap_into(g, m, name, c);
	return m;
}

// The same map in the type of maps of any dimension (or back): the darts in
// the order of the live darts of m, with the same relations, boundary marks
// and attributes; FROM... and TO... are the orbits of the cells of dimension
// 0, 1, ... in each type.
template <typename TARGET, Orbit... TO, Orbit... FROM, typename SOURCE>
TARGET same_map_as(const SOURCE& m, std::integer_sequence<Orbit, TO...>, std::integer_sequence<Orbit, FROM...>)
{
	TARGET t;
	const AttributeContainer& darts = *detail::state_of(m).darts;
	std::vector<uint32> a(darts.end_index(), INVALID_INDEX);
	if constexpr (is_gmap_v<SOURCE>)
		foreach_dart(m, [&](Dart d) {
			if (d.index % 2 == 0)
			{
				a[d.index] = detail::add_dart_pair(t).index;
				a[d.index + 1] = a[d.index] + 1;
			}
		});
	else
		foreach_dart(m, [&](Dart d) { a[d.index] = detail::add_dart(t).index; });
	auto A = [&](Dart d) { return Dart(a[d.index]); };
	foreach_dart(m, [&](Dart d) {
		for (uint32 i = 1; i <= SOURCE::dimension; ++i)
			detail::set_relation(t, i, A(d), A(detail::relation(m, i, d)));
		if (is_boundary(m, d))
			detail::set_boundary(t, A(d), true);
	});
	detail::copy_attributes(darts, *detail::state_of(t).darts, [&](uint32 i, const auto& put) { put(a[i]); });
	(copy_orbit<TO, FROM>(t, m, A), ...);
	detail::release_idle_marks(t);
	return t;
}

template <Orbit... O>
using Orbits = std::integer_sequence<Orbit, O...>;
using NCells2 = Orbits<Orbit::CELL0, Orbit::CELL1, Orbit::CELL2>;
using NCells3 = Orbits<Orbit::CELL0, Orbit::CELL1, Orbit::CELL2, Orbit::CELL3>;

} // namespace

GMap2 to_gmap(const CMap2& m)
{
	return gmap_of<GMap2>(m);
}

GMap3 to_gmap(const CMap3& m)
{
	return gmap_of<GMap3>(m);
}

CMap2 to_cmap(const GMap2& g)
{
	return cmap_of<CMap2>(g, "to_cmap");
}

CMap3 to_cmap(const GMap3& g)
{
	return cmap_of<CMap3>(g, "to_cmap");
}

template <uint32 D>
GMapN<D> to_gmap(const CMapN<D>& m)
{
	return gmap_of<GMapN<D>>(m);
}

template <uint32 D>
CMapN<D> to_cmap(const GMapN<D>& g)
{
	return cmap_of<CMapN<D>>(g, "to_cmap");
}

CMapN<2> to_nmap(const CMap2& m)
{
	return same_map_as<CMapN<2>>(m, NCells2{}, Orbits<Orbit::PHI21, Orbit::PHI2, Orbit::PHI1>{});
}

CMapN<3> to_nmap(const CMap3& m)
{
	return same_map_as<CMapN<3>>(m, NCells3{},
								 Orbits<Orbit::PHI21_PHI31, Orbit::PHI2_PHI3, Orbit::PHI1_PHI3, Orbit::PHI1_PHI2>{});
}

GMapN<2> to_nmap(const GMap2& m)
{
	return same_map_as<GMapN<2>>(m, NCells2{}, Orbits<Orbit::BETA1_BETA2, Orbit::BETA0_BETA2, Orbit::BETA0_BETA1>{});
}

GMapN<3> to_nmap(const GMap3& m)
{
	return same_map_as<GMapN<3>>(m, NCells3{},
								 Orbits<Orbit::BETA1_BETA2_BETA3, Orbit::BETA0_BETA2_BETA3, Orbit::BETA0_BETA1_BETA3,
										Orbit::BETA0_BETA1_BETA2>{});
}

CMap2 to_fixed_map(const CMapN<2>& m)
{
	return same_map_as<CMap2>(m, Orbits<Orbit::PHI21, Orbit::PHI2, Orbit::PHI1>{}, NCells2{});
}

CMap3 to_fixed_map(const CMapN<3>& m)
{
	return same_map_as<CMap3>(m, Orbits<Orbit::PHI21_PHI31, Orbit::PHI2_PHI3, Orbit::PHI1_PHI3, Orbit::PHI1_PHI2>{},
							  NCells3{});
}

GMap2 to_fixed_map(const GMapN<2>& m)
{
	return same_map_as<GMap2>(m, Orbits<Orbit::BETA1_BETA2, Orbit::BETA0_BETA2, Orbit::BETA0_BETA1>{}, NCells2{});
}

GMap3 to_fixed_map(const GMapN<3>& m)
{
	return same_map_as<GMap3>(m,
							  Orbits<Orbit::BETA1_BETA2_BETA3, Orbit::BETA0_BETA2_BETA3, Orbit::BETA0_BETA1_BETA3,
									 Orbit::BETA0_BETA1_BETA2>{},
							  NCells3{});
}

#define CGOGN_NMAP_CONVERSIONS(D)                                                                                      \
	template GMapN<D> to_gmap(const CMapN<D>&);                                                                        \
	template CMapN<D> to_cmap(const GMapN<D>&);                                                                        \
	template void detail::cmap_into(const GMapN<D>&, CMapN<D>&, const char*, std::vector<uint32>&);
CGOGN_NMAP_CONVERSIONS(1)
CGOGN_NMAP_CONVERSIONS(2)
CGOGN_NMAP_CONVERSIONS(3)
CGOGN_NMAP_CONVERSIONS(4)
CGOGN_NMAP_CONVERSIONS(5)
CGOGN_NMAP_CONVERSIONS(6)
CGOGN_NMAP_CONVERSIONS(7)
#undef CGOGN_NMAP_CONVERSIONS

} // namespace cgogn
