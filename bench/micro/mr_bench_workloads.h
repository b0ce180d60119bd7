// SPDX-License-Identifier: MIT
// The workloads bench_mr runs on a multiresolution map and on the flat map
// of a level, whatever their dimension: held memory, a one-ring
// circulator, a smoothing pass, a walk of every face.
#pragma once

#include <cgogn/cgogn.h>

#include <benchmark/benchmark.h>

#include <malloc.h>

// Internal to each file that includes it: with external linkage, the
// compilers stop inlining the multiresolution traversals into these loops
// (the MRMap2 circulator measured 1.9x the flat map instead of 1.1x).
namespace cgogn::bench_mr
{
namespace
{

/// The bytes the process holds (malloc and the line storage).
std::size_t held_bytes()
{
	const struct mallinfo2 mi = mallinfo2();
	return mi.uordblks + mi.hblkhd + committed_storage_bytes();
}

/// The mean of the neighbours' first coordinate, summed over the vertices.
template <typename MESH>
double circulate(const MESH& m, const AttributeArray<Vec3>& pos)
{
	using V = typename mesh_traits<MESH>::Vertex;
	double sum = 0.0;
	foreach_cell(m, [&](V v) {
		Vec3 s = Vec3::Zero();
		uint32 n = 0;
		foreach_adjacent_vertex_through_edge(m, v, [&](V w) {
			s += value<Vec3>(m, pos, w);
			++n;
		});
		sum += s.x() / n;
	});
	return sum;
}

/// One Laplacian smoothing pass of pos into out.
template <typename MESH>
void smooth(MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<Vec3>& out)
{
	using V = typename mesh_traits<MESH>::Vertex;
	foreach_cell(m, [&](V v) {
		Vec3 s = Vec3::Zero();
		uint32 n = 0;
		foreach_adjacent_vertex_through_edge(m, v, [&](V w) {
			s += pos[index_of(m, w)];
			++n;
		});
		out[index_of(m, v)] = 0.5 * pos[index_of(m, v)] + 0.5 * s / n;
	});
}

/// Times circulate on a flat map by its "position" vertex attribute.
template <typename MAP>
void time_flat_circulator(benchmark::State& state, const MAP& m)
{
	const auto pos = get_attribute<Vec3, typename MAP::Vertex>(m, "position");
	for (auto _ : state)
		benchmark::DoNotOptimize(circulate(m, *pos));
}

/// Times smooth on a flat map, from "position" into "smoothed" (added once).
template <typename MAP>
void time_flat_smoothing(benchmark::State& state, MAP& m)
{
	using V = typename MAP::Vertex;
	const auto pos = get_attribute<Vec3, V>(m, "position");
	auto out = get_attribute<Vec3, V>(m, "smoothed");
	if (!out)
		out = add_attribute<Vec3, V>(m, "smoothed");
	for (auto _ : state)
		smooth(m, *pos, *out);
}

/// The darts of every face walked by phi1.
template <typename MESH>
uint32 walk_faces(const MESH& m)
{
	using F = typename mesh_traits<MESH>::Face;
	uint32 n = 0;
	foreach_cell(m, [&](F f) {
		const Dart d = f.dart;
		Dart it = d;
		do
		{
			it = phi1(m, it);
			++n;
		} while (it != d);
	});
	return n;
}

} // namespace
} // namespace cgogn::bench_mr
