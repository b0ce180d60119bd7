// SPDX-License-Identifier: MIT
// The DMPlex bridge under mpiexec (1 to 4 ranks): on tet and hex grids,
// prism columns, a mesh of every kind of volume, a real tetrahedral mesh and
// surfaces, PETSc's DMPlexCheck passes; each local cell is one plex point of
// its dimension (the rim's copies of a cell are one), at its position; the
// star forest's roots are the cgogn owners; DMGlobalToLocal moves the same
// values as exchange(), for vertices alone and for every dimension; and
// unsupported cells, a non-conforming mesh or a missing position are
// refused on every rank.
#include <cgogn/core.h>
#include <cgogn/distributed/distribute.h>
#include <cgogn/distributed/dmplex.h>
#include <cgogn/distributed/exchange.h>
#include <cgogn/distributed/reductions.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io/volume.h>

#include "cgogn_test_data.h"
#include "mpi_test_utils.h"

#include <gtest/gtest.h>

#include <map>
#include <petscsf.h>
#include <set>
#include <string>
#include <vector>

namespace cgogn_test_dmplex
{

using namespace cgogn;
using namespace cgogn_test_mpi;

/// The positions of a soup on the vertices its builder made.
template <typename MAP, typename SOUP>
void set_positions(MAP& m, const SOUP& s, const BuildReport& r)
{
	auto pos = add_attribute<Vec3, typename MAP::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
}

/// Each line's cell is one plex point of its depth, lines of the same
/// global id share it and lines of different ids do not, and each vertex
/// point has the vertex's position as coordinates.
template <typename MAP>
bool points_are_the_local_cells(const dist::DistributedMap<MAP>& dm, const dist::PlexMesh& pm)
{
	bool ok = true;
	const MAP& m = dm.map();
	for (uint32 k = 0; k <= MAP::dimension; ++k)
	{
		PetscInt start = 0, end = 0;
		DMPlexGetDepthStratum(pm.dm(), PetscInt(k), &start, &end);
		std::map<uint64, PetscInt> point_of_gid;
		std::set<PetscInt> used;
		dist::detail::foreach_cell_type<MAP>([&](auto cell, uint32 dim) {
			if (dim != k)
				return;
			foreach_cell(m, [&](decltype(cell) c) {
				const PetscInt p = dist::plex_point(pm, dm, c);
				const auto [it, inserted] = point_of_gid.emplace(dist::global_id(dm, c), p);
				ok = ok && p >= start && p < end && it->second == p;
				used.insert(p);
			});
		});
		ok = ok && used.size() == point_of_gid.size() && PetscInt(used.size()) == end - start;
	}
	Vec coordinates = nullptr;
	DMGetCoordinatesLocal(pm.dm(), &coordinates);
	PetscSection section = nullptr;
	DMGetCoordinateSection(pm.dm(), &section);
	const PetscScalar* x = nullptr;
	VecGetArrayRead(coordinates, &x);
	auto pos = get_attribute<Vec3, typename MAP::Vertex>(m, "position");
	foreach_cell(m, [&](typename MAP::Vertex v) {
		PetscInt offset = 0;
		PetscSectionGetOffset(section, dist::plex_point(pm, dm, v), &offset);
		for (uint32 i = 0; i < 3; ++i)
			ok = ok && x[offset + PetscInt(i)] == (*pos)[v][i];
	});
	VecRestoreArrayRead(coordinates, &x);
	return ok;
}

/// The star forest's leaves are exactly the ghost cells, rooted at their
/// owners.
template <typename MAP>
bool roots_are_the_owners(const dist::DistributedMap<MAP>& dm, const dist::PlexMesh& pm)
{
	PetscSF sf = nullptr;
	DMGetPointSF(pm.dm(), &sf);
	PetscInt nb_roots = 0, nb_leaves = 0;
	const PetscInt* leaves = nullptr;
	const PetscSFNode* remotes = nullptr;
	PetscSFGetGraph(sf, &nb_roots, &nb_leaves, &leaves, &remotes);
	std::map<PetscInt, PetscInt> root_rank;
	for (PetscInt i = 0; i < nb_leaves; ++i)
		root_rank[leaves ? leaves[i] : i] = remotes[i].rank;
	bool ok = true;
	std::set<PetscInt> ghosts;
	dist::detail::foreach_cell_type<MAP>([&](auto cell, uint32) {
		foreach_cell(dm.map(), [&](decltype(cell) c) {
			const PetscInt p = dist::plex_point(pm, dm, c);
			const auto it = root_rank.find(p);
			if (dist::is_owned(dm, c))
				ok = ok && it == root_rank.end();
			else
			{
				ok = ok && it != root_rank.end() && it->second == dist::owner(dm, c);
				ghosts.insert(p);
			}
		});
	});
	return ok && ghosts.size() == root_rank.size();
}

/// With one value on each point of the dimensions `dims`, a global vector
/// holding f(dimension, global id) on the owned cells, moved by
/// DMGlobalToLocal, gives every local cell the value exchange() gives it.
/// The global vector's size is the global number of those cells.
template <typename MAP>
bool global_to_local_is_exchange(const dist::DistributedMap<MAP>& dm, const dist::PlexMesh& pm,
								 const std::vector<uint32>& dims)
{
	DM plex = nullptr;
	DMClone(pm.dm(), &plex);
	PetscInt chart_start = 0, chart_end = 0;
	DMPlexGetChart(plex, &chart_start, &chart_end);
	PetscSection local_section = nullptr;
	PetscSectionCreate(dm.comm(), &local_section);
	PetscSectionSetChart(local_section, chart_start, chart_end);
	uint64 global_count = 0;
	for (uint32 k : dims)
	{
		PetscInt start = 0, end = 0;
		DMPlexGetDepthStratum(plex, PetscInt(k), &start, &end);
		for (PetscInt p = start; p < end; ++p)
			PetscSectionSetDof(local_section, p, 1);
		dist::detail::foreach_cell_type<MAP>([&](auto cell, uint32 dim) {
			if (dim == k)
				global_count += dist::global_nb_cells<decltype(cell)>(dm);
		});
	}
	PetscSectionSetUp(local_section);
	DMSetLocalSection(plex, local_section);
	PetscSectionDestroy(&local_section);
	PetscSection global_section = nullptr;
	DMGetGlobalSection(plex, &global_section);

	auto f = [](uint32 k, uint64 gid) { return double(gid) * 4.0 + double(k) + 0.5; };
	Vec global = nullptr, local = nullptr;
	DMCreateGlobalVector(plex, &global);
	DMCreateLocalVector(plex, &local);
	PetscInt size = 0, first = 0, last = 0;
	VecGetSize(global, &size);
	VecGetOwnershipRange(global, &first, &last);
	PetscScalar* g = nullptr;
	VecGetArray(global, &g);
	bool ok = uint64(size) == global_count;
	dist::detail::foreach_cell_type<MAP>([&](auto cell, uint32 k) {
		if (std::find(dims.begin(), dims.end(), k) == dims.end())
			return;
		foreach_cell(dm.map(), [&](decltype(cell) c) {
			PetscInt offset = 0;
			PetscSectionGetOffset(global_section, dist::plex_point(pm, dm, c), &offset);
			// owned points have their place in this rank's range, ghosts -(place + 1)
			ok = ok && (offset >= 0) == dist::is_owned(dm, c);
			if (offset >= 0 && offset >= first && offset < last)
				g[offset - first] = f(k, dist::global_id(dm, c));
		});
	});
	VecRestoreArray(global, &g);
	VecSet(local, -1.0);
	ok = DMGlobalToLocal(plex, global, INSERT_VALUES, local) == 0 && ok;

	PetscSection section = nullptr;
	DMGetLocalSection(plex, &section);
	const PetscScalar* l = nullptr;
	VecGetArrayRead(local, &l);
	dist::detail::foreach_cell_type<MAP>([&](auto cell, uint32 k) {
		if (std::find(dims.begin(), dims.end(), k) == dims.end())
			return;
		std::vector<double> values(container_of<decltype(cell)::ORBIT>(dm.map()).end_index(), -2.0);
		foreach_cell(dm.map(), [&](decltype(cell) c) {
			if (dist::is_owned(dm, c))
				values[index_of(dm.map(), c)] = f(k, dist::global_id(dm, c));
		});
		dist::exchange_lines(dm, k, values);
		foreach_cell(dm.map(), [&](decltype(cell) c) {
			PetscInt offset = 0;
			PetscSectionGetOffset(section, dist::plex_point(pm, dm, c), &offset);
			ok = ok && l[offset] == values[index_of(dm.map(), c)] &&
				 values[index_of(dm.map(), c)] == f(k, dist::global_id(dm, c));
		});
	});
	VecRestoreArrayRead(local, &l);
	VecDestroy(&global);
	VecDestroy(&local);
	DMDestroy(&plex);
	return ok;
}

/// Everything the bridge promises, on every rank.
template <typename MAP>
void expect_plex_of(const dist::DistributedMap<MAP>& dm)
{
	const dist::PlexMesh pm = dist::to_dmplex(dm);
	ASSERT_NE(pm.dm(), nullptr);
	PetscInt dimension = 0;
	DMGetDimension(pm.dm(), &dimension);
	EXPECT_EQ(dimension, PetscInt(MAP::dimension));
	PetscInt overlap = 0;
	DMPlexGetOverlap(pm.dm(), &overlap);
	EXPECT_EQ(overlap, 1);
	EXPECT_TRUE(everywhere(DMPlexCheck(pm.dm()) == 0));
	EXPECT_TRUE(everywhere(points_are_the_local_cells(dm, pm)));
	EXPECT_TRUE(everywhere(roots_are_the_owners(dm, pm)));
	EXPECT_TRUE(everywhere(global_to_local_is_exchange(dm, pm, {0})));
	std::vector<uint32> all;
	for (uint32 k = 0; k <= MAP::dimension; ++k)
		all.push_back(k);
	EXPECT_TRUE(everywhere(global_to_local_is_exchange(dm, pm, all)));
}

dist::DistributedCMap3 distributed(const VolumeSoup& s)
{
	CMap3 m;
	if (world_rank() == 0)
		set_positions(m, s, build_volume(m, s));
	return dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &m : nullptr);
}

