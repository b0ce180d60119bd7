// SPDX-License-Identifier: MIT
// The multiresolution 2-map beside the flat CMap2 of its finest level, in one
// run: a quad torus of 6,400 faces (level 0) with 3 Catmull-Clark levels
// (409,600 faces at level 3).
// - memory: the labels' bytes per dart, and bytes per face of the hierarchy
//   (every level's lines included) and of the flat map of the finest level;
// - at the finest level: a one-ring circulator (the mean of the neighbours'
//   positions) and a Laplacian smoothing pass, on both, and on the flat map
//   made by 3 catmull_clark_subdivision steps in place (its darts in the
//   order the steps create them, as the hierarchy's; the extract_level copy
//   has them face by face, which its walks find closer in memory);
// - phi1 at level l, for L - l = 0 ... 3: every face of the level walked,
//   next to the same walk on the level's extract_level copy;
// - add_level with the Catmull-Clark synthesis of the new level, next to one
//   catmull_clark_subdivision step of the flat level 2;
// - adaptive refinement: every face of a 102,400-quad torus subdivided once,
//   with balance, faces per second.
#include <cgogn/cgogn.h>

#include "mr_bench_workloads.h"

#include <benchmark/benchmark.h>

using namespace cgogn;
using namespace cgogn::modeling;
using namespace cgogn::bench_mr;

