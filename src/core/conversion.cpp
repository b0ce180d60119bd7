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
template <Orbit TO, typename TARGET, typename SOURCE, typename DART_OF>
void copy_orbit(TARGET& target, const SOURCE& source, const DART_OF& dart_of)
{
	constexpr Orbit FROM = surface_counterpart(TO);
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
		detail::set_beta<1>(g, B(d), A(phi1(m, d)));
		detail::set_beta<1>(g, A(phi1(m, d)), B(d));
		detail::set_beta<2>(g, A(d), B(phi2(m, d)));
		detail::set_beta<2>(g, B(phi2(m, d)), A(d));
		if constexpr (CMAP::dimension >= 3)
		{
			detail::set_beta<3>(g, A(d), B(phi3(m, d)));
			detail::set_beta<3>(g, B(phi3(m, d)), A(d));
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
	copy_orbit<Orbit::BETA1_BETA2>(g, m, A);
	copy_orbit<Orbit::BETA0_BETA2>(g, m, A);
	copy_orbit<Orbit::BETA0_BETA1>(g, m, A);
	copy_orbit<Orbit::BETA0_BETA1_BETA2>(g, m, A);
	if constexpr (CMAP::dimension >= 3)
	{
		copy_orbit<Orbit::BETA1_BETA2_BETA3>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA2_BETA3>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA1_BETA3>(g, m, A);
		copy_orbit<Orbit::BETA0_BETA1_BETA2_BETA3>(g, m, A);
	}
	detail::release_idle_marks(g);
	return g;
}

// The combinatorial map of an orientable G-map: the darts of one colour
// class, phi1 = beta1 o beta0 and phi_i = beta0 o beta_i (i >= 2).
template <typename CMAP, typename GMAP>
CMAP cmap_of(const GMAP& g, const char* name)
{
	// the kept darts: in each component, the colour class of its smallest dart
	DartMarker<GMAP> kept(g);
	if (!detail::two_colour(g, kept))
		throw TopologyError(std::string(name) +
							": the G-map is not orientable (a Möbius strip, a Klein bottle, ...): no combinatorial "
							"map can hold it");
	CMAP m;
	const AttributeContainer& darts = *detail::state_of(g).darts;
	std::vector<uint32> c(darts.end_index(), INVALID_INDEX);
	foreach_dart(g, [&](Dart d) {
		if (kept.is_marked(d))
			c[d.index] = detail::add_dart(m).index;
	});
	auto C = [&](Dart d) { return Dart(c[d.index]); };
	foreach_dart(g, [&](Dart d) {
		if (!kept.is_marked(d))
			return;
		detail::set_phi1(m, C(d), C(beta1(g, beta0(g, d))));
		detail::set_phi2(m, C(d), C(beta0(g, beta2(g, d))));
		if constexpr (CMAP::dimension >= 3)
			detail::set_phi3(m, C(d), C(beta0(g, beta3(g, d))));
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
	copy_orbit<Orbit::PHI21>(m, g, kept_in(true));
	copy_orbit<Orbit::PHI2>(m, g, kept_in(false));
	copy_orbit<Orbit::PHI1>(m, g, kept_in(false));
	copy_orbit<Orbit::PHI1_PHI2>(m, g, kept_in(false));
	if constexpr (CMAP::dimension >= 3)
	{
		copy_orbit<Orbit::PHI21_PHI31>(m, g, kept_in(true));
		copy_orbit<Orbit::PHI2_PHI3>(m, g, kept_in(false));
		copy_orbit<Orbit::PHI1_PHI3>(m, g, kept_in(false));
		copy_orbit<Orbit::PHI1_PHI2_PHI3>(m, g, kept_in(false));
	}
	detail::release_idle_marks(m);
	return m;
}

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

} // namespace cgogn
