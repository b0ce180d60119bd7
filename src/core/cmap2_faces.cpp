// SPDX-License-Identifier: MIT
// Face and vertex operators of 2-maps: cut and merge faces, merge edges,
// split vertices, triangulate and remove faces.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/detail/dart_buffer.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/properties/properties.h>

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
constexpr Orbit F = Orbit::PHI1;
constexpr Orbit W = Orbit::PHI1_PHI2;

// A new edge {x, y}, phi2 of each other: x inserted before dx in its face (it
// ends where dx starts), y before dy. Each takes the boundary mark of the dart
// it precedes; callers set the indices.
std::pair<Dart, Dart> insert_edge_before(CMap2& m, Dart dx, Dart dy)
{
	const Dart px = phi_1(m, dx), py = phi_1(m, dy);
	const Dart x = detail::add_dart(m), y = detail::add_dart(m);
	detail::set_phi1(m, px, x);
	detail::set_phi1(m, x, dx);
	detail::set_phi1(m, py, y);
	detail::set_phi1(m, y, dy);
	phi2_sew(m, x, y);
	detail::set_boundary(m, x, is_boundary(m, dx));
	detail::set_boundary(m, y, is_boundary(m, dy));
	return {x, y};
}
// True when the face of d has at least k edges. O(k), whatever the degree of
// the face (a boundary face, a hole, can be as long as the mesh's border).
bool face_has_at_least(const CMap2& m, Dart d, uint32 k)
{
	Dart it = d;
	for (uint32 i = 1; i < k; ++i)
		if ((it = phi1(m, it)) == d)
			return false;
	return true;
}
// True when x and y are darts of one face, walking both faces at once: O(the
// smaller degree), a hole on one side is not walked whole.
bool same_face(const CMap2& m, Dart x, Dart y)
{
	for (Dart a = phi1(m, x), b = phi1(m, y);; a = phi1(m, a), b = phi1(m, b))
	{
		if (a == y || b == x)
			return true;
		if (a == x || b == y)
			return false;
	}
}
} // namespace

bool can_cut_face(const CMap2& m, CMap2::Vertex v1, CMap2::Vertex v2)
{
	const Dart d = v1.dart, e = v2.dart;
	if (d == e || is_boundary(m, d) || phi1(m, d) == e || phi1(m, e) == d)
		return false;
	return same_orbit(m, CMap2::Face(d), CMap2::Face(e));
}

CMap2::Edge cut_face(CMap2& m, CMap2::Vertex v1, CMap2::Vertex v2, bool set_indices)
{
	assert(can_cut_face(m, v1, v2));
	const Dart d = v1.dart, e = v2.dart;
	// x: origin(e) -> origin(d), before d (stays in d's part)
	// y: origin(d) -> origin(e), before e (in the new face)
	// the face (d, ..., pe, e, ..., pd) becomes (d, ..., pe, x) and (e, ..., pd, y):
	// unlike insert_edge_before, the links cross (x follows pe, y follows pd)
	const Dart pd = phi_1(m, d), pe = phi_1(m, e);
	const Dart x = detail::add_dart(m), y = detail::add_dart(m);
	detail::set_phi1(m, pe, x);
	detail::set_phi1(m, x, d);
	detail::set_phi1(m, pd, y);
	detail::set_phi1(m, y, e);
	phi2_sew(m, x, y);
	if (set_indices)
	{
		detail::copy_dart_index<V>(m, x, e);
		detail::copy_dart_index<V>(m, y, d);
		detail::copy_dart_index<W>(m, x, d);
		detail::copy_dart_index<W>(m, y, d);
		detail::index_new_cell(m, CMap2::Edge(x));
		detail::copy_dart_index<F>(m, x, d);
		detail::set_representative<F>(m, d);
		if (detail::state_of(m).cell_index[orbit_index(F)] != nullptr)
			detail::new_index(m, CMap2::Face(y));
		// rules: the new face is a part of the old one; the new edge has no
		// parent edge; each new corner is a part of the corner it cut
		if (detail::has_rules(m))
		{
			detail::inherit<F>(m, y, d);
			detail::inherit<Orbit::DART>(m, x, e);
			detail::inherit<Orbit::DART>(m, y, d);
		}
	}
	return CMap2::Edge(y);
}

