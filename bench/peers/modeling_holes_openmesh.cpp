// SPDX-License-Identifier: MIT
// OpenMesh's triangulate() of a quad mesh, for bench_modeling_holes.
#include "modeling_holes.h"

#include <benchmark/benchmark.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <filesystem>

namespace cgogn::bench_holes
{

namespace
{

struct Traits : OpenMesh::DefaultTraits
{
	using Point = OpenMesh::Vec3d;
};
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<Traits>;

void openmesh_triangulate(benchmark::State& state, const std::string& path)
{
	PolyMesh original;
	if (!OpenMesh::IO::read_mesh(original, path))
	{
		state.SkipWithError("OpenMesh could not read the mesh");
		return;
	}
	std::size_t faces = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		PolyMesh m = original;
		state.ResumeTiming();
		m.triangulate();
		faces = m.n_faces();
	}
	state.counters["faces"] = double(faces);
}

} // namespace

void register_openmesh_benchmarks()
{
	const std::string path = data_file(quad_mesh);
	if (std::filesystem::exists(path))
		benchmark::RegisterBenchmark("triangulate_quads/openmesh/spot", openmesh_triangulate, path)
			->Unit(benchmark::kMillisecond);
}

} // namespace cgogn::bench_holes