namespace
{

constexpr uint32 LEVELS = 3;

CMap2 torus(uint32 nu, uint32 nv)
{
	CMap2 m;
	const SurfaceSoup s = torus_soup(nu, nv, false);
	const BuildReport r = build_surface(m, s);
	auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return m;
}

struct Hierarchy
{
	MRMap2 m;
	std::shared_ptr<AttributeArray<Vec3>> pos, details;
};

Hierarchy make_hierarchy()
{
	Hierarchy h{MRMap2(torus(100, 64)), nullptr, nullptr};
	h.pos = get_attribute<Vec3, MRMap2::Vertex>(h.m, "position");
	h.details = add_attribute<Vec3, MRMap2::Vertex>(h.m, "details");
	for (uint32 l = 0; l < LEVELS; ++l)
		add_level(h.m, Refinement::Quadrangular);
	synthesis(h.m, *h.pos, *h.details, MRBank::CatmullClark);
	return h;
}

Hierarchy& hierarchy()
{
	static Hierarchy h = make_hierarchy();
	return h;
}

CMap2& flat_level(uint32 l)
{
	static std::vector<std::unique_ptr<CMap2>> flats(LEVELS + 1);
	if (!flats[l])
		flats[l] = std::make_unique<CMap2>(extract_level(hierarchy().m, l));
	return *flats[l];
}

// The finest level made by LEVELS flat Catmull-Clark steps of level 0, in
// place: its darts in the order the steps create them, as in the hierarchy.
CMap2& subdivided_flat()
{
	static CMap2 m = [] {
		CMap2 t = torus(100, 64);
		auto pos = get_attribute<Vec3, CMap2::Vertex>(t, "position");
		for (uint32 l = 0; l < LEVELS; ++l)
			catmull_clark_subdivision(t, *pos);
		return t;
	}();
	return m;
}

void BM_CirculatorFlatSubdivided(benchmark::State& state)
{
	time_flat_circulator(state, subdivided_flat());
}
BENCHMARK(BM_CirculatorFlatSubdivided)->Unit(benchmark::kMillisecond);

void BM_SmoothingFlatSubdivided(benchmark::State& state)
{
	time_flat_smoothing(state, subdivided_flat());
}
BENCHMARK(BM_SmoothingFlatSubdivided)->Unit(benchmark::kMillisecond);

void BM_Memory(benchmark::State& state)
{
	double mr_bytes = 0, flat_bytes = 0;
	uint32 faces = 0;
	const MRMap2& source = hierarchy().m; // made before measuring
	for (auto _ : state)
	{
		std::size_t before = held_bytes();
		{
			Hierarchy h = make_hierarchy();
			mr_bytes = double(held_bytes() - before);
			faces = nb_cells<MRMap2::Face>(level_view(h.m, LEVELS));
		}
		before = held_bytes();
		{
			CMap2 flat = extract_level(source, LEVELS);
			flat_bytes = double(held_bytes() - before);
		}
	}
	state.counters["label_B_per_dart"] = double(sizeof(uint8) + sizeof(uint8));
	state.counters["mr_B_per_face"] = mr_bytes / faces;
	state.counters["flat_B_per_face"] = flat_bytes / faces;
	state.counters["ratio"] = mr_bytes / flat_bytes;
}
BENCHMARK(BM_Memory)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_CirculatorFlat(benchmark::State& state)
{
	time_flat_circulator(state, flat_level(LEVELS));
}
BENCHMARK(BM_CirculatorFlat)->Unit(benchmark::kMillisecond);

void BM_CirculatorMR(benchmark::State& state)
{
	Hierarchy& h = hierarchy();
	set_current_level(h.m, LEVELS);
	for (auto _ : state)
		benchmark::DoNotOptimize(circulate(h.m, *h.pos));
}
BENCHMARK(BM_CirculatorMR)->Unit(benchmark::kMillisecond);

void BM_SmoothingFlat(benchmark::State& state)
{
	time_flat_smoothing(state, flat_level(LEVELS));
}
BENCHMARK(BM_SmoothingFlat)->Unit(benchmark::kMillisecond);

void BM_SmoothingMR(benchmark::State& state)
{
	Hierarchy& h = hierarchy();
	set_current_level(h.m, LEVELS);
	auto out = get_attribute<Vec3, MRMap2::Vertex>(h.m, "smoothed");
	if (!out)
		out = add_attribute<Vec3, MRMap2::Vertex>(h.m, "smoothed");
	for (auto _ : state)
		smooth(h.m, *h.pos, *out);
}
BENCHMARK(BM_SmoothingMR)->Unit(benchmark::kMillisecond);

// state.range(0) = L - l
void BM_Phi1AtLevelMR(benchmark::State& state)
{
	const MRLevelView2 v = level_view(hierarchy().m, LEVELS - uint32(state.range(0)));
	uint32 n = 0;
	for (auto _ : state)
		benchmark::DoNotOptimize(n = walk_faces(v));
	state.counters["darts_per_s"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Phi1AtLevelMR)->DenseRange(0, LEVELS)->Unit(benchmark::kMillisecond);

void BM_Phi1AtLevelExtracted(benchmark::State& state)
{
	const CMap2& m = flat_level(LEVELS - uint32(state.range(0)));
	uint32 n = 0;
	for (auto _ : state)
		benchmark::DoNotOptimize(n = walk_faces(m));
	state.counters["darts_per_s"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Phi1AtLevelExtracted)->DenseRange(0, LEVELS)->Unit(benchmark::kMillisecond);

void BM_AddLevelMR(benchmark::State& state)
{
	// level 3 of the hierarchy made again from level 2, its positions included
	Hierarchy& h = hierarchy();
	for (auto _ : state)
	{
		state.PauseTiming();
		remove_finest_level(h.m);
		state.ResumeTiming();
		add_level(h.m, Refinement::Quadrangular);
		synthesis(h.m, *h.pos, *h.details, MRBank::CatmullClark, LEVELS - 1);
	}
}
BENCHMARK(BM_AddLevelMR)->Unit(benchmark::kMillisecond);

void BM_CatmullClarkStepFlat(benchmark::State& state)
{
	for (auto _ : state)
	{
		state.PauseTiming();
		CMap2 m = extract_level(hierarchy().m, LEVELS - 1);
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		state.ResumeTiming();
		catmull_clark_subdivision(m, *pos);
	}
}
BENCHMARK(BM_CatmullClarkStepFlat)->Unit(benchmark::kMillisecond);

void BM_AdaptiveRefinement(benchmark::State& state)
{
	uint32 faces = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		MRMap2 m(torus(400, 256));
		std::vector<MRMap2::Face> all;
		foreach_cell(m, [&](MRMap2::Face f) { all.push_back(f); });
		faces = uint32(all.size());
		state.ResumeTiming();
		for (MRMap2::Face f : all)
			subdivide_face(m, f, Refinement::Quadrangular);
	}
	state.counters["faces_per_s"] = benchmark::Counter(double(faces), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AdaptiveRefinement)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace

BENCHMARK_MAIN();
