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

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

using namespace cgogn;
using Vec3 = std::array<double, 3>;

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
	std::shared_ptr<AttributeArray<Vec3>> position;
	Mesh()
	{
		const BuildReport r = build_surface(map, soup());
		position = add_attribute<Vec3, Vertex>(map, "position");
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
	AttributeArray<Vec3>& pos = *mesh<MAP>().position;
	uint64 incidences = 0;
	for (auto _ : state)
	{
		incidences = 0;
		foreach_cell(m, [&](Vertex v) {
			Vec3 sum = {0, 0, 0};
			uint32 n = 0;
			foreach_adjacent_vertex_through_edge(m, v, [&](Vertex w) {
				const Vec3& q = value<Vec3>(m, pos, w);
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

// ---- the rows, in the order of the table, and the table

/// What a row ("workload<model>") measured: CPU ms per iteration (the
/// fastest repetition), bytes per face, check value.
struct Result
{
	double ms = 0;
	double bytes_per_face = 0;
	double check = 0;
};
std::vector<std::string> workloads, models;
std::map<std::string, std::map<std::string, Result>> results;

void add_row(const std::string& workload, const std::string& model, std::function<void(benchmark::State&)> fn)
{
	auto* b = benchmark::RegisterBenchmark((workload + "<" + model + ">").c_str(), fn)->Unit(benchmark::kMillisecond);
	if (workload == "build")
		b->Iterations(3);
	else
		b->MinTime(1.0);
	if (std::find(workloads.begin(), workloads.end(), workload) == workloads.end())
		workloads.push_back(workload);
	if (std::find(models.begin(), models.end(), model) == models.end())
		models.push_back(model);
}

/// The display reporter chosen by the flags, the results kept on the way.
class Collector : public benchmark::BenchmarkReporter
{
public:
	explicit Collector(benchmark::BenchmarkReporter* display) : display_(display)
	{
	}
	bool ReportContext(const Context& context) override
	{
		return display_->ReportContext(context);
	}
	void ReportRuns(const std::vector<Run>& runs) override
	{
		display_->ReportRuns(runs);
		for (const Run& r : runs)
		{
			if (r.run_type != Run::RT_Iteration || r.error_occurred)
				continue;
			const std::string& name = r.run_name.function_name;
			const std::size_t open = name.find('<');
			if (open == std::string::npos || name.back() != '>')
				continue;
			auto& row = results[name.substr(0, open)];
			const std::string model = name.substr(open + 1, name.size() - open - 2);
			const bool first = row.find(model) == row.end();
			Result& res = row[model];
			const double ms = r.GetAdjustedCPUTime(); // in the row's unit, ms
			res.ms = first ? ms : std::min(res.ms, ms);
			const auto get = [&](const char* key) {
				const auto it = r.counters.find(key);
				return it == r.counters.end() ? 0.0 : double(it->second);
			};
			res.bytes_per_face = get("bytes_per_face");
			res.check = get("check");
		}
	}
	void Finalize() override
	{
		display_->Finalize();
	}

private:
	benchmark::BenchmarkReporter* display_;
};

/// Prints the table (GMap2 against every other model) and returns false when
/// the rows of a workload disagree on their check value.
bool print_table()
{
	bool same = true;
	std::printf("\n| workload |");
	for (const std::string& model : models)
		std::printf(" %s |", model.c_str());
	for (const std::string& model : models)
		if (model != "GMap2")
			std::printf(" GMap2 / %s |", model.c_str());
	std::printf("\n|---|");
	for (std::size_t i = 0; i + 1 < 2 * models.size(); ++i)
		std::printf("---:|");
	std::printf("\n");
	const auto row = [&](const std::string& label, const std::map<std::string, Result>& r, const char* unit,
						 double (*get)(const Result&)) {
		std::printf("| %s |", label.c_str());
		for (const std::string& model : models)
		{
			const auto it = r.find(model);
			if (it == r.end())
				std::printf(" - |");
			else
				std::printf(" %.1f %s |", get(it->second), unit);
		}
		const auto g = r.find("GMap2");
		for (const std::string& model : models)
		{
			if (model == "GMap2")
				continue;
			const auto it = r.find(model);
			if (g == r.end() || it == r.end() || get(it->second) == 0)
				std::printf(" - |");
			else
				std::printf(" %.2f |", get(g->second) / get(it->second));
		}
		std::printf("\n");
	};
	for (const std::string& w : workloads)
	{
		const auto r = results.find(w);
		if (r == results.end())
			continue;
		row(w, r->second, "ms", [](const Result& x) { return x.ms; });
		if (w == "build")
			row("memory, bytes per face", r->second, "B", [](const Result& x) { return x.bytes_per_face; });
		for (const auto& [model, res] : r->second)
			if (res.check != r->second.begin()->second.check)
			{
				std::printf("check of %s<%s>: %.0f, of %s<%s>: %.0f\n", w.c_str(), model.c_str(), res.check, w.c_str(),
							r->second.begin()->first.c_str(), r->second.begin()->second.check);
				same = false;
			}
	}
	return same;
}

} // namespace

int main(int argc, char** argv)
{
#ifdef CGOGN_BENCH_HAS_CGAL
	namespace peer = cgogn::bench::cgal_gmap;
#endif
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
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv))
		return 1;
	Collector collector(benchmark::CreateDefaultDisplayReporter());
	benchmark::RunSpecifiedBenchmarks(&collector);
	benchmark::Shutdown();
	return print_table() ? 0 : 1;
}
