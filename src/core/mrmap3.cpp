// SPDX-License-Identifier: MIT
// The multiresolution 3-map: construction, levels, and the regular
// hexahedral refinement.
#include <cgogn/core/map/mrmap3_attributes.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_mrmap3.h>

#include "mr_indexing.h"
#include "mrmap3_refine.h"
#include "mrmap3_tetra_octa.h"

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

/// Throws std::invalid_argument when a volume of the finest map is not a
/// hexahedron (6 quads, 3 edges at each corner).
void check_hexahedra(const CMap3& map)
{
	foreach_cell(map, [&](CMap3::Volume w) {
		uint32 nb = 0;
		bool ok = true;
		foreach_dart_of_orbit(map, w, [&](Dart d) {
			++nb;
			ok = ok && codegree(static_cast<const CMap1&>(map), CMap1::Face(d)) == 4 &&
				 phi1(map, phi2(map, phi1(map, phi2(map, phi1(map, phi2(map, d)))))) == d;
			return ok;
		});
		if (!ok || nb != 24)
			throw std::invalid_argument("add_level: Hexahedral refinement of a volume that is not a hexahedron (dart " +
										std::to_string(w.dart.index) + ")");
	});
}

/// Refines every volume of the finest map: `read(d)` reads the volume of
/// dart d before any cut, then every edge is cut at its middle, every face
/// refined by `refine_face(refinement, f)` and every volume read split by
/// `split(refinement, cell)`; the new darts get a new level.
template <typename READ, typename REFINE_FACE, typename SPLIT>
void refine_every_volume(detail::MRState3& s, const READ& read, const REFINE_FACE& refine_face, const SPLIT& split)
{
	CMap3& map = s.map;
	std::vector<decltype(read(Dart()))> cells;
	foreach_cell(map, [&](CMap3::Volume w) { cells.push_back(read(w.dart)); });
	std::vector<Dart> faces;
	foreach_cell(map, [&](CMap3::Face f) { faces.push_back(f.dart); });
	std::vector<Dart> edges;
	foreach_cell(map, [&](CMap3::Edge e) { edges.push_back(e.dart); });

	detail::MRVolumeRefinement refinement(s);
	for (Dart d : edges)
		refinement.cut_edge(d);
	for (Dart f : faces)
		refine_face(refinement, f);
	for (const auto& c : cells)
		split(refinement, c);
	const uint32 level = uint32(s.darts_per_level.size());
	s.darts_per_level.push_back(0);
	refinement.label_created(level);
	s.current_level = level;
}

/// Hexahedral: all faces quadrangulated, every hexahedron into 8.
void refine_every_hexahedron(detail::MRState3& s)
{
	const uint32 finest = uint32(s.darts_per_level.size() - 1);
	refine_every_volume(
		s,
		// the corners are old darts, which keep their origin through the cuts
		[&](Dart d) { return detail::mr_hexahedron_corners(s, finest, d); },
		[](detail::MRVolumeRefinement& r, Dart f) { r.quadrangulate(f); },
		[](detail::MRVolumeRefinement& r, const std::array<Dart, 4>& h) { r.split_hexahedron(h); });
}

/// TetraOcta: all faces into 4 triangles, every tetrahedron and octahedron
/// split. Throws std::invalid_argument before any change when a volume is
/// neither a tetrahedron nor an octahedron.
void refine_every_tetra_octa(detail::MRState3& s)
{
	detail::MRTetraOctaScratch scratch;
	refine_every_volume(
		s,
		[&](Dart d) {
			auto c = detail::mr_read_tetra_octa(s.map, d);
			if (!c)
				throw std::invalid_argument("add_level: TetraOcta refinement of a volume that is neither a "
											"tetrahedron nor an octahedron (dart " +
											std::to_string(d.index) + ")");
			return std::move(*c);
		},
		[](detail::MRVolumeRefinement& r, Dart f) { r.triangulate(f); },
		[&](detail::MRVolumeRefinement& r, const detail::MRTetraOctaCell& c) {
			detail::mr_split_tetra_octa(r, c, scratch);
		});
}

} // namespace

void add_level(MRMap3& m, Refinement r)
{
	if (r != Refinement::Hexahedral && r != Refinement::TetraOcta)
		throw std::invalid_argument("add_level: a multiresolution 3-map is refined by Hexahedral or TetraOcta levels");
	detail::MRState3& s = detail::mr_state_of(m);
	if (max_level(m) >= 254)
		throw std::invalid_argument("add_level: 255 levels at most");
	if (r == Refinement::Hexahedral)
	{
		check_hexahedra(s.map);
		refine_every_hexahedron(s);
	}
	else
		refine_every_tetra_octa(s);
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
