// SPDX-License-Identifier: MIT
// distribute() on each rank: its part rebuilt from the root's message, with
// the global id and owner of every cell and the carried attributes.
#pragma once

#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/traversals/global.h>

#include "distribute_common.h"
#include "part_message.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn::dist::detail
{

// Adds the carried attribute col to the cells of type CELL: line l gets the
// column's row row_of_line[l] (lines without one keep the default value).
// A plain loop over the lines, so that each carried type costs little code.
template <typename CELL, typename MAP>
void add_column(MAP& m, const PartMessage::Column& col, const std::vector<uint32>& row_of_line, std::size_t nb_rows)
{
	visit_carried_type(col.type, [&]<typename T>() {
		auto a = add_attribute<T, CELL>(m, col.name);
		if (a == nullptr || col.values.size() != nb_rows * sizeof(T))
			throw std::runtime_error("distribute: the attribute '" + col.name + "' cannot be rebuilt");
		for (uint32 line = 0; line < row_of_line.size(); ++line)
			if (row_of_line[line] != INVALID_INDEX)
				std::memcpy(static_cast<void*>(&(*a)[line]),
							col.values.data() + std::size_t(row_of_line[line]) * sizeof(T), sizeof(T));
	});
}

// Rebuilds a rank's part from its message and gives every cell its global
// id and owner.
template <typename MAP>
void build_part(DistributedMap<MAP>& dm, int rank, const PartMessage& msg)
{
	constexpr uint32 D = MAP::dimension;
	MAP& m = dm.map();
	const uint32 nb_vertices = uint32(msg.vertex_gid.size());
	BuildReport report;
	if constexpr (D == 3)
		report = build_polyhedra(m, nb_vertices, msg.cell_nb_faces, msg.face_sizes, msg.corner_vertex);
	else
		report = build_surface(m, nb_vertices, msg.face_sizes, msg.corner_vertex);
	if (report.nb_cells_built != msg.cell_gid.size())
		throw std::runtime_error("distribute: rank " + std::to_string(rank) + " rebuilt " +
								 std::to_string(report.nb_cells_built) + " of its " +
								 std::to_string(msg.cell_gid.size()) + " cells (is the map manifold?)");

	foreach_cell_type<MAP>([&](auto cell, uint32) { index_cells<decltype(cell)>(m); });
	auto& gids = dm.gid_attributes();
	auto& owners = dm.owner_attributes();
	foreach_cell_type<MAP>([&](auto cell, uint32 k) {
		constexpr Orbit O = decltype(cell)::ORBIT;
		gids[k] = container_of<O>(m).template add_attribute<uint64, CellAttribute<uint64, O>>("__gid", NO_GID);
		owners[k] = container_of<O>(m).template add_attribute<int32, CellAttribute<int32, O>>("__owner", -1);
	});

	// vertices: soup vertex i is line offset + i, or a line split from it
	std::vector<uint32> soup_of(container_of<MAP::Vertex::ORBIT>(m).end_index(), INVALID_INDEX);
	for (uint32 i = 0; i < nb_vertices; ++i)
		soup_of[report.vertex_offset + i] = i;
	for (const auto& [line, i] : report.split_vertices)
		soup_of[line] = i;
	foreach_cell(m, [&](typename MAP::Vertex v) {
		const uint32 line = index_of(m, v), i = soup_of[line];
		(*gids[0])[line] = msg.vertex_gid[i];
		(*owners[0])[line] = msg.vertex_owner[i];
	});
	dm.set_not_carried(msg.not_carried);

	// the other cells, through the corner of each dart. The builders make
	// the darts of a fresh map in the order of the corners, so dart i is
	// corner i: checked by the corner's vertices (its vertex and the next
	// two, the next one on a surface). A dart that fails the check is looked
	// up by those vertices, unique in a manifold map whose faces share at
	// most two consecutive vertices.
	struct Key
	{
		uint32 u, v, w, corner;
		bool operator<(const Key& o) const
		{
			return u != o.u ? u < o.u : v != o.v ? v < o.v : w < o.w;
		}
		bool same_corner(const Key& o) const
		{
			return u == o.u && v == o.v && w == o.w;
		}
	};
	std::vector<Key> keys; // by corner
	keys.reserve(msg.corner_vertex.size());
	std::vector<uint32> corner_cell(msg.corner_vertex.size());
	{
		uint32 corner = 0, face = 0;
		for (uint32 c = 0; c < msg.cell_gid.size(); ++c)
		{
			const uint32 nb_faces = D == 3 ? msg.cell_nb_faces[c] : 1;
			for (uint32 f = 0; f < nb_faces; ++f, ++face)
			{
				const uint32 n = msg.face_sizes[face];
				for (uint32 i = 0; i < n; ++i)
				{
					corner_cell[corner + i] = c;
					keys.push_back({msg.corner_vertex[corner + i], msg.corner_vertex[corner + (i + 1) % n],
									D == 3 ? msg.corner_vertex[corner + (i + 2) % n] : 0, corner + i});
				}
				corner += n;
			}
		}
	}
	std::vector<Key> sorted; // made on the first dart out of order
	auto find_corner = [&](const Key& k) -> uint32 {
		if (sorted.empty())
		{
			sorted = keys;
			std::sort(sorted.begin(), sorted.end());
			for (std::size_t i = 1; i < sorted.size(); ++i)
				if (sorted[i].same_corner(sorted[i - 1]))
					throw std::runtime_error("distribute: two faces of rank " + std::to_string(rank) +
											 " share three consecutive vertices (not supported)");
		}
		const auto it = std::lower_bound(sorted.begin(), sorted.end(), k);
		return it == sorted.end() || !it->same_corner(k) ? INVALID_INDEX : it->corner;
	};
	uint64 nb_unmatched = 0;
	std::vector<uint32> top_cell_of_line(container_of<Top<MAP>::ORBIT>(m).end_index(), INVALID_INDEX);
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			return;
		const Dart e = phi1(m, d);
		const Key key{soup_of[index_of(m, typename MAP::Vertex(d))], soup_of[index_of(m, typename MAP::Vertex(e))],
					  D == 3 ? soup_of[index_of(m, typename MAP::Vertex(phi1(m, e)))] : 0, 0};
		const uint32 corner = d.index < keys.size() && keys[d.index].same_corner(key) ? d.index : find_corner(key);
		if (corner == INVALID_INDEX)
		{
			++nb_unmatched;
			return;
		}
		auto set_ids = [&](auto c, uint32 k) {
			const uint32 line = index_of(m, c);
			(*gids[k])[line] = msg.corner_gid[k - 1][corner];
			(*owners[k])[line] = msg.corner_owner[k - 1][corner];
		};
		set_ids(typename MAP::Edge(d), 1);
		if constexpr (D == 3)
			set_ids(CMap3::Face(d), 2);
		const uint32 line = index_of(m, Top<MAP>(d));
		(*gids[D])[line] = msg.cell_gid[corner_cell[corner]];
		(*owners[D])[line] = msg.cell_owner[corner_cell[corner]];
		top_cell_of_line[line] = corner_cell[corner];
	});
	for (const PartMessage::Column& col : msg.columns)
		if (col.of_top_cells)
			add_column<Top<MAP>>(m, col, top_cell_of_line, msg.cell_gid.size());
		else
			add_column<typename MAP::Vertex>(m, col, soup_of, nb_vertices);
	if (nb_unmatched != 0)
		throw std::runtime_error("distribute: rank " + std::to_string(rank) + " could not match " +
								 std::to_string(nb_unmatched) + " darts to their cells");
	foreach_cell_type<MAP>([&](auto cell, uint32 k) {
		foreach_cell(m, [&](decltype(cell) c) {
			if ((*gids[k])[index_of(m, c)] == NO_GID)
				throw std::runtime_error("distribute: rank " + std::to_string(rank) + " has a cell without global id");
		});
	});
}

} // namespace cgogn::dist::detail
