// SPDX-License-Identifier: MIT
// Between the two models of surfaces: CMap2 <-> GMap2, with every attribute.
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

GMap2 to_gmap(const CMap2& m)
{
	GMap2 g;
	// dart d of m: a(d) = 2k at its origin, b(d) = 2k + 1 at its end
	const AttributeContainer& darts = *detail::state_of(m).darts;
	std::vector<uint32> a(darts.end_index(), INVALID_INDEX);
	foreach_dart(m, [&](Dart d) {
		a[d.index] = detail::add_dart(g).index;
		detail::add_dart(g);
	});
	auto A = [&](Dart d) { return Dart(a[d.index]); };
	auto B = [&](Dart d) { return Dart(a[d.index] + 1); };
	foreach_dart(m, [&](Dart d) {
		detail::set_beta<0>(g, A(d), B(d));
		detail::set_beta<0>(g, B(d), A(d));
		detail::set_beta<1>(g, B(d), A(phi1(m, d)));
		detail::set_beta<1>(g, A(phi1(m, d)), B(d));
		detail::set_beta<2>(g, A(d), B(phi2(m, d)));
		detail::set_beta<2>(g, B(phi2(m, d)), A(d));
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
	detail::release_idle_marks(g);
	return g;
}

CMap2 to_cmap(const GMap2& g)
{
	// the kept darts: in each component, the colour class of its smallest dart
	DartMarker<GMap2> kept(g);
	if (!detail::two_colour(g, kept))
		throw TopologyError("to_cmap: the G-map is not orientable (a Möbius strip, a Klein bottle, ...): no CMap2 "
							"can hold it");
	CMap2 m;
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
		if (is_boundary(g, d))
			detail::set_boundary(m, C(d), true);
	});
	detail::copy_attributes(darts, *detail::state_of(m).darts, [&](uint32 i, const auto& put) {
		if (c[i] != INVALID_INDEX)
			put(c[i]);
	});
	// a cell's kept dart: the representative, or its beta1 (vertices) or beta0
	// neighbour (edges, faces, components), which lies in the same cell
	auto kept_in = [&](bool vertex) {
		return [&, vertex](Dart d) { return C(kept.is_marked(d) ? d : vertex ? beta1(g, d) : beta0(g, d)); };
	};
	copy_orbit<Orbit::PHI21>(m, g, kept_in(true));
	copy_orbit<Orbit::PHI2>(m, g, kept_in(false));
	copy_orbit<Orbit::PHI1>(m, g, kept_in(false));
	copy_orbit<Orbit::PHI1_PHI2>(m, g, kept_in(false));
	detail::release_idle_marks(m);
	return m;
}

} // namespace cgogn