bool can_merge_incident_faces(const CMap2& m, CMap2::Edge e)
{
	const Dart d = e.dart, d2 = phi2(m, d);
	return !is_boundary(m, d) && !is_boundary(m, d2) && !same_orbit(m, CMap2::Face(d), CMap2::Face(d2));
}

CMap2::Face merge_incident_faces(CMap2& m, CMap2::Edge e, bool set_indices)
{
	assert(can_merge_incident_faces(m, e));
	const Dart d = e.dart, d2 = phi2(m, d);
	const Dart pd = phi_1(m, d), pd2 = phi_1(m, d2);
	const Dart nd = phi1(m, d), nd2 = phi1(m, d2);
	if (set_indices)
	{
		detail::release_index<E>(m, detail::index_or_invalid<E>(m, d));
		const uint32 kept = detail::index_or_invalid<F>(m, d);
		const uint32 gone = detail::index_or_invalid<F>(m, d2);
		for (Dart x = nd2; x != d2; x = phi1(m, x))
			detail::set_dart_index<F>(m, x, kept);
		detail::release_index<F>(m, gone);
		detail::set_representative<F>(m, nd);
		detail::set_representative<V>(m, nd);  // origin of d2's end... nd starts at the end of d
		detail::set_representative<V>(m, nd2); // nd2 starts at the origin of d
		detail::set_representative<W>(m, nd);
	}
	detail::set_phi1(m, pd, nd2);
	detail::set_phi1(m, pd2, nd);
	detail::remove_dart(m, d);
	detail::remove_dart(m, d2);
	return CMap2::Face(nd);
}

bool can_merge_incident_faces(const CMap2& m, CMap2::Vertex v)
{
	if (is_incident_to_boundary(m, v) || degree(m, v) < 2)
		return false;
	DartMarkerStore<CMap2> faces(m);
	bool ok = true;
	// the merged face keeps the edges of the faces that are not v's: each face
	// gives its degree minus the two edges at v
	uint32 merged_degree = 0;
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		// distinct faces, none reduced to 2 edges
		if (faces.is_marked(d) || phi1(m, phi1(m, d)) == d)
			return ok = false;
		faces.mark_orbit(CMap2::Face(d));
		merged_degree += codegree(m, CMap2::Face(d)) - 2;
		return true;
	});
	return ok && merged_degree >= 3;
}

CMap2::Face merge_incident_faces(CMap2& m, CMap2::Vertex v, bool set_indices)
{
	assert(can_merge_incident_faces(m, v));
	std::vector<Dart> around; // d_i: v -> w_i, d_i+1 = phi1(phi2(d_i))
	foreach_dart_of_orbit(m, v, [&](Dart d) { around.push_back(d); });
	const std::size_t k = around.size();
	// r_i = phi1(d_i) leaves w_i; q_i = phi_1(phi2(d_i-1)) arrives at w_i-1... in face i
	std::vector<Dart> r(k), q(k);
	for (std::size_t i = 0; i < k; ++i)
	{
		r[i] = phi1(m, around[i]);
		q[i] = phi_1(m, phi2(m, around[(i + k - 1) % k]));
	}
	const uint32 kept_face = detail::index_or_invalid<F>(m, around[0]);
	if (set_indices)
	{
		detail::release_index<V>(m, detail::index_or_invalid<V>(m, around[0]));
		for (std::size_t i = 0; i < k; ++i)
		{
			detail::release_index<E>(m, detail::index_or_invalid<E>(m, around[i]));
			if (i > 0)
				detail::release_index<F>(m, detail::index_or_invalid<F>(m, around[i]));
			detail::set_representative<V>(m, r[i]); // r_i starts at w_i, which loses phi2(d_i)
		}
		detail::set_representative<W>(m, r[0]);
	}
	// the merged face runs q_i -> r_i-1: face i's path from w_i to w_i-1, then face i-1's
	for (std::size_t i = 0; i < k; ++i)
		detail::set_phi1(m, q[i], r[(i + k - 1) % k]);
	for (Dart d : around)
	{
		detail::remove_dart(m, phi2(m, d));
		detail::remove_dart(m, d);
	}
	if (set_indices && kept_face != INVALID_INDEX)
		detail::write_index(m, CMap2::Face(r[0]), kept_face);
	return CMap2::Face(r[0]);
}

