// SPDX-License-Identifier: MIT
// The multiresolution 3-map beside the flat CMap3 of its finest level, in the
// run of bench_mr: a grid of 12 x 12 x 12 hexahedra (level 0) with 2
// hexahedral levels (110,592 hexahedra at level 2).
// - memory: the labels' bytes per dart, and bytes per volume of the
//   hierarchy (every level's lines included) and of the flat map of the
//   finest level;
// - at the finest level: a one-ring circulator (the mean of the neighbours'
//   positions) and a Laplacian smoothing pass, on both, and on the flat map
//   made by 2 hex_subdivision steps in place (its darts in the order the
//   steps create them, as the hierarchy's);
// - phi1 at level l, for L - l = 0 ... 2: every face of the level walked,
//   next to the same walk on the level's extract_level copy;
// - add_level (positions by the attribute rules: the hexahedral scheme's),
//   next to one hex_subdivision step of the flat level 1;
// - a TetraOcta add_level on a grid of 12 x 12 x 12 cubes cut in 6
//   tetrahedra each (10,368 tetrahedra), next to one tet_subdivision step
//   of the same mesh (which also cuts each inner octahedron in 4);
// - adaptive refinement: the 4,096 hexahedra of a 16^3 grid subdivided one
//   by one with subdivide_volume (the rate in hexahedra per second).
#include <cgogn/cgogn.h>

#include "mr_bench_workloads.h"

#include <benchmark/benchmark.h>

using namespace cgogn;
using namespace cgogn::bench_mr;

