// SPDX-License-Identifier: MIT
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/marking/dart_marker.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/distributed/distribute.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "part_message.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <tuple>

namespace cgogn::dist
{

namespace
{

constexpr uint64 NO_GID = std::numeric_limits<uint64>::max();
constexpr int MESSAGE_TAG = 8101;

template <typename MAP>
using Top = typename DistributedMap<MAP>::TopCell;

// The attribute types distribute() carries to the ranks, by index.
using CarriedTypes =
	std::tuple<double, float, int8, uint8, std::int16_t, uint16, int32, uint32, int64, uint64, Vec2, Vec3, Vec4>;

// Calls f.template operator()<T>() with the carried type of index i.
template <typename F, std::size_t I = 0>
void visit_carried_type(uint8 i, const F& f)
{
	if constexpr (I < std::tuple_size_v<CarriedTypes>)
	{
		if (i == I)
			f.template operator()<std::tuple_element_t<I, CarriedTypes>>();
		else
			visit_carried_type<F, I + 1>(i, f);
	}
}

// The index of a's type among the carried types; -1 when it is not carried.
inline int carried_type_of(const AttributeBase& a)
{
	int found = -1;
	for (uint8 i = 0; i < std::tuple_size_v<CarriedTypes>; ++i)
		visit_carried_type(i, [&]<typename T>() {
			if (a.type() == typeid(T))
				found = i;
		});
	return found;
}

// The cell of dimension k of dart d (k < the map's dimension).
template <typename MAP, typename FUNC>
void with_cell_of_dimension(uint32 k, Dart d, const FUNC& f)
{
	if (k == 0)
		f(typename MAP::Vertex(d));
	else if (k == 1)
		f(typename MAP::Edge(d));
	else if constexpr (MAP::dimension == 3)
	{
		if (k == 2)
			f(CMap3::Face(d));
		else
			f(CMap3::Volume(d));
	}
	else
		f(CMap2::Face(d));
}

// ---------------------------------------------------------------- the root

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
	std::vector<uint64> gid[D + 1]; // by line
	uint64 count[D + 1] = {};
	std::vector<int32> owner[D + 1]; // by global id
	std::vector<Dart> top_dart;      // by global id
	// the parts of the top cells around each vertex (compressed rows by vertex gid)
	std::vector<uint64> vertex_part_starts;
	std::vector<int32> vertex_parts;

	uint64 gid_of(uint32 k, Dart d) const
	{
		uint64 g = NO_GID;
		with_cell_of_dimension<MAP>(k, d, [&](auto c) { g = gid[k][index_of(m, c)]; });
		return g;
	}

