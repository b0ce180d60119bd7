// SPDX-License-Identifier: MIT
// Decimation and isotropic remeshing of nefertiti.obj (100k faces): cgogn
// against OpenMesh's Decimater and CGAL's Surface_mesh_simplification and
// Polygon_mesh_processing::isotropic_remeshing, side by side. Thread CPU time
// of the operation alone (the mesh is rebuilt untimed before each run). The
// quality counters are measured the same way for every library, by cgogn's
// vertex_distance_to_surface: `to_input_*` from the result's vertices to the
// input surface, `from_input_*` from the input's vertices to the result.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "modeling_peers.h"

#include <benchmark/benchmark.h>

#include <ctime>
#include <filesystem>
#include <functional>
#include <string>

using namespace cgogn;
using cgogn_bench::TriangleSoup;

double cgogn_bench::modeling_thread_seconds()
{
	timespec t{};
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
	return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

namespace
{

constexpr uint32 TARGET_FACES = 10000;
constexpr uint32 REMESH_ITERATIONS = 3;

TriangleSoup soup_of(const CMap2& m, const AttributeArray<Vec3>& pos)
{
	TriangleSoup s;
	std::vector<uint32> id(container_of<Orbit::PHI21>(m).end_index(), 0);
	foreach_cell(m, [&](CMap2::Vertex v) {
		const Vec3& p = pos[index_of(m, v)];
		id[index_of(m, v)] = uint32(s.points.size());
		s.points.push_back({p.x(), p.y(), p.z()});
	});
	foreach_cell(m, [&](CMap2::Face f) {
		const Dart d = f.dart;
		s.triangles.push_back({id[index_of(m, CMap2::Vertex(d))], id[index_of(m, CMap2::Vertex(phi1(m, d)))],
							   id[index_of(m, CMap2::Vertex(phi_1(m, d)))]});
	});
	return s;
}

std::shared_ptr<AttributeArray<Vec3>> build(CMap2& m, const TriangleSoup& s)
{
	std::vector<uint32> sizes(s.triangles.size(), 3), vertices;
	vertices.reserve(3 * s.triangles.size());
	for (const auto& t : s.triangles)
		vertices.insert(vertices.end(), t.begin(), t.end());
	const BuildReport r = build_surface(m, uint32(s.points.size()), sizes, vertices);
	auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
	for (uint32 i = 0; i < s.points.size(); ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.points[i][0], s.points[i][1], s.points[i][2]);
	return pos;
}

struct Input
{
	TriangleSoup soup;
	CMap2 map;
	std::shared_ptr<AttributeArray<Vec3>> pos;
	std::unique_ptr<modeling::TriangleTree> tree;
	double mean_edge_length = 0.0;
};

Input& input()
{
	static Input in = [] {
		Input i;
		const std::string path = cgogn_test_data::path("surface/nefertiti.obj");
		io::load_surface(i.map, path);
		i.pos = get_attribute<Vec3, CMap2::Vertex>(i.map, "position");
		i.soup = soup_of(i.map, *i.pos);
		i.tree = std::make_unique<modeling::TriangleTree>(i.map, *i.pos);
		i.mean_edge_length = geometry::mean_edge_length(i.map, *i.pos);
		return i;
	}();
	return in;
}

/// Quality counters of a result, the same for every library.
void measure(benchmark::State& state, const TriangleSoup& result)
{
	Input& in = input();
	CMap2 m;
	auto pos = build(m, result);
	const modeling::SurfaceDistance to = modeling::vertex_distance_to_surface(m, *pos, *in.tree);
	const modeling::TriangleTree tree(m, *pos);
	const modeling::SurfaceDistance from = modeling::vertex_distance_to_surface(in.map, *in.pos, tree);
	uint32 regular = 0, total = 0;
	foreach_cell(m, [&](CMap2::Vertex v) {
		regular += degree(m, v) == (is_incident_to_boundary(m, v) ? 4u : 6u) ? 1 : 0;
		++total;
	});
	state.counters["faces"] = double(result.triangles.size());
	state.counters["to_input_max"] = to.max;
	state.counters["to_input_mean"] = to.mean;
	state.counters["from_input_max"] = from.max;
	state.counters["from_input_mean"] = from.mean;
	state.counters["mean_edge"] = geometry::mean_edge_length(m, *pos);
	state.counters["valence_regular"] = double(regular) / double(total);
}

/// Runs op (which returns the CPU seconds of the operation and fills a soup) per iteration.
void run(benchmark::State& state, const std::function<double(TriangleSoup&)>& op)
{
	TriangleSoup result;
	for (auto _ : state)
		state.SetIterationTime(op(result));
	measure(state, result);
}

double cgogn_decimate(TriangleSoup& out, modeling::CollapsePlacement placement, bool rules = false)
{
	CMap2 m;
	auto pos = build(m, input().soup);
	if (rules)
	{
		// attributes that follow the edit: a colour per vertex (interpolated
		// at the new position) and a region per face (copied)
		auto colour = add_attribute<Vec3, CMap2::Vertex>(m, "colour");
		auto region = add_attribute<int32, CMap2::Face>(m, "region");
		foreach_cell(m, [&](CMap2::Vertex v) { value<Vec3>(m, colour, v) = (*pos)[index_of(m, v)]; });
		foreach_cell(m, [&](CMap2::Face f) { value<int32>(m, region, f) = int32(index_of(m, f) % 7); });
	}
	modeling::DecimationOptions o;
	o.target_faces = TARGET_FACES;
	o.placement = placement;
	const double t0 = cgogn_bench::modeling_thread_seconds();
	modeling::decimate(m, *pos, o);
	const double seconds = cgogn_bench::modeling_thread_seconds() - t0;
	out = soup_of(m, *pos);
	return seconds;
}

double cgogn_remesh(TriangleSoup& out)
{
	CMap2 m;
	auto pos = build(m, input().soup);
	modeling::RemeshingOptions o;
	o.target_edge_length = input().mean_edge_length;
	o.iterations = REMESH_ITERATIONS;
	const double t0 = cgogn_bench::modeling_thread_seconds();
	modeling::isotropic_remeshing(m, *pos, o);
	const double seconds = cgogn_bench::modeling_thread_seconds() - t0;
	out = soup_of(m, *pos);
	return seconds;
}

void add(const std::string& name, int iterations, std::function<double(TriangleSoup&)> op)
{
	benchmark::RegisterBenchmark(name.c_str(), [op](benchmark::State& s) { run(s, op); })
		->UseManualTime()
		->Iterations(iterations)
		->Unit(benchmark::kMillisecond);
}

} // namespace

int main(int argc, char** argv)
{
	if (!std::filesystem::exists(cgogn_test_data::path("surface/nefertiti.obj")))
	{
		std::fprintf(stderr, "bench_modeling: %s\n", cgogn_test_data::missing_large("surface/nefertiti.obj").c_str());
		return 0;
	}
	add("decimate/cgogn", 5, [](TriangleSoup& o) { return cgogn_decimate(o, modeling::CollapsePlacement::Optimal); });
	add("decimate/cgogn_rules", 5,
		[](TriangleSoup& o) { return cgogn_decimate(o, modeling::CollapsePlacement::Optimal, true); });
	add("decimate/cgogn_midedge", 5,
		[](TriangleSoup& o) { return cgogn_decimate(o, modeling::CollapsePlacement::Midpoint); });
#ifdef CGOGN_BENCH_HAS_OPENMESH
	add("decimate/openmesh", 5,
		[](TriangleSoup& o) { return cgogn_bench::openmesh_decimate(input().soup, TARGET_FACES, o); });
#endif
#ifdef CGOGN_BENCH_HAS_CGAL
	add("decimate/cgal", 5, [](TriangleSoup& o) { return cgogn_bench::cgal_decimate(input().soup, TARGET_FACES, o); });
#endif
	add("remesh/cgogn", 3, [](TriangleSoup& o) { return cgogn_remesh(o); });
#ifdef CGOGN_BENCH_HAS_CGAL
	add("remesh/cgal", 3, [](TriangleSoup& o) {
		return cgogn_bench::cgal_remesh(input().soup, input().mean_edge_length, REMESH_ITERATIONS, o);
	});
#endif
	benchmark::Initialize(&argc, argv);
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}
