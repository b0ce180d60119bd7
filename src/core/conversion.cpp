// SPDX-License-Identifier: MIT
// Between the two models of surfaces: CMap2 <-> GMap2, with every attribute.
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/utils/error.h>

#include <array>
#include <string>
#include <utility>

namespace cgogn
{

namespace
{

// Copies the user attributes (not the key, not the "__" ones) of `from` into
// `to`, creating them there: lines_of(i, put) calls put on each line of `to`
// that takes line i's values.
template <typename LINES>
void copy_attributes(const AttributeContainer& from, AttributeContainer& to, const LINES& lines_of)
{
	for (const auto& a : from.attributes())
	{
		if (a.get() == &from.key() || a->name().rfind("__", 0) == 0)
			continue;
		auto target = to.find(a->name());
		if (!target)
			target = a->clone_empty(to);
		for (uint32 i = 0; i < from.end_index(); ++i)
			if (from.is_live(i))
				lines_of(i, [&](uint32 line) { target->copy_line_from(line, *a, i); });
	}
}

// The cells of one orbit of the source, copied into the target map: each live
// line of the source becomes a new line of the target, written on the target
// cell of its representative dart (dart_of gives it), and its values copied.
template <Orbit TO, typename TARGET, typename SOURCE, typename DART_OF>
void copy_orbit(TARGET& target, const SOURCE& source, Orbit from, const DART_OF& dart_of)
{
	const AttributeContainer& fc = *detail::state_of(source).cells[orbit_index(from)];
	if (detail::state_of(source).cell_index[orbit_index(from)] == nullptr)
		return;
	AttributeArray<uint32>*& idx = detail::state_of(target).cell_index[orbit_index(TO)];
	if (idx == nullptr)
	{
		idx = detail::state_of(target)
				  .darts->template add_attribute<uint32>("__index_" + std::string(orbit_name(TO)), INVALID_INDEX)
				  .get();
		detail::state_of(target).cells[orbit_index(TO)]->set_cell_index(idx);
	}
	AttributeContainer& tc = *detail::state_of(target).cells[orbit_index(TO)];
	std::vector<uint32> line(fc.end_index(), INVALID_INDEX);
	for (uint32 i = 0; i < fc.end_index(); ++i)
		if (fc.is_live(i))
		{
			const Dart d = dart_of(Dart(fc.key()[i]));
			line[i] = tc.new_line(d.index);
			detail::write_index(target, Cell<TO>(d), line[i]);
		}
	copy_attributes(fc, tc, [&](uint32 i, const auto& put) { put(line[i]); });
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
	copy_attributes(darts, *detail::state_of(g).darts, [&](uint32 i, const auto& put) {
		put(a[i]);
		put(a[i] + 1);
	});
	copy_orbit<Orbit::BETA1_BETA2>(g, m, Orbit::PHI21, A);
	copy_orbit<Orbit::BETA0_BETA2>(g, m, Orbit::PHI2, A);
	copy_orbit<Orbit::BETA0_BETA1>(g, m, Orbit::PHI1, A);
	copy_orbit<Orbit::BETA0_BETA1_BETA2>(g, m, Orbit::PHI1_PHI2, A);
	detail::release_idle_marks(g);
	return g;
}

CMap2 to_cmap(const GMap2& g)
{
	if (!is_orientable(g))
		throw TopologyError("to_cmap: the G-map is not orientable (a Möbius strip, a Klein bottle, ...): no CMap2 "
							"can hold it");
	// the kept darts: in each component, the colour class of its smallest dart
	DartMarker<GMap2> kept(g), seen(g);
	std::vector<Dart> work;
	foreach_dart(g, [&](Dart s) {
		if (seen.is_marked(s))
			return;
		seen.mark(s);
		kept.mark(s);
		work.assign(1, s);
		while (!work.empty())
		{
			const Dart d = work.back();
			work.pop_back();
			for (Dart e : {beta0(g, d), beta1(g, d), beta2(g, d)})
				if (!seen.is_marked(e))
				{
					seen.mark(e);
					if (!kept.is_marked(d))
						kept.mark(e);
					work.push_back(e);
				}
		}
	});
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
	copy_attributes(darts, *detail::state_of(m).darts, [&](uint32 i, const auto& put) {
		if (c[i] != INVALID_INDEX)
			put(c[i]);
	});
	// a cell's kept dart: the representative, or its beta1 (vertices) or beta0
	// neighbour (edges, faces, components), which lies in the same cell
	auto kept_in = [&](bool vertex) {
		return [&, vertex](Dart d) { return C(kept.is_marked(d) ? d : vertex ? beta1(g, d) : beta0(g, d)); };
	};
	copy_orbit<Orbit::PHI21>(m, g, Orbit::BETA1_BETA2, kept_in(true));
	copy_orbit<Orbit::PHI2>(m, g, Orbit::BETA0_BETA2, kept_in(false));
	copy_orbit<Orbit::PHI1>(m, g, Orbit::BETA0_BETA1, kept_in(false));
	copy_orbit<Orbit::PHI1_PHI2>(m, g, Orbit::BETA0_BETA1_BETA2, kept_in(false));
	detail::release_idle_marks(m);
	return m;
}

} // namespace cgogn
