// SPDX-License-Identifier: MIT
// CGAL's side of the subdivision benchmark (its own translation unit: CGAL
// headers are slow to compile): Catmull-Clark and Loop on a Surface_mesh.
#include "modeling_subdivision_bench.h"

#include <benchmark/benchmark.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

namespace
{

using Kernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;

void build_cgal(CgalMesh& sm)
{
	const auto& in = cgogn::bench::subdivision_input();
	std::vector<CgalMesh::Vertex_index> vh;
	for (const auto& p : in.points)
		vh.push_back(sm.add_vertex(Kernel::Point_3(p[0], p[1], p[2])));
	std::vector<CgalMesh::Vertex_index> fv;
	for (const auto& f : in.faces)
	{
		fv.clear();
		for (std::uint32_t i : f)
			fv.push_back(vh[i]);
		sm.add_face(fv);
	}
}

template <bool CATMULL_CLARK>
void cgal_subdivision(benchmark::State& state)
{
	if (cgogn::bench::subdivision_input().faces.empty())
	{
		state.SkipWithError("nefertiti.obj not found");
		return;
	}
	double faces = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		{
			CgalMesh sm;
			build_cgal(sm);
			state.ResumeTiming();
			if constexpr (CATMULL_CLARK)
				CGAL::Subdivision_method_3::CatmullClark_subdivision(sm, CGAL::parameters::number_of_iterations(1));
			else
				CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
			state.PauseTiming();
			faces = double(sm.number_of_faces());
		}
		state.ResumeTiming();
	}
	state.counters["faces"] = faces;
}

} // namespace

namespace cgogn::bench
{

void register_cgal_subdivision_benchmarks()
{
	benchmark::RegisterBenchmark("catmull_clark/cgal", cgal_subdivision<true>)->Unit(benchmark::kMillisecond);
	benchmark::RegisterBenchmark("loop/cgal", cgal_subdivision<false>)->Unit(benchmark::kMillisecond);
}

} // namespace cgogn::bench
