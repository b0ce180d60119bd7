// SPDX-License-Identifier: MIT
#include <cgogn/core/map/darts.h>
#include <cgogn/core/operators/creation.h>

#include "index_lines.h"

namespace cgogn
{

namespace
{
// A phi1 cycle of n new darts; returns them in cycle order.
std::vector<Dart> new_cycle(CMap1& m, uint32 n)
{
	std::vector<Dart> darts;
	darts.reserve(n);
	for (uint32 i = 0; i < n; ++i)
		darts.push_back(detail::add_dart(m));
	for (uint32 i = 0; i < n; ++i)
		detail::set_phi1(m, darts[i], darts[(i + 1) % n]);
	return darts;
}
} // namespace

CMap1::Face add_face(CMap1& m, uint32 n, bool set_indices)
{
	assert(n >= 1);
	std::vector<Dart> darts = new_cycle(m, n);
	if (set_indices)
		detail::index_new_darts(m, darts);
	return CMap1::Face(darts[0]);
}

CMap2::Face add_face(CMap2& m, uint32 n, bool set_indices)
{
	assert(n >= 1);
	std::vector<Dart> darts = new_cycle(m, n);
	std::vector<Dart> boundary = new_cycle(m, n);
	// the boundary face runs the other way round: darts[i] goes from v_i to
	// v_i+1, its phi2 boundary[n-1-i] from v_i+1 to v_i, whose phi1 (the next
	// boundary dart) is the phi2 of darts[i-1]
	for (uint32 i = 0; i < n; ++i)
	{
		phi2_sew(m, darts[i], boundary[n - 1 - i]);
		detail::set_boundary(m, boundary[i], true);
	}
	if (set_indices)
	{
		darts.insert(darts.end(), boundary.begin(), boundary.end());
		detail::index_new_darts(m, darts);
	}
	return CMap2::Face(darts[0]);
}

} // namespace cgogn
