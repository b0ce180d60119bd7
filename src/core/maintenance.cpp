// SPDX-License-Identifier: MIT
#include <cgogn/core/operators/maintenance.h>
#include <cgogn/core/traversals/global.h>

#include <algorithm>
#include <numeric>

namespace cgogn
{

namespace
{
// darts moved: relations and representative darts follow
void remap_darts(CMapBase& m, const std::vector<uint32>& dart_map)
{
	const AttributeContainer& darts = *detail::state_of(m).darts;
	for (AttributeArray<uint32>* r : detail::state_of(m).relations)
		for (uint32 i = 0; i < darts.end_index(); ++i)
			if (darts.is_live(i))
				(*r)[i] = dart_map[(*r)[i]];
	for (auto& c : detail::state_of(m).cells)
		for (uint32 i = 0; i < c->end_index(); ++i)
			if (c->is_live(i))
				c->key()[i] = dart_map[c->key()[i]];
}

// lines of orbit o moved: dart indices follow
void remap_cells(CMapBase& m, uint32 o, const std::vector<uint32>& line_map)
{
	AttributeArray<uint32>* idx = detail::state_of(m).cell_index[o];
	if (idx == nullptr)
		return;
	const AttributeContainer& darts = *detail::state_of(m).darts;
	for (uint32 i = 0; i < darts.end_index(); ++i)
		if (darts.is_live(i) && (*idx)[i] != INVALID_INDEX)
			(*idx)[i] = line_map[(*idx)[i]];
}

// new_position[i] for lines in `order` (given in their new order); free lines go last
std::vector<uint32> positions_from_order(const std::vector<uint32>& order, uint32 size)
{
	std::vector<uint32> pos(size, INVALID_INDEX);
	uint32 p = 0;
	for (uint32 i : order)
		pos[i] = p++;
	for (uint32 i = 0; i < size; ++i)
		if (pos[i] == INVALID_INDEX)
			pos[i] = p++;
	return pos;
}

template <typename MAP>
void reorder_map(MAP& m, const std::function<uint64(typename MAP::Vertex)>& key)
{
	using Vertex = typename MAP::Vertex;
	compact(m);
	// 1. vertices in key order, their darts together
	std::vector<std::pair<uint64, Dart>> vertices;
	{
		DartMarker<MAP> seen(m);
		foreach_dart(m, [&](Dart d) {
			if (seen.is_marked(d))
				return;
			seen.mark_orbit(Vertex(d));
			vertices.emplace_back(key(Vertex(d)), d);
		});
	}
	std::stable_sort(vertices.begin(), vertices.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
	std::vector<uint32> dart_order;
	dart_order.reserve(nb_darts(m));
	const uint32 nd = detail::state_of(m).darts->end_index();
	if constexpr (is_gmap_v<MAP>)
	{
		// a G-map's darts move in their pairs (beta0 is implicit): each pair
		// goes with the first vertex that reaches one of its darts
		std::vector<bool> placed(nd / 2, false);
		for (const auto& [k, d] : vertices)
			foreach_dart_of_orbit(m, Vertex(d), [&](Dart x) {
				if (placed[x.index / 2])
					return;
				placed[x.index / 2] = true;
				dart_order.push_back(x.index & ~1u);
				dart_order.push_back(x.index | 1u);
			});
	}
	else
	{
		for (const auto& [k, d] : vertices)
			foreach_dart_of_orbit(m, Vertex(d), [&](Dart x) { dart_order.push_back(x.index); });
	}
	const std::vector<uint32> dart_pos = positions_from_order(dart_order, nd);
	detail::state_of(m).darts->permute(dart_pos);
	remap_darts(m, dart_pos);
	// 2. cells: vertices in key order, other orbits by their representative's new place
	for (uint32 o = 0; o < NB_ORBITS; ++o)
	{
		if (detail::state_of(m).cell_index[o] == nullptr)
			continue;
		AttributeContainer& c = *detail::state_of(m).cells[o];
		std::vector<uint32> lines;
		for (uint32 i = 0; i < c.end_index(); ++i)
			if (c.is_live(i))
				lines.push_back(i);
		if (o == orbit_index(Vertex::ORBIT))
		{
			std::vector<uint32> rank(c.end_index(), 0);
			// vertices were listed in key order: the dart of rank r belongs to the r-th vertex
			for (uint32 r = 0; r < vertices.size(); ++r)
			{
				const uint32 line = (*detail::state_of(m).cell_index[o])[dart_pos[vertices[r].second.index]];
				if (line != INVALID_INDEX)
					rank[line] = r;
			}
			std::stable_sort(lines.begin(), lines.end(), [&](uint32 a, uint32 b) { return rank[a] < rank[b]; });
		}
		else
		{
			// the first dart of each cell in the new dart order
			std::vector<uint32> first(c.end_index(), INVALID_INDEX);
			const AttributeArray<uint32>& idx = *detail::state_of(m).cell_index[o];
			for (uint32 i = 0; i < detail::state_of(m).darts->end_index(); ++i)
				if (detail::state_of(m).darts->is_live(i) && idx[i] != INVALID_INDEX)
					first[idx[i]] = std::min(first[idx[i]], i);
			std::stable_sort(lines.begin(), lines.end(), [&](uint32 a, uint32 b) { return first[a] < first[b]; });
		}
		const std::vector<uint32> pos = positions_from_order(lines, c.end_index());
		c.permute(pos);
		remap_cells(m, o, pos);
	}
}
} // namespace

void clear(CMapBase& m)
{
	detail::state_of(m).incidence_tables.clear();
	detail::state_of(m).darts->clear();
	detail::state_of(m).nb_boundary_darts = 0;
	for (auto& c : detail::state_of(m).cells)
		c->clear();
}

namespace
{
CompactMaps compact_map(CMapBase& m)
{
	detail::drop_incidence_caches(m); // relations are remapped below, behind set_phi* / set_beta
	CompactMaps maps;
	maps.darts = detail::state_of(m).darts->compact();
	remap_darts(m, maps.darts);
	for (uint32 o = 0; o < NB_ORBITS; ++o)
	{
		if (detail::state_of(m).cells[o]->end_index() == 0)
			continue;
		maps.cells[o] = detail::state_of(m).cells[o]->compact();
		remap_cells(m, o, maps.cells[o]);
	}
	return maps;
}
} // namespace

CompactMaps compact(CMap1& m)
{
	return compact_map(m);
}

CompactMaps compact(GMap1& m)
{
	return compact_map(m);
}

void reorder(CMap2& m, const std::function<uint64(CMap2::Vertex)>& key)
{
	reorder_map(m, key);
}

void reorder(CMap3& m, const std::function<uint64(CMap3::Vertex)>& key)
{
	reorder_map(m, key);
}

void reorder(GMap2& m, const std::function<uint64(GMap2::Vertex)>& key)
{
	reorder_map(m, key);
}

} // namespace cgogn
