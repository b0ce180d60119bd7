// SPDX-License-Identifier: MIT
// Loading a 1M-triangle mesh (torus_soup(1000, 500, true): 500,000 vertices,
// 1,000,000 faces) from binary PLY and OFF: cgogn's reader (parse + build of
// the closed 2-map) against OpenMesh's reader into a TriMesh, when OpenMesh is
// available. The files are written once to a temporary folder.
#include <cgogn/cgogn.h>

#include "file_io.h"
#include "formats.h"

#include <benchmark/benchmark.h>

#ifdef CGOGN_BENCH_HAS_OPENMESH
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#endif

#include <filesystem>

using namespace cgogn;

namespace
{

// Writes the torus once per process, in both formats.
const std::string& mesh_file(const char* ext)
{
	static const std::string dir = [] {
		const auto d = std::filesystem::temp_directory_path() / ("cgogn_io_bench_" + std::to_string(::getpid()));
		std::filesystem::create_directories(d);
		// written from the soup by the io writers (what save_surface writes for this map)
		const SurfaceSoup s = torus_soup(1000, 500, true);
		io::detail::MeshData md;
		for (const auto& p : s.positions)
			md.positions.insert(md.positions.end(), p.begin(), p.end());
		md.cell_sizes = s.face_sizes;
		md.cell_vertices = s.face_vertices;
		io::detail::write_file((d / "torus.ply").string(), io::detail::write_ply(md, true, (d / "torus.ply").string()));
		io::detail::write_file((d / "torus.off").string(), io::detail::write_off(md));
		return d.string();
	}();
	static const std::string ply = dir + "/torus.ply", off = dir + "/torus.off";
	return std::string(ext) == "ply" ? ply : off;
}

void cgogn_load(benchmark::State& state, const char* ext)
{
	const std::string& path = mesh_file(ext);
	double faces = 0;
	for (auto _ : state)
	{
		CMap2 m;
		const io::LoadReport r = io::load_surface(m, path);
		faces = double(r.nb_cells_built);
	}
	state.counters["faces"] = faces;
}

// Reading and parsing only (no map): where the time of a load goes.
void cgogn_parse(benchmark::State& state, const char* ext)
{
	const std::string& path = mesh_file(ext);
	for (auto _ : state)
	{
		const std::string data = io::detail::read_file(path);
		const io::detail::MeshData d =
			std::string(ext) == "ply" ? io::detail::read_ply(data, path) : io::detail::read_off(data, path);
		benchmark::DoNotOptimize(d.cell_vertices.data());
	}
}

// build_surface alone on the same soup (the core builder).
void cgogn_build_only(benchmark::State& state)
{
	const SurfaceSoup s = torus_soup(1000, 500, true);
	for (auto _ : state)
	{
		CMap2 m;
		benchmark::DoNotOptimize(build_surface(m, s).nb_cells_built);
	}
}

#ifdef CGOGN_BENCH_HAS_OPENMESH
void openmesh_load(benchmark::State& state, const char* ext)
{
	const std::string& path = mesh_file(ext);
	double faces = 0;
	for (auto _ : state)
	{
		OpenMesh::TriMesh_ArrayKernelT<> m;
		OpenMesh::IO::Options opt;
		if (std::string(ext) == "ply")
			opt += OpenMesh::IO::Options::Binary;
		if (!OpenMesh::IO::read_mesh(m, path, opt))
			state.SkipWithError("OpenMesh could not read the file");
		faces = double(m.n_faces());
	}
	state.counters["faces"] = faces;
}
BENCHMARK_CAPTURE(openmesh_load, ply_binary, "ply")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(openmesh_load, off, "off")->Unit(benchmark::kMillisecond)->MinTime(2.0);
#endif

} // namespace

BENCHMARK_CAPTURE(cgogn_load, ply_binary, "ply")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(cgogn_load, off, "off")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(cgogn_parse, ply_binary, "ply")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(cgogn_parse, off, "off")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(cgogn_build_only)->Unit(benchmark::kMillisecond)->MinTime(2.0);

BENCHMARK_MAIN();
