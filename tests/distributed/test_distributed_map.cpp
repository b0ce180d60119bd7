// SPDX-License-Identifier: MIT
// Distributed maps under mpiexec (1 to 4 ranks): every cell has one owner
// that all its holders agree on, the ghost layer is exactly the vertex
// neighbourhood of the owned cells, exchange and accumulate move the
// owners' and the ghosts' values, the global counts and measures equal the
// serial ones, and distributed smoothing gives the serial result (to the
// bit in deterministic mode). Every check is reduced over the ranks, so a
// failure on any rank fails on every rank.
#include <cgogn/core.h>
#include <cgogn/distributed/distribute.h>
#include <cgogn/distributed/exchange.h>
#include <cgogn/distributed/files.h>
#include <cgogn/distributed/reductions.h>
#include <cgogn/distributed/smoothing.h>
#include <cgogn/geometry.h>
#include <cgogn/io/volume.h>

#include "mpi_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <vector>

namespace cgogn_test_distributed_map
{

using namespace cgogn;
using namespace cgogn_test_mpi;

// A tet grid with positions, its cells indexed and numbered as distribute()
// numbers them (foreach_cell order of each orbit).
struct Serial
{
	CMap3 m;
	std::shared_ptr<CellAttribute<Vec3, CMap3::Vertex::ORBIT>> pos;
	std::vector<Dart> cell[4]; // by global id

