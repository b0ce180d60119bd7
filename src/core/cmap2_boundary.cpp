// SPDX-License-Identifier: MIT
// Holes and boundary of 2-maps: close, fill, sew and unsew faces.
#include <cgogn/core/functions/properties.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/index_helpers.h>

#include "cmap2_close.h"

#include <algorithm>

namespace cgogn
{

namespace
{
constexpr Orbit V = Orbit::PHI21;
constexpr Orbit E = Orbit::PHI2;
constexpr Orbit W = Orbit::PHI1_PHI2;

// After a sew, the vertices of d1 and d2 (one or two orbits) get lines from
// `olds` (the lines of the vertices that came together, in preference
// order); the lines left over are released.
void reassign_vertex_lines(CMap2& m, Dart d1, Dart d2, std::initializer_list<uint32> olds)
{
	std::vector<uint32> lines;
	for (uint32 l : olds)
		if (l != INVALID_INDEX && std::find(lines.begin(), lines.end(), l) == lines.end())
			lines.push_back(l);
	AttributeContainer& vc = *m.cells_[orbit_index(V)];
	const bool one = same_orbit(m, CMap2::Vertex(d1), CMap2::Vertex(d2));
	const uint32 l1 = lines.empty() ? vc.new_line(d1.index) : lines[0];
	detail::write_index(m, CMap2::Vertex(d1), l1);
	uint32 l2 = l1;
	if (!one)
	{
		l2 = lines.size() > 1 ? lines[1] : vc.new_line(d2.index);
		detail::write_index(m, CMap2::Vertex(d2), l2);
	}
	for (uint32 l : lines)
		if (l != l1 && l != l2)
			vc.release_line(l);
}
} // namespace

void detail::close_hole_topology(CMap2& m, Dart d, bool mark_boundary, std::vector<Dart>& created)
{
	assert(phi2(m, d) == d);
	std::vector<Dart> hole;
	Dart it = d;
	do
	{
		hole.push_back(it);
		// the next free dart along the hole: turn around the origin of it
		Dart e = phi_1(m, it);
		while (phi2(m, e) != e)
			e = phi_1(m, phi2(m, e));
		it = e;
	} while (it != d);
	const std::size_t k = hole.size(), first = created.size();
	for (std::size_t j = 0; j < k; ++j)
	{
		const Dart b = add_dart(m);
		set_boundary(m, b, mark_boundary);
		copy_dart_index<V>(m, b, phi1(m, hole[j]));
		created.push_back(b);
	}
	for (std::size_t j = 0; j < k; ++j)
	{
		set_phi1(m, created[first + j], created[first + (j + 1) % k]);
		phi2_sew(m, hole[j], created[first + j]);
	}
}

CMap2::Face close_hole(CMap2& m, Dart d, bool mark_boundary, bool set_indices)
{
	std::vector<Dart> created;
	detail::close_hole_topology(m, d, mark_boundary, created);
	if (set_indices)
	{
		for (Dart b : created)
		{
			detail::copy_dart_index<E>(m, b, phi2(m, b));
			detail::copy_dart_index<W>(m, b, phi2(m, b));
		}
		detail::index_new_darts(m, created);
	}
	return CMap2::Face(created.front());
}

uint32 close(CMap2& m, bool set_indices)
{
	std::vector<Dart> free_darts;
	foreach_dart(m, [&](Dart d) {
		if (phi2(m, d) == d)
			free_darts.push_back(d);
	});
	uint32 n = 0;
	for (Dart d : free_darts)
		if (phi2(m, d) == d)
		{
			close_hole(m, d, true, set_indices);
			++n;
		}
	return n;
}

CMap2::Face fill_hole(CMap2& m, Dart d, bool set_indices)
{
	assert(is_boundary(m, d));
	foreach_dart_of_orbit(m, CMap2::Face(d), [&](Dart x) { detail::set_boundary(m, x, false); });
	if (set_indices)
		detail::index_new_cell(m, CMap2::Face(d));
	return CMap2::Face(d);
}

bool can_sew_faces(const CMap2& m, CMap2::Edge e1, CMap2::Edge e2)
{
	const Dart d1 = e1.dart, d2 = e2.dart;
	return d1 != d2 && !is_boundary(m, d1) && !is_boundary(m, d2) && is_boundary(m, phi2(m, d1)) &&
		   is_boundary(m, phi2(m, d2));
}

void sew_faces(CMap2& m, CMap2::Edge e1, CMap2::Edge e2, bool set_indices)
{
	assert(can_sew_faces(m, e1, e2));
	const Dart d1 = e1.dart, d2 = e2.dart;
	const Dart b1 = phi2(m, d1), b2 = phi2(m, d2);
	// lines of the vertices that come together: (origin d1, end d2) and (end d1, origin d2)
	const uint32 a1 = detail::index_or_invalid<V>(m, d1), a2 = detail::index_or_invalid<V>(m, b2);
	const uint32 c1 = detail::index_or_invalid<V>(m, b1), c2 = detail::index_or_invalid<V>(m, d2);
	const uint32 w1 = detail::index_or_invalid<W>(m, d1), w2 = detail::index_or_invalid<W>(m, d2);
	// take b1 and b2 out of their boundary cycles
	const Dart p1 = phi_1(m, b1), n1 = phi1(m, b1), p2 = phi_1(m, b2), n2 = phi1(m, b2);
	if (n1 == b2 && n2 == b1)
		; // the two darts were the whole boundary face
	else if (n1 == b2)
		detail::set_phi1(m, p1, n2);
	else if (n2 == b1)
		detail::set_phi1(m, p2, n1);
	else
	{
		detail::set_phi1(m, p1, n2);
		detail::set_phi1(m, p2, n1);
	}
	if (set_indices)
		detail::release_index<E>(m, detail::index_or_invalid<E>(m, d2));
	detail::remove_dart(m, b1);
	detail::remove_dart(m, b2);
	detail::set_phi2(m, d1, d2);
	detail::set_phi2(m, d2, d1);
	if (set_indices)
	{
		detail::copy_dart_index<E>(m, d2, d1);
		detail::set_representative<E>(m, d1);
		if (m.cell_index_[orbit_index(V)] != nullptr)
			reassign_vertex_lines(m, d1, d2, {a1, a2, c1, c2});
		if (w1 != w2 && m.cell_index_[orbit_index(W)] != nullptr)
			detail::merge_cell_indices(m, CMap2::Volume(d1), w1, w2);
	}
}

void unsew_faces(CMap2& m, CMap2::Edge e, bool set_indices)
{
	assert(!is_incident_to_boundary(m, e));
	const Dart d = e.dart;    // a -> b
	const Dart d2 = phi2(m, d); // b -> a
	// the boundary darts leaving a and b, if those vertices are on the boundary
	auto boundary_out = [&](Dart start) {
		Dart it = start;
		do
		{
			if (is_boundary(m, it))
				return it;
			it = phi1(m, phi2(m, it));
		} while (it != start);
		return Dart();
	};
	const Dart out_a = boundary_out(d), out_b = boundary_out(d2);
	// read the boundary darts arriving at a and b before any relinking
	const Dart in_a = out_a.is_valid() ? phi_1(m, out_a) : Dart();
	const Dart in_b = out_b.is_valid() ? phi_1(m, out_b) : Dart();
	const Dart b1 = detail::add_dart(m); // b -> a, phi2 of d
	const Dart b2 = detail::add_dart(m); // a -> b, phi2 of d2
	detail::set_boundary(m, b1, true);
	detail::set_boundary(m, b2, true);
	// at a: b1 arrives, b2 leaves; at b: b2 arrives, b1 leaves
	if (out_a.is_valid())
	{
		detail::set_phi1(m, in_a, b2);
		detail::set_phi1(m, b1, out_a);
	}
	else
		detail::set_phi1(m, b1, b2);
	if (out_b.is_valid())
	{
		detail::set_phi1(m, in_b, b1);
		detail::set_phi1(m, b2, out_b);
	}
	else
		detail::set_phi1(m, b2, b1);
	phi2_unsew(m, d);
	phi2_sew(m, d, b1);
	phi2_sew(m, d2, b2);
	if (!set_indices)
		return;
	detail::copy_dart_index<V>(m, b1, d2);
	detail::copy_dart_index<V>(m, b2, d);
	detail::copy_dart_index<E>(m, b1, d);
	detail::copy_dart_index<W>(m, b1, d);
	detail::copy_dart_index<W>(m, b2, d);
	detail::set_representative<E>(m, d);
	detail::set_dart_index<E>(m, d2, INVALID_INDEX);
	detail::index_new_cell(m, CMap2::Edge(d2));
	// an end vertex already on the boundary is now two vertices: the part
	// without d (resp. d2) gets a new line
	if (m.cell_index_[orbit_index(V)] != nullptr)
	{
		if (out_a.is_valid() && !same_orbit(m, CMap2::Vertex(d), CMap2::Vertex(b2)))
		{
			detail::set_representative<V>(m, d);
			detail::set_dart_index<V>(m, b2, INVALID_INDEX);
			detail::new_index(m, CMap2::Vertex(b2));
		}
		if (out_b.is_valid() && !same_orbit(m, CMap2::Vertex(d2), CMap2::Vertex(b1)))
		{
			detail::set_representative<V>(m, d2);
			detail::new_index(m, CMap2::Vertex(b1));
		}
	}
	if (m.cell_index_[orbit_index(W)] != nullptr && !same_orbit(m, CMap2::Volume(d), CMap2::Volume(d2)))
	{
		detail::set_representative<W>(m, d);
		detail::new_index(m, CMap2::Volume(d2));
	}
}

} // namespace cgogn
