// SPDX-License-Identifier: MIT
// Adaptive refinement of multiresolution 3-maps: one hexahedron at a time.
#include <cgogn/core/map/mrmap3_attributes.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_mrmap3.h>

#include "mr_indexing.h"
#include "mrmap3_refine.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <stdexcept>
#include <vector>

namespace cgogn
{

namespace
{

using detail::MRState3;
using Vertex = MRMap3::Vertex;
using Edge = MRMap3::Edge;
using Face = MRMap3::Face;
using Face2 = MRMap3::Face2;
using Vertex2 = MRMap3::Vertex2;
using Volume = MRMap3::Volume;

using Slots = detail::MRDim<MRState3>;
constexpr uint32 vertex_slot = Slots::vertex_slot, edge_slot = Slots::edge_slot, face_slot = Slots::face_slot,
				 volume_slot = Slots::volume_slot, component_slot = Slots::component_slot;

/// The line of the cell of d in slot `slot` at level l, or INVALID_INDEX when
/// the slot is not indexed.
uint32 line_or_none(const MRState3& s, uint32 l, uint32 slot, Dart d)
{
	return detail::mr_indexed(s, slot) ? detail::mr_line_of(s, l, slot, d) : INVALID_INDEX;
}

/// The k-th smallest level (k >= 1) of the darts f gives to its callback.
template <typename FOREACH>
uint32 kth_smallest_level(const MRState3& s, uint32 k, const FOREACH& foreach)
{
	std::array<uint32, 4> smallest{255, 255, 255, 255};
	foreach ([&](Dart d) {
		uint32 x = detail::mr_dart_level(s, d);
		for (uint32 i = 0; i < k; ++i)
			if (x < smallest[i])
				std::swap(x, smallest[i]);
	})
		;
	return smallest[k - 1];
}

/// A dart of volume w, read at the level of v, made at or before level k.
Dart dart_up_to(const MRLevelView3& v, Dart w, uint32 k)
{
	Dart r;
	foreach_dart_of_orbit(v, Volume(w), [&](Dart d) {
		if (detail::mr_dart_level(v.state(), d) > k)
			return true;
		r = d;
		return false;
	});
	return r;
}

/// Throws std::invalid_argument unless the volume of d at level k is a
/// hexahedron whose surface holds no cut finer than level k + 1.
void check_subdividable(const MRState3& s, Dart d, uint32 k)
{
	const MRLevelView3 vk(s, k);
	uint32 nb = 0;
	bool hexahedron = true;
	foreach_dart_of_orbit(vk, Volume(d), [&](Dart x) {
		++nb;
		const auto p1 = [&](Dart y) { return detail::mr_phi1(s, k, y); };
		const auto p2 = [&](Dart y) { return detail::mr_phi2(s, k, y); };
		hexahedron = hexahedron && p1(p1(p1(p1(x)))) == x && p1(p2(p1(p2(p1(p2(x)))))) == x;
		return hexahedron;
	});
	if (!hexahedron || nb != 24)
		throw std::invalid_argument("subdivide_volume: the volume is not a hexahedron");
	bool regular = true;
	foreach_dart_of_orbit(s.map, CMap3::Volume(d), [&](Dart x) {
		regular = detail::mr_dart_level(s, x) <= k + 1;
		return regular;
	});
	if (!regular)
		throw std::invalid_argument("subdivide_volume: a neighbour more than one level finer cut the volume's surface "
									"(subdivide with balance)");
}

/// The line held by a dart of the finest cell of d in slot `slot`
/// (INVALID_INDEX when none holds one).
uint32 line_held(const MRState3& s, uint32 slot, Dart d)
{
	uint32 line = INVALID_INDEX;
	detail::mr_foreach_dart_of_cell(s, slot, uint32(s.darts_per_level.size() - 1), d, [&](Dart x) {
		line = (*s.cells[slot].index)[x.index];
		return line == INVALID_INDEX;
	});
	return line;
}

/// What a subdivision of a hexahedron cut, read before the cuts.
struct Subdivision
{
	struct Cut
	{
		Dart x, n1;    // x keeps the first half, n1 starts the second
		uint32 parent; // the edge's line before the cut
	};
	struct Split
	{
		std::vector<Dart> corners; // the face's darts of the level below, one per quad
		uint32 parent;             // the face's line before the cut
	};
	std::vector<Dart> volume_darts; // the hexahedron's darts of the level below
	std::vector<Dart> corners;      // one dart per corner
	std::vector<Cut> cuts;
	std::vector<Split> splits;
	uint32 volume_line = INVALID_INDEX;
};

/// For a created dart y without a line in `slot`: the line its finest cell
/// holds already, or a new one (no parent) when the cell is new, written on
/// the cell.
void give_line(MRState3& s, uint32 slot, uint32 l, Dart y)
{
	if (detail::mr_index(s, slot)[y.index] != INVALID_INDEX)
		return;
	uint32 line = line_held(s, slot, y);
	if (line == INVALID_INDEX)
		line = detail::mr_add_line(s, slot, l, y, INVALID_INDEX);
	detail::mr_write_line(s, slot, y, line);
}

/// Gives lines to the cells a subdivision made at level l (see
/// subdivide_volume).
void index_subdivision(MRState3& s, uint32 l, const Subdivision& sub, const std::vector<Dart>& created)
{
	if (detail::mr_indexed(s, vertex_slot))
	{
		for (Dart c : sub.corners)
			detail::mr_ensure_vertex_line(s, c, l);
		AttributeContainer& c = detail::mr_slot_container(s, vertex_slot);
		std::vector<double> weights;
		for (Dart y : created)
		{
			if (detail::mr_index(s, vertex_slot)[y.index] != INVALID_INDEX)
				continue;
			uint32 line = line_held(s, vertex_slot, y);
			if (line == INVALID_INDEX)
			{
				line = detail::mr_add_line(s, vertex_slot, l, y, INVALID_INDEX);
				if (c.has_rules())
				{
					const std::vector<uint32> parents = detail::mr_vertex_parents(s, l, y);
					weights.assign(parents.size(), parents.empty() ? 0.0 : 1.0 / double(parents.size()));
					if (!parents.empty())
						c.apply_rules(line, parents, weights);
				}
			}
			detail::mr_write_line(s, vertex_slot, y, line);
		}
	}
	if (detail::mr_indexed(s, edge_slot))
	{
		for (const Subdivision::Cut& cut : sub.cuts)
		{
			detail::mr_write_line(s, edge_slot, cut.x, detail::mr_add_line(s, edge_slot, l, cut.x, cut.parent));
			detail::mr_write_line(s, edge_slot, cut.n1, detail::mr_add_line(s, edge_slot, l, cut.n1, cut.parent));
		}
		for (Dart y : created)
			give_line(s, edge_slot, l, y);
	}
	if (detail::mr_indexed(s, face_slot))
	{
		for (const Subdivision::Split& split : sub.splits)
			for (Dart c : split.corners)
				detail::mr_write_line(s, face_slot, c, detail::mr_add_line(s, face_slot, l, c, split.parent));
		for (Dart y : created)
			give_line(s, face_slot, l, y);
	}
	if (detail::mr_indexed(s, volume_slot))
	{
		// the 8 children refine the hexahedron's line; new darts of the
		// volumes around read theirs
		for (Dart a : sub.volume_darts)
			if (detail::mr_index(s, volume_slot)[a.index] == sub.volume_line)
				detail::mr_write_line(s, volume_slot, a, detail::mr_add_line(s, volume_slot, l, a, sub.volume_line));
		for (Dart y : created)
			if (!is_boundary(s.map, y))
				give_line(s, volume_slot, l, y);
	}
	if (detail::mr_indexed(s, component_slot))
		for (Dart y : created)
			detail::mr_index(s, component_slot)[y.index] =
				detail::mr_index(s, component_slot)[sub.volume_darts.front().index];
}

/// Subdivides the leaf hexahedron of dart d (made at or before k, the
/// volume's level), after its coarser neighbours when balancing.
void subdivide_leaf(MRState3& s, Dart d, uint32 k, bool balance)
{
	if (k >= 254)
		throw std::invalid_argument("subdivide_volume: 255 levels at most");
	check_subdividable(s, d, k);
	while (balance && k > 0) // no volume is made before level 0
	{
		// a volume sharing an edge, made before level k, would be two levels
		// coarser than the children
		const MRLevelView3 vk(s, k);
		Dart coarser;
		uint32 coarser_level = 0;
		foreach_incident_edge(vk, Volume(d), [&](Edge e) {
			foreach_incident_volume(vk, e, [&](Volume x) {
				if (is_boundary(s.map, x.dart))
					return true;
				coarser_level = volume_level(vk, x);
				if (coarser_level >= k)
					return true;
				coarser = dart_up_to(vk, x.dart, coarser_level);
				return false;
			});
			return !coarser.is_valid();
		});
		if (!coarser.is_valid())
			break;
		subdivide_leaf(s, coarser, coarser_level, true);
	}
	const uint32 l = k + 1;
	if (l >= s.darts_per_level.size())
		s.darts_per_level.push_back(0);

	// what the cuts reuse and what they make, read before them
	const MRLevelView3 vk(s, k);
	Subdivision sub;
	foreach_dart_of_orbit(vk, Volume(d), [&](Dart x) { sub.volume_darts.push_back(x); });
	foreach_incident_vertex(vk, Volume(d), [&](Vertex v) { sub.corners.push_back(v.dart); });
	foreach_incident_edge(vk, Volume(d), [&](Edge e) {
		if (!edge_is_subdivided(vk, e))
			sub.cuts.push_back({e.dart, Dart(), line_or_none(s, k, edge_slot, e.dart)});
	});
	foreach_incident_face(vk, Volume(d), [&](Face f) {
		if (face_is_subdivided(vk, f))
			return;
		Subdivision::Split split{{}, line_or_none(s, k, face_slot, f.dart)};
		foreach_dart_of_orbit(vk, Face2(f.dart), [&](Dart x) { split.corners.push_back(x); });
		sub.splits.push_back(std::move(split));
	});
	sub.volume_line = line_or_none(s, k, volume_slot, d);
	const std::array<Dart, 4> hexahedron = detail::mr_hexahedron_corners(s, k, d);

	detail::MRVolumeRefinement refinement(s);
	for (Subdivision::Cut& cut : sub.cuts)
		cut.n1 = refinement.cut_edge(cut.x);
	for (const Subdivision::Split& split : sub.splits)
		refinement.quadrangulate(split.corners.front());
	refinement.split_hexahedron(hexahedron);
	refinement.label_created(l);
	index_subdivision(s, l, sub, refinement.created());
}

/// What a coarsening removes: darts marked, and the lines to release or
/// to bring back, read before the darts go.
struct Coarsening
{
	std::vector<Dart> removed;
	std::array<std::vector<uint32>, 4> released; // per slot (vertices ... volumes)
	struct Restored
	{
		uint32 slot;
		Dart d;      // a dart of the cell that stays
		uint32 line; // its line of the level below
	};
	std::vector<Restored> restored;
};

/// Whether a volume other than the one of `self` around edge e (read at level
/// k) has children.
bool other_volume_subdivided(const MRLevelView3& vk, Dart e, const DartMarkerStore<CMap3>& self)
{
	bool found = false;
	foreach_incident_volume(vk, Edge(e), [&](Volume x) {
		found = !self.is_marked(x.dart) && volume_is_subdivided(vk, x);
		return !found;
	});
	return found;
}

/// The new relations of the darts left by removing the marked darts: phi1
/// steps over the removed pieces of its edge and turns, inside its face,
/// around the removed inner edges; phi2 and phi3 are those of the last
/// piece of the edge (phi2 goes on around the edge past removed faces).
struct Relinked
{
	Dart d, p1, p2, p3;
};
std::vector<Relinked> relink(const MRState3& s, const std::vector<Dart>& removed, const DartMarkerStore<CMap3>& gone)
{
	const CMap3& map = s.map;
	const auto edge_id = s.edge_id->view();
	std::vector<Relinked> relinked;
	DartMarkerStore<CMap3> seen(map);
	for (Dart r : removed)
		for (Dart a : {phi_1(map, r), phi2(map, r), phi3(map, r)})
		{
			if (gone.is_marked(a) || seen.is_marked(a))
				continue;
			seen.mark(a);
			Dart last = a, it = phi1(map, a);
			while (gone.is_marked(it))
			{
				if (edge_id[it.index] == edge_id[a.index])
				{
					last = it; // a removed piece of a's edge
					it = phi1(map, it);
				}
				else
				{
					detail::MRNoStepLimit budget;
					it = phi1(map, detail::mr_phi2_in_face(s, it, budget));
				}
			}
			Dart p2 = phi2(map, last);
			while (gone.is_marked(p2))
				p2 = phi2(map, phi3(map, p2));
			relinked.push_back({a, it, p2, phi3(map, last)});
		}
	return relinked;
}

} // namespace

bool can_coarsen_volume(const MRMap3& m, MRMap3::Volume w)
{
	const MRState3& s = detail::mr_state_of(m);
	const MRLevelView3 v = detail::read_level(m);
	const uint32 l = v.level() + 1;
	if (is_boundary(s.map, w.dart) || volume_level(v, w) != v.level() || !volume_is_subdivided(v, w))
		return false;
	// every child is a leaf without cuts of level l + 1 on its surface
	bool ok = true;
	foreach_dart_of_orbit(v, w, [&](Dart a) {
		foreach_dart_of_orbit(s.map, CMap3::Volume(a), [&](Dart x) {
			ok = detail::mr_dart_level(s, x) <= l;
			return ok;
		});
		return ok;
	});
	return ok;
}

void coarsen_volume(MRMap3& m, MRMap3::Volume w)
{
	assert(can_coarsen_volume(m, w));
	MRState3& s = detail::mr_state_of(m);
	CMap3& map = s.map;
	const uint32 k = current_level(m), l = k + 1;
	const MRLevelView3 vk(s, k), vl(s, l);

	// the children's darts, and the hexahedron's own (of level k)
	DartMarkerStore<CMap3> children(map), self(map), gone(map);
	std::vector<Dart> volume_darts;
	foreach_dart_of_orbit(vk, w, [&](Dart a) {
		volume_darts.push_back(a);
		self.mark(a);
	});
	std::vector<Dart> child_darts;
	for (Dart a : volume_darts)
		if (!children.is_marked(a))
			foreach_dart_of_orbit(map, CMap3::Volume(a), [&](Dart x) {
				children.mark(x);
				child_darts.push_back(x);
			});

	Coarsening c;
	const auto remove = [&](Dart x) {
		if (!gone.is_marked(x))
		{
			gone.mark(x);
			c.removed.push_back(x);
		}
	};
	// the inner faces (both sides inside), with their edges and the centre
	for (Dart x : child_darts)
		if (children.is_marked(phi3(map, x)))
			remove(x);
	// the quads of a face that the volume across does not use
	std::vector<Dart> unsplit; // a dart of w of each such face
	foreach_incident_face(vk, w, [&](Face f) {
		const Dart across = detail::mr_phi3(s, k, f.dart);
		if (!is_boundary(map, across) && volume_level(vk, Volume(across)) == k &&
			volume_is_subdivided(vk, Volume(across)))
			return;
		unsplit.push_back(f.dart);
		const uint8 id = (*s.face_id)[f.dart.index];
		// the darts leaving the face's centre in its quads, and those coming to it
		const Dart centre = phi1(map, phi1(map, f.dart));
		foreach_dart_of_orbit(map, CMap3::Vertex(centre), [&](Dart x) {
			if ((*s.face_id)[x.index] == id)
			{
				remove(x);
				remove(phi_1(map, x));
			}
		});
	});
	// the second halves of an edge that no other subdivided volume uses
	std::vector<std::pair<Dart, std::vector<Dart>>> uncut; // per such edge: a dart of w, its darts leaving the middle
	foreach_incident_edge(vk, w, [&](Edge e) {
		if (other_volume_subdivided(vk, e.dart, self))
			return;
		const Dart middle = phi1(map, e.dart);
		uncut.emplace_back(e.dart, std::vector<Dart>{});
		const uint8 id = (*s.edge_id)[e.dart.index];
		foreach_dart_of_orbit(map, CMap3::Vertex(middle), [&](Dart x) {
			if ((*s.edge_id)[x.index] == id)
			{
				remove(x);
				uncut.back().second.push_back(x);
			}
		});
	});
	assert(std::all_of(c.removed.begin(), c.removed.end(), [&](Dart x) { return detail::mr_dart_level(s, x) == l; }));

	// the lines of what goes, read while its darts are there
	for (uint32 slot = vertex_slot; slot <= volume_slot; ++slot)
	{
		if (!detail::mr_indexed(s, slot))
			continue;
		const AttributeArray<uint32>& idx = detail::mr_index(s, slot);
		const auto release = [&](uint32 i) {
			std::vector<uint32>& r = c.released[slot];
			if (i != INVALID_INDEX && std::find(r.begin(), r.end(), i) == r.end())
				r.push_back(i);
		};
		// the cells all of whose darts go
		for (Dart x : c.removed)
		{
			if (slot == volume_slot && is_boundary(map, x))
				continue;
			bool all_gone = true;
			detail::mr_foreach_dart_of_cell(s, slot, l, x, [&](Dart y) {
				all_gone = gone.is_marked(y);
				return all_gone;
			});
			if (all_gone)
				release(idx[x.index]);
		}
		const auto restore = [&](Dart d, uint32 piece_line) {
			release(piece_line);
			c.restored.push_back({slot, d, (*s.cells[slot].down)[piece_line]});
		};
		if (slot == volume_slot)
		{
			for (Dart a : volume_darts)
				release(idx[a.index]);
			c.restored.push_back({slot, w.dart, detail::mr_line_of(s, k, slot, w.dart)});
		}
		else if (slot == face_slot)
			for (Dart f : unsplit)
			{
				foreach_dart_of_orbit(vk, Face2(f), [&](Dart x) { release(idx[x.index]); });
				c.restored.push_back({slot, f, detail::mr_line_of(s, k, slot, f)});
			}
		else if (slot == edge_slot)
			for (const auto& [e, from_middle] : uncut)
			{
				// both halves' lines (each half keeps old darts, of one orientation)
				for (Dart x : from_middle)
					release(idx[x.index]);
				restore(e, idx[e.index]);
			}
	}

	// the topology: the darts left take the relations they have once the
	// removed darts are gone
	const std::vector<Relinked> relinked = relink(s, c.removed, gone);
	for (Dart x : c.removed)
		detail::remove_dart(map, x);
	for (const Relinked& r : relinked)
	{
		detail::set_phi1(map, r.d, r.p1);
		detail::set_phi2(map, r.d, r.p2);
		detail::set_phi3(map, r.d, r.p3);
	}
	s.darts_per_level[l] -= uint32(c.removed.size());

	// the lines
	for (uint32 slot = vertex_slot; slot <= volume_slot; ++slot)
		for (uint32 i : c.released[slot])
			detail::mr_slot_container(s, slot).release_line(i);
	for (const Coarsening::Restored& r : c.restored)
	{
		(*s.cells[r.slot].replaced)[r.line] = detail::MR_NOT_REPLACED;
		detail::mr_write_line(s, r.slot, r.d, r.line);
	}
	if (detail::mr_indexed(s, vertex_slot))
	{
		// a corner keeps a line at level l while a volume of level l touches it
		std::vector<Dart> corners;
		foreach_incident_vertex(vk, w, [&](Vertex v) { corners.push_back(v.dart); });
		for (Dart x : corners)
		{
			bool touched = false;
			if (l < s.darts_per_level.size() && s.darts_per_level[l] > 0)
				foreach_incident_volume(vl, Vertex(x), [&](Volume y) {
					touched = volume_level(vl, y) == l;
					return !touched;
				});
			if (!touched)
				detail::mr_drop_vertex_line(s, x, l);
		}
	}
	while (s.darts_per_level.size() > 1 && s.darts_per_level.back() == 0)
		s.darts_per_level.pop_back();
	s.current_level = std::min<uint32>(s.current_level, uint32(s.darts_per_level.size() - 1));
}

uint32 edge_level(const MRLevelView3& v, MRMap3::Edge e)
{
	const MRState3& s = v.state();
	return std::max(detail::mr_dart_level(s, e.dart), detail::mr_dart_level(s, detail::mr_phi2(s, v.level(), e.dart)));
}

uint32 face_level(const MRLevelView3& v, MRMap3::Face f)
{
	return kth_smallest_level(v.state(), 2, [&](const auto& g) { foreach_dart_of_orbit(v, Face2(f.dart), g); });
}

uint32 volume_level(const MRLevelView3& v, MRMap3::Volume w)
{
	// a child keeps the darts of its parent at one corner (3 for a
	// hexahedron or tetrahedron, 4 for an octahedron), older than every
	// other dart of it: past the c darts of the oldest dart's corner, the
	// next smallest level is the child's (a corner of more than 7 darts
	// belongs to a volume of level 0, whose 8 smallest levels are 0)
	const MRState3& s = v.state();
	Dart oldest = w.dart;
	std::array<uint32, 8> smallest;
	smallest.fill(255);
	foreach_dart_of_orbit(v, Volume(w.dart), [&](Dart d) {
		uint32 x = detail::mr_dart_level(s, d);
		if (x < detail::mr_dart_level(s, oldest))
			oldest = d;
		for (uint32& y : smallest)
			if (x < y)
				std::swap(x, y);
	});
	uint32 corner = 0;
	foreach_dart_of_orbit(v, Vertex2(oldest), [&](Dart) { ++corner; });
	return smallest[std::min<uint32>(corner, uint32(smallest.size() - 1))];
}

bool edge_is_subdivided(const MRLevelView3& v, MRMap3::Edge e)
{
	const MRState3& s = v.state();
	const uint32 l = v.level();
	if (detail::mr_is_finest(s, l))
		return false;
	// cut: the other side of e.dart's first piece is a new dart
	return detail::mr_phi2(s, l + 1, e.dart) != detail::mr_phi2(s, l, e.dart);
}

bool face_is_subdivided(const MRLevelView3& v, MRMap3::Face f)
{
	const MRState3& s = v.state();
	const uint32 l = v.level();
	if (detail::mr_is_finest(s, l) || face_level(v, f) < l)
		return false;
	// at the midpoint of f.dart's edge, phi1 of level l + 1 turns into the face
	const Dart x = detail::mr_phi1(s, l + 1, f.dart);
	return detail::mr_dart_level(s, x) == l + 1 && (*s.edge_id)[x.index] != (*s.edge_id)[f.dart.index];
}

bool volume_is_subdivided(const MRLevelView3& v, MRMap3::Volume w)
{
	const MRState3& s = v.state();
	const uint32 l = v.level();
	if (detail::mr_is_finest(s, l) || is_boundary(s.map, w.dart) || volume_level(v, w) < l ||
		!face_is_subdivided(v, Face(w.dart)))
		return false;
	// the inner edge of w.dart's face leaving the midpoint of its edge: on
	// w's side, an inner face of w (another face id) when w is cut
	const Dart inner = detail::mr_phi1(s, l + 1, w.dart);
	return (*s.face_id)[detail::mr_phi2(s, l + 1, inner).index] != (*s.face_id)[w.dart.index];
}

void subdivide_volume(MRMap3& m, MRMap3::Volume w, bool balance)
{
	MRState3& s = detail::mr_state_of(m);
	if (is_boundary(s.map, w.dart))
		throw std::invalid_argument("subdivide_volume: a boundary volume");
	const MRLevelView3 v = detail::read_level(m);
	const uint32 k = volume_level(v, w);
	const Dart d = dart_up_to(v, w.dart, k);
	if (volume_is_subdivided(MRLevelView3(s, k), Volume(d)))
		throw std::invalid_argument("subdivide_volume: the volume has children already");
	subdivide_leaf(s, d, k, balance);
}

} // namespace cgogn