	explicit Serial(uint32 n)
	{
		const VolumeSoup s = tet_grid_soup(n, n, n);
		const BuildReport r = build_volume(m, s);
		pos = add_attribute<Vec3, CMap3::Vertex>(m, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		index_cells<CMap3::Edge>(m);
		index_cells<CMap3::Face>(m);
		index_cells<CMap3::Volume>(m);
		foreach_cell(m, [&](CMap3::Vertex c) { cell[0].push_back(c.dart); });
		foreach_cell(m, [&](CMap3::Edge c) { cell[1].push_back(c.dart); });
		foreach_cell(m, [&](CMap3::Face c) { cell[2].push_back(c.dart); });
		foreach_cell(m, [&](CMap3::Volume c) { cell[3].push_back(c.dart); });
	}
};

// A smooth displacement of a vertex from its global id, the same on every rank.
Vec3 shake(uint64 gid)
{
	uint64 h = gid * 0x9E3779B97F4A7C15ull;
	h ^= h >> 29;
	h *= 0xBF58476D1CE4E5B9ull;
	h ^= h >> 32;
	const auto unit = [](uint64 x) { return double(x & 0xFFFF) / 65536.0 - 0.5; };
	return 0.2 * Vec3(unit(h), unit(h >> 16), unit(h >> 32));
}

template <typename CELL>
void collect_ids(const dist::DistributedCMap3& dm, std::vector<uint64>& owned, std::vector<uint64>& holder_pairs)
{
	foreach_cell(dm.map(), [&](CELL c) {
		const uint64 g = dist::global_id(dm, c);
		if (dist::is_owned(dm, c))
			owned.push_back(g);
		holder_pairs.push_back(g);
		holder_pairs.push_back(uint64(dist::owner(dm, c)));
	});
}

class DistributedTetGrid : public ::testing::TestWithParam<uint32>
{
};

TEST_P(DistributedTetGrid, EveryCellHasOneOwnerThatAllHoldersAgreeOn)
{
	Serial serial(GetParam());
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	EXPECT_TRUE(everywhere(check_integrity(dm.map()).ok()));
	EXPECT_EQ(dm.nb_ranks(), world_size());

	std::vector<uint64> owned[4], pairs[4];
	collect_ids<CMap3::Vertex>(dm, owned[0], pairs[0]);
	collect_ids<CMap3::Edge>(dm, owned[1], pairs[1]);
	collect_ids<CMap3::Face>(dm, owned[2], pairs[2]);
	collect_ids<CMap3::Volume>(dm, owned[3], pairs[3]);
	for (int k = 0; k < 4; ++k)
	{
		// owned once in all: the owned ids of all ranks are 0 .. n-1, once each
		std::vector<uint64> all = gather_on_root(owned[k]);
		std::vector<int> owner_of(serial.cell[k].size(), -1);
		const std::vector<int> counts = [&] {
			const int n = int(owned[k].size());
			std::vector<int> c(static_cast<std::size_t>(world_size()));
			MPI_Gather(&n, 1, MPI_INT, c.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
			return c;
		}();
		bool ok = true;
		if (world_rank() == 0)
		{
			std::vector<uint64> sorted = all;
			std::sort(sorted.begin(), sorted.end());
			ok = sorted.size() == serial.cell[k].size();
			for (std::size_t i = 0; ok && i < sorted.size(); ++i)
				ok = sorted[i] == i;
			std::size_t at = 0;
			for (int r = 0; ok && r < world_size(); ++r)
				for (int i = 0; i < counts[std::size_t(r)]; ++i)
					owner_of[all[at++]] = r;
			// every holder names the rank that owns the cell
			const std::vector<uint64> held = gather_on_root(pairs[k]);
			for (std::size_t i = 0; ok && i < held.size(); i += 2)
				ok = owner_of[held[i]] == int(held[i + 1]);
		}
		else
			gather_on_root(pairs[k]);
		EXPECT_TRUE(everywhere(ok)) << "cells of dimension " << k;
	}
}

TEST_P(DistributedTetGrid, GhostLayerIsTheVertexNeighbourhoodOfOwnedVolumes)
{
	Serial serial(GetParam());
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	const CMap3& m = dm.map();
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	ASSERT_NE(pos, nullptr);

	bool faces_ok = true, degrees_ok = true, positions_ok = true, needed_ok = true;
	std::vector<uint8> near_owned(container_of<CMap3::Vertex::ORBIT>(m).end_index(), 0);
	foreach_cell(m, [&](CMap3::Volume w) {
		if (!dist::is_owned(dm, w))
			return;
		foreach_dart_of_orbit(m, w, [&](Dart d) {
			// a face of an owned volume: its neighbour is here, or it is on
			// the boundary of the whole mesh
			if (is_boundary(m, phi3(m, d)))
			{
				const Dart s = serial.cell[2][dist::global_id(dm, CMap3::Face(d))];
				faces_ok = faces_ok && (is_boundary(serial.m, s) || is_boundary(serial.m, phi3(serial.m, s)));
			}
			near_owned[index_of(m, CMap3::Vertex(d))] = 1;
		});
	});
	foreach_cell(m, [&](CMap3::Vertex v) {
		const Dart s = serial.cell[0][dist::global_id(dm, v)];
		positions_ok = positions_ok && (*pos)[v] == (*serial.pos)[CMap3::Vertex(s)];
		if (!near_owned[index_of(m, v)])
			return;
		uint32 here = 0, there = 0;
		foreach_incident_volume(m, v, [&](CMap3::Volume) { ++here; });
		foreach_incident_volume(serial.m, CMap3::Vertex(s), [&](CMap3::Volume) { ++there; });
		degrees_ok = degrees_ok && here == there;
	});
	// each ghost volume touches an owned one
	foreach_cell(m, [&](CMap3::Volume w) {
		if (dist::is_owned(dm, w))
			return;
		bool touches = false;
		foreach_incident_vertex(m, w, [&](CMap3::Vertex v) { touches = touches || near_owned[index_of(m, v)]; });
		needed_ok = needed_ok && touches;
	});
	EXPECT_TRUE(everywhere(faces_ok));
	EXPECT_TRUE(everywhere(degrees_ok));
	EXPECT_TRUE(everywhere(positions_ok));
	EXPECT_TRUE(everywhere(needed_ok));
}

// Owners write f(gid), ghosts hold a wrong value; after exchange every copy
// holds f(gid).
template <typename T, typename CELL, typename F>
bool exchange_reaches_ghosts(dist::DistributedCMap3& dm, const F& f, dist::Transport transport)
{
	auto a = add_attribute<T, CELL>(dm.map(), "exchanged");
	foreach_cell(dm.map(), [&](CELL c) { (*a)[c] = dist::is_owned(dm, c) ? f(dist::global_id(dm, c)) : f(~0ull); });
	dist::exchange(dm, a, transport);
	bool ok = true;
	foreach_cell(dm.map(), [&](CELL c) { ok = ok && (*a)[c] == f(dist::global_id(dm, c)); });
	remove_attribute(dm.map(), a);
	return everywhere(ok);
}

template <typename CELL>
void expect_exchange_of_every_type(dist::DistributedCMap3& dm, dist::Transport t)
{
	EXPECT_TRUE((exchange_reaches_ghosts<double, CELL>(
		dm, [](uint64 g) { return 0.5 * double(g) + 0.25; }, t)));
	EXPECT_TRUE((exchange_reaches_ghosts<Vec3, CELL>(
		dm, [](uint64 g) { return Vec3(double(g), -double(g), 1.0 / (double(g) + 1.0)); }, t)));
	EXPECT_TRUE((exchange_reaches_ghosts<int64, CELL>(
		dm, [](uint64 g) { return -int64(g) * 7 - 3; }, t)));
}

TEST_P(DistributedTetGrid, ExchangeSendsOwnersValuesToGhosts)
{
	Serial serial(GetParam());
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	for (dist::Transport t : {dist::Transport::NeighborhoodCollective, dist::Transport::PointToPoint})
	{
		expect_exchange_of_every_type<CMap3::Vertex>(dm, t);
		expect_exchange_of_every_type<CMap3::Edge>(dm, t);
		expect_exchange_of_every_type<CMap3::Face>(dm, t);
		expect_exchange_of_every_type<CMap3::Volume>(dm, t);
	}
}

TEST_P(DistributedTetGrid, AccumulateGivesEachVertexItsGlobalDegree)
{
	Serial serial(GetParam());
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	const CMap3& m = dm.map();
	for (dist::Transport t : {dist::Transport::NeighborhoodCollective, dist::Transport::PointToPoint})
	{
		auto degree = add_attribute<int64, CMap3::Vertex>(dm.map(), "degree");
		foreach_cell(m, [&](CMap3::Vertex v) { (*degree)[v] = 0; });
		foreach_cell(m, [&](CMap3::Volume w) {
			if (dist::is_owned(dm, w))
				foreach_incident_vertex(m, w, [&](CMap3::Vertex v) { ++(*degree)[v]; });
		});
		dist::accumulate(dm, degree, std::plus<>{}, t);
		bool ok = true;
		foreach_cell(m, [&](CMap3::Vertex v) {
			if (!dist::is_owned(dm, v))
				return;
			int64 expected = 0;
			foreach_incident_volume(serial.m, CMap3::Vertex(serial.cell[0][dist::global_id(dm, v)]),
									[&](CMap3::Volume) { ++expected; });
			ok = ok && (*degree)[v] == expected;
		});
		EXPECT_TRUE(everywhere(ok));
		// then exchange: every copy knows the degree
		dist::exchange(dm, degree, t);
		foreach_cell(m, [&](CMap3::Vertex v) {
			int64 expected = 0;
			foreach_incident_volume(serial.m, CMap3::Vertex(serial.cell[0][dist::global_id(dm, v)]),
									[&](CMap3::Volume) { ++expected; });
			ok = ok && (*degree)[v] == expected;
		});
		EXPECT_TRUE(everywhere(ok));
		remove_attribute(dm.map(), degree);
	}
}

TEST_P(DistributedTetGrid, GlobalCountsAndMeasuresEqualSerial)
{
	Serial serial(GetParam());
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	EXPECT_EQ(dist::global_nb_cells<CMap3::Vertex>(dm), nb_cells<CMap3::Vertex>(serial.m));
	EXPECT_EQ(dist::global_nb_cells<CMap3::Edge>(dm), nb_cells<CMap3::Edge>(serial.m));
	EXPECT_EQ(dist::global_nb_cells<CMap3::Face>(dm), nb_cells<CMap3::Face>(serial.m));
	EXPECT_EQ(dist::global_nb_cells<CMap3::Volume>(dm), nb_cells<CMap3::Volume>(serial.m));
	EXPECT_EQ(dist::global_euler_characteristic(dm), euler_characteristic(serial.m));

	auto pos = get_attribute<Vec3, CMap3::Vertex>(dm.map(), "position");
	const double volume =
		dist::global_sum_of<CMap3::Volume>(dm, [&](CMap3::Volume w) { return geometry::volume(dm.map(), w, *pos); });
	const double n = GetParam();
	EXPECT_NEAR(volume, n * n * n, 1e-12 * n * n * n);
	// the boundary area: the boundary faces, each counted by its owner
	const double area = dist::global_sum_of<CMap3::Face>(dm, [&](CMap3::Face f) {
		const Dart d = is_boundary(dm.map(), f.dart) ? phi3(dm.map(), f.dart) : f.dart;
		return is_boundary(dm.map(), phi3(dm.map(), d)) ? geometry::face_area(dm.map(), f, *pos) : 0.0;
	});
	EXPECT_NEAR(area, 6 * n * n, 1e-12 * n * n);
	const dist::BoundingBox box = dist::global_bounding_box(dm, *pos);
	EXPECT_EQ(box.min, Vec3(0, 0, 0));
	EXPECT_EQ(box.max, Vec3(n, n, n));
}

// Ten Jacobi steps from shaken positions: within 1e-12 of the diagonal of
// the serial filter, and to the bit of a 1-rank run in deterministic mode.
TEST_P(DistributedTetGrid, SmoothingEqualsSerial)
{
	// shaken by global id: vertex k of foreach_cell order has global id k
	Serial serial(GetParam());
	for (uint64 g = 0; g < serial.cell[0].size(); ++g)
		(*serial.pos)[CMap3::Vertex(serial.cell[0][g])] += shake(g);
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	auto pos = get_attribute<Vec3, CMap3::Vertex>(dm.map(), "position");

	// (gid, x, y, z) of the owned vertices, gathered on rank 0
	auto owned_positions = [&](const dist::DistributedCMap3& d, const CellAttribute<Vec3, CMap3::Vertex::ORBIT>& p) {
		std::vector<double> out;
		foreach_cell(d.map(), [&](CMap3::Vertex v) {
			if (dist::is_owned(d, v))
				out.insert(out.end(), {double(dist::global_id(d, v)), p[v][0], p[v][1], p[v][2]});
		});
		return out;
	};

	dist::laplacian_smoothing(dm, *pos, 10);
	const std::vector<double> smoothed = gather_on_root(owned_positions(dm, *pos));
	bool close = true;
	if (world_rank() == 0)
	{
		Serial reference(GetParam());
		for (uint64 g = 0; g < reference.cell[0].size(); ++g)
			(*reference.pos)[CMap3::Vertex(reference.cell[0][g])] += shake(g);
		geometry::laplacian_smoothing(reference.m, *reference.pos, 10);
		const double diagonal = std::sqrt(3.0) * GetParam();
		close = smoothed.size() == 4 * reference.cell[0].size();
		for (std::size_t i = 0; close && i < smoothed.size(); i += 4)
		{
			const Vec3 p(smoothed[i + 1], smoothed[i + 2], smoothed[i + 3]);
			close = (p - (*reference.pos)[CMap3::Vertex(reference.cell[0][uint64(smoothed[i])])]).norm() <=
					1e-12 * diagonal;
		}
	}
	EXPECT_TRUE(everywhere(close));

	// deterministic: the same bits as the whole map on one rank
	Serial again(GetParam());
	for (uint64 g = 0; g < again.cell[0].size(); ++g)
		(*again.pos)[CMap3::Vertex(again.cell[0][g])] += shake(g);
	dist::DistributedCMap3 dm2 = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &again.m : nullptr);
	auto pos2 = get_attribute<Vec3, CMap3::Vertex>(dm2.map(), "position");
	dist::SmoothingOptions deterministic;
	deterministic.deterministic = true;
	dist::laplacian_smoothing(dm2, *pos2, 10, deterministic);
	const std::vector<double> spread = gather_on_root(owned_positions(dm2, *pos2));
	bool same = true;
	if (world_rank() == 0)
	{
		Serial one(GetParam());
		for (uint64 g = 0; g < one.cell[0].size(); ++g)
			(*one.pos)[CMap3::Vertex(one.cell[0][g])] += shake(g);
		dist::DistributedCMap3 whole = dist::distribute(MPI_COMM_SELF, &one.m);
		auto p1 = get_attribute<Vec3, CMap3::Vertex>(whole.map(), "position");
		dist::laplacian_smoothing(whole, *p1, 10, deterministic);
		std::map<uint64, Vec3> by_gid;
		foreach_cell(whole.map(), [&](CMap3::Vertex v) { by_gid[dist::global_id(whole, v)] = (*p1)[v]; });
		same = spread.size() == 4 * by_gid.size();
		for (std::size_t i = 0; same && i < spread.size(); i += 4)
		{
			const Vec3& q = by_gid[uint64(spread[i])];
			same = std::memcmp(&spread[i + 1], q.data(), 3 * sizeof(double)) == 0;
		}
	}
	EXPECT_TRUE(everywhere(same));
}

// Grid sides: 3, 12 and 20; the sanitizer runs, 10 times slower, stop at
// CGOGN_DISTRIBUTED_LARGEST_GRID when it is set.
std::vector<uint32> grid_sides()
{
	const char* largest = std::getenv("CGOGN_DISTRIBUTED_LARGEST_GRID");
	std::vector<uint32> sides;
	for (uint32 n : {3u, 12u, 20u})
		if (largest == nullptr || n <= uint32(std::atoi(largest)))
			sides.push_back(n);
	return sides;
}

INSTANTIATE_TEST_SUITE_P(Grids, DistributedTetGrid, ::testing::ValuesIn(grid_sides()));

// A surface: faces are the partitioned cells.
TEST(DistributedSurface, TorusCountsExchangeAndSmoothing)
{
	const SurfaceSoup s = torus_soup(40, 24, true);
	auto build = [&](CMap2& m) {
		const BuildReport r = build_surface(m, s);
		auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	};
	CMap2 serial;
	build(serial);
	dist::DistributedCMap2 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial : nullptr);
	EXPECT_TRUE(everywhere(check_integrity(dm.map()).ok()));
	EXPECT_EQ(dist::global_nb_cells<CMap2::Vertex>(dm), nb_cells<CMap2::Vertex>(serial));
	EXPECT_EQ(dist::global_nb_cells<CMap2::Edge>(dm), nb_cells<CMap2::Edge>(serial));
	EXPECT_EQ(dist::global_nb_cells<CMap2::Face>(dm), nb_cells<CMap2::Face>(serial));
	EXPECT_EQ(dist::global_euler_characteristic(dm), 0);