bool can_merge_incident_edges(const CMap2& m, CMap2::Vertex v)
{
	const Dart x = v.dart;
	const Dart y = phi1(m, phi2(m, x));
	if (phi1(m, phi2(m, y)) != x || x == y)
		return false; // degree != 2
	// the two edges must be distinct and both faces keep at least 3 edges: x
	// and y leave their faces, both the same one when v is on a path that
	// dangles inside a face (which then loses 2 edges)
	if (same_orbit(m, CMap2::Edge(x), CMap2::Edge(y)))
		return false;
	if (same_face(m, x, y))
		return face_has_at_least(m, x, 5);
	return face_has_at_least(m, x, 4) && face_has_at_least(m, y, 4);
}

CMap2::Edge merge_incident_edges(CMap2& m, CMap2::Vertex v, bool set_indices)
{
	assert(can_merge_incident_edges(m, v));
	// v = {x: v -> b, y: v -> a}; d = phi2(y): a -> v, e2 = phi2(x): b -> v
	const Dart x = v.dart;
	const Dart e2 = phi2(m, x);
	const Dart y = phi1(m, e2);
	const Dart d = phi2(m, y);
	if (set_indices)
	{
		detail::release_index<V>(m, detail::index_or_invalid<V>(m, x));
		detail::release_index<E>(m, detail::index_or_invalid<E>(m, x));
		detail::copy_dart_index<E>(m, e2, d);
		detail::set_representative<E>(m, d);
		detail::set_representative<F>(m, d);
		detail::set_representative<F>(m, e2);
		detail::set_representative<W>(m, d);
	}
	detail::set_phi1(m, d, phi1(m, x));
	detail::set_phi1(m, e2, phi1(m, y));
	detail::remove_dart(m, x);
	detail::remove_dart(m, y);
	detail::set_phi2(m, d, e2);
	detail::set_phi2(m, e2, d);
	return CMap2::Edge(d);
}

bool can_split_vertex(const CMap2& m, Dart d1, Dart d2)
{
	return d1 != d2 && !(is_boundary(m, d1) && is_boundary(m, d2)) &&
		   same_orbit(m, CMap2::Vertex(d1), CMap2::Vertex(d2));
}

CMap2::Edge split_vertex(CMap2& m, Dart d1, Dart d2, bool set_indices)
{
	assert(can_split_vertex(m, d1, d2));
	// x: old vertex -> new vertex, before d1; y: new -> old, before d2
	auto [x, y] = insert_edge_before(m, d1, d2);
	if (set_indices)
	{
		detail::copy_dart_index<F>(m, x, d1);
		detail::copy_dart_index<F>(m, y, d2);
		detail::copy_dart_index<W>(m, x, d1);
		detail::copy_dart_index<W>(m, y, d1);
		detail::index_new_cell(m, CMap2::Edge(x));
		// the old vertex keeps its line on {d2, ..., x}; the new one gets d1's side
		const uint32 old = detail::index_or_invalid<V>(m, d2);
		detail::set_dart_index<V>(m, x, old);
		detail::set_representative<V>(m, d2);
		if (detail::state_of(m).cell_index[orbit_index(V)] != nullptr)
			detail::new_index(m, CMap2::Vertex(d1));
		// rules: the new vertex is a part of the old one, and each new corner
		// a part of the corner it cut
		if (detail::has_rules(m))
		{
			detail::inherit<V>(m, d1, d2);
			detail::inherit<Orbit::DART>(m, x, d1);
			detail::inherit<Orbit::DART>(m, y, d2);
		}
	}
	return CMap2::Edge(x);
}

