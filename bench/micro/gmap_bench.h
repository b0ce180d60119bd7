// SPDX-License-Identifier: MIT
// What bench_gmap shares with its peer's translation unit
// (peers/cgal_gmap_surface.cpp: CGAL headers are slow to compile and add
// -frounding-math): the torus every row works on, and the peer's workloads,
// registered by gmap_bench.cpp next to the CMap2 and GMap2 rows.
#pragma once

#include <benchmark/benchmark.h>

namespace cgogn
{
struct SurfaceSoup;
}

namespace cgogn::bench
{

/// The closed torus of 1M triangles (built once).
const SurfaceSoup& gmap_soup();

/// CGAL's Linear_cell_complex_for_generalized_map<2, 3>: the workloads of
/// gmap_bench.cpp, each with the same counters and check value as cgogn's.
/// `alpha_walk` walks around vertices and faces by alpha steps, as the GMap2
/// does; otherwise by CGAL's cell ranges (one_dart_per_incident_cell).
namespace cgal_gmap
{
void circulator(benchmark::State& state, bool alpha_walk);
void smoothing(benchmark::State& state, bool alpha_walk);
void count_cells(benchmark::State& state);
void build(benchmark::State& state);
} // namespace cgal_gmap

} // namespace cgogn::bench