	auto a = add_attribute<uint64, CMap2::Face>(dm.map(), "id");
	foreach_cell(dm.map(), [&](CMap2::Face f) { (*a)[f] = dist::is_owned(dm, f) ? dist::global_id(dm, f) : 0; });
	dist::exchange(dm, a);
	bool ok = true;
	foreach_cell(dm.map(), [&](CMap2::Face f) { ok = ok && (*a)[f] == dist::global_id(dm, f); });
	EXPECT_TRUE(everywhere(ok));

	dist::SmoothingOptions deterministic;
	deterministic.deterministic = true;
	auto pos = get_attribute<Vec3, CMap2::Vertex>(dm.map(), "position");
	dist::laplacian_smoothing(dm, *pos, 5, deterministic);
	std::vector<double> mine;
	foreach_cell(dm.map(), [&](CMap2::Vertex v) {
		if (dist::is_owned(dm, v))
			mine.insert(mine.end(), {double(dist::global_id(dm, v)), (*pos)[v][0], (*pos)[v][1], (*pos)[v][2]});
	});
	const std::vector<double> spread = gather_on_root(mine);
	bool same = true;
	if (world_rank() == 0)
	{
		CMap2 one;
		build(one);
		dist::DistributedCMap2 whole = dist::distribute(MPI_COMM_SELF, &one);
		auto p1 = get_attribute<Vec3, CMap2::Vertex>(whole.map(), "position");
		dist::laplacian_smoothing(whole, *p1, 5, deterministic);
		std::map<uint64, Vec3> by_gid;
		foreach_cell(whole.map(), [&](CMap2::Vertex v) { by_gid[dist::global_id(whole, v)] = (*p1)[v]; });
		same = spread.size() == 4 * by_gid.size();
		for (std::size_t i = 0; same && i < spread.size(); i += 4)
			same = std::memcmp(&spread[i + 1], by_gid[uint64(spread[i])].data(), 3 * sizeof(double)) == 0;
	}
	EXPECT_TRUE(everywhere(same));
}

} // namespace cgogn_test_distributed_map

