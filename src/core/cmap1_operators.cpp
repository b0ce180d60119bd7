// SPDX-License-Identifier: MIT
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/operators/cmap1.h>

#include "index_lines.h"

namespace cgogn
{

void remove_face(CMap1& m, CMap1::Face f, bool set_indices)
{
	if (set_indices)
		detail::release_index<Orbit::PHI1>(m, detail::index_or_invalid<Orbit::PHI1>(m, f.dart));
	std::vector<Dart> darts;
	foreach_dart_of_orbit(m, f, [&](Dart d) { darts.push_back(d); });
	for (Dart d : darts)
		detail::remove_dart(m, d);
}

CMap1::Vertex cut_edge(CMap1& m, CMap1::Edge e, bool set_indices)
{
	const Dart d = e.dart;
	const Dart nd = detail::add_dart(m);
	detail::set_phi1(m, nd, phi1(m, d));
	detail::set_phi1(m, d, nd);
	if (set_indices)
		detail::copy_dart_index<Orbit::PHI1>(m, nd, d);
	return CMap1::Vertex(nd);
}

CMap1::Vertex collapse_edge(CMap1& m, CMap1::Edge e, bool set_indices)
{
	const Dart d = e.dart;
	const Dart next = phi1(m, d);
	assert(next != d && "collapse_edge: the face has a single edge");
	const Dart prev = phi_1(m, d);
	detail::set_phi1(m, prev, next);
	if (set_indices)
		detail::set_representative<Orbit::PHI1>(m, next);
	detail::remove_dart(m, d);
	return CMap1::Vertex(next);
}

} // namespace cgogn
