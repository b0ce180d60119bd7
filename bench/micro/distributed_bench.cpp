// SPDX-License-Identifier: MIT
// The distributed layer under mpiexec: partition and distribution of a tet
// grid, one halo exchange of the positions, ten Jacobi smoothing steps, and
// one tetrahedral refinement beside the serial one, and (with the DMPlex
// bridge) the conversion of each rank's part to a PETSc DMPlex.
// Every rank runs the same fixed number of iterations (collectives inside
// keep them in step); each iteration's time is the slowest rank's, and
// rank 0 reports. Counters: tetrahedra owned per rank, ghost tetrahedra per
// rank, and the halo bytes of one Vec3 vertex exchange (largest rank)
// beside the surface law (N/P)^(2/3), and the local map's bytes per owned
// tetrahedron (largest rank).
//   mpiexec -n P bench_distributed [--benchmark_filter=...]
// Sizes: n = 56 (1,053,696 tetrahedra) for the strong scaling; n = 35, 44,
// 50, 55 for about 2.5e5 tetrahedra per rank on 1, 2, 3, 4 ranks; n = 28
// (131,712 tetrahedra, 1,053,696 after) for the refinement; n = 56 for the
// DMPlex.
#include <cgogn/core.h>
#include <cgogn/distributed/distribute.h>
#include <cgogn/distributed/exchange.h>
#include <cgogn/distributed/smoothing.h>
#include <cgogn/distributed/subdivision.h>
#include <cgogn/modeling/subdivision.h>

#ifdef CGOGN_BENCH_DMPLEX
#include <cgogn/distributed/dmplex.h>
#endif

#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <memory>

