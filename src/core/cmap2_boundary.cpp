// SPDX-License-Identifier: MIT
// Holes and boundary of 2-maps: close, fill, sew and unsew faces.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/properties/properties.h>

#include "cmap2_close.h"
#include "cmap2_unlink.h"
#include "component_split.h"
#include "index_lines.h"

#include <algorithm>

namespace cgogn
{

namespace
{
constexpr Orbit V = Orbit::PHI21;
constexpr Orbit E = Orbit::PHI2;
constexpr Orbit W = Orbit::PHI1_PHI2;

// After a sew, gives lines to the vertices of `darts` (the darts of the
// vertices that came together, or were cut apart at a pinched vertex): the
// vertex of d1 takes the first live line of `lines_d1`, that of d2 the first
// of `lines_d2`, any other vertex the first unclaimed line its darts carry,
// and vertices left without one get a new line. Lines no vertex claims are
// released. O(number of darts).
void reassign_vertex_lines(CMap2& m, const std::vector<Dart>& darts, Dart d1, std::initializer_list<uint32> lines_d1,
						   Dart d2, std::initializer_list<uint32> lines_d2)
{
	const AttributeArray<uint32>& idx = *detail::state_of(m).cell_index[orbit_index(V)];
	AttributeContainer& vc = *detail::state_of(m).cells[orbit_index(V)];
	std::vector<uint32> olds;
	for (Dart x : darts)
		if (idx[x.index] != INVALID_INDEX)
			olds.push_back(idx[x.index]);
	std::vector<uint32> claimed;
	const auto is_claimed = [&](uint32 l) { return std::find(claimed.begin(), claimed.end(), l) != claimed.end(); };
	DartMarkerStore<CMap2> done(m);
	const auto assign = [&](Dart d, std::initializer_list<uint32> preferred) {
		if (done.is_marked(d))
			return;
		done.mark_orbit(CMap2::Vertex(d));
		uint32 line = INVALID_INDEX, seen = INVALID_INDEX;
		for (uint32 l : preferred)
			if (line == INVALID_INDEX && l != INVALID_INDEX && !is_claimed(l))
				line = l;
		if (line == INVALID_INDEX)
			foreach_dart_of_orbit(m, CMap2::Vertex(d), [&](Dart x) {
				const uint32 l = idx[x.index];
				if (seen == INVALID_INDEX)
					seen = l;
				if (l != INVALID_INDEX && !is_claimed(l))
					line = l;
				return line == INVALID_INDEX;
			});
		if (line == INVALID_INDEX)
		{
			// a part of a vertex cut apart: its rules' values come from the
			// line the vertex had
			line = vc.new_line(d.index);
			detail::inherit_line<V>(m, line, seen);
		}
		claimed.push_back(line);
		detail::write_index(m, CMap2::Vertex(d), line);
	};
	assign(d1, lines_d1);
	assign(d2, lines_d2);
	for (Dart x : darts)
		assign(x, {});
	std::sort(olds.begin(), olds.end());
	olds.erase(std::unique(olds.begin(), olds.end()), olds.end());
	for (uint32 l : olds)
		if (!is_claimed(l))
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

bool can_fill_hole_with_face(const CMap2& m, Dart d)
{
	return is_boundary(m, d) && phi<1, 1>(m, d) != d && phi1(m, d) != d;
}

CMap2::Face fill_hole_with_face(CMap2& m, Dart d, bool set_indices)
{
	assert(can_fill_hole_with_face(m, d));
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
	// the darts of the four end vertices: at a pinched vertex, the sew can
	// split a vertex as well as merge two
	const bool vertices_indexed = set_indices && detail::state_of(m).cell_index[orbit_index(V)] != nullptr;
	std::vector<Dart> around;
	if (vertices_indexed)
		for (Dart d : {d1, d2, b1, b2})
			foreach_dart_of_orbit(m, CMap2::Vertex(d), [&](Dart x) {
				if (x != b1 && x != b2)
					around.push_back(x);
			});
	// the boundary darts that followed b1 and b2: a component held together
	// only by the boundary face through a pinched vertex falls apart when the
	// sew takes b1 or b2 out of it, and these darts are in the parts
	const Dart next1 = phi1(m, b1) == b1 || phi1(m, b1) == b2 ? d1 : phi1(m, b1);
	const Dart next2 = phi1(m, b2) == b2 || phi1(m, b2) == b1 ? d1 : phi1(m, b2);
	// the map is still consistent: phi_1 of the boundary darts b1, b2 is found
	// around their vertices, not along the hole
	detail::unlink_from_faces(m, b1, b2, phi_1(m, b1), phi_1(m, b2));
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
		if (vertices_indexed)
			reassign_vertex_lines(m, around, d1, {a1, a2}, d2, {c1, c2});
		if (detail::state_of(m).cell_index[orbit_index(W)] != nullptr)
		{
			if (w2 != w1)
			{
				// e2's component takes e1's line, including a part of it
				// that the sew cut off (split below)
				for (Dart s : {d2, next1, next2})
					if (detail::index_or_invalid<W>(m, s) == w2)
						detail::relabel_part<CMap2::Volume>(m, s, w2, w1);
				detail::state_of(m).cells[orbit_index(W)]->release_line(w2);
			}
			detail::split_component_lines<CMap2::Volume>(m, w1, {d1, next1, next2});
		}
	}
}

bool can_unsew_faces(const CMap2& m, CMap2::Edge e)
{
	if (is_incident_to_boundary(m, e))
		return false;
	const CMap2::Vertex a(e.dart), b(phi2(m, e.dart));
	return !(is_incident_to_boundary(m, a) && same_orbit(m, a, b));
}

void unsew_faces(CMap2& m, CMap2::Edge e, bool set_indices)
{
	assert(can_unsew_faces(m, e));
	const Dart d = e.dart;      // a -> b
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
	if (detail::state_of(m).cell_index[orbit_index(V)] != nullptr)
	{
		if (out_a.is_valid() && !same_orbit(m, CMap2::Vertex(d), CMap2::Vertex(b2)))
		{
			detail::set_representative<V>(m, d);
			detail::set_dart_index<V>(m, b2, INVALID_INDEX);
			detail::inherit_line<V>(m, detail::new_index(m, CMap2::Vertex(b2)), detail::index_or_invalid<V>(m, d));
		}
		if (out_b.is_valid() && !same_orbit(m, CMap2::Vertex(d2), CMap2::Vertex(b1)))
		{
			detail::set_representative<V>(m, d2);
			detail::inherit_line<V>(m, detail::new_index(m, CMap2::Vertex(b1)), detail::index_or_invalid<V>(m, d2));
		}
	}
	if (detail::state_of(m).cell_index[orbit_index(W)] != nullptr)
		detail::split_component_lines<CMap2::Volume>(m, detail::index_or_invalid<W>(m, d), {d, d2});
}

} // namespace cgogn
