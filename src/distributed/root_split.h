// SPDX-License-Identifier: MIT
// distribute() on the root: the serial map numbered (global ids), its
// cells' owners, and the message of each rank.
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/marking/dart_marker.h>
#include <cgogn/core/traversals/global.h>

#include "distribute_common.h"
#include "part_columns.h"
#include "part_message.h"

#include <algorithm>
#include <cstring>
#include <string>
#include <vector>

namespace cgogn::dist::detail
{

// Global ids of the cells of dimension k by line: their rank in foreach_cell
// order. Indexes the orbit when it is not.
template <typename MAP, typename CELL>
std::vector<uint64> number_cells(MAP& m, uint64& count)
{
	if (!is_indexed<CELL>(m))
		index_cells<CELL>(m);
	std::vector<uint64> gid(container_of<CELL::ORBIT>(m).end_index(), NO_GID);
	count = 0;
	foreach_cell(m, [&](CELL c) { gid[index_of(m, c)] = count++; });
	return gid;
}

// The serial map, numbered and partitioned, ready to be cut into parts.
template <typename MAP>
struct RootSplit
{
	static constexpr uint32 D = MAP::dimension;
	MAP& m;
	std::vector<uint64> gid[D + 1]; // by line, per dimension
	uint64 count[D + 1] = {};
	std::vector<int32> owner[D + 1]; // by global id
	std::vector<Dart> top_dart;      // by global id
	// the parts of the top cells around each vertex (compressed rows by vertex gid)
	std::vector<uint64> vertex_part_starts;
	std::vector<int32> vertex_parts;

	// The global id of the cell of type CELL of dart d.
	template <typename CELL>
	uint64 gid_of(Dart d) const
	{
		return gid[DistributedMap<MAP>::template dimension_of<CELL>()][index_of(m, CELL(d))];
	}

	RootSplit(MAP& map, const AttributeArray<uint32>& part) : m(map)
	{
		foreach_cell_type<MAP>([&](auto cell, uint32 k) { gid[k] = number_cells<MAP, decltype(cell)>(m, count[k]); });

		top_dart.resize(count[D]);
		for (uint32 k = 0; k <= D; ++k)
			owner[k].assign(count[k], std::numeric_limits<int32>::max());
		std::vector<std::pair<uint64, int32>> incidences; // (vertex gid, part)
		// the part that last named each vertex: neighbouring volumes mostly
		// share their part, so most repeats are dropped before the sort
		std::vector<int32> last_part(count[0], -1);
		foreach_cell(m, [&](Top<MAP> t) {
			const uint64 g = gid[D][index_of(m, t)];
			const int32 p = int32(part[index_of(m, t)]);
			top_dart[g] = t.dart;
			owner[D][g] = p;
			foreach_dart_of_orbit(m, t, [&](Dart d) {
				foreach_cell_type<MAP>([&](auto cell, uint32 k) {
					if (k < D)
					{
						int32& o = owner[k][gid_of<decltype(cell)>(d)];
						o = std::min(o, p);
					}
				});
				const uint64 v = gid_of<typename MAP::Vertex>(d);
				if (last_part[v] != p)
				{
					last_part[v] = p;
					incidences.emplace_back(v, p);
				}
			});
		});
		std::sort(incidences.begin(), incidences.end());
		incidences.erase(std::unique(incidences.begin(), incidences.end()), incidences.end());
		vertex_part_starts.assign(count[0] + 1, 0);
		for (const auto& [v, p] : incidences)
		{
			++vertex_part_starts[v + 1];
			vertex_parts.push_back(p);
		}
		for (uint64 v = 0; v < count[0]; ++v)
			vertex_part_starts[v + 1] += vertex_part_starts[v];
	}