namespace cgogn_test_distributed_map
{

// A folder all ranks share, made by rank 0 and removed by the caller's end.
std::filesystem::path shared_folder(const std::string& name)
{
	const std::filesystem::path dir =
		std::filesystem::temp_directory_path() / ("cgogn_" + name + "_" + std::to_string(world_size()));
	if (world_rank() == 0)
	{
		std::filesystem::remove_all(dir);
		std::filesystem::create_directories(dir);
	}
	MPI_Barrier(MPI_COMM_WORLD);
	return dir;
}

// Written with all the ranks, read back on one rank as one mesh and with
// every number of ranks from 1 to all: the same f-vector, and each vertex
// at its serial position (found through the GlobalNodeIds the pieces carry).
TEST(DistributedFiles, PvtuReadsBackWithAnyNumberOfRanks)
{
	Serial serial(6);
	auto temperature = add_attribute<double, CMap3::Vertex>(serial.m, "temperature");
	auto material = add_attribute<int32, CMap3::Volume>(serial.m, "material");
	for (uint64 g = 0; g < serial.cell[0].size(); ++g)
		(*temperature)[CMap3::Vertex(serial.cell[0][g])] = 0.5 * double(g);
	for (uint64 g = 0; g < serial.cell[3].size(); ++g)
		(*material)[CMap3::Volume(serial.cell[3][g])] = int32(g % 7);
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	EXPECT_TRUE(dm.not_carried().empty());
	const std::filesystem::path dir = shared_folder("pvtu");
	const std::string path = (dir / "grid.pvtu").string();
	io::save_pvtu(dm, path);

	bool ok = true;
	if (world_rank() == 0)
	{
		CMap3 whole;
		io::load_volume(whole, path);
		ok = nb_cells<CMap3::Vertex>(whole) == serial.cell[0].size() &&
			 nb_cells<CMap3::Edge>(whole) == serial.cell[1].size() &&
			 nb_cells<CMap3::Face>(whole) == serial.cell[2].size() &&
			 nb_cells<CMap3::Volume>(whole) == serial.cell[3].size();
		auto ids = get_attribute<uint64, CMap3::Vertex>(whole, "GlobalNodeIds");
		auto pos = get_attribute<Vec3, CMap3::Vertex>(whole, "position");
		auto t = get_attribute<double, CMap3::Vertex>(whole, "temperature");
		ok = ok && ids && pos && t && get_attribute<uint8, CMap3::Vertex>(whole, "vtkGhostType") == nullptr;
		if (ok)
			foreach_cell(whole, [&](CMap3::Vertex v) {
				const uint64 g = (*ids)[v];
				ok = ok && g < serial.cell[0].size() && (*pos)[v] == (*serial.pos)[CMap3::Vertex(serial.cell[0][g])] &&
					 (*t)[v] == 0.5 * double(g);
			});
	}
	EXPECT_TRUE(everywhere(ok));

	for (int q = 1; q <= world_size(); ++q)
	{
		MPI_Comm sub;
		MPI_Comm_split(MPI_COMM_WORLD, world_rank() < q ? 0 : MPI_UNDEFINED, world_rank(), &sub);
		bool same = true;
		if (sub != MPI_COMM_NULL)
		{
			{
				dist::DistributedCMap3 back = dist::load_volume(sub, path);
				same = dist::global_nb_cells<CMap3::Vertex>(back) == serial.cell[0].size() &&
					   dist::global_nb_cells<CMap3::Edge>(back) == serial.cell[1].size() &&
					   dist::global_nb_cells<CMap3::Face>(back) == serial.cell[2].size() &&
					   dist::global_nb_cells<CMap3::Volume>(back) == serial.cell[3].size();
				auto ids = get_attribute<uint64, CMap3::Vertex>(back.map(), "GlobalNodeIds");
				auto pos = get_attribute<Vec3, CMap3::Vertex>(back.map(), "position");
				same = same && ids && pos;
				if (same)
					foreach_cell(back.map(), [&](CMap3::Vertex v) {
						same = same && (*pos)[v] == (*serial.pos)[CMap3::Vertex(serial.cell[0][(*ids)[v]])];
					});
				auto m = get_attribute<int32, CMap3::Volume>(back.map(), "material");
				auto cell_ids = get_attribute<uint64, CMap3::Volume>(back.map(), "GlobalCellIds");
				same = same && m && cell_ids;
				if (same)
					foreach_cell(back.map(),
								 [&](CMap3::Volume w) { same = same && (*m)[w] == int32((*cell_ids)[w] % 7); });
			}
			MPI_Comm_free(&sub);
		}
		EXPECT_TRUE(everywhere(same)) << "read back with " << q << " ranks";
	}
	MPI_Barrier(MPI_COMM_WORLD);
	if (world_rank() == 0)
		std::filesystem::remove_all(dir);
}

TEST(DistributedFiles, AttributesOfOtherTypesAreNamed)
{
	Serial serial(3);
	add_attribute<std::string, CMap3::Vertex>(serial.m, "label");
	add_attribute<double, CMap3::Edge>(serial.m, "sharpness");
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &serial.m : nullptr);
	const std::vector<std::string> expected = {"edge attribute 'sharpness'",
											   "vertex attribute 'label' (of a type not carried)"};
	EXPECT_TRUE(everywhere(dm.not_carried() == expected)) << ::testing::PrintToString(dm.not_carried());
	EXPECT_TRUE(everywhere(get_attribute<Vec3, CMap3::Vertex>(dm.map(), "position") != nullptr));
}

} // namespace cgogn_test_distributed_map
