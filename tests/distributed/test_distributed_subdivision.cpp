// SPDX-License-Identifier: MIT
// Distributed volume refinement under mpiexec (1 to 4 ranks): after one or
// two steps every cell has one owner that all its holders agree on, the
// global ids are dense and name the same cell (same vertices, same
// position bits) as a 1-rank refinement of the same grid, the ghost layer is
// again the vertex neighbourhood of the owned volumes, exchange works on the
// new plan, the global counts and measures equal the serial scheme's, and
// volume attributes pass to the children.
#include <cgogn/core.h>
#include <cgogn/distributed/distribute.h>
#include <cgogn/distributed/exchange.h>
#include <cgogn/distributed/reductions.h>
#include <cgogn/distributed/subdivision.h>
#include <cgogn/geometry.h>
#include <cgogn/modeling/subdivision.h>

#include "mpi_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace cgogn_test_distributed_subdivision
{

using namespace cgogn;
using namespace cgogn_test_mpi;
using Vertex = CMap3::Vertex;
using Edge = CMap3::Edge;
using Face = CMap3::Face;
using Volume = CMap3::Volume;

/// A tet or hex grid of side n with positions.
struct Grid
{
	CMap3 m;
	std::shared_ptr<CellAttribute<Vec3, Vertex::ORBIT>> pos;

	/// With `rotated`, each tetrahedron is listed from another corner (b, c,
	/// a, d for a, b, c, d): the same mesh, stored from other darts.
	Grid(bool hex, uint32 n, bool rotated = false)
	{
		VolumeSoup s = hex ? hex_grid_soup(n, n, n) : tet_grid_soup(n, n, n);
		if (rotated && !hex)
			for (std::size_t i = 0; i + 3 < s.cell_vertices.size(); i += 4)
				std::rotate(s.cell_vertices.begin() + long(i), s.cell_vertices.begin() + long(i) + 1,
							s.cell_vertices.begin() + long(i) + 3);
		const BuildReport r = build_volume(m, s);
		pos = add_attribute<Vec3, Vertex>(m, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	}
};

struct Case
{
	bool hex;
	uint32 n;
	uint32 steps;
};

void refine(dist::DistributedCMap3& dm, bool hex)
{
	if (hex)
		dist::hex_subdivision(dm);
	else
		dist::tet_subdivision(dm);
}

/// The sorted vertex ids of each cell of type CELL, by global id.
template <typename CELL>
std::map<uint64, std::vector<uint64>> vertices_by_gid(const dist::DistributedCMap3& dm)
{
	std::map<uint64, std::vector<uint64>> cells;
	foreach_cell(dm.map(), [&](CELL c) {
		std::vector<uint64>& v = cells[dist::global_id(dm, c)];
		foreach_incident_vertex(dm.map(), c, [&](Vertex x) { v.push_back(dist::global_id(dm, x)); });
		std::sort(v.begin(), v.end());
	});
	return cells;
}

/// Every cell of type CELL of dm is the reference's cell of the same id.
template <typename CELL>
bool same_cells(const dist::DistributedCMap3& dm, const dist::DistributedCMap3& ref)
{
	const auto mine = vertices_by_gid<CELL>(dm), theirs = vertices_by_gid<CELL>(ref);
	for (const auto& [gid, vertices] : mine)
		if (const auto it = theirs.find(gid); it == theirs.end() || it->second != vertices)
			return false;
	return true;
}

/// Every id of dimension k below `count` is owned by exactly one rank, and
/// every rank holding a cell names that rank. Collective.
template <typename CELL>
bool owned_once_and_agreed(const dist::DistributedCMap3& dm, uint64 count)
{
	std::vector<uint64> owned, pairs;
	foreach_cell(dm.map(), [&](CELL c) {
		if (dist::is_owned(dm, c))
			owned.push_back(dist::global_id(dm, c));
		pairs.push_back(dist::global_id(dm, c));
		pairs.push_back(uint64(dist::owner(dm, c)));
	});
	const std::vector<uint64> all_owned = gather_on_root(owned);
	std::vector<uint64> counts = gather_on_root(std::vector<uint64>{owned.size()});
	const std::vector<uint64> all_pairs = gather_on_root(pairs);
	bool ok = true;
	if (world_rank() == 0)
	{
		ok = all_owned.size() == count;
		std::vector<int64> owner_of(count, -1);
		std::size_t at = 0;
		for (std::size_t r = 0; ok && r < counts.size(); ++r)
			for (uint64 i = 0; ok && i < counts[r]; ++i, ++at)
			{
				ok = all_owned[at] < count && owner_of[all_owned[at]] == -1;
				if (ok)
					owner_of[all_owned[at]] = int64(r);
			}
		for (std::size_t i = 0; ok && i < all_pairs.size(); i += 2)
			ok = all_pairs[i] < count && owner_of[all_pairs[i]] == int64(all_pairs[i + 1]);
	}
	return everywhere(ok);
}

/// Volume w as its corner positions (rounded to 1e-9), sorted.
std::vector<double> shape(const CMap3& m, const AttributeArray<Vec3>& pos, Volume w)
{
	std::vector<std::array<double, 3>> corners;
	foreach_incident_vertex(m, w, [&](Vertex v) {
		corners.push_back(
			{std::round(pos[v][0] * 1e9) / 1e9, std::round(pos[v][1] * 1e9) / 1e9, std::round(pos[v][2] * 1e9) / 1e9});
	});
	std::sort(corners.begin(), corners.end());
	std::vector<double> flat;
	for (const auto& c : corners)
		flat.insert(flat.end(), c.begin(), c.end());
	return flat;
}

/// The shapes of the volumes of a serial map, sorted.
std::vector<std::vector<double>> volume_shapes(const CMap3& m, const AttributeArray<Vec3>& pos)
{
	std::vector<std::vector<double>> shapes;
	foreach_cell(m, [&](Volume w) { shapes.push_back(shape(m, pos, w)); });
	std::sort(shapes.begin(), shapes.end());
	return shapes;
}

/// The shapes of the owned volumes of all ranks, sorted, on rank 0.
std::vector<std::vector<double>> owned_volume_shapes(const dist::DistributedCMap3& dm)
{
	auto pos = get_attribute<Vec3, Vertex>(dm.map(), "position");
	std::vector<double> flat;
	uint32 size = 0;
	foreach_cell(dm.map(), [&](Volume w) {
		if (!dist::is_owned(dm, w))
			return;
		const std::vector<double> s = shape(dm.map(), *pos, w);
		size = uint32(s.size());
		flat.insert(flat.end(), s.begin(), s.end());
	});
	MPI_Allreduce(MPI_IN_PLACE, &size, 1, MPI_UINT32_T, MPI_MAX, dm.comm());
	const std::vector<double> all = gather_on_root(flat);
	std::vector<std::vector<double>> shapes;
	for (std::size_t i = 0; size != 0 && i < all.size(); i += size)
		shapes.emplace_back(all.begin() + long(i), all.begin() + long(i + size));
	std::sort(shapes.begin(), shapes.end());
	return shapes;
}

class DistributedRefinement : public ::testing::TestWithParam<Case>
{
};

TEST_P(DistributedRefinement, IdsOwnersAndGhostsAreThoseOfOneRank)
{
	const Case c = GetParam();
	Grid root(c.hex, c.n);
	auto parent = add_attribute<int64, Volume>(root.m, "parent");
	foreach_cell(root.m, [&](Volume w) { (*parent)[w] = -1; });
	add_attribute<double, Vertex>(root.m, "weight");
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &root.m : nullptr);
	// each volume names itself, so that its children can be checked
	{
		auto p = get_attribute<int64, Volume>(dm.map(), "parent");
		foreach_cell(dm.map(), [&](Volume w) { (*p)[w] = int64(dist::global_id(dm, w)); });
	}
	// the same grid refined on one rank
	Grid local(c.hex, c.n);
	dist::DistributedCMap3 ref = dist::distribute(MPI_COMM_SELF, &local.m);
	// and by the serial scheme
	Grid serial(c.hex, c.n);
	for (uint32 s = 0; s < c.steps; ++s)
	{
		refine(dm, c.hex);
		refine(ref, c.hex);
		if (c.hex)
			modeling::hex_subdivision(serial.m, *serial.pos);
		else
			modeling::tet_subdivision(serial.m, *serial.pos);
	}
	const CMap3& m = dm.map();
	EXPECT_TRUE(everywhere(check_integrity(m).ok()));

	// global ids: dense, owned once, agreed on
	EXPECT_TRUE(owned_once_and_agreed<Vertex>(dm, nb_cells<Vertex>(serial.m)));
	EXPECT_TRUE(owned_once_and_agreed<Edge>(dm, nb_cells<Edge>(serial.m)));
	EXPECT_TRUE(owned_once_and_agreed<Face>(dm, nb_cells<Face>(serial.m)));
	EXPECT_TRUE(owned_once_and_agreed<Volume>(dm, nb_cells<Volume>(serial.m)));

	// the same cells and position bits as one rank
	EXPECT_TRUE(everywhere(same_cells<Edge>(dm, ref)));
	EXPECT_TRUE(everywhere(same_cells<Face>(dm, ref)));
	EXPECT_TRUE(everywhere(same_cells<Volume>(dm, ref)));
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	auto ref_pos = get_attribute<Vec3, Vertex>(ref.map(), "position");
	ASSERT_NE(pos, nullptr);
	std::map<uint64, Vec3> ref_positions;
	foreach_cell(ref.map(), [&](Vertex v) { ref_positions[dist::global_id(ref, v)] = (*ref_pos)[v]; });
	bool same_positions = true;
	foreach_cell(
		m, [&](Vertex v) { same_positions = same_positions && ref_positions[dist::global_id(dm, v)] == (*pos)[v]; });
	EXPECT_TRUE(everywhere(same_positions));

	// the ghost layer: the vertex neighbourhood of the owned volumes, whole
	std::map<uint64, Dart> ref_faces, ref_vertices;
	foreach_cell(ref.map(), [&](Face f) { ref_faces[dist::global_id(ref, f)] = f.dart; });
	foreach_cell(ref.map(), [&](Vertex v) { ref_vertices[dist::global_id(ref, v)] = v.dart; });
	std::vector<uint8> near_owned(container_of<Vertex::ORBIT>(m).end_index(), 0);
	bool faces_ok = true, degrees_ok = true, needed_ok = true;
	foreach_cell(m, [&](Volume w) {
		if (!dist::is_owned(dm, w))
			return;
		foreach_dart_of_orbit(m, w, [&](Dart d) {
			if (is_boundary(m, phi3(m, d)))
			{
				const Dart r = ref_faces[dist::global_id(dm, Face(d))];
				faces_ok = faces_ok && (is_boundary(ref.map(), r) || is_boundary(ref.map(), phi3(ref.map(), r)));
			}
			near_owned[index_of(m, Vertex(d))] = 1;
		});
	});
	foreach_cell(m, [&](Vertex v) {
		if (!near_owned[index_of(m, v)])
			return;
		uint32 here = 0, there = 0;
		foreach_incident_volume(m, v, [&](Volume) { ++here; });
		foreach_incident_volume(ref.map(), Vertex(ref_vertices[dist::global_id(dm, v)]), [&](Volume) { ++there; });
		degrees_ok = degrees_ok && here == there;
	});
	foreach_cell(m, [&](Volume w) {
		bool touches = false;
		foreach_incident_vertex(m, w, [&](Vertex v) { touches = touches || near_owned[index_of(m, v)]; });
		needed_ok = needed_ok && touches;
	});
	EXPECT_TRUE(everywhere(faces_ok));
	EXPECT_TRUE(everywhere(degrees_ok));
	EXPECT_TRUE(everywhere(needed_ok));

	// the children carry their parent's value (8 children per volume per step)
	auto p = get_attribute<int64, Volume>(m, "parent");
	ASSERT_NE(p, nullptr);
	uint64 per_parent = 1;
	for (uint32 s = 0; s < c.steps; ++s)
		per_parent *= 8;
	bool parents_ok = true;
	foreach_cell(m,
				 [&](Volume w) { parents_ok = parents_ok && uint64((*p)[w]) == dist::global_id(dm, w) / per_parent; });
	EXPECT_TRUE(everywhere(parents_ok));
	const auto& named = dm.not_carried();
	EXPECT_NE(std::find(named.begin(), named.end(), "vertex attribute 'weight' (no value for the new vertices)"),
			  named.end());

	// exchange on the new halo plan
	auto probe = add_attribute<uint64, Face>(dm.map(), "probe");
	foreach_cell(m, [&](Face f) { (*probe)[f] = dist::is_owned(dm, f) ? 3 * dist::global_id(dm, f) + 1 : 0; });
	dist::exchange(dm, *probe);
	bool exchanged = true;
	foreach_cell(m, [&](Face f) { exchanged = exchanged && (*probe)[f] == 3 * dist::global_id(dm, f) + 1; });
	EXPECT_TRUE(everywhere(exchanged));

	// global counts and measures of the serial scheme
	EXPECT_EQ(dist::global_nb_cells<Vertex>(dm), nb_cells<Vertex>(serial.m));
	EXPECT_EQ(dist::global_nb_cells<Edge>(dm), nb_cells<Edge>(serial.m));
	EXPECT_EQ(dist::global_nb_cells<Face>(dm), nb_cells<Face>(serial.m));
	EXPECT_EQ(dist::global_nb_cells<Volume>(dm), nb_cells<Volume>(serial.m));
	EXPECT_EQ(dist::global_euler_characteristic(dm), euler_characteristic(serial.m));
	const double n = c.n;
	const double volume = dist::global_sum_of<Volume>(dm, [&](Volume w) { return geometry::volume(m, w, *pos); });
	EXPECT_NEAR(volume, n * n * n, 1e-12 * n * n * n);
	const double area = dist::global_sum_of<Face>(dm, [&](Face f) {
		const Dart d = is_boundary(m, f.dart) ? phi3(m, f.dart) : f.dart;
		return is_boundary(m, phi3(m, d)) ? geometry::face_area(m, f, *pos) : 0.0;
	});
	EXPECT_NEAR(area, 6 * n * n, 1e-12 * n * n);
	// the serial scheme's cells, at the same places (within rounding)
	const auto shapes = owned_volume_shapes(dm);
	EXPECT_TRUE(everywhere(world_rank() != 0 || shapes == volume_shapes(serial.m, *serial.pos)));
}

INSTANTIATE_TEST_SUITE_P(Schemes, DistributedRefinement,
						 ::testing::Values(Case{false, 3, 1}, Case{false, 4, 2}, Case{true, 3, 1}, Case{true, 2, 2}));

// The octahedron of a grid tetrahedron has two diagonals of the same
// length: each rank must cut a ghost as its owner, whatever dart the local
// map stores it from, so the cut cannot depend on the storage.
TEST(DistributedRefinementTies, CutDoesNotDependOnHowTetrahedraAreStored)
{
	Grid root(false, 3), rotated(false, 3, true);
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &root.m : nullptr);
	dist::DistributedCMap3 other = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &rotated.m : nullptr);
	dist::tet_subdivision(dm);
	dist::tet_subdivision(other);
	const auto a = owned_volume_shapes(dm), b = owned_volume_shapes(other);
	EXPECT_TRUE(everywhere(world_rank() != 0 || (a.size() == 8 * 162 && a == b)));
}

TEST(DistributedRefinementErrors, WrongCellsOrNoPositionsThrowOnEveryRankAndKeepTheMap)
{
	Grid root(false, 3);
	dist::DistributedCMap3 dm = dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &root.m : nullptr);
	const uint64 volumes = dist::global_nb_cells<Volume>(dm);
	EXPECT_THROW(dist::hex_subdivision(dm), modeling::SubdivisionError);
	EXPECT_THROW(dist::tet_subdivision(dm, "no such attribute"), std::invalid_argument);
	EXPECT_EQ(dist::global_nb_cells<Volume>(dm), volumes);
	EXPECT_TRUE(everywhere(check_integrity(dm.map()).ok()));
}

} // namespace cgogn_test_distributed_subdivision
