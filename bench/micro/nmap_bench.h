// SPDX-License-Identifier: MIT
// What bench_nmap shares with its peer's translation unit
// (peers/cgal_lcc4.cpp: CGAL headers are slow to compile and add
// -frounding-math): the 4-D grid every D = 4 row works on, and the peer's
// workloads, registered by nmap_bench.cpp next to cgogn's rows.
#pragma once

#include <cgogn/core/map/nmap.h>

#include <benchmark/benchmark.h>

namespace cgogn::bench
{

/// The hypercube grid of the D = 4 rows, its vertices indexed with their
/// positions (PointD<4>) and no other orbit indexed (built once).
const CMapN<4>& grid4();

/// CGAL's Linear_cell_complex_for_combinatorial_map<4> holding the same
/// grid (its darts and betas copied from grid4(), without the boundary
/// darts: a CGAL map is open), 0-attributes with the points: the workloads of
/// nmap_bench.cpp, with the same check values.
namespace cgal_lcc4
{
void vertex_star(benchmark::State& state);
void adjacency(benchmark::State& state);
void f_vector(benchmark::State& state);
void memory(benchmark::State& state);
} // namespace cgal_lcc4

} // namespace cgogn::bench