	// The top cells each rank holds (owned, and those sharing a vertex with
	// an owned one), in increasing global id.
	std::vector<std::vector<uint64>> cells_per_rank(int nb_ranks) const
	{
		std::vector<std::vector<uint64>> cells{std::size_t(nb_ranks)};
		std::vector<int32> ranks;
		for (uint64 g = 0; g < count[D]; ++g)
		{
			ranks.clear();
			foreach_dart_of_orbit(m, Top<MAP>(top_dart[g]), [&](Dart d) {
				const uint64 v = gid_of<typename MAP::Vertex>(d);
				for (uint64 i = vertex_part_starts[v]; i < vertex_part_starts[v + 1]; ++i)
					ranks.push_back(vertex_parts[i]);
			});
			std::sort(ranks.begin(), ranks.end());
			ranks.erase(std::unique(ranks.begin(), ranks.end()), ranks.end());
			for (int32 r : ranks)
				cells[std::size_t(r)].push_back(g);
		}
		return cells;
	}

	// The message of one rank: its cells, faces in phi1 order (counterclockwise
	// seen from outside the cell, as build_polyhedra takes them).
	PartMessage message(const std::vector<uint64>& cells, std::vector<uint32>& local_vertex,
						std::vector<uint64>& vertex_stamp, uint64 stamp) const
	{
		PartMessage msg;
		std::vector<uint32> vertex_lines, top_lines;
		DartMarker<MAP> visited(m);
		auto add_corner = [&](Dart x) {
			const uint64 v = gid_of<typename MAP::Vertex>(x);
			if (vertex_stamp[v] != stamp)
			{
				vertex_stamp[v] = stamp;
				local_vertex[v] = uint32(msg.vertex_gid.size());
				msg.vertex_gid.push_back(v);
				msg.vertex_owner.push_back(owner[0][v]);
				vertex_lines.push_back(index_of(m, typename MAP::Vertex(x)));
			}
			msg.corner_vertex.push_back(local_vertex[v]);
			auto add_cell = [&](auto cell, uint32 k) {
				const uint64 g = gid_of<decltype(cell)>(x);
				msg.corner_gid[k - 1].push_back(g);
				msg.corner_owner[k - 1].push_back(owner[k][g]);
			};
			add_cell(typename MAP::Edge(), 1);
			if constexpr (D == 3)
				add_cell(CMap3::Face(), 2);
		};
		auto add_face = [&](Dart x) {
			uint32 n = 0;
			Dart it = x;
			do
			{
				if constexpr (D == 3)
					visited.mark(it);
				add_corner(it);
				++n;
				it = phi1(m, it);
			} while (it != x);
			msg.face_sizes.push_back(n);
		};
		std::vector<Dart> darts;
		for (uint64 g : cells)
		{
			msg.cell_gid.push_back(g);
			msg.cell_owner.push_back(owner[D][g]);
			top_lines.push_back(index_of(m, Top<MAP>(top_dart[g])));
			if constexpr (D == 3)
			{
				darts.clear();
				uint32 nb_faces = 0;
				foreach_dart_of_orbit(m, CMap3::Volume(top_dart[g]), [&](Dart x) {
					darts.push_back(x);
					if (!visited.is_marked(x))
					{
						add_face(x);
						++nb_faces;
					}
				});
				for (Dart x : darts)
					visited.unmark(x);
				msg.cell_nb_faces.push_back(nb_faces);
			}
			else
				add_face(top_dart[g]); // a face is one phi1 cycle
		}
		add_columns(msg, container_of<MAP::Vertex::ORBIT>(m), vertex_lines, 0, "vertex");
		add_columns(msg, container_of<Top<MAP>::ORBIT>(m), top_lines, 1, D == 3 ? "volume" : "face");
		name_attributes_of<typename MAP::Edge>(m, msg.not_carried, "edge");
		if constexpr (D == 3)
			name_attributes_of<CMap3::Face>(m, msg.not_carried, "face");
		std::sort(msg.not_carried.begin(), msg.not_carried.end());
		return msg;
	}
};

} // namespace cgogn::dist::detail
