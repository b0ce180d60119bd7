// Parallel traversals and quick incidence caches, on the largest meshes of the
// data folder (nefertiti.obj, armadillo_tet_461k.mesh) or, with
// CGOGN_BENCH_GENERATED=1 or without the folder, on a generated closed
// triangle torus of 1,000,000 faces and a 998,250-tet grid (see surface() and
// volume()). "seq" runs foreach_cell, "par" parallel_foreach_cell
// with the default number of workers, "par1" parallel_foreach_cell limited to
// one worker (its sequential fallback).
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"

#include <Eigen/Geometry>
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <sys/resource.h>
#include <utility>

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Face = CMap2::Face;

namespace
{

// a per-thread accumulator on its own cache line (no false sharing)
template <typename T>
struct alignas(64) PerThread
{
	T v{};
};

struct Surface
{
	CMap2 map;
	std::shared_ptr<AttributeArray<Vec3>> position, position2, normal;
	std::shared_ptr<AttributeArray<double>> scalar;
	Surface()
	{
		// the largest surface of the data folder (CGOGN_BENCH_GENERATED=1, or no
		// data folder: the generated 1M-triangle torus)
		const std::string file = cgogn_test_data::path("surface/nefertiti.obj");
		if (!std::getenv("CGOGN_BENCH_GENERATED") && std::filesystem::exists(file))
		{
			io::load_surface(map, file);
			position = get_attribute<Vec3, Vertex>(map, "position");
		}
		else
		{
			SurfaceSoup soup = torus_soup(1000, 500, true);
			BuildReport r = build_surface(map, soup);
			position = add_attribute<Vec3, Vertex>(map, "position");
			for (uint32 i = 0; i < soup.nb_vertices; ++i)
			{
				const auto& p = soup.positions[i];
				(*position)[r.vertex_offset + i] = Vec3(p[0], p[1], p[2]);
			}
		}
		position2 = add_attribute<Vec3, Vertex>(map, "position2");
		normal = add_attribute<Vec3, Vertex>(map, "normal");
		scalar = add_attribute<double, Vertex>(map, "scalar");
	}
};

Surface& surface()
{
	static Surface s;
	return s;
}

enum class Mode
{
	seq,
	par,
	par1
};

template <typename MESH, typename FUNC>
void run(Mode mode, const MESH& m, const FUNC& f)
{
	if (mode == Mode::seq)
		foreach_cell(m, f);
	else
		parallel_foreach_cell(m, f);
}

double process_cpu_ms()
{
	rusage u;
	getrusage(RUSAGE_SELF, &u);
	return (u.ru_utime.tv_sec + u.ru_stime.tv_sec) * 1e3 + (u.ru_utime.tv_usec + u.ru_stime.tv_usec) * 1e-3;
}

// Sets the number of workers for one benchmark and restores the default.
// Also reports the CPU time of the whole process per iteration (all threads):
// on a loaded machine wall time says little, but seq CPU / par CPU tells how
// much extra work the parallel split costs.
struct Workers
{
	Workers(benchmark::State& state, Mode mode) : state_(state), mode_(mode), cpu0_(process_cpu_ms())
	{
		set_nb_workers(mode == Mode::par1 ? 1 : 0);
	}
	~Workers()
	{
		state_.counters["proc_cpu_ms"] = (process_cpu_ms() - cpu0_) / double(std::max<int64>(1, state_.iterations()));
		state_.counters["workers"] = mode_ == Mode::seq ? 1 : thread_pool()->nb_workers();
		set_nb_workers(0);
	}
	Workers(const Workers&) = delete;
	Workers& operator=(const Workers&) = delete;

private:
	benchmark::State& state_;
	Mode mode_;
	double cpu0_;
};

void vertex_normals(benchmark::State& state, Mode mode)
{
	Surface& s = surface();
	const CMap2& m = s.map;
	Workers w(state, mode);
	for (auto _ : state)
		run(mode, m, [&](Vertex v) {
			Vec3 n = Vec3::Zero();
			foreach_incident_face(m, v, [&](Face f) {
				const Vec3& a = value(m, s.position, Vertex(f.dart));
				const Vec3& b = value(m, s.position, Vertex(phi1(m, f.dart)));
				const Vec3& c = value(m, s.position, Vertex(phi<1, 1>(m, f.dart)));
				n += (b - a).cross(c - a);
			});
			(*s.normal)[v] = n.normalized();
		});
	state.SetItemsProcessed(int64(state.iterations()) * nb_cells<Vertex>(m));
}

// one Jacobi pass of Laplacian smoothing: reads position, writes position2
void smoothing(benchmark::State& state, Mode mode)
{
	Surface& s = surface();
	const CMap2& m = s.map;
	Workers w(state, mode);
	for (auto _ : state)
		run(mode, m, [&](Vertex v) {
			Vec3 sum = Vec3::Zero();
			uint32 n = 0;
			foreach_adjacent_vertex_through_edge(m, v, [&](Vertex x) {
				sum += value(m, s.position, x);
				++n;
			});
			(*s.position2)[v] = sum / double(n);
		});
	state.SetItemsProcessed(int64(state.iterations()) * nb_cells<Vertex>(m));
}

// memory-light, compute-heavy: 64 transcendental steps per vertex
void compute_heavy(benchmark::State& state, Mode mode)
{
	Surface& s = surface();
	const CMap2& m = s.map;
	Workers w(state, mode);
	for (auto _ : state)
		run(mode, m, [&](Vertex v) {
			double x = value(m, s.position, v)[0];
			for (int i = 0; i < 64; ++i)
				x = std::sin(x) * std::cos(x + 0.5) + 0.25;
			(*s.scalar)[v] = x;
		});
	state.SetItemsProcessed(int64(state.iterations()) * nb_cells<Vertex>(m));
}

// faces are not indexed in this mesh: the dart-split strategy (cells owned by
// their smallest dart, per-chunk marks)
void face_areas_unindexed(benchmark::State& state, Mode mode)
{
	Surface& s = surface();
	const CMap2& m = s.map;
	Workers w(state, mode);
	for (auto _ : state)
	{
		std::vector<PerThread<double>> sum(thread_pool()->nb_workers());
		run(mode, m, [&](Face f) {
			const Vec3& a = value(m, s.position, Vertex(f.dart));
			const Vec3& b = value(m, s.position, Vertex(phi1(m, f.dart)));
			const Vec3& c = value(m, s.position, Vertex(phi<1, 1>(m, f.dart)));
			sum[current_thread_index()].v += 0.5 * (b - a).cross(c - a).norm();
		});
		benchmark::DoNotOptimize(sum.data());
	}
	state.SetItemsProcessed(int64(state.iterations()) * nb_cells<Face>(m));
}

// ---- circulators with and without quick incidence caches

void circulator_surface(benchmark::State& state, bool cached)
{
	Surface& s = surface();
	CMap2& m = s.map;
	using VF = IncidenceCache<CMap2, Vertex, Face>;
	if (cached)
		VF::build(m);
	for (auto _ : state)
	{
		uint64 c = 0;
		foreach_cell(m, [&](Vertex v) { foreach_incident_face(m, v, [&](Face f) { c += f.dart.index; }); });
		benchmark::DoNotOptimize(c);
	}
	state.SetItemsProcessed(int64(state.iterations()) * 3 * nb_cells<Face>(m)); // triangles
	state.counters["cache_MB"] = double(VF::memory_bytes(m)) / 1e6;
	VF::remove(m);
}

struct Volume3
{
	CMap3 map;
	Volume3()
	{
		// the largest tet mesh of the data folder; CGOGN_BENCH_VOLUME=elephant:
		// the hex mesh of the data folder; CGOGN_BENCH_GENERATED=1 (or no data
		// folder): a generated 998,250-tet grid
		const char* which = std::getenv("CGOGN_BENCH_VOLUME");
		const std::string name =
			which != nullptr && std::string(which) == "elephant" ? "elephant_hex_110k.mesh" : "armadillo_tet_461k.mesh";
		const std::string file = cgogn_test_data::path("volume/" + name);
		if (!std::getenv("CGOGN_BENCH_GENERATED") && std::filesystem::exists(file))
			io::load_volume(map, file);
		else
			build_volume(map, tet_grid_soup(55, 55, 55));
	}
};

Volume3& volume()
{
	static Volume3 v;
	return v;
}

void circulator_volume(benchmark::State& state, bool cached)
{
	CMap3& m = volume().map;
	using V = CMap3::Vertex;
	using W = CMap3::Volume;
	if (cached)
	{
		IncidenceCache<CMap3, V, W>::build(m);
		IncidenceCache<CMap3, V, V, W>::build(m);
	}
	for (auto _ : state)
	{
		uint64 c = 0;
		foreach_cell(m, [&](V v) {
			foreach_incident_volume(m, v, [&](W w) { c += w.dart.index; });
			foreach_adjacent_vertex_through_volume(m, v, [&](V x) { c += x.dart.index; });
		});
		benchmark::DoNotOptimize(c);
	}
	state.SetItemsProcessed(int64(state.iterations()) * nb_cells<V>(m));
	state.counters["cache_MB"] =
		double(IncidenceCache<CMap3, V, W>::memory_bytes(m) + IncidenceCache<CMap3, V, V, W>::memory_bytes(m)) / 1e6;
	IncidenceCache<CMap3, V, W>::remove(m);
	IncidenceCache<CMap3, V, V, W>::remove(m);
}

// 3-D edges are not indexed: cyclic orbits split by darts without marks;
// 3-D volumes are not indexed either: flooded orbits split with per-chunk marks
void edge_degrees_volume_unindexed(benchmark::State& state, Mode mode)
{
	const CMap3& m = volume().map;
	Workers w(state, mode);
	for (auto _ : state)
	{
		std::vector<PerThread<uint64>> sum(thread_pool()->nb_workers());
		run(mode, m, [&](CMap3::Edge e) { sum[current_thread_index()].v += degree(m, e); });
		benchmark::DoNotOptimize(sum.data());
	}
}
void volume_sizes_unindexed(benchmark::State& state, Mode mode)
{
	const CMap3& m = volume().map;
	const uint32 nb_volumes = nb_cells<CMap3::Volume>(m);
	Workers w(state, mode);
	for (auto _ : state)
	{
		std::vector<PerThread<uint64>> sum(thread_pool()->nb_workers());
		run(mode, m, [&](CMap3::Volume v) { sum[current_thread_index()].v += v.dart.index; });
		benchmark::DoNotOptimize(sum.data());
	}
	state.counters["cells"] = double(nb_volumes);
}

// Hides the vertex index of a 3-map for one scope, so that the non-indexed
// path is measured on the same map (the index attribute stays in the dart
// container and is given back at the end of the scope).
struct HideVertexIndex
{
	explicit HideVertexIndex(CMap3& m)
		: m_(m), idx_(std::exchange(cgogn::detail::state_of(m).cell_index[orbit_index(CMap3::Vertex::ORBIT)], nullptr))
	{
	}
	~HideVertexIndex()
	{
		cgogn::detail::state_of(m_).cell_index[orbit_index(CMap3::Vertex::ORBIT)] = idx_;
	}
	HideVertexIndex(const HideVertexIndex&) = delete;
	HideVertexIndex& operator=(const HideVertexIndex&) = delete;

private:
	CMap3& m_;
	AttributeArray<uint32>* idx_;
};

// 3-D vertices not indexed: flooded orbits (phi21 / phi31), each vertex spread
// over the darts of all its incident volumes
void vertices_volume_unindexed(benchmark::State& state, Mode mode)
{
	CMap3& m = volume().map;
	HideVertexIndex hidden(m);
	const uint32 nb_vertices = nb_cells<CMap3::Vertex>(m); // before Workers starts counting CPU time
	Workers w(state, mode);
	for (auto _ : state)
	{
		std::vector<PerThread<uint64>> sum(thread_pool()->nb_workers());
		run(mode, m, [&](CMap3::Vertex v) { sum[current_thread_index()].v += v.dart.index; });
		benchmark::DoNotOptimize(sum.data());
	}
	state.counters["cells"] = double(nb_vertices);
}

void cache_build_volume(benchmark::State& state, Mode mode)
{
	CMap3& m = volume().map;
	using V = CMap3::Vertex;
	using W = CMap3::Volume;
	Workers w(state, mode);
	for (auto _ : state)
		IncidenceCache<CMap3, V, W>::build(m);
	IncidenceCache<CMap3, V, W>::remove(m);
}

} // namespace

#define CGOGN_PAR_BENCH(NAME)                                                                                          \
	BENCHMARK_CAPTURE(NAME, seq, Mode::seq)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);               \
	BENCHMARK_CAPTURE(NAME, par1, Mode::par1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);             \
	BENCHMARK_CAPTURE(NAME, par, Mode::par)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(1.0);

CGOGN_PAR_BENCH(vertex_normals)
CGOGN_PAR_BENCH(smoothing)
CGOGN_PAR_BENCH(compute_heavy)
CGOGN_PAR_BENCH(face_areas_unindexed)
CGOGN_PAR_BENCH(edge_degrees_volume_unindexed)
CGOGN_PAR_BENCH(volume_sizes_unindexed)
CGOGN_PAR_BENCH(vertices_volume_unindexed)
BENCHMARK_CAPTURE(circulator_surface, dart_walk, false)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(circulator_surface, cached, true)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(circulator_volume, dart_walk, false)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(circulator_volume, cached, true)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(cache_build_volume, one_worker, Mode::par1)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(cache_build_volume, par, Mode::par)->Unit(benchmark::kMillisecond)->UseRealTime();

BENCHMARK_MAIN();
