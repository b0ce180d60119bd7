// SPDX-License-Identifier: MIT
// Holes and boundary of 2-G-maps: close, fill, sew and unsew faces.
#include <cgogn/core/operators/gmap2.h>
#include <cgogn/core/properties/gmap_properties.h>

#include "gmap_darts.h"
#include "index_lines.h"
#include "reindex.h"

#include <algorithm>
#include <cassert>

namespace cgogn
{

namespace
{
constexpr Orbit V = Orbit::BETA1_BETA2;
constexpr Orbit E = Orbit::BETA0_BETA2;
constexpr Orbit W = Orbit::BETA0_BETA1_BETA2;

// The next beta2 fixed point around the vertex of x, starting with beta1(x).
Dart next_free_around_vertex(const GMap2& m, Dart x)
{
	Dart y = beta1(m, x);
	while (beta2(m, y) != y)
		y = beta<2, 1>(m, y);
	return y;
}

// The boundary dart at the vertex of `start` met first when turning from
// start away from beta2(start) (beta1, then beta2, ...); an invalid dart when
// the vertex has no boundary. O(degree).
Dart boundary_dart_turning_from(const GMap2& m, Dart start)
{
	const Dart stop = beta2(m, start);
	for (Dart x = beta1(m, start); x != stop; x = beta1(m, beta2(m, x)))
		if (is_boundary(m, beta2(m, x)))
			return beta2(m, x);
	return Dart();
}
} // namespace

GMap2::Face close_hole(GMap2& m, Dart d, bool mark_boundary, bool set_indices)
{
	assert(beta2(m, d) == d);
	// the free darts along the hole: edge by edge (beta0), then turning around
	// the vertex to the next free dart
	std::vector<Dart> hole;
	Dart it = d;
	do
	{
		assert(beta2(m, beta0(m, it)) == beta0(m, it) && "both darts of a free edge side are free");
		hole.insert(hole.end(), {it, beta0(m, it)});
		it = next_free_around_vertex(m, beta0(m, it));
	} while (it != d);
	std::vector<Dart> created;
	created.reserve(hole.size());
	for (std::size_t j = 0; j < hole.size(); j += 2)
	{
		const Dart b = detail::add_dart_pair(m);
		created.insert(created.end(), {b, beta0(m, b)});
	}
	for (std::size_t j = 0; j < hole.size(); ++j)
	{
		detail::set_boundary(m, created[j], mark_boundary);
		beta_sew<2>(m, hole[j], created[j]);
	}
	for (std::size_t j = 0; j < created.size(); j += 2)
		beta_sew<1>(m, created[j + 1], created[(j + 2) % created.size()]);
	if (set_indices)
	{
		for (Dart b : created)
		{
			const Dart h = beta2(m, b);
			detail::copy_dart_index<V>(m, b, h);
			detail::copy_dart_index<E>(m, b, h);
			detail::copy_dart_index<W>(m, b, h);
		}
		detail::index_new_darts(m, created);
	}
	return GMap2::Face(created.front());
}

uint32 close(GMap2& m, bool set_indices)
{
	std::vector<Dart> free_darts;
	foreach_dart(m, [&](Dart d) {
		if (beta2(m, d) == d)
			free_darts.push_back(d);
	});
	uint32 n = 0;
	for (Dart d : free_darts)
		if (beta2(m, d) == d)
		{
			close_hole(m, d, true, set_indices);
			++n;
		}
	return n;
}

bool can_fill_hole_with_face(const GMap2& m, Dart d)
{
	return is_boundary(m, d) && codegree(m, GMap2::Face(d)) >= 3;
}

GMap2::Face fill_hole_with_face(GMap2& m, Dart d, bool set_indices)
{
	assert(can_fill_hole_with_face(m, d));
	foreach_dart_of_orbit(m, GMap2::Face(d), [&](Dart x) { detail::set_boundary(m, x, false); });
	if (set_indices)
		detail::index_new_cell(m, GMap2::Face(d));
	return GMap2::Face(d);
}

bool can_sew_faces(const GMap2& m, GMap2::Edge e1, GMap2::Edge e2)
{
	const Dart d1 = e1.dart, d2 = e2.dart;
	return !is_boundary(m, d1) && !is_boundary(m, d2) && is_boundary(m, beta2(m, d1)) && is_boundary(m, beta2(m, d2)) &&
		   !same_orbit(m, e1, e2);
}

void sew_faces(GMap2& m, GMap2::Edge e1, GMap2::Edge e2, bool set_indices)
{
	assert(can_sew_faces(m, e1, e2));
	const Dart d1 = e1.dart, d2 = e2.dart, d10 = beta0(m, d1), d20 = beta0(m, d2);
	// the boundary darts that go, and the dart each is identified with
	const std::array<Dart, 4> gone{beta2(m, d1), beta2(m, d10), beta2(m, d2), beta2(m, d20)};
	const auto counterpart = [&](Dart b) {
		const std::size_t i = std::find(gone.begin(), gone.end(), b) - gone.begin();
		return gone[(i + 2) % 4];
	};
	const auto is_gone = [&](Dart b) { return std::find(gone.begin(), gone.end(), b) != gone.end(); };
	// boundary darts left with a beta1 partner that goes: each is linked to
	// the one met by following the identification through the darts that go
	std::vector<std::pair<Dart, Dart>> links;
	std::vector<Dart> region{d1, d10, d2, d20};
	for (Dart b : gone)
	{
		const Dart loose = beta1(m, b);
		if (is_gone(loose))
			continue;
		Dart t = beta1(m, counterpart(b));
		while (is_gone(t))
			t = beta1(m, counterpart(t));
		assert(t != loose && "the sew would leave a boundary corner of one dart");
		links.emplace_back(loose, t);
		region.insert(region.end(), {loose, t});
	}
	detail::RegionReindexer<GMap2> reindex;
	if (set_indices)
	{
		reindex.record(m, region);
		reindex.record(m, {gone.begin(), gone.end()});
		reindex.components_may_split();
	}
	detail::remove_dart_pairs(m, {gone.begin(), gone.end()});
	for (const auto& [a, b] : links)
		detail::link_beta<1>(m, a, b);
	detail::link_beta<2>(m, d1, d2);
	detail::link_beta<2>(m, d10, d20);
	if (set_indices)
		reindex.apply(m, region);
}

bool can_unsew_faces(const GMap2& m, GMap2::Edge e)
{
	if (is_incident_to_boundary(m, e))
		return false;
	const GMap2::Vertex a(e.dart), b(beta0(m, e.dart));
	return !(is_incident_to_boundary(m, a) && same_orbit(m, a, b));
}

void unsew_faces(GMap2& m, GMap2::Edge e, bool set_indices)
{
	assert(can_unsew_faces(m, e));
	const auto [d, d0, d2, d20] = detail::edge_darts(m, e.dart);
	// at each end, the boundary corner met turning from the edge's second
	// side: it is cut open, each part of the vertex getting one of the new
	// boundary darts (an end without boundary gets a new corner instead)
	const Dart u_a = boundary_dart_turning_from(m, d2), u_b = boundary_dart_turning_from(m, d20);
	const Dart v_a = u_a.is_valid() ? beta1(m, u_a) : Dart(), v_b = u_b.is_valid() ? beta1(m, u_b) : Dart();
	std::vector<Dart> region{d, d0, d2, d20};
	for (Dart x : {u_a, v_a, u_b, v_b})
		if (x.is_valid())
			region.push_back(x);
	detail::RegionReindexer<GMap2> reindex;
	if (set_indices)
	{
		reindex.record(m, region);
		reindex.components_may_split();
	}
	// b, b0 become beta2 of d, d0; c, c0 of d2, d20
	const Dart b = detail::add_dart_pair(m), b0 = beta0(m, b), c = detail::add_dart_pair(m), c0 = beta0(m, c);
	for (Dart x : {b, b0, c, c0})
		detail::set_boundary(m, x, true);
	beta_unsew<2>(m, d);
	beta_unsew<2>(m, d0);
	beta_sew<2>(m, d, b);
	beta_sew<2>(m, d0, b0);
	beta_sew<2>(m, d2, c);
	beta_sew<2>(m, d20, c0);
	const auto open_corner = [&](Dart u, Dart v, Dart on_d_side, Dart on_d2_side) {
		if (!u.is_valid())
		{
			beta_sew<1>(m, on_d_side, on_d2_side);
			return;
		}
		// u was reached from the second side: it closes that part
		detail::link_beta<1>(m, u, on_d2_side);
		detail::link_beta<1>(m, v, on_d_side);
	};
	open_corner(u_a, v_a, b, c);
	open_corner(u_b, v_b, b0, c0);
	region.insert(region.end(), {b, b0, c, c0});
	if (set_indices)
		reindex.apply(m, region);
}

} // namespace cgogn
