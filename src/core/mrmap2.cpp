// SPDX-License-Identifier: MIT
#include <cgogn/core/map/mrmap2_attributes.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_cmap2.h>

#include "mr_indexing.h"
#include "mrmap2_refine.h"

#include <cassert>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn
{

MRMap2::MRMap2(CMap2&& base)
{
	state_.map = std::move(base);
	AttributeContainer& darts = *detail::state_of(state_.map).darts;
	state_.level = darts.add_attribute<uint8>("__mr_level", 0);
	state_.edge_id = darts.add_attribute<uint8>("__mr_edge_id", 0);
	assert(state_.level && state_.edge_id); // no CMap2 has them: only MRMap2 adds them
	state_.darts_per_level = {nb_darts(state_.map)};
	// the orbits the map indexes become level-0 lines of the hierarchy, which
	// indexes them from now on (the finest map's operators run without indices)
	detail::mr_take_over_indexing(state_);
}

void detail::mr_index_orbit(MRMap2& m, Orbit o)
{
	mr_index_new_orbit(mr_state_of(m), o);
}

void set_current_level(MRMap2& m, uint32 l)
{
	if (l > max_level(m))
		throw std::out_of_range("set_current_level: level " + std::to_string(l) + " above the finest level " +
								std::to_string(max_level(m)));
	detail::mr_state_of(m).current_level = l;
}

MRLevelView2 level_view(const MRMap2& m, uint32 l)
{
	if (l > max_level(m))
		throw std::out_of_range("level_view: level " + std::to_string(l) + " above the finest level " +
								std::to_string(max_level(m)));
	return MRLevelView2(m, l);
}

void add_level(MRMap2& m, Refinement r)
{
	if (r != Refinement::Triangular && r != Refinement::Quadrangular && r != Refinement::Mixed)
		throw std::invalid_argument("add_level: a 3-D refinement pattern on a 2-D map");
	detail::MRState2& s = detail::mr_state_of(m);
	CMap2& map = s.map;
	const uint32 finest = max_level(m);
	if (finest >= 254)
		throw std::invalid_argument("add_level: 255 levels at most");
	// the faces and edges of the finest level, checked before any change
	std::vector<Dart> faces, edges;
	bool regular = true, triangles = true;
	const MRLevelView2 top(s, finest);
	foreach_cell(map, [&](CMap2::Face f) {
		// a face of a coarser level, whose neighbours' midpoints cut its edges, is not regular
		regular = regular && face_level(top, f) == finest;
		triangles = triangles && codegree(map, f) == 3;
		faces.push_back(f.dart);
	});
	if (!regular)
		throw std::invalid_argument("add_level: the finest level is not regular (a face of a coarser level is not "
									"refined)");
	if (r == Refinement::Triangular && !triangles)
		throw std::invalid_argument("add_level: Triangular refinement of a face that is not a triangle");
	foreach_dart(map, [&](Dart d) {
		if (d.index < phi2(map, d).index)
			edges.push_back(d);
	});

	s.darts_per_level.push_back(0);
	detail::MRNewDarts labels(s, uint8(finest + 1));
	for (Dart d : edges)
	{
		const uint8 id = (*s.edge_id)[d.index];
		const CMap2::Vertex mid = cut_edge(map, CMap2::Edge(d), false);
		labels.label(mid.dart, id);
		labels.label(phi2(map, d), id);
	}
	std::vector<Dart> mids;
	for (Dart f : faces)
	{
		// f leaves a corner: the face alternates old darts (from corners) and
		// new ones (from midpoints)
		mids.clear();
		Dart it = f;
		do
		{
			mids.push_back(phi1(map, it));
			it = phi1(map, phi1(map, it));
		} while (it != f);
		if (mids.size() == 3 && r != Refinement::Quadrangular)
			detail::mr_refine_triangle(s, labels, {mids[0], mids[1], mids[2]});
		else
			detail::mr_refine_quadrangular(s, labels, mids);
	}
	s.darts_per_level.back() = labels.count();
	s.current_level = finest + 1;
	for (uint32 slot = 0; slot < 4; ++slot)
		if (s.cells[slot].index != nullptr)
			detail::mr_index_cells_at(s, slot, finest + 1);
}

void remove_finest_level(MRMap2& m)
{
	detail::MRState2& s = detail::mr_state_of(m);
	CMap2& map = s.map;
	const uint32 finest = max_level(m);
	if (finest == 0)
		throw std::invalid_argument("remove_finest_level: the map has no level above 0");
	const auto is_new = [&](Dart d) { return (*s.level)[d.index] == finest; };
	// an inner edge has two new darts; a piece of a cut edge has an old twin
	const auto inner = [&](Dart d) { return is_new(d) && is_new(phi2(map, d)); };

	// face centres: vertices whose edges are all inner
	std::vector<Dart> found;
	foreach_cell(map, [&](CMap2::Vertex v) {
		bool centre = true;
		foreach_dart_of_orbit(map, v, [&](Dart d) { return centre = inner(d) && !is_boundary(map, d); });
		if (centre)
			found.push_back(v.dart);
	});
	for (Dart d : found)
		merge_incident_faces(map, CMap2::Vertex(d), false);
	// the inner edges left: those of the middle triangles
	found.clear();
	foreach_dart(map, [&](Dart d) {
		if (d.index < phi2(map, d).index && inner(d))
			found.push_back(d);
	});
	for (Dart d : found)
		merge_incident_faces(map, CMap2::Edge(d), false);
	// the midpoints: each keeps its two new darts, which go with it
	found.clear();
	foreach_dart(map, [&](Dart d) {
		if (is_new(d) && d.index < phi1(map, phi2(map, d)).index)
			found.push_back(d);
	});
	for (Dart d : found)
		merge_incident_edges(map, CMap2::Vertex(d), false);
	for (uint32 slot = 0; slot < 4; ++slot)
		if (s.cells[slot].index != nullptr)
			detail::mr_unindex_cells_at(s, slot, finest);
	s.darts_per_level.pop_back();
	s.current_level = std::min(s.current_level, finest - 1);
}

} // namespace cgogn