	RootSplit(MAP& map, const AttributeArray<uint32>& part) : m(map)
	{
		gid[0] = number_cells<MAP, typename MAP::Vertex>(m, count[0]);
		gid[1] = number_cells<MAP, typename MAP::Edge>(m, count[1]);
		gid[2] = number_cells<MAP, typename MAP::Face>(m, count[2]);
		if constexpr (D == 3)
			gid[3] = number_cells<MAP, CMap3::Volume>(m, count[3]);

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
				for (uint32 k = 0; k < D; ++k)
				{
					int32& o = owner[k][gid_of(k, d)];
					o = std::min(o, p);
				}
				const uint64 v = gid_of(0, d);
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
				const uint64 v = gid_of(0, d);
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
	detail::PartMessage message(const std::vector<uint64>& cells, std::vector<uint32>& local_vertex,
								std::vector<uint64>& vertex_stamp, uint64 stamp) const
	{
		detail::PartMessage msg;
		std::vector<uint32> vertex_lines, top_lines;
		DartMarker<MAP> visited(m);
		auto add_corner = [&](Dart x) {
			const uint64 v = gid_of(0, x);
			if (vertex_stamp[v] != stamp)
			{
				vertex_stamp[v] = stamp;
				local_vertex[v] = uint32(msg.vertex_gid.size());
				msg.vertex_gid.push_back(v);
				msg.vertex_owner.push_back(owner[0][v]);
				vertex_lines.push_back(index_of(m, typename MAP::Vertex(x)));
			}
			msg.corner_vertex.push_back(local_vertex[v]);
			for (uint32 k = 1; k < D; ++k)
			{
				const uint64 g = gid_of(k, x);
				msg.corner_gid[k - 1].push_back(g);
				msg.corner_owner[k - 1].push_back(owner[k][g]);
			}
		};
		auto add_face = [&](Dart x) {
			uint32 n = 0;
			Dart it = x;
			do
			{
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
			{
				add_face(top_dart[g]);
				foreach_dart_of_orbit(m, CMap2::Face(top_dart[g]), [&](Dart x) { visited.unmark(x); });
			}
		}
		add_columns(msg, container_of<MAP::Vertex::ORBIT>(m), vertex_lines, 0);
		add_columns(msg, container_of<Top<MAP>::ORBIT>(m), top_lines, 1);
		name_attributes_of<typename MAP::Edge>(msg.not_carried, "edge");
		if constexpr (D == 3)
			name_attributes_of<CMap3::Face>(msg.not_carried, "face");
		std::sort(msg.not_carried.begin(), msg.not_carried.end());
		return msg;
	}

	// Names the user attributes of the cells of type CELL as not carried.
	template <typename CELL>
	void name_attributes_of(std::vector<std::string>& names, const char* cells) const
	{
		if (!is_indexed<CELL>(m))
			return;
		const AttributeContainer& c = container_of<CELL::ORBIT>(m);
		for (const auto& a : c.attributes())
			if (a.get() != &c.key() && a->name().rfind("__", 0) != 0)
				names.push_back(std::string(cells) + " attribute '" + a->name() + "'");
	}

	// The values of the container's attributes on the given lines, those of
	// a carried type; the others are named in msg.not_carried.
	void add_columns(detail::PartMessage& msg, const AttributeContainer& c, const std::vector<uint32>& lines,
					 uint8 of_top_cells) const
	{
		for (const auto& a : c.attributes())
		{
			if (a.get() == &c.key() || a->name().rfind("__", 0) == 0)
				continue;
			const int type = carried_type_of(*a);
			if (type < 0)
			{
				msg.not_carried.push_back(std::string(of_top_cells ? (D == 3 ? "volume" : "face") : "vertex") +
										  " attribute '" + a->name() + "' (of a type not carried)");
				continue;
			}
			detail::PartMessage::Column& col = msg.columns.emplace_back();
			col.name = a->name();
			col.of_top_cells = of_top_cells;
			col.type = uint8(type);
			visit_carried_type(col.type, [&]<typename T>() {
				const auto& values = static_cast<const AttributeArray<T>&>(*a);
				col.values.resize(lines.size() * sizeof(T));
				for (std::size_t i = 0; i < lines.size(); ++i)
					std::memcpy(col.values.data() + i * sizeof(T), &values[lines[i]], sizeof(T));
			});
		}
	}
};

// The parts: the attribute partition() writes, or the user's.
template <typename MAP>
std::shared_ptr<CellAttribute<uint32, Top<MAP>::ORBIT>> root_parts(MAP& m, int nb_ranks,
																   const DistributeOptions& options)
{
	if (!options.use_existing_parts)
	{
		partition(m, uint32(nb_ranks), options.partition);
		return get_attribute<uint32, Top<MAP>>(m, options.partition.attribute);
	}
	auto parts = get_attribute<uint32, Top<MAP>>(m, options.partition.attribute);
	if (parts == nullptr)
		throw PartitionError("distribute: the map has no uint32 attribute '" + options.partition.attribute +
							 "' on its top cells");
	foreach_cell(m, [&](Top<MAP> t) {
		if ((*parts)[t] >= uint32(nb_ranks))
			throw PartitionError("distribute: part " + std::to_string((*parts)[t]) + " for " +
								 std::to_string(nb_ranks) + " ranks");
	});
	return parts;
}

// ------------------------------------------------------------ messages

void send_bytes(MPI_Comm comm, int to, const std::vector<std::byte>& bytes)
{
	const uint64 n = bytes.size();
	MPI_Send(&n, 1, MPI_UINT64_T, to, MESSAGE_TAG, comm);
	constexpr uint64 chunk = uint64(1) << 30;
	for (uint64 at = 0; at < n; at += chunk)
		MPI_Send(bytes.data() + at, int(std::min(chunk, n - at)), MPI_BYTE, to, MESSAGE_TAG, comm);
}

std::vector<std::byte> receive_bytes(MPI_Comm comm, int from)
{
	uint64 n = 0;
	MPI_Recv(&n, 1, MPI_UINT64_T, from, MESSAGE_TAG, comm, MPI_STATUS_IGNORE);
	std::vector<std::byte> bytes(n);
	constexpr uint64 chunk = uint64(1) << 30;
	for (uint64 at = 0; at < n; at += chunk)
		MPI_Recv(bytes.data() + at, int(std::min(chunk, n - at)), MPI_BYTE, from, MESSAGE_TAG, comm, MPI_STATUS_IGNORE);
	return bytes;
}

// Whether the root failed, and why, on every rank: every rank throws alike.
void share_root_error(MPI_Comm comm, int root, std::string& error, int& kind)
{
	MPI_Bcast(&kind, 1, MPI_INT, root, comm);
	if (kind == 0)
		return;
	int length = int(error.size());
	MPI_Bcast(&length, 1, MPI_INT, root, comm);
	error.resize(std::size_t(length));
	MPI_Bcast(error.data(), length, MPI_CHAR, root, comm);
	if (kind == 1)
		throw PartitionError(error);
	throw std::runtime_error(error);
}

// ---------------------------------------------------------- each rank

// Rebuilds a rank's part from its message and gives every cell its global
// id and owner.
template <typename MAP>
void build_part(DistributedMap<MAP>& dm, int rank, const detail::PartMessage& msg)
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

	index_cells<typename MAP::Edge>(m);
	index_cells<typename MAP::Face>(m);
	if constexpr (D == 3)
		index_cells<CMap3::Volume>(m);
	auto& gids = dm.gid_attributes();
	auto& owners = dm.owner_attributes();
	auto add_ids = [&](auto cell, uint32 k) {
		constexpr Orbit O = decltype(cell)::ORBIT;
		gids[k] = container_of<O>(m).template add_attribute<uint64, CellAttribute<uint64, O>>("__gid", NO_GID);
		owners[k] = container_of<O>(m).template add_attribute<int32, CellAttribute<int32, O>>("__owner", -1);
	};
	add_ids(typename MAP::Vertex(), 0);
	add_ids(typename MAP::Edge(), 1);
	add_ids(typename MAP::Face(), 2);
	if constexpr (D == 3)
		add_ids(CMap3::Volume(), 3);

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
	for (const detail::PartMessage::Column& col : msg.columns)
		if (col.of_top_cells == 0)
			visit_carried_type(col.type, [&]<typename T>() {
				auto a = add_attribute<T, typename MAP::Vertex>(m, col.name);
				if (a == nullptr || col.values.size() != nb_vertices * sizeof(T))
					throw std::runtime_error("distribute: the vertex attribute '" + col.name + "' cannot be rebuilt");
				foreach_cell(m, [&](typename MAP::Vertex v) {
					std::memcpy(static_cast<void*>(&(*a)[v]), col.values.data() + soup_of[index_of(m, v)] * sizeof(T),
								sizeof(T));
				});
			});
	dm.set_not_carried(msg.not_carried);

	// the other cells, through the corner of each dart: a corner is known by
	// its vertex and the next two (the next one on a surface), unique in a
	// manifold map whose faces share at most two consecutive vertices
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
	std::vector<Key> keys;
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
	std::sort(keys.begin(), keys.end());
	for (std::size_t i = 1; i < keys.size(); ++i)
		if (keys[i].same_corner(keys[i - 1]))
			throw std::runtime_error("distribute: two faces of rank " + std::to_string(rank) +
									 " share three consecutive vertices (not supported)");
	uint64 nb_unmatched = 0;
	std::vector<uint32> top_cell_of_line(container_of<Top<MAP>::ORBIT>(m).end_index(), INVALID_INDEX);
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			return;
		const Dart e = phi1(m, d);
		const Key k{soup_of[index_of(m, typename MAP::Vertex(d))], soup_of[index_of(m, typename MAP::Vertex(e))],
					D == 3 ? soup_of[index_of(m, typename MAP::Vertex(phi1(m, e)))] : 0, 0};
		const auto it = std::lower_bound(keys.begin(), keys.end(), k);
		if (it == keys.end() || !it->same_corner(k))
		{
			++nb_unmatched;
			return;
		}
		const uint32 corner = it->corner;
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
	for (const detail::PartMessage::Column& col : msg.columns)
		if (col.of_top_cells == 1)
			visit_carried_type(col.type, [&]<typename T>() {
				auto a = add_attribute<T, Top<MAP>>(m, col.name);
				if (a == nullptr || col.values.size() != msg.cell_gid.size() * sizeof(T))
					throw std::runtime_error("distribute: the cell attribute '" + col.name + "' cannot be rebuilt");
				foreach_cell(m, [&](Top<MAP> t) {
					std::memcpy(static_cast<void*>(&(*a)[t]),
								col.values.data() + top_cell_of_line[index_of(m, t)] * sizeof(T), sizeof(T));
				});
			});
	if (nb_unmatched != 0)
		throw std::runtime_error("distribute: rank " + std::to_string(rank) + " could not match " +
								 std::to_string(nb_unmatched) + " darts to their cells");
	for (uint32 k = 0; k <= D; ++k)
		with_cell_of_dimension<MAP>(k, Dart(), [&](auto cell) {
			foreach_cell(m, [&](decltype(cell) c) {
				if ((*gids[k])[index_of(m, c)] == NO_GID)
					throw std::runtime_error("distribute: rank " + std::to_string(rank) +
											 " has a cell without global id");
			});
		});
}

template <typename MAP>
DistributedMap<MAP> distribute_map(MPI_Comm comm, MAP* serial, const DistributeOptions& options, int root)
{
	int rank = 0, nb_ranks = 1;
	MPI_Comm_rank(comm, &rank);
	MPI_Comm_size(comm, &nb_ranks);
	DistributedMap<MAP> dm;
	detail::PartMessage own;
	if (rank == root)
	{
		std::string error;
		int kind = 0;
		std::shared_ptr<CellAttribute<uint32, Top<MAP>::ORBIT>> parts;
		try
		{
			if (serial == nullptr)
				throw PartitionError("distribute: the root has no map");
			parts = root_parts(*serial, nb_ranks, options);
		}
		catch (const PartitionError& e)
		{
			error = e.what();
			kind = 1;
		}
		catch (const std::exception& e)
		{
			error = e.what();
			kind = 2;
		}
		share_root_error(comm, root, error, kind);
		const RootSplit<MAP> split(*serial, *parts);
		const auto cells = split.cells_per_rank(nb_ranks);
		std::vector<uint32> local_vertex(split.count[0]);
		std::vector<uint64> stamp(split.count[0], NO_GID);
		for (int r = 0; r < nb_ranks; ++r)
		{
			detail::PartMessage msg = split.message(cells[std::size_t(r)], local_vertex, stamp, uint64(r));
			if (r == root)
				own = std::move(msg);
			else
				send_bytes(comm, r, detail::serialize(msg));
		}
	}
	else
	{
		std::string error;
		int kind = 0;
		share_root_error(comm, root, error, kind);
		own = detail::deserialize(receive_bytes(comm, root));
	}
	// every rank builds; a failure anywhere is raised everywhere after the
	// plans' collective calls would otherwise wait forever
	std::string error;
	try
	{
		build_part(dm, rank, own);
		own = detail::PartMessage(); // the map holds it all now
	}
	catch (const std::exception& e)
	{
		error = e.what();
	}
	int failed = !error.empty(), any_failed = 0;
	MPI_Allreduce(&failed, &any_failed, 1, MPI_INT, MPI_MAX, comm);
	if (any_failed)
		throw std::runtime_error(failed ? error : "distribute: another rank could not rebuild its part");
	dm.finish(comm);
	return dm;
}

} // namespace

DistributedCMap3 distribute(MPI_Comm comm, CMap3* serial, const DistributeOptions& options, int root)
{
	return distribute_map(comm, serial, options, root);
}

DistributedCMap2 distribute(MPI_Comm comm, CMap2* serial, const DistributeOptions& options, int root)
{
	return distribute_map(comm, serial, options, root);
}

DistributedCMap3 distribute(MPI_Comm comm, CMap3* serial)
{
	return distribute_map(comm, serial, DistributeOptions(), 0);
}

DistributedCMap2 distribute(MPI_Comm comm, CMap2* serial)
{
	return distribute_map(comm, serial, DistributeOptions(), 0);
}

} // namespace cgogn::dist
