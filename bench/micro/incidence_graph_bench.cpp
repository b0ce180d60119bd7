// SPDX-License-Identifier: MIT
// The incidence graph beside the CMap2 on the same manifold triangle mesh
// (torus_soup(1000, 500, true): 500,000 vertices, 1,000,000 faces): the
// connectivity's bytes per face, the local traversals, and the load of the
// same OFF file. Then the load of a non-manifold file of the same size (as
// many vertices and triangles: every other triangle of the torus, each with
// a fin on its first edge toward the vertex opposite on the torus, so that
// that edge has three faces) into the incidence graph, against the manifold
// load into the CMap2.
#include <cgogn/cgogn.h>

#include "file_io.h"
#include "formats.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <malloc.h>

using namespace cgogn;
using IG = IncidenceGraph;

namespace
{

const SurfaceSoup& torus()
{
	static const SurfaceSoup s = torus_soup(1000, 500, true);
	return s;
}

// The memory held by the process: the allocator's and cgogn's attribute pages.
std::size_t held_bytes()
{
	const struct mallinfo2 mi = mallinfo2();
	return mi.uordblks + mi.hblkhd + committed_storage_bytes();
}

IG build_complex(const SurfaceSoup& s)
{
	IG ig;
	std::vector<IG::Vertex> v(s.nb_vertices);
	for (auto& x : v)
		x = add_vertex(ig);
	std::size_t k = 0;
	std::vector<IG::Vertex> face;
	for (uint32 n : s.face_sizes)
	{
		face.clear();
		for (uint32 i = 0; i < n; ++i)
			face.push_back(v[s.face_vertices[k + i]]);
		k += n;
		add_face_through_vertices(ig, face);
	}
	return ig;
}

CMap2& cmap()
{
	static CMap2 m = [] {
		CMap2 x;
		build_surface(x, torus());
		return x;
	}();
	return m;
}

IG& complex()
{
	static IG ig = build_complex(torus());
	return ig;
}

// Bytes per face of each structure's connectivity (a CMap2: phi1, phi2, the
// vertex index and the boundary marks; an incidence graph: its records),
// measured as the memory the build adds.
void memory(benchmark::State& state)
{
	double cmap2_bytes = 0, ig_bytes = 0;
	const double faces = double(torus().face_sizes.size());
	for (auto _ : state)
	{
		std::size_t before = held_bytes();
		{
			CMap2 m;
			build_surface(m, torus());
			cmap2_bytes = double(held_bytes() - before) / faces;
		}
		before = held_bytes();
		{
			const IG ig = build_complex(torus());
			ig_bytes = double(held_bytes() - before) / faces;
		}
	}
	state.counters["cmap2_B_per_face"] = cmap2_bytes;
	state.counters["ig_B_per_face"] = ig_bytes;
	state.counters["ratio"] = ig_bytes / cmap2_bytes;
}

// Vertex -> faces, face -> vertices, edge -> faces: the incidences visited.
void cmap2_vertex_faces(benchmark::State& state)
{
	const CMap2& m = cmap();
	for (auto _ : state)
	{
		uint64 n = 0;
		foreach_cell(m, [&](CMap2::Vertex v) { foreach_incident_face(m, v, [&](CMap2::Face) { ++n; }); });
		benchmark::DoNotOptimize(n);
	}
}
void ig_vertex_faces(benchmark::State& state)
{
	const IG& ig = complex();
	for (auto _ : state)
	{
		uint64 n = 0;
		foreach_cell(ig, [&](IG::Vertex v) { foreach_incident_face(ig, v, [&](IG::Face) { ++n; }); });
		benchmark::DoNotOptimize(n);
	}
}
void cmap2_face_vertices(benchmark::State& state)
{
	const CMap2& m = cmap();
	for (auto _ : state)
	{
		uint64 n = 0;
		foreach_cell(
			m, [&](CMap2::Face f) { foreach_incident_vertex(m, f, [&](CMap2::Vertex v) { n += v.dart.index; }); });
		benchmark::DoNotOptimize(n);
	}
}
void ig_face_vertices(benchmark::State& state)
{
	const IG& ig = complex();
	for (auto _ : state)
	{
		uint64 n = 0;
		foreach_cell(ig, [&](IG::Face f) { foreach_incident_vertex(ig, f, [&](IG::Vertex v) { n += v.dart.index; }); });
		benchmark::DoNotOptimize(n);
	}
}
void cmap2_edge_faces(benchmark::State& state)
{
	const CMap2& m = cmap();
	for (auto _ : state)
	{
		uint64 n = 0;
		foreach_cell(m, [&](CMap2::Edge e) { foreach_incident_face(m, e, [&](CMap2::Face) { ++n; }); });
		benchmark::DoNotOptimize(n);
	}
}
void ig_edge_faces(benchmark::State& state)
{
	const IG& ig = complex();
	for (auto _ : state)
	{
		uint64 n = 0;
		foreach_cell(ig, [&](IG::Edge e) { foreach_incident_face(ig, e, [&](IG::Face) { ++n; }); });
		benchmark::DoNotOptimize(n);
	}
}

// The OFF files, written once per process: the torus, and the non-manifold
// file of as many vertices and faces (even triangles of the torus, each with
// a fin on its first edge toward the vertex half the torus away).
const std::string& file(bool non_manifold)
{
	static const std::string dir = [] {
		const auto d = std::filesystem::temp_directory_path() / ("cgogn_ig_bench_" + std::to_string(::getpid()));
		std::filesystem::create_directories(d);
		const SurfaceSoup& s = torus();
		io::detail::MeshData md;
		for (const auto& p : s.positions)
			md.positions.insert(md.positions.end(), p.begin(), p.end());
		md.cell_sizes = s.face_sizes;
		md.cell_vertices = s.face_vertices;
		io::detail::write_file((d / "torus.off").string(), io::detail::write_off(md));
		io::detail::MeshData fins;
		fins.positions = md.positions;
		const uint32 nv = s.nb_vertices;
		for (std::size_t f = 0; f < s.face_sizes.size(); f += 2)
		{
			const uint32* t = &s.face_vertices[3 * f];
			fins.cell_sizes.insert(fins.cell_sizes.end(), {3, 3});
			const uint32 apex = (t[2] + nv / 2) % nv;
			fins.cell_vertices.insert(fins.cell_vertices.end(), {t[0], t[1], t[2], t[0], t[1], apex});
		}
		io::detail::write_file((d / "fins.off").string(), io::detail::write_off(fins));
		return d.string();
	}();
	static const std::string torus_path = dir + "/torus.off", fins_path = dir + "/fins.off";
	return non_manifold ? fins_path : torus_path;
}

void load_cmap2(benchmark::State& state, bool non_manifold)
{
	file(non_manifold); // written before the timing
	for (auto _ : state)
	{
		CMap2 m;
		benchmark::DoNotOptimize(io::load_surface(m, file(non_manifold)).nb_cells_built);
	}
}
void load_ig(benchmark::State& state, bool non_manifold)
{
	file(non_manifold); // written before the timing
	for (auto _ : state)
	{
		IG ig;
		benchmark::DoNotOptimize(io::load_surface(ig, file(non_manifold)).nb_cells_built);
	}
}

} // namespace

BENCHMARK(memory)->Iterations(1)->Unit(benchmark::kMillisecond);
BENCHMARK(cmap2_vertex_faces)->Unit(benchmark::kMillisecond);
BENCHMARK(ig_vertex_faces)->Unit(benchmark::kMillisecond);
BENCHMARK(cmap2_face_vertices)->Unit(benchmark::kMillisecond);
BENCHMARK(ig_face_vertices)->Unit(benchmark::kMillisecond);
BENCHMARK(cmap2_edge_faces)->Unit(benchmark::kMillisecond);
BENCHMARK(ig_edge_faces)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load_cmap2, manifold, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load_ig, manifold, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load_ig, non_manifold, true)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(load_cmap2, non_manifold, true)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