namespace
{

using namespace cgogn;

int rank()
{
	int r = 0;
	MPI_Comm_rank(MPI_COMM_WORLD, &r);
	return r;
}

int nb_ranks()
{
	int p = 1;
	MPI_Comm_size(MPI_COMM_WORLD, &p);
	return p;
}

// The tet grid of side n, with positions, on rank 0 only.
std::unique_ptr<CMap3> grid_on_root(uint32 n)
{
	auto m = std::make_unique<CMap3>();
	if (rank() != 0)
		return m;
	const VolumeSoup s = tet_grid_soup(n, n, n);
	const BuildReport r = build_volume(*m, s);
	auto pos = add_attribute<Vec3, CMap3::Vertex>(*m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return m;
}

// The slowest rank's time of f, in seconds.
template <typename F>
double slowest(const F& f)
{
	MPI_Barrier(MPI_COMM_WORLD);
	const auto start = std::chrono::steady_clock::now();
	f();
	const double mine = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
	double worst = 0;
	MPI_Allreduce(&mine, &worst, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
	return worst;
}

void spread_counters(benchmark::State& state, const dist::DistributedCMap3& dm, uint32 n)
{
	uint64 mine[3] = {0, 0, 0}; // owned, ghost tetrahedra, halo bytes received
	foreach_cell(dm.map(), [&](CMap3::Volume w) { ++mine[dist::is_owned(dm, w) ? 0 : 1]; });
	for (int c : dm.plan(0).recv_counts)
		mine[2] += uint64(c) * sizeof(Vec3);
	uint64 largest[3] = {0, 0, 0};
	MPI_Allreduce(mine, largest, 3, MPI_UINT64_T, MPI_MAX, MPI_COMM_WORLD);
	// the local map's memory (darts, cells, attributes, ids, owners) per owned tetrahedron
	const CMap3& m = dm.map();
	const double bytes =
		double(container_of<Orbit::DART>(m).memory_bytes() + container_of<CMap3::Vertex::ORBIT>(m).memory_bytes() +
			   container_of<CMap3::Edge::ORBIT>(m).memory_bytes() + container_of<CMap3::Face::ORBIT>(m).memory_bytes() +
			   container_of<CMap3::Volume::ORBIT>(m).memory_bytes()) /
		double(mine[0]);
	double most = 0;
	MPI_Allreduce(&bytes, &most, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
	state.counters["bytes_per_owned_tet"] = most;
	const double tets = 6.0 * n * n * n;
	state.counters["ranks"] = nb_ranks();
	state.counters["owned_tets_max"] = double(largest[0]);
	state.counters["ghost_tets_max"] = double(largest[1]);
	state.counters["halo_bytes_max"] = double(largest[2]);
	state.counters["surface_law"] = std::pow(tets / nb_ranks(), 2.0 / 3.0);
}

void BM_PartitionAndDistribute(benchmark::State& state)
{
	const uint32 n = uint32(state.range(0));
	auto serial = grid_on_root(n);
	dist::DistributedCMap3 dm;
	for (auto _ : state)
		state.SetIterationTime(
			slowest([&] { dm = dist::distribute(MPI_COMM_WORLD, rank() == 0 ? serial.get() : nullptr); }));
	spread_counters(state, dm, n);
}

// The tet grid of side n spread over the ranks, the root's map freed.
dist::DistributedCMap3 spread_grid(uint32 n)
{
	auto serial = grid_on_root(n);
	return dist::distribute(MPI_COMM_WORLD, rank() == 0 ? serial.get() : nullptr);
}

void BM_ExchangePositions(benchmark::State& state)
{
	dist::DistributedCMap3 dm = spread_grid(uint32(state.range(0)));
	auto pos = get_attribute<Vec3, CMap3::Vertex>(dm.map(), "position");
	for (auto _ : state)
		state.SetIterationTime(slowest([&] { dist::exchange(dm, *pos); }));
	spread_counters(state, dm, uint32(state.range(0)));
}

void BM_TenSmoothingSteps(benchmark::State& state)
{
	dist::DistributedCMap3 dm = spread_grid(uint32(state.range(0)));
	auto pos = get_attribute<Vec3, CMap3::Vertex>(dm.map(), "position");
	for (auto _ : state)
		state.SetIterationTime(slowest([&] { dist::laplacian_smoothing(dm, *pos, 10); }));
	spread_counters(state, dm, uint32(state.range(0)));
}

// One step of dist::tet_subdivision (the map spread again before each).
void BM_TetSubdivision(benchmark::State& state)
{
	dist::DistributedCMap3 dm;
	for (auto _ : state)
	{
		dm = spread_grid(uint32(state.range(0)));
		state.SetIterationTime(slowest([&] { dist::tet_subdivision(dm); }));
	}
	spread_counters(state, dm, 2 * uint32(state.range(0)));
}

// The serial modeling::tet_subdivision of the same grid on rank 0.
void BM_SerialTetSubdivision(benchmark::State& state)
{
	for (auto _ : state)
	{
		auto serial = grid_on_root(uint32(state.range(0)));
		state.SetIterationTime(slowest([&] {
			if (rank() == 0)
				modeling::tet_subdivision(*serial, *get_attribute<Vec3, CMap3::Vertex>(*serial, "position"));
		}));
	}
}

#ifdef CGOGN_BENCH_DMPLEX
// dist::to_dmplex on the distributed grid: the DMPlex of each rank's part.
void BM_ToDMPlex(benchmark::State& state)
{
	dist::DistributedCMap3 dm = spread_grid(uint32(state.range(0)));
	for (auto _ : state)
	{
		dist::PlexMesh plex;
		state.SetIterationTime(slowest([&] { plex = dist::to_dmplex(dm); }));
	}
	spread_counters(state, dm, uint32(state.range(0)));
}
BENCHMARK(BM_ToDMPlex)->Arg(56)->Iterations(2)->UseManualTime()->Unit(benchmark::kMillisecond);
#endif

BENCHMARK(BM_PartitionAndDistribute)->Arg(56)->Iterations(1)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ExchangePositions)->Arg(56)->Iterations(20)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TenSmoothingSteps)
	->Arg(56)
	->Arg(35)
	->Arg(44)
	->Arg(50)
	->Arg(55)
	->Iterations(3)
	->UseManualTime()
	->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TetSubdivision)->Arg(28)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SerialTetSubdivision)->Arg(28)->Iterations(3)->UseManualTime()->Unit(benchmark::kMillisecond);

// Ranks other than 0 run the same benchmarks and report nothing.
class Silent : public benchmark::BenchmarkReporter
{
public:
	bool ReportContext(const Context&) override
	{
		return true;
	}
	void ReportRuns(const std::vector<Run>&) override
	{
	}
};

} // namespace

int main(int argc, char** argv)
{
	int provided = 0;
	MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
#ifdef CGOGN_BENCH_DMPLEX
	PetscInitializeNoArguments();
#endif
	// the ranks of a node share its cores
	MPI_Comm node;
	MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank(), MPI_INFO_NULL, &node);
	int node_size = 1;
	MPI_Comm_size(node, &node_size);
	MPI_Comm_free(&node);
	cgogn::set_nb_workers(std::max(1u, cgogn::ThreadPool::default_nb_workers() / uint32_t(node_size)));
	benchmark::Initialize(&argc, argv);
	if (rank() == 0)
		benchmark::RunSpecifiedBenchmarks();
	else
	{
		Silent silent;
		benchmark::RunSpecifiedBenchmarks(&silent);
	}
	benchmark::Shutdown();
#ifdef CGOGN_BENCH_DMPLEX
	PetscFinalize();
#endif
	MPI_Finalize();
	return 0;
}