CMap2::Vertex triangulate_face(CMap2& m, CMap2::Face f, bool set_indices)
{
	assert(!is_boundary(m, f.dart));
	// one pooled buffer (no allocation once warm): the sides d_i: v_i -> v_i+1,
	// then for each side the pair x_i: v_i+1 -> c, y_i: c -> v_i
	detail::DartBuffer buffer;
	std::vector<Dart>& darts = *buffer;
	foreach_dart_of_orbit(m, f, [&](Dart d) { darts.push_back(d); });
	const std::size_t k = darts.size();
	for (std::size_t i = 0; i < 2 * k; ++i)
		darts.push_back(detail::add_dart(m));
	auto side = [&](std::size_t i) { return darts[i]; };
	auto to_centre = [&](std::size_t i) { return darts[k + 2 * i]; };
	auto from_centre = [&](std::size_t i) { return darts[k + 2 * i + 1]; };
	for (std::size_t i = 0; i < k; ++i)
	{
		const std::size_t next = i + 1 == k ? 0 : i + 1;
		detail::set_phi1(m, side(i), to_centre(i));
		detail::set_phi1(m, to_centre(i), from_centre(i));
		detail::set_phi1(m, from_centre(i), side(i));
		phi2_sew(m, to_centre(i), from_centre(next));
	}
	if (set_indices)
	{
		for (std::size_t i = 0; i < k; ++i)
		{
			const std::size_t next = i + 1 == k ? 0 : i + 1;
			detail::copy_dart_index<V>(m, to_centre(i), side(next));
			detail::copy_dart_index<W>(m, to_centre(i), side(i));
			detail::copy_dart_index<W>(m, from_centre(i), side(i));
			detail::index_new_cell(m, CMap2::Edge(to_centre(i)));
		}
		detail::index_new_cell(m, CMap2::Vertex(from_centre(0)));
		// the triangle on d_0 keeps the face's line, the others get new ones
		detail::copy_dart_index<F>(m, to_centre(0), side(0));
		detail::copy_dart_index<F>(m, from_centre(0), side(0));
		detail::set_representative<F>(m, side(0));
		if (detail::state_of(m).cell_index[orbit_index(F)] != nullptr)
			for (std::size_t i = 1; i < k; ++i)
			{
				const uint32 line = detail::state_of(m).cells[orbit_index(F)]->new_line(side(i).index);
				detail::set_dart_index<F>(m, side(i), line);
				detail::set_dart_index<F>(m, to_centre(i), line);
				detail::set_dart_index<F>(m, from_centre(i), line);
			}
		// rules: the centre and its corners are the means of the face's
		// vertices and corners, the triangles parts of the face, the corners
		// at the old vertices parts of the old corners
		if (detail::has_rules(m))
		{
			const std::span<const Dart> sides(darts.data(), k);
			detail::inherit_mean<V>(m, from_centre(0), sides);
			detail::inherit_mean<Orbit::DART>(m, from_centre(0), sides);
			for (std::size_t i = 0; i < k; ++i)
			{
				if (i > 0)
				{
					detail::inherit<F>(m, side(i), side(0));
					detail::inherit<Orbit::DART>(m, from_centre(i), from_centre(0));
				}
				detail::inherit<Orbit::DART>(m, to_centre(i), side(i + 1 == k ? 0 : i + 1));
			}
		}
	}
	return CMap2::Vertex(from_centre(0));
}

