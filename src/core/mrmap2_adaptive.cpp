// SPDX-License-Identifier: MIT
// Adaptive refinement of multiresolution 2-maps: one face at a time.
#include <cgogn/core/map/mrmap2_attributes.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/properties/properties.h>

#include "mr_indexing.h"
#include "mrmap2_refine.h"

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <vector>

namespace cgogn
{

namespace
{

using detail::MRState2;
using Face = MRMap2::Face;
using Edge = MRMap2::Edge;
using Vertex = MRMap2::Vertex;

uint8 id_of(const MRState2& s, Dart d)
{
	return (*s.edge_id)[d.index];
}

/// A dart of face f, read at the level of v, made at or before level k.
Dart dart_up_to(const MRLevelView2& v, Dart f, uint32 k)
{
	Dart r;
	foreach_dart_of_orbit(v, Face(f), [&](Dart d) {
		if (detail::mr_dart_level(v.state(), d) > k)
			return true;
		r = d;
		return false;
	});
	return r;
}

/// The darts of face f read at level l.
std::vector<Dart> face_darts(const MRState2& s, uint32 l, Dart f)
{
	std::vector<Dart> darts;
	foreach_dart_of_orbit(MRLevelView2(s, l), Face(f), [&](Dart d) { darts.push_back(d); });
	return darts;
}

/// At the midpoint that cuts the edge of x at level l + 1, the piece of the
/// edge after it on x's side (what phi1 at level l turns to there).
Dart piece_after_midpoint(const MRState2& s, uint32 l, Dart x)
{
	Dart it = detail::mr_phi1(s, l + 1, x);
	while (id_of(s, it) != id_of(s, x) || detail::mr_dart_level(s, it) != l + 1)
		it = detail::mr_phi1(s, l + 1, detail::mr_phi2(s, l + 1, it));
	return it;
}

/// A cut made by a subdivision: x keeps the first piece, n1 starts the second.
struct Cut
{
	Dart x, n1;
	uint32 parent; // the edge's line before the cut
};

/// Gives lines to the cells a subdivision of the face of corners `corners`
/// (level k) made at level l = k + 1.
void index_subdivision(MRState2& s, uint32 l, const std::vector<Dart>& corners, const std::vector<Cut>& cuts,
					   const std::vector<Dart>& created, uint32 face_line)
{
	if (detail::mr_indexed(s, 0))
	{
		AttributeArray<uint32>& idx = detail::mr_index(s, 0);
		for (Dart x : corners)
			detail::mr_ensure_vertex_line(s, x, l);
		std::vector<double> weights;
		AttributeContainer& c = *detail::state_of(s.map).cells[orbit_index(Orbit::PHI21)];
		for (Dart y : created)
		{
			if (idx[y.index] != INVALID_INDEX)
				continue;
			// a vertex made now, or one a neighbour made (whose line the new darts take)
			uint32 line = INVALID_INDEX;
			foreach_dart_of_orbit(s.map, CMap2::Vertex(y), [&](Dart z) {
				line = idx[z.index];
				return line == INVALID_INDEX;
			});
			if (line == INVALID_INDEX)
			{
				line = detail::mr_add_line(s, 0, l, y, INVALID_INDEX);
				if (c.has_rules())
				{
					const std::vector<uint32> parents = detail::mr_vertex_parents(s, l, y);
					weights.assign(parents.size(), parents.empty() ? 0.0 : 1.0 / double(parents.size()));
					if (!parents.empty())
						c.apply_rules(line, parents, weights);
				}
			}
			detail::mr_write_line(s, 0, y, line);
		}
	}
	if (detail::mr_indexed(s, 1))
	{
		AttributeArray<uint32>& idx = detail::mr_index(s, 1);
		for (const Cut& cut : cuts)
		{
			detail::mr_write_line(s, 1, cut.x, detail::mr_add_line(s, 1, l, cut.x, cut.parent));
			detail::mr_write_line(s, 1, cut.n1, detail::mr_add_line(s, 1, l, cut.n1, cut.parent));
		}
		for (Dart y : created)
			if (idx[y.index] == INVALID_INDEX) // an inner edge
				detail::mr_write_line(s, 1, y, detail::mr_add_line(s, 1, l, y, INVALID_INDEX));
	}
	if (detail::mr_indexed(s, 2))
	{
		AttributeArray<uint32>& idx = detail::mr_index(s, 2);
		// the new darts on the neighbours' side read their faces' lines
		for (const Cut& cut : cuts)
		{
			const Dart n2 = phi2(s.map, cut.x);
			idx[n2.index] = idx[phi1(s.map, n2).index];
		}
		// the children: the faces of the corners and of the new inner darts
		std::vector<uint32> children;
		auto child = [&](Dart y) {
			if (is_boundary(s.map, y) || std::find(children.begin(), children.end(), idx[y.index]) != children.end())
				return;
			const uint32 line = detail::mr_add_line(s, 2, l, y, face_line);
			detail::mr_write_line(s, 2, y, line);
			children.push_back(line);
		};
		for (Dart x : corners)
			child(x);
		for (Dart y : created)
			if (detail::mr_dart_level(s, detail::mr_phi2(s, l, y)) == l)
				child(y);
	}
	if (detail::mr_indexed(s, 3))
	{
		AttributeArray<uint32>& idx = detail::mr_index(s, 3);
		for (Dart y : created)
			idx[y.index] = idx[corners.front().index];
	}
}

/// Subdivides the leaf face of dart d (made at or before k, the face's
/// level), after its coarser neighbours when balancing.
void subdivide_leaf(MRState2& s, Dart d, uint32 k, Refinement r, bool balance)
{
	if (k >= 254)
		throw std::invalid_argument("subdivide_face: 255 levels at most");
	while (balance)
	{
		// a neighbour made before level k would be two levels coarser than the children
		const MRLevelView2 vk(s, k);
		Dart coarser;
		uint32 coarser_level = 0;
		foreach_dart_of_orbit(vk, Face(d), [&](Dart x) {
			const Dart y = detail::mr_phi2(s, k, x);
			if (is_boundary(s.map, y))
				return true;
			coarser_level = face_level(vk, Face(y));
			if (coarser_level >= k)
				return true;
			coarser = dart_up_to(vk, y, coarser_level);
			return false;
		});
		if (!coarser.is_valid())
			break;
		subdivide_leaf(s, coarser, coarser_level, r == Refinement::Triangular ? Refinement::Mixed : r, true);
	}
	const uint32 l = k + 1;
	if (l >= s.darts_per_level.size())
		s.darts_per_level.push_back(0);
	const std::vector<Dart> corners = face_darts(s, k, d);
	const uint32 face_line = detail::mr_indexed(s, 2) ? detail::mr_line_of(s, k, 2, d) : INVALID_INDEX;
	detail::MRNewDarts labels(s, uint8(l), true);
	std::vector<Cut> cuts;
	for (Dart x : corners)
	{
		const Dart y = detail::mr_phi1(s, l, x);
		if (detail::mr_dart_level(s, y) == l && id_of(s, y) == id_of(s, x))
			continue; // a neighbour cut it already
		const uint32 parent = detail::mr_indexed(s, 1) ? detail::mr_line_of(s, k, 1, x) : INVALID_INDEX;
		const Dart n1 = cut_edge(s.map, CMap2::Edge(x), false).dart;
		labels.label(n1, id_of(s, x));
		labels.label(phi2(s.map, x), id_of(s, x));
		cuts.push_back({x, n1, parent});
	}
	std::vector<Dart> mids;
	for (Dart x : corners)
		mids.push_back(detail::mr_phi1(s, l, x));
	if (corners.size() == 3 && r != Refinement::Quadrangular)
		detail::mr_refine_triangle(s, labels, {mids[0], mids[1], mids[2]});
	else
		detail::mr_refine_quadrangular(s, labels, mids);
	s.darts_per_level[l] += labels.count();
	index_subdivision(s, l, corners, cuts, labels.darts(), face_line);
}

} // namespace

uint32 edge_level(const MRLevelView2& v, MRMap2::Edge e)
{
	const MRState2& s = v.state();
	return std::max(detail::mr_dart_level(s, e.dart), detail::mr_dart_level(s, detail::mr_phi2(s, v.level(), e.dart)));
}

uint32 face_level(const MRLevelView2& v, MRMap2::Face f)
{
	uint32 a = 255, b = 255; // the two smallest levels
	foreach_dart_of_orbit(v, f, [&](Dart d) {
		const uint32 x = detail::mr_dart_level(v.state(), d);
		if (x < a)
		{
			b = a;
			a = x;
		}
		else if (x < b)
			b = x;
	});
	return b;
}

bool edge_is_subdivided(const MRLevelView2& v, MRMap2::Edge e)
{
	const MRState2& s = v.state();
	const uint32 l = v.level();
	if (detail::mr_is_finest(s, l))
		return false;
	// cut: the other side of e.dart's piece is a new dart
	return detail::mr_phi2(s, l + 1, e.dart) != detail::mr_phi2(s, l, e.dart);
}

bool face_is_subdivided(const MRLevelView2& v, MRMap2::Face f)
{
	const MRState2& s = v.state();
	const uint32 l = v.level();
	if (detail::mr_is_finest(s, l) || face_level(v, f) < l)
		return false;
	const Dart x = detail::mr_phi1(s, l + 1, f.dart);
	return detail::mr_dart_level(s, x) == l + 1 && id_of(s, x) != id_of(s, f.dart);
}

void subdivide_face(MRMap2& m, MRMap2::Face f, Refinement r, bool balance)
{
	if (r != Refinement::Triangular && r != Refinement::Quadrangular && r != Refinement::Mixed)
		throw std::invalid_argument("subdivide_face: a 3-D refinement pattern on a 2-D map");
	MRState2& s = detail::mr_state_of(m);
	if (is_boundary(s.map, f.dart))
		throw std::invalid_argument("subdivide_face: a boundary face");
	const MRLevelView2 v = detail::read_level(m);
	const uint32 k = face_level(v, f);
	const Dart d = dart_up_to(v, f.dart, k);
	const MRLevelView2 vk(s, k);
	if (face_is_subdivided(vk, Face(d)))
		throw std::invalid_argument("subdivide_face: the face has children already");
	if (r == Refinement::Triangular && codegree(vk, Face(d)) != 3)
		throw std::invalid_argument("subdivide_face: Triangular refinement of a face that is not a triangle");
	subdivide_leaf(s, d, k, r, balance);
}

bool can_coarsen_face(const MRMap2& m, MRMap2::Face f)
{
	const MRState2& s = detail::mr_state_of(m);
	const MRLevelView2 v = detail::read_level(m);
	const uint32 k = v.level(), l = k + 1;
	if (is_boundary(s.map, f.dart) || face_level(v, f) != k || !face_is_subdivided(v, f))
		return false;
	const MRLevelView2 vl(s, l);
	bool ok = true;
	const std::vector<Dart> corners = face_darts(s, k, f.dart);
	for (Dart x : corners)
	{
		// the child at x, and the two pieces of x's edge on f's side
		ok = ok && !face_is_subdivided(vl, Face(x)) && !edge_is_subdivided(vl, Edge(x)) &&
			 !edge_is_subdivided(vl, Edge(piece_after_midpoint(s, k, x)));
	}
	if (ok && corners.size() == 3 && codegree(vl, Face(corners[0])) == 3)
		ok = !face_is_subdivided(vl, Face(detail::mr_phi2(s, l, detail::mr_phi1(s, l, corners[0]))));
	return ok;
}

void coarsen_face(MRMap2& m, MRMap2::Face f)
{
	assert(can_coarsen_face(m, f));
	MRState2& s = detail::mr_state_of(m);
	const uint32 k = current_level(m), l = k + 1;
	const MRLevelView2 vk(s, k), vl(s, l);
	const std::vector<Dart> corners = face_darts(s, k, f.dart);
	const bool triangles = corners.size() == 3 && codegree(vl, Face(corners[0])) == 3;

	// what goes: the inner edges (around the centre, or of the middle
	// triangle) and the midpoints that no neighbour uses
	struct Mid
	{
		Dart x, piece; // x leads to the midpoint, piece leaves it on f's side
		bool removed;
	};
	std::vector<Mid> mids;
	for (Dart x : corners)
	{
		const Dart y = detail::mr_phi2(s, k, x);
		const bool used = !is_boundary(s.map, y) && face_is_subdivided(vk, Face(y));
		mids.push_back({x, piece_after_midpoint(s, k, x), !used});
	}
	std::vector<Dart> inner; // the inner dart after each corner's piece
	for (Dart x : corners)
		inner.push_back(detail::mr_phi1(s, l, x));
	const Dart centre = triangles ? Dart() : detail::mr_phi1(s, l, inner[0]);

	// the lines of what goes, read while its darts are there
	std::vector<uint32> vertex_lines, edge_lines, face_lines;
	uint32 face_line = INVALID_INDEX;
	if (detail::mr_indexed(s, 2))
	{
		for (Dart x : corners)
			face_lines.push_back(detail::mr_index(s, 2)[x.index]);
		if (triangles)
			face_lines.push_back(detail::mr_index(s, 2)[phi2(s.map, inner[0]).index]);
		face_line = (*s.cells[2].down)[face_lines.front()];
	}
	if (detail::mr_indexed(s, 1))
	{
		if (triangles)
			for (Dart y : inner)
				edge_lines.push_back(detail::mr_index(s, 1)[y.index]);
		else // every inner edge touches the centre
			foreach_dart_of_orbit(s.map, CMap2::Vertex(centre),
								  [&](Dart y) { edge_lines.push_back(detail::mr_index(s, 1)[y.index]); });
		for (const Mid& mid : mids)
			if (mid.removed)
				edge_lines.insert(edge_lines.end(),
								  {detail::mr_index(s, 1)[mid.x.index], detail::mr_index(s, 1)[mid.piece.index]});
	}
	if (detail::mr_indexed(s, 0))
	{
		if (!triangles)
			vertex_lines.push_back(detail::mr_index(s, 0)[centre.index]);
		for (const Mid& mid : mids)
			if (mid.removed)
				vertex_lines.push_back(detail::mr_index(s, 0)[mid.piece.index]);
	}

	// the topology
	uint32 removed = 0;
	if (triangles)
	{
		for (Dart y : inner)
			merge_incident_faces(s.map, CMap2::Edge(y), false);
		removed += 6;
	}
	else
	{
		removed += 2 * degree(s.map, CMap2::Vertex(centre));
		merge_incident_faces(s.map, CMap2::Vertex(centre), false);
	}
	for (const Mid& mid : mids)
		if (mid.removed)
		{
			merge_incident_edges(s.map, CMap2::Vertex(mid.piece), false);
			removed += 2;
		}

	// the lines: f and its cut edges read their own again
	const auto release = [&](Orbit o, const std::vector<uint32>& lines) {
		for (uint32 i : lines)
			detail::state_of(s.map).cells[orbit_index(o)]->release_line(i);
	};
	if (detail::mr_indexed(s, 2))
	{
		(*s.cells[2].replaced)[face_line] = detail::MR_NOT_REPLACED;
		detail::mr_write_line(s, 2, corners[0], face_line);
		release(Orbit::PHI1, face_lines);
	}
	if (detail::mr_indexed(s, 1))
	{
		for (const Mid& mid : mids)
			if (mid.removed)
			{
				const uint32 parent = (*s.cells[1].down)[detail::mr_index(s, 1)[mid.x.index]];
				(*s.cells[1].replaced)[parent] = detail::MR_NOT_REPLACED;
				detail::mr_write_line(s, 1, mid.x, parent);
			}
		release(Orbit::PHI2, edge_lines);
	}
	if (detail::mr_indexed(s, 0))
	{
		release(Orbit::PHI21, vertex_lines);
		// a corner keeps a line at level l while a face of level l touches it
		for (Dart x : corners)
		{
			bool touched = false;
			foreach_dart_of_orbit(vl, Vertex(x), [&](Dart y) {
				touched = !is_boundary(s.map, y) && face_level(vl, Face(y)) == l;
				return !touched;
			});
			if (!touched)
				detail::mr_drop_vertex_line(s, x, l);
		}
	}
	s.darts_per_level[l] -= removed;
	while (s.darts_per_level.size() > 1 && s.darts_per_level.back() == 0)
		s.darts_per_level.pop_back();
	s.current_level = std::min<uint32>(s.current_level, uint32(s.darts_per_level.size() - 1));
}

} // namespace cgogn
