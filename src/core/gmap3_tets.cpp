// SPDX-License-Identifier: MIT
// Edge collapse in tetrahedral 3-G-maps, by the contractions of an edge, of
// the faces it flattens and of the volumes it flattens.
#include <cgogn/core/operators/gmap3.h>

#include "gmap_darts.h"
#include "reindex.h"
#include "tet_star.h"

#include <cassert>
#include <unordered_set>

namespace cgogn
{

namespace
{
// Contraction of an i-cell of a G-map (Damiand and Lienhardt): each dart x
// beta_i-linked to the cell from outside is relinked to the dart reached
// from the cell by beta_i o beta_(i-1), skipping the cell's own darts. The
// cell's darts are then removed. Precondition: the cell's codegree is at
// most 2 (an edge; a face of 2 edges; a volume of 2 faces).
template <int I>
void contract(GMap3& m, const std::vector<Dart>& cell)
{
	std::unordered_set<uint32> in;
	for (Dart d : cell)
		in.insert(d.index);
	std::vector<std::pair<Dart, Dart>> links;
	for (Dart d : cell)
	{
		const Dart outside = beta<I>(m, d);
		if (in.count(outside.index))
			continue;
		Dart target = beta<I - 1, I>(m, d);
		while (in.count(target.index))
			target = beta<I - 1, I>(m, target);
		links.emplace_back(outside, target);
	}
	for (const auto& [a, b] : links)
		detail::set_beta<uint32(I)>(m, a, b);
	detail::remove_dart_pairs(m, cell);
}

// The darts of the cells containing the darts of `from`, each cell once,
// without the darts in `skip`.
template <typename CELL>
std::vector<std::vector<Dart>> cells_of(const GMap3& m, const std::vector<Dart>& from,
										const std::unordered_set<uint32>& skip)
{
	std::vector<std::vector<Dart>> cells;
	std::unordered_set<uint32> seen;
	for (Dart d : from)
	{
		if (seen.count(d.index) || (CELL::ORBIT == Orbit::BETA0_BETA1_BETA2 && is_boundary(m, d)))
			continue;
		std::vector<Dart> darts;
		foreach_dart_of_orbit(m, CELL(d), [&](Dart x) {
			seen.insert(x.index);
			if (!skip.count(x.index))
				darts.push_back(x);
		});
		cells.push_back(std::move(darts));
	}
	return cells;
}
} // namespace

bool can_collapse_edge(const GMap3& m, GMap3::Edge e)
{
	return detail::can_collapse_tet_edge(m, e);
}

GMap3::Vertex collapse_edge(GMap3& m, GMap3::Edge e, bool set_indices)
{
	assert(can_collapse_edge(m, e));
	const std::vector<Dart> edge = detail::orbit_darts(m, e);
	std::unordered_set<uint32> removed(edge.size());
	for (Dart x : edge)
		removed.insert(x.index);
	// the triangles around e become faces of 2 edges, the tetrahedra around
	// e volumes of 2 faces
	const auto triangles = cells_of<GMap3::Face>(m, edge, removed);
	for (const auto& t : triangles)
		for (Dart x : t)
			removed.insert(x.index);
	const auto tets = cells_of<GMap3::Volume>(m, edge, removed);
	for (const auto& t : tets)
		for (Dart x : t)
			removed.insert(x.index);
	// the region: both stars (the surviving one first, so that its cells keep
	// their lines), and the darts beside the removed ones (the third corners,
	// the edges between them), whose cells lose darts
	std::vector<Dart> region = detail::orbit_darts(m, GMap3::Vertex(beta0(m, e.dart)));
	const std::vector<Dart> star_a = detail::orbit_darts(m, GMap3::Vertex(e.dart));
	region.insert(region.end(), star_a.begin(), star_a.end());
	for (uint32 r : removed)
		region.insert(region.end(), {beta0(m, Dart(r)), beta1(m, Dart(r)), beta2(m, Dart(r)), beta3(m, Dart(r))});
	detail::RegionReindexer<GMap3> reindex;
	if (set_indices)
		reindex.record(m, region);
	contract<1>(m, edge);
	for (const auto& t : triangles)
		contract<2>(m, t);
	for (const auto& t : tets)
		contract<3>(m, t);
	std::erase_if(region, [&](Dart d) { return removed.count(d.index) > 0; });
	if (set_indices)
		reindex.apply(m, region);
	return GMap3::Vertex(region.front());
}

} // namespace cgogn
