// SPDX-License-Identifier: MIT
// The multiresolution 3-map: construction, levels, and the regular
// hexahedral refinement.
#include <cgogn/core/map/mrmap3_attributes.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_mrmap3.h>

#include "mr_indexing.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn
{

MRMap3::MRMap3(CMap3&& base)
{
	for (Orbit o : {Orbit::PHI1, Orbit::PHI2, Orbit::PHI21})
		if (detail::state_of(base).cell_index[orbit_index(o)] != nullptr)
			throw std::invalid_argument("MRMap3: the map indexes the cells of one volume (orbit " +
										std::string(orbit_name(o)) + "), which a multiresolution 3-map does not carry");
	state_.map = std::move(base);
	AttributeContainer& darts = *detail::state_of(state_.map).darts;
	state_.level = darts.add_attribute<uint8>("__mr_level", 0);
	state_.edge_id = darts.add_attribute<uint8>("__mr_edge_id", 0);
	state_.face_id = darts.add_attribute<uint8>("__mr_face_id", 0);
	state_.darts_per_level = {nb_darts(state_.map)};
	// the orbits the map indexes become level-0 lines of the hierarchy, which
	// indexes them from now on (the finest map's operators run without indices)
	detail::mr_take_over_indexing(state_);
}

void detail::mr_index_orbit(MRMap3& m, Orbit o)
{
	mr_index_new_orbit(mr_state_of(m), o);
}

void set_current_level(MRMap3& m, uint32 l)
{
	if (l > max_level(m))
		throw std::out_of_range("set_current_level: level " + std::to_string(l) + " above the finest level " +
								std::to_string(max_level(m)));
	detail::mr_state_of(m).current_level = l;
}

MRLevelView3 level_view(const MRMap3& m, uint32 l)
{
	if (l > max_level(m))
		throw std::out_of_range("level_view: level " + std::to_string(l) + " above the finest level " +
								std::to_string(max_level(m)));
	return MRLevelView3(m, l);
}

namespace
{

/// The hexahedral refinement of the finest level of a multiresolution
/// 3-map, with the finest map's operators (without indices).
class HexRefinement
{
public:
	explicit HexRefinement(detail::MRState3& s) : s_(s), map_(s.map)
	{
	}

	/// Throws std::invalid_argument when a volume is not a hexahedron.
	void check_hexahedra() const
	{
		foreach_cell(map_, [&](CMap3::Volume w) {
			uint32 nb = 0;
			bool ok = true;
			foreach_dart_of_orbit(map_, w, [&](Dart d) {
				++nb;
				ok = ok && codegree(static_cast<const CMap1&>(map_), CMap1::Face(d)) == 4 &&
					 phi1(map_, phi2(map_, phi1(map_, phi2(map_, phi1(map_, phi2(map_, d)))))) == d;
				return ok;
			});
			if (!ok || nb != 24)
				throw std::invalid_argument("add_level: Hexahedral refinement of a volume that is not a hexahedron "
											"(dart " +
											std::to_string(w.dart.index) + ")");
		});
	}

	void run()
	{
		const uint32 end = detail::state_of(map_).darts->end_index();
		std::vector<bool> old(end, false);
		foreach_dart(map_, [&](Dart d) { old[d.index] = true; });
		// per hexahedron: a dart a of a face B and a dart t of the opposite face
		// T, with the darts two steps on along their faces (all old darts,
		// which keep their origin)
		std::vector<std::array<Dart, 4>> hexes;
		foreach_cell(map_, [&](CMap3::Volume w) {
			const Dart a = w.dart;
			const Dart t = phi2(map_, phi1(map_, phi1(map_, phi2(map_, a))));
			hexes.push_back({a, phi1(map_, phi1(map_, a)), t, phi1(map_, phi1(map_, t))});
		});
		std::vector<Dart> faces;
		foreach_cell(map_, [&](CMap3::Face f) { faces.push_back(f.dart); });
		std::vector<Dart> edges;
		foreach_cell(map_, [&](CMap3::Edge e) { edges.push_back(e.dart); });

		for (Dart d : edges)
			cut_edge_labelled(d);
		for (Dart f : faces)
			quadrangulate(f);
		for (const auto& h : hexes)
			split_hexahedron(h);

		uint32 count = 0;
		const uint8 level = uint8(s_.darts_per_level.size());
		foreach_dart(map_, [&](Dart d) {
			if (d.index >= end || !old[d.index])
			{
				(*s_.level)[d.index] = level;
				++count;
			}
		});
		s_.darts_per_level.push_back(count);
		s_.current_level = level;
	}

private:
	uint8 edge_id(Dart d) const
	{
		return (*s_.edge_id)[d.index];
	}
	uint8 face_id(Dart d) const
	{
		return (*s_.face_id)[d.index];
	}
	/// Gives the darts of d's edge edge id `id`.
	void set_edge_id(Dart d, uint8 id)
	{
		foreach_dart_of_orbit(map_, CMap3::Edge(d), [&](Dart x) { (*s_.edge_id)[x.index] = id; });
	}
	/// Gives the darts of d's edge face id `id`.
	void set_face_id_of_edge(Dart d, uint8 id)
	{
		foreach_dart_of_orbit(map_, CMap3::Edge(d), [&](Dart x) { (*s_.face_id)[x.index] = id; });
	}

	/// Cuts d's edge; the new halves keep the ids of the darts they follow.
	/// Returns the dart leaving the new vertex along d's direction.
	Dart cut_edge_labelled(Dart d)
	{
		std::vector<Dart> ring;
		foreach_dart_of_orbit(map_, CMap3::Edge(d), [&](Dart x) { ring.push_back(x); });
		cut_edge(map_, CMap3::Edge(d), false);
		for (Dart x : ring)
		{
			const Dart n = phi1(map_, x);
			(*s_.edge_id)[n.index] = edge_id(x);
			(*s_.face_id)[n.index] = face_id(x);
		}
		return phi1(map_, d);
	}

	/// Cuts the face of d and e by a new edge from origin(d) to origin(e),
	/// of the face's face id and edge id `id`. Returns its dart from
	/// origin(d).
	Dart cut_face_labelled(Dart d, Dart e, uint8 id)
	{
		const Dart y = cut_face(map_, d, e, false).dart;
		set_edge_id(y, id);
		set_face_id_of_edge(y, face_id(d));
		return y;
	}

	/// The smallest edge id in {0, 1, 2} different from a and b.
	static uint8 new_edge_id(uint8 a, uint8 b)
	{
		uint8 id = 0;
		while (id == a || id == b)
			++id;
		return id;
	}

	/// Joins the midpoints of the cut edges of face f (a dart leaving a
	/// corner) to a new centre: k quads.
	void quadrangulate(Dart f)
	{
		std::vector<Dart> c; // the darts leaving the midpoints, in phi1 order
		Dart it = f;
		do
		{
			c.push_back(phi1(map_, it));
			it = phi1(map_, phi1(map_, it));
		} while (it != f);
		const auto inner_id = [&](Dart mid) { return new_edge_id(edge_id(mid), edge_id(mid)); };
		const Dart y = cut_face_labelled(c[0], c[2], inner_id(c[0])); // midpoint 0 -> midpoint 2
		cut_edge_labelled(y);
		const Dart to_second = phi1(map_, y); // centre -> midpoint 2
		set_edge_id(to_second, inner_id(c[2]));
		// the centre's dart in the part holding midpoint 1
		cut_face_labelled(phi2(map_, y), c[1], inner_id(c[1]));
		Dart from_centre = to_second;
		for (std::size_t i = 3; i < c.size(); ++i)
			from_centre = cut_face_labelled(from_centre, c[i], inner_id(c[i]));
	}

	/// Goes straight on across a vertex of 4 edges on the surface of d's
	/// finest volume: the dart leaving the end of d opposite to d.
	Dart straight(Dart d) const
	{
		return phi1(map_, phi2(map_, phi1(map_, d)));
	}

	/// Cuts the volume of `start` along the closed path of k darts that goes
	/// straight on from it; the new face takes the smallest face id not used
	/// around the path's edges, its darts the edge ids of the path's. Returns
	/// the new face's dart on the path side, from the end of start to its
	/// origin.
	Dart cut_volume_straight(Dart start, uint32 k)
	{
		std::vector<Dart> path{start};
		while (path.size() < k)
			path.push_back(straight(path.back()));
		if (straight(path.back()) != start || !can_cut_volume(map_, path))
			throw std::logic_error("add_level: a hexahedron's inner path is not closed");
		std::vector<bool> used(256, false);
		for (Dart p : path)
			foreach_dart_of_orbit(map_, CMap3::Edge(p), [&](Dart x) { used[face_id(x)] = true; });
		uint8 id = 0;
		while (used[id])
			++id;
		const Dart f = cut_volume(map_, path, false).dart;
		for (Dart p : path)
		{
			for (Dart x : {phi2(map_, p), phi3(map_, phi2(map_, p))})
			{
				(*s_.face_id)[x.index] = id;
				(*s_.edge_id)[x.index] = edge_id(p);
			}
		}
		return f;
	}

	/// Cuts a hexahedron (its edges and faces cut, see run) into 8: h holds
	/// a dart a of a face B, phi1^2(a) (old), a dart t of the face opposite
	/// to B and phi1^2(t).
	void split_hexahedron(const std::array<Dart, 4>& h)
	{
		const Dart a = h[0], a2 = h[1], t = h[2], t2 = h[3];
		// the middle section, parallel to B and T, through the midpoints of
		// the 4 edges joining them: an octagon, cut into 4 quads around the
		// volume's centre
		const Dart o = cut_volume_straight(phi1(map_, phi1(map_, phi2(map_, a))), 8);
		const Dart y = cut_face_labelled(o, phi1(map_, phi1(map_, phi1(map_, phi1(map_, o)))), 0);
		cut_edge_labelled(y);
		const Dart from_centre = phi1(map_, y);
		cut_face_labelled(from_centre, phi1(map_, phi1(map_, phi1(map_, from_centre))), 0);
		const Dart other = phi2(map_, y);
		cut_face_labelled(other, phi1(map_, phi1(map_, phi1(map_, other))), 0);
		// each half: a section through the centres of B (or T) and of the
		// volume, cut in 2 along them, then a section across it in each quarter
		for (const auto& [b, b2] : {std::pair{a, a2}, std::pair{t, t2}})
		{
			const Dart s = cut_volume_straight(phi2(map_, phi1(map_, b)), 6);
			// s: midpoint of b's edge -> centre of B; on the section: centre of
			// B at phi1(s), the volume's centre 3 darts further
			const Dart from_face_centre = phi1(map_, s);
			cut_face_labelled(from_face_centre, phi1(map_, phi1(map_, phi1(map_, from_face_centre))), 0);
			cut_volume_straight(phi1(map_, phi1(map_, b)), 4);
			cut_volume_straight(phi1(map_, phi1(map_, b2)), 4);
		}
	}

	detail::MRState3& s_;
	CMap3& map_;
};

} // namespace

void add_level(MRMap3& m, Refinement r)
{
	if (r != Refinement::Hexahedral)
		throw std::invalid_argument("add_level: a multiresolution 3-map is refined by Hexahedral levels");
	detail::MRState3& s = detail::mr_state_of(m);
	if (max_level(m) >= 254)
		throw std::invalid_argument("add_level: 255 levels at most");
	HexRefinement refinement(s);
	refinement.check_hexahedra();
	refinement.run();
	for (uint32 slot = 0; slot < s.cells.size(); ++slot)
		if (s.cells[slot].index != nullptr)
			detail::mr_index_cells_at(s, slot, max_level(m));
}

void remove_finest_level(MRMap3& m)
{
	detail::MRState3& s = detail::mr_state_of(m);
	CMap3& map = s.map;
	const uint32 finest = max_level(m);
	if (finest == 0)
		throw std::invalid_argument("remove_finest_level: the map has no level above 0");
	const auto level = s.level->view();
	// the relations of the level below, read before any dart goes
	struct Relations
	{
		Dart d, p1, p2, p3;
	};
	std::vector<Relations> kept;
	std::vector<Dart> removed;
	foreach_dart(map, [&](Dart d) {
		if (level[d.index] == finest)
			removed.push_back(d);
		else
			kept.push_back({d, detail::mr_phi1(s, finest - 1, d), detail::mr_phi2(s, finest - 1, d),
							detail::mr_phi3(s, finest - 1, d)});
	});
	for (Dart d : removed)
		detail::remove_dart(map, d);
	for (const Relations& r : kept)
	{
		detail::set_phi1(map, r.d, r.p1);
		detail::set_phi2(map, r.d, r.p2);
		detail::set_phi3(map, r.d, r.p3);
	}
	for (uint32 slot = 0; slot < s.cells.size(); ++slot)
		if (s.cells[slot].index != nullptr)
			detail::mr_unindex_cells_at(s, slot, finest);
	s.darts_per_level.pop_back();
	s.current_level = std::min(s.current_level, finest - 1);
}

} // namespace cgogn
