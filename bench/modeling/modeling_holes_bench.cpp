// SPDX-License-Identifier: MIT
// Hole filling of stanford-bunny.obj (5 holes) and elephant-with-holes.off
// (106 holes): cgogn's modeling::fill_holes against CGAL's
// Polygon_mesh_processing (triangulate_hole, triangulate_refine_and_fair_hole)
// when CGAL is found; and the triangulation of spot_quadrangulated.obj's quads
// (ear clipping) against OpenMesh's triangulate() when OpenMesh is found.
// Each iteration works on a fresh copy of the mesh, loaded or copied with the
// timer paused. Read the CPU time column.
#include <cgogn/cgogn.h>

#include "modeling_holes.h"

#include <benchmark/benchmark.h>

#include <filesystem>

using namespace cgogn;
using namespace cgogn::bench_holes;

namespace
{

void cgogn_fill_holes(benchmark::State& state, const std::string& path, bool refine_and_fair)
{
	modeling::HoleFillingOptions options;
	options.refine = refine_and_fair;
	options.fair = refine_and_fair;
	modeling::HoleFillingResult r;
	for (auto _ : state)
	{
		state.PauseTiming();
		CMap2 m;
		io::load_surface(m, path);
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		state.ResumeTiming();
		r = modeling::fill_holes(m, *pos, options);
		benchmark::DoNotOptimize(r);
	}
	state.counters["holes"] = r.holes_filled;
	state.counters["faces_added"] = r.faces_added;
	state.counters["vertices_added"] = r.vertices_added;
}

void cgogn_triangulate(benchmark::State& state, const std::string& path)
{
	uint32 cut = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		CMap2 m;
		io::load_surface(m, path);
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		state.ResumeTiming();
		cut = modeling::triangulate_faces(m, *pos);
	}
	state.counters["faces_cut"] = cut;
}

/// The cost of the optimal triangulation alone (O(n^3)): the two boundary
/// circles of an open cylinder of n edges each (2 holes, no refinement).
void cgogn_fill_cylinder(benchmark::State& state)
{
	const uint32 n = uint32(state.range(0));
	const SurfaceSoup s = cylinder_soup(n, 4, true);
	modeling::HoleFillingOptions options;
	options.refine = false;
	modeling::HoleFillingResult r;
	for (auto _ : state)
	{
		state.PauseTiming();
		CMap2 m;
		const BuildReport b = build_surface(m, s);
		auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[b.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		state.ResumeTiming();
		r = modeling::fill_holes(m, *pos, options);
	}
	state.counters["faces_added"] = r.faces_added;
}

} // namespace

int main(int argc, char** argv)
{
	for (const HoleMesh& h : hole_meshes)
	{
		const std::string path = data_file(h.file);
		if (!std::filesystem::exists(path))
			continue;
		benchmark::RegisterBenchmark((std::string("fill_holes/triangulate/cgogn/") + h.name).c_str(), cgogn_fill_holes,
									 path, false)
			->Unit(benchmark::kMillisecond);
		benchmark::RegisterBenchmark((std::string("fill_holes/refine_fair/cgogn/") + h.name).c_str(), cgogn_fill_holes,
									 path, true)
			->Unit(benchmark::kMillisecond);
	}
	if (std::filesystem::exists(data_file(quad_mesh)))
		benchmark::RegisterBenchmark("triangulate_quads/cgogn/spot", cgogn_triangulate, data_file(quad_mesh))
			->Unit(benchmark::kMillisecond);
	benchmark::RegisterBenchmark("fill_holes/cylinder_loops/cgogn", cgogn_fill_cylinder)
		->Arg(125)
		->Arg(250)
		->Arg(500)
		->Arg(1000)
		->Unit(benchmark::kMillisecond);
#ifdef CGOGN_BENCH_HAS_CGAL
	register_cgal_benchmarks();
#endif
#ifdef CGOGN_BENCH_HAS_OPENMESH
	register_openmesh_benchmarks();
#endif
	benchmark::Initialize(&argc, argv);
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}