namespace
{

constexpr uint32 LEVELS3 = 2;

/// The cells of soup s as a CMap3 with a "position" vertex attribute.
CMap3 with_positions(const VolumeSoup& s)
{
	CMap3 m;
	const BuildReport r = build_volume(m, s);
	auto pos = add_attribute<Vec3, CMap3::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return m;
}

CMap3 hex_grid(uint32 n)
{
	return with_positions(hex_grid_soup(n, n, n));
}

struct Hierarchy3
{
	MRMap3 m;
	std::shared_ptr<AttributeArray<Vec3>> pos;
};

Hierarchy3 make_hierarchy3()
{
	Hierarchy3 h{MRMap3(hex_grid(12)), nullptr};
	h.pos = get_attribute<Vec3, MRMap3::Vertex>(h.m, "position");
	for (uint32 l = 0; l < LEVELS3; ++l)
		add_level(h.m, Refinement::Hexahedral);
	return h;
}

Hierarchy3& hierarchy3()
{
	static Hierarchy3 h = make_hierarchy3();
	return h;
}

CMap3& flat_level3(uint32 l)
{
	static std::vector<std::unique_ptr<CMap3>> flats(LEVELS3 + 1);
	if (!flats[l])
		flats[l] = std::make_unique<CMap3>(extract_level(hierarchy3().m, l));
	return *flats[l];
}

// The finest level made by LEVELS3 flat hex_subdivision steps of level 0, in
// place: its darts in the order the steps create them, as in the hierarchy.
CMap3& subdivided_flat3()
{
	static CMap3 m = [] {
		CMap3 g = hex_grid(12);
		auto pos = get_attribute<Vec3, CMap3::Vertex>(g, "position");
		for (uint32 l = 0; l < LEVELS3; ++l)
			modeling::hex_subdivision(g, *pos);
		return g;
	}();
	return m;
}

void BM_Memory3(benchmark::State& state)
{
	double mr_bytes = 0, flat_bytes = 0;
	uint32 volumes = 0;
	const MRMap3& source = hierarchy3().m; // made before measuring
	for (auto _ : state)
	{
		std::size_t before = held_bytes();
		{
			Hierarchy3 h = make_hierarchy3();
			mr_bytes = double(held_bytes() - before);
			volumes = nb_cells<MRMap3::Volume>(level_view(h.m, LEVELS3));
		}
		before = held_bytes();
		{
			CMap3 flat = extract_level(source, LEVELS3);
			flat_bytes = double(held_bytes() - before);
		}
	}
	state.counters["label_B_per_dart"] = double(3 * sizeof(uint8));
	state.counters["mr_B_per_volume"] = mr_bytes / volumes;
	state.counters["flat_B_per_volume"] = flat_bytes / volumes;
	state.counters["ratio"] = mr_bytes / flat_bytes;
}
BENCHMARK(BM_Memory3)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_Circulator3Flat(benchmark::State& state)
{
	time_flat_circulator(state, flat_level3(LEVELS3));
}
BENCHMARK(BM_Circulator3Flat)->Unit(benchmark::kMillisecond);

void BM_Circulator3FlatSubdivided(benchmark::State& state)
{
	time_flat_circulator(state, subdivided_flat3());
}
BENCHMARK(BM_Circulator3FlatSubdivided)->Unit(benchmark::kMillisecond);

void BM_Circulator3MR(benchmark::State& state)
{
	Hierarchy3& h = hierarchy3();
	set_current_level(h.m, LEVELS3);
	for (auto _ : state)
		benchmark::DoNotOptimize(circulate(h.m, *h.pos));
}
BENCHMARK(BM_Circulator3MR)->Unit(benchmark::kMillisecond);

void BM_Smoothing3Flat(benchmark::State& state)
{
	time_flat_smoothing(state, flat_level3(LEVELS3));
}
BENCHMARK(BM_Smoothing3Flat)->Unit(benchmark::kMillisecond);

void BM_Smoothing3FlatSubdivided(benchmark::State& state)
{
	time_flat_smoothing(state, subdivided_flat3());
}
BENCHMARK(BM_Smoothing3FlatSubdivided)->Unit(benchmark::kMillisecond);

void BM_Smoothing3MR(benchmark::State& state)
{
	Hierarchy3& h = hierarchy3();
	set_current_level(h.m, LEVELS3);
	auto out = get_attribute<Vec3, MRMap3::Vertex>(h.m, "smoothed");
	if (!out)
		out = add_attribute<Vec3, MRMap3::Vertex>(h.m, "smoothed");
	for (auto _ : state)
		smooth(h.m, *h.pos, *out);
}
BENCHMARK(BM_Smoothing3MR)->Unit(benchmark::kMillisecond);

// state.range(0) = L - l
void BM_Phi1AtLevel3MR(benchmark::State& state)
{
	const MRLevelView3 v = level_view(hierarchy3().m, LEVELS3 - uint32(state.range(0)));
	uint32 n = 0;
	for (auto _ : state)
		benchmark::DoNotOptimize(n = walk_faces(v));
	state.counters["darts_per_s"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Phi1AtLevel3MR)->DenseRange(0, LEVELS3)->Unit(benchmark::kMillisecond);

void BM_Phi1AtLevel3Extracted(benchmark::State& state)
{
	const CMap3& m = flat_level3(LEVELS3 - uint32(state.range(0)));
	uint32 n = 0;
	for (auto _ : state)
		benchmark::DoNotOptimize(n = walk_faces(m));
	state.counters["darts_per_s"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_Phi1AtLevel3Extracted)->DenseRange(0, LEVELS3)->Unit(benchmark::kMillisecond);

void BM_AddLevel3MR(benchmark::State& state)
{
	// level 2 of the hierarchy made again from level 1, its positions included
	Hierarchy3& h = hierarchy3();
	for (auto _ : state)
	{
		state.PauseTiming();
		remove_finest_level(h.m);
		state.ResumeTiming();
		add_level(h.m, Refinement::Hexahedral);
	}
}
BENCHMARK(BM_AddLevel3MR)->Unit(benchmark::kMillisecond);

void BM_HexSubdivisionStepFlat(benchmark::State& state)
{
	for (auto _ : state)
	{
		state.PauseTiming();
		CMap3 m = extract_level(hierarchy3().m, LEVELS3 - 1);
		auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
		state.ResumeTiming();
		modeling::hex_subdivision(m, *pos);
	}
}
BENCHMARK(BM_HexSubdivisionStepFlat)->Unit(benchmark::kMillisecond);

CMap3 tet_grid(uint32 n)
{
	return with_positions(tet_grid_soup(n, n, n));
}

void BM_AddLevelTetraOctaMR(benchmark::State& state)
{
	// level 1 made again from level 0, its positions included
	static MRMap3 m(tet_grid(12));
	for (auto _ : state)
	{
		state.PauseTiming();
		if (max_level(m) > 0)
			remove_finest_level(m);
		state.ResumeTiming();
		add_level(m, Refinement::TetraOcta);
	}
	state.counters["tetrahedra"] = double(nb_cells<MRMap3::Volume>(level_view(m, 0)));
}
BENCHMARK(BM_AddLevelTetraOctaMR)->Unit(benchmark::kMillisecond);

void BM_TetSubdivisionStepFlat(benchmark::State& state)
{
	for (auto _ : state)
	{
		state.PauseTiming();
		CMap3 m = tet_grid(12);
		auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
		state.ResumeTiming();
		modeling::tet_subdivision(m, *pos);
	}
}
BENCHMARK(BM_TetSubdivisionStepFlat)->Unit(benchmark::kMillisecond);

void BM_AdaptiveRefinement3(benchmark::State& state)
{
	uint32 volumes = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		MRMap3 m(hex_grid(16));
		std::vector<MRMap3::Volume> all;
		foreach_cell(m, [&](MRMap3::Volume w) { all.push_back(w); });
		volumes = uint32(all.size());
		state.ResumeTiming();
		for (MRMap3::Volume w : all)
			subdivide_volume(m, w);
	}
	state.counters["hexahedra_per_s"] =
		benchmark::Counter(double(volumes), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_AdaptiveRefinement3)->Unit(benchmark::kMillisecond)->Iterations(3);

} // namespace
