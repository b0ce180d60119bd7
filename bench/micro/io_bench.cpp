// SPDX-License-Identifier: MIT
// Loading a 1M-triangle mesh (torus_soup(1000, 500, true): 500,000 vertices,
// 1,000,000 faces) from binary PLY and OFF: cgogn's reader (parse + build of
// the closed 2-map) against OpenMesh's reader into a TriMesh, when OpenMesh is
// available. The files are written once to a temporary folder.
//
// Saving and loading the same torus with 4 attributes (position, a Vec3
// vertex normal, a double vertex value, a double face value) as a whole-map
// .cgmap file against binary PLY, the surface format that carries them all.
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

// This process's folder for the files it writes, removed at exit.
const std::filesystem::path& bench_dir()
{
	struct Folder
	{
		std::filesystem::path path =
			std::filesystem::temp_directory_path() / ("cgogn_io_bench_" + std::to_string(::getpid()));
		Folder()
		{
			std::filesystem::create_directories(path);
		}
		~Folder()
		{
			std::error_code ignored;
			std::filesystem::remove_all(path, ignored);
		}
	};
	static const Folder folder;
	return folder.path;
}

// Writes the torus once per process, in both formats.
const std::string& mesh_file(const char* ext)
{
	static const std::string dir = [] {
		const auto d = bench_dir();
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

// The torus with its 4 attributes, built once per process.
const CMap2& attributed_torus()
{
	static const CMap2 map = [] {
		CMap2 m;
		const SurfaceSoup s = torus_soup(1000, 500, true);
		const BuildReport r = build_surface(m, s);
		auto position = add_attribute<Vec3, CMap2::Vertex>(m, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*position)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		auto normal = add_attribute<Vec3, CMap2::Vertex>(m, "normal");
		auto value = add_attribute<double, CMap2::Vertex>(m, "value");
		auto area = add_attribute<double, CMap2::Face>(m, "area");
		foreach_cell(m, [&](CMap2::Vertex v) {
			(*normal)[v] = (*position)[v].normalized();
			(*value)[v] = (*position)[v].x();
		});
		uint32 k = 0;
		foreach_cell(m, [&](CMap2::Face f) { (*area)[f] = 0.5 + 1e-6 * double(k++); });
		return m;
	}();
	return map;
}

// Where the attributed torus is saved, in each format, by this process.
std::string attributed_path(const char* ext)
{
	return (bench_dir() / (std::string("attributed.") + ext)).string();
}

void save_attributed(benchmark::State& state, const char* ext)
{
	const CMap2& m = attributed_torus();
	const std::string path = attributed_path(ext);
	io::SaveOptions binary;
	binary.binary = true;
	for (auto _ : state)
	{
		// Each save makes a new file, as a single save does. Saved over the
		// previous iteration's file, the save would first wait for the disk
		// to finish writing that file (replacing a file's contents flushes
		// it on ext4), and the loop would time the disk, not the writer.
		state.PauseTiming();
		std::filesystem::remove(path);
		state.ResumeTiming();
		if (std::string(ext) == "cgmap")
			benchmark::DoNotOptimize(io::save_map(m, path).nb_attributes_written);
		else
			io::save_surface(m, path, binary);
	}
	state.counters["MB"] = double(std::filesystem::file_size(path)) / 1e6;
}

void load_attributed(benchmark::State& state, const char* ext)
{
	const std::string path = attributed_path(ext);
	if (!std::filesystem::exists(path))
	{
		state.SkipWithError("run the save benchmark of this format first");
		return;
	}
	for (auto _ : state)
	{
		CMap2 m;
		if (std::string(ext) == "cgmap")
			io::load_map(m, path);
		else
			io::load_surface(m, path);
		benchmark::DoNotOptimize(nb_darts(m));
	}
}

} // namespace

BENCHMARK_CAPTURE(save_attributed, ply_binary, "ply")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(save_attributed, cgmap, "cgmap")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(load_attributed, ply_binary, "ply")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(load_attributed, cgmap, "cgmap")->Unit(benchmark::kMillisecond)->MinTime(2.0);

BENCHMARK_CAPTURE(cgogn_load, ply_binary, "ply")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(cgogn_load, off, "off")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(cgogn_parse, ply_binary, "ply")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK_CAPTURE(cgogn_parse, off, "off")->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(cgogn_build_only)->Unit(benchmark::kMillisecond)->MinTime(2.0);

BENCHMARK_MAIN();