void remove_face(CMap2& m, CMap2::Face f, bool set_indices)
{
	assert(!is_boundary(m, f.dart));
	std::vector<Dart> darts;
	foreach_dart_of_orbit(m, f, [&](Dart d) { darts.push_back(d); });
	// the vertices of f with their darts, before anything changes
	std::vector<std::vector<Dart>> vertex_darts(darts.size());
	for (std::size_t i = 0; i < darts.size(); ++i)
		foreach_dart_of_orbit(m, CMap2::Vertex(darts[i]), [&](Dart x) { vertex_darts[i].push_back(x); });
	if (set_indices)
		detail::release_index<F>(m, detail::index_or_invalid<F>(m, f.dart));
	for (Dart d : darts)
	{
		detail::set_boundary(m, d, true);
		detail::set_dart_index<F>(m, d, INVALID_INDEX);
	}
	// edges between two boundary darts disappear: their boundary faces merge.
	// Both darts of an edge can be darts of f (a dangling edge inside it): the
	// edge is removed once.
	DartMarkerStore<CMap2> removed_mark(m);
	std::vector<Dart> removed;
	for (Dart d : darts)
	{
		const Dart d2 = phi2(m, d);
		if (removed_mark.is_marked(d) || !is_boundary(m, d2))
			continue;
		if (set_indices)
			detail::release_index<E>(m, detail::index_or_invalid<E>(m, d));
		detail::unlink_from_faces(m, d, d2);
		removed_mark.mark(d);
		removed_mark.mark(d2);
		removed.push_back(d);
		removed.push_back(d2);
	}
	auto is_removed = [&](Dart x) { return removed_mark.is_marked(x); };
	if (set_indices)
		for (Dart d : darts)
			if (!is_removed(d))
				detail::set_representative<E>(m, d);
	const uint32 w = detail::index_or_invalid<W>(m, f.dart);
	// the vertex lines of f, and the surviving darts around its vertices
	std::vector<uint32> vertex_lines;
	std::vector<Dart> survivors;
	for (std::size_t i = 0; i < darts.size(); ++i)
	{
		vertex_lines.push_back(detail::index_or_invalid<V>(m, darts[i]));
		for (Dart x : vertex_darts[i])
			if (!is_removed(x))
				survivors.push_back(x);
	}
	for (Dart d : removed)
		detail::remove_dart(m, d);
	// one dart per vertex left around f (a vertex met twice along f, at a
	// pinch or the end of a dangling edge, can have come apart into several)
	std::vector<Dart> vertices;
	{
		DartMarkerStore<CMap2> done(m);
		for (Dart x : survivors)
			if (!done.is_marked(x))
			{
				done.mark_orbit(CMap2::Vertex(x));
				vertices.push_back(x);
			}
	}
	if (set_indices && detail::state_of(m).cell_index[orbit_index(V)] != nullptr)
	{
		// each vertex claims the line its darts carry, a second part of the
		// same line gets a new one; lines of vertices left without darts are
		// released once
		std::vector<uint32> claimed;
		const auto is_claimed = [&](uint32 l) { return std::find(claimed.begin(), claimed.end(), l) != claimed.end(); };
		for (Dart x : vertices)
		{
			const uint32 l = detail::index_or_invalid<V>(m, x);
			if (l != INVALID_INDEX && !is_claimed(l))
			{
				claimed.push_back(l);
				detail::set_representative<V>(m, x);
			}
			else // a part of a vertex that came apart: its rules' values come from l
				detail::inherit_line<V>(m, detail::new_index(m, CMap2::Vertex(x)), l);
		}
		std::sort(vertex_lines.begin(), vertex_lines.end());
		vertex_lines.erase(std::unique(vertex_lines.begin(), vertex_lines.end()), vertex_lines.end());
		for (uint32 l : vertex_lines)
			if (l != INVALID_INDEX && !is_claimed(l))
				detail::release_index<V>(m, l);
	}
	// the component can come apart the same way: one part keeps its line, the
	// others get new ones (split_component_lines, from one dart per vertex); a
	// part left with boundary darts only is removed. A part's walk stops at
	// its first real dart, so only boundary-only parts (removed anyway) are
	// walked whole.
	DartMarkerStore<CMap2> boundary_part(m);
	std::vector<Dart> boundary_only, seeds;
	for (Dart x : vertices)
	{
		if (boundary_part.is_marked(x))
			continue;
		bool real = false;
		foreach_dart_of_orbit(m, CMap2::Volume(x), [&](Dart y) { return !(real = !is_boundary(m, y)); });
		if (real)
			seeds.push_back(x);
		else
		{
			boundary_part.mark_orbit(CMap2::Volume(x));
			boundary_only.push_back(x);
		}
	}
	if (set_indices && detail::state_of(m).cell_index[orbit_index(W)] != nullptr && w != INVALID_INDEX)
	{
		if (seeds.empty())
			detail::release_index<W>(m, w);
		else
			detail::split_component_lines<CMap2::Volume>(m, w, seeds);
	}
	for (Dart x : boundary_only)
	{
		// its component line is released above (or belongs to another part)
		if (set_indices)
			foreach_dart_of_orbit(m, CMap2::Volume(x), [&](Dart y) { detail::set_dart_index<W>(m, y, INVALID_INDEX); });
		remove_volume(m, CMap2::Volume(x));
	}
}

} // namespace cgogn