dist::DistributedCMap3 distributed(const PolyhedronSoup& s)
{
	CMap3 m;
	if (world_rank() == 0)
		set_positions(m, s, build_polyhedra(m, s));
	return dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &m : nullptr);
}

dist::DistributedCMap2 distributed(const SurfaceSoup& s)
{
	CMap2 m;
	if (world_rank() == 0)
		set_positions(m, s, build_surface(m, s));
	return dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &m : nullptr);
}

dist::DistributedCMap3 distributed_file(const std::string& name)
{
	CMap3 m;
	if (world_rank() == 0)
		io::load_volume(m, cgogn_test_data::path(name));
	return dist::distribute(MPI_COMM_WORLD, world_rank() == 0 ? &m : nullptr);
}

TEST(DMPlex, TetGrid)
{
	const dist::DistributedCMap3 dm = distributed(tet_grid_soup(5, 4, 3));
	expect_plex_of(dm);
	// the DM moves with its owner, and release() hands it over
	dist::PlexMesh a = dist::to_dmplex(dm);
	const DM plex = a.dm();
	dist::PlexMesh b = std::move(a);
	EXPECT_EQ(a.dm(), nullptr);
	EXPECT_EQ(b.dm(), plex);
	EXPECT_FALSE(b.points(0).empty());
	DM released = b.release();
	EXPECT_EQ(released, plex);
	EXPECT_EQ(b.dm(), nullptr);
	EXPECT_EQ(DMDestroy(&released), 0);
}

