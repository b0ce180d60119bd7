// SPDX-License-Identifier: MIT
// GMap2 against CMap2 on the same surface, in one process: the read-only
// workloads of the surface suite (bench/README.md) that run on both models,
// on a closed torus of 1M triangles with vertices and faces indexed, and
// the memory of each map. A G-map has twice the darts of a 2-map: the target
// is at most 2x the CMap2's time and bytes. CGAL's Generalized_map is the
// peer, when found (peers/cgal_gmap_surface.cpp). Each benchmark's counters
// give ns per visited incidence and, for "build", bytes per face, and a check
// value that every row of a workload must share; a table of the times and
// ratios follows the run.
#include "gmap_bench.h"

#include <cgogn/core.h>

#include "harness.h"
#include "row_table.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <functional>
#include <string>
#include <vector>

using namespace cgogn;
using Point3 = std::array<double, 3>;

const SurfaceSoup& cgogn::bench::gmap_soup()
{
	static const SurfaceSoup s = torus_soup(1000, 500, true); // 1,000,000 triangles, closed
	return s;
}

namespace
{

const SurfaceSoup& soup()
{
	return cgogn::bench::gmap_soup();
}

template <typename MAP>
struct Mesh
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;
	MAP map;
	std::shared_ptr<AttributeArray<Point3>> position;
	Mesh()
	{
		const BuildReport r = build_surface(map, soup());
		position = add_attribute<Point3, Vertex>(map, "position");
		for (uint32 i = 0; i < soup().nb_vertices; ++i)
			(*position)[r.vertex_offset + i] = soup().positions[i];
		add_attribute<double, Face>(map, "face_data"); // faces indexed, as in the suite
	}
};

template <typename MAP>
Mesh<MAP>& mesh()
{
	static Mesh<MAP> m;
	return m;
}

// every vertex's faces, then every face's vertices
template <typename MAP>
void circulator(benchmark::State& state)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;
	const MAP& m = mesh<MAP>().map;
	int64 up = 0;
	for (auto _ : state)
	{
		int64 c = 0;
		foreach_cell(m, [&](Vertex v) { foreach_incident_face(m, v, [&](Face) { ++c; }); });
		up = c;
		foreach_cell(m, [&](Face f) { foreach_incident_vertex(m, f, [&](Vertex) { --c; }); });
		if (c != 0)
			state.SkipWithError("circulator check failed");
		benchmark::DoNotOptimize(c);
	}
	state.counters["ns_per_incidence"] = benchmark::Counter(6.0 * double(soup().face_sizes.size()) * state.iterations(),
															benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
	state.counters["check"] = double(up); // vertex -> face incidences
}

// one in-place pass of umbrella smoothing over the vertices
template <typename MAP>
void smoothing(benchmark::State& state)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	const MAP& m = mesh<MAP>().map;
	AttributeArray<Point3>& pos = *mesh<MAP>().position;
	uint64 incidences = 0;
	for (auto _ : state)
	{
		incidences = 0;
		foreach_cell(m, [&](Vertex v) {
			Point3 sum = {0, 0, 0};
			uint32 n = 0;
			foreach_adjacent_vertex_through_edge(m, v, [&](Vertex w) {
				const Point3& q = value<Point3>(m, pos, w);
				sum[0] += q[0], sum[1] += q[1], sum[2] += q[2];
				++n;
			});
			pos[v] = {sum[0] / n, sum[1] / n, sum[2] / n};
			incidences += n;
		});
	}
	state.counters["ns_per_incidence"] = benchmark::Counter(double(incidences) * state.iterations(),
															benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
	state.counters["check"] = double(incidences);
}

// counting the cells of every kind: vertices and faces are indexed (their
// containers' counts), edges are not (a walk of the darts with a mark)
template <typename MAP>
void count_cells(benchmark::State& state)
{
	using T = mesh_traits<MAP>;
	const MAP& m = mesh<MAP>().map;
	uint64 n = 0;
	for (auto _ : state)
	{
		n = nb_cells<typename T::Vertex>(m) + nb_cells<typename T::Edge>(m) + nb_cells<typename T::Face>(m);
		benchmark::DoNotOptimize(n);
	}
	state.counters["check"] = double(n);
}

// building the map from the soup, and its memory once built
template <typename MAP>
void build(benchmark::State& state)
{
	using T = mesh_traits<MAP>;
	double bytes = 0, cells = 0;
	for (auto _ : state)
	{
		const std::size_t before = cgogn_bench::heap_bytes();
		{
			MAP m;
			build_surface(m, soup());
			bytes = double(cgogn_bench::heap_bytes() - before);
			state.PauseTiming();
			cells = nb_cells<typename T::Vertex>(m) + nb_cells<typename T::Edge>(m) + nb_cells<typename T::Face>(m);
			state.ResumeTiming();
			benchmark::DoNotOptimize(m);
		}
	}
	state.counters["bytes_per_face"] = bytes / double(soup().face_sizes.size());
	state.counters["check"] = cells; // V + E + F
}

} // namespace

int main(int argc, char** argv)
{
#ifdef CGOGN_BENCH_HAS_CGAL
	namespace peer = cgogn::bench::cgal_gmap;
#endif
	cgogn::bench::RowTable table("GMap2", "bytes_per_face");
	const auto add_row = [&](const std::string& workload, const std::string& model,
							 std::function<void(benchmark::State&)> fn) {
		table.add(workload, model, fn, workload == "build" ? 3 : 0);
	};
	add_row("circulator", "CMap2", circulator<CMap2>);
	add_row("circulator", "GMap2", circulator<GMap2>);
#ifdef CGOGN_BENCH_HAS_CGAL
	add_row("circulator", "CGAL_GMap", [](benchmark::State& s) { peer::circulator(s, false); });
	add_row("circulator", "CGAL_GMap_alpha", [](benchmark::State& s) { peer::circulator(s, true); });
#endif
	add_row("smoothing", "CMap2", smoothing<CMap2>);
	add_row("smoothing", "GMap2", smoothing<GMap2>);
#ifdef CGOGN_BENCH_HAS_CGAL
	add_row("smoothing", "CGAL_GMap", [](benchmark::State& s) { peer::smoothing(s, false); });
	add_row("smoothing", "CGAL_GMap_alpha", [](benchmark::State& s) { peer::smoothing(s, true); });
#endif
	add_row("count_cells", "CMap2", count_cells<CMap2>);
	add_row("count_cells", "GMap2", count_cells<GMap2>);
#ifdef CGOGN_BENCH_HAS_CGAL
	add_row("count_cells", "CGAL_GMap", peer::count_cells);
#endif
	add_row("build", "CMap2", build<CMap2>);
	add_row("build", "GMap2", build<GMap2>);
#ifdef CGOGN_BENCH_HAS_CGAL
	add_row("build", "CGAL_GMap", peer::build);
#endif
	return table.run(argc, argv);
}