TEST(DMPlex, HexGrid)
{
	expect_plex_of(distributed(hex_grid_soup(4, 3, 3)));
}

TEST(DMPlex, PrismColumns)
{
	expect_plex_of(distributed(prism_column_soup(3, 8)));
	expect_plex_of(distributed(prism_column_soup(4, 8)));
}

TEST(DMPlex, RealTetrahedralMesh)
{
	expect_plex_of(distributed_file("volume/armadillo_tet_4k.mesh"));
}

/// A hexahedron, a cube cut into six pyramids beside it, a prism lying on
/// the hexahedron and a tetrahedron on the prism's end: every kind of volume
/// DMPlex has, glued face to face.
VolumeSoup mixed_soup()
{
	VolumeSoup s;
	s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1},     {1, 0, 1},  {1, 1, 1},  {0, 1, 1},
				   {2, 0, 0}, {2, 1, 0}, {2, 0, 1}, {2, 1, 1}, {1.5, .5, .5}, {.5, 0, 2}, {.5, 1, 2}, {.5, -1, 1.5}};
	s.nb_vertices = uint32(s.positions.size());
	auto add = [&](std::vector<uint32> cell) {
		s.cell_sizes.push_back(uint32(cell.size()));
		s.cell_vertices.insert(s.cell_vertices.end(), cell.begin(), cell.end());
	};
	add({0, 1, 2, 3, 4, 5, 6, 7});
	// each face of the cube [1, 2] x [0, 1]^2 turned towards its centre 12
	for (std::vector<uint32> base :
		 {std::vector<uint32>{1, 2, 6, 5}, {8, 10, 11, 9}, {1, 5, 10, 8}, {2, 9, 11, 6}, {1, 8, 9, 2}, {5, 6, 11, 10}})
	{
		base.push_back(12);
		add(base);
	}
	add({4, 13, 5, 7, 14, 6});
	add({4, 5, 13, 15});
	return s;
}

TEST(DMPlex, EveryKindOfVolume)
{
	expect_plex_of(distributed(mixed_soup()));
}

// Faces of hexahedra meet pairs of tetrahedron faces: an edge of the map on
// the vertices of another, which DMPlex cannot hold apart
TEST(DMPlex, RefusesNonConformingMeshOnEveryRank)
{
	dist::DistributedCMap3 dm = distributed_file("volume/hex_dominant_11k.mesh");
	EXPECT_THROW(dist::to_dmplex(dm), std::invalid_argument);
}

TEST(DMPlex, Surfaces)
{
	expect_plex_of(distributed(torus_soup(24, 16, true)));
	expect_plex_of(distributed(torus_soup(24, 16, false)));
	expect_plex_of(distributed(sphere_soup(24, 12, false)));
}

TEST(DMPlex, RefusesOtherCellsAndMissingPositionsOnEveryRank)
{
	dist::DistributedCMap3 hexagonal = distributed(prism_column_soup(6, 8));
	EXPECT_THROW(dist::to_dmplex(hexagonal), std::invalid_argument);
	dist::DistributedCMap3 grid = distributed(tet_grid_soup(3, 3, 3));
	EXPECT_THROW(dist::to_dmplex(grid, "no_such_attribute"), std::invalid_argument);
	// the map stays usable
	EXPECT_NO_THROW(dist::to_dmplex(grid));
}

} // namespace cgogn_test_dmplex
