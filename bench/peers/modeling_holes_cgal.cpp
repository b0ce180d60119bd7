// SPDX-License-Identifier: MIT
// CGAL's hole filling on a Surface_mesh, for bench_modeling_holes.
#include "modeling_holes.h"

#include <benchmark/benchmark.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>
#include <filesystem>
#include <iterator>
#include <vector>

namespace cgogn::bench_holes
{

namespace
{

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Halfedge = boost::graph_traits<Mesh>::halfedge_descriptor;
using Face = boost::graph_traits<Mesh>::face_descriptor;
using Vertex = boost::graph_traits<Mesh>::vertex_descriptor;
namespace PMP = CGAL::Polygon_mesh_processing;

/// refine_and_fair: triangulate_refine_and_fair_hole, else triangulate_hole.
/// delaunay: CGAL's default search space (the 3D Delaunay triangulation of
/// the loop, falling back to all triangles), else the full O(n^3) one.
void cgal_fill_holes(benchmark::State& state, const std::string& path, bool refine_and_fair, bool delaunay)
{
	Mesh original;
	if (!CGAL::IO::read_polygon_mesh(path, original))
	{
		state.SkipWithError("CGAL could not read the mesh");
		return;
	}
	std::size_t holes = 0, faces = 0, vertices = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		Mesh m = original;
		std::vector<Face> new_faces;
		std::vector<Vertex> new_vertices;
		state.ResumeTiming();
		std::vector<Halfedge> borders;
		PMP::extract_boundary_cycles(m, std::back_inserter(borders));
		for (Halfedge h : borders)
		{
			const auto np = PMP::parameters::use_delaunay_triangulation(delaunay);
			if (refine_and_fair)
				PMP::triangulate_refine_and_fair_hole(m, h, std::back_inserter(new_faces),
													  std::back_inserter(new_vertices), np);
			else
				PMP::triangulate_hole(m, h, std::back_inserter(new_faces), np);
		}
		holes = borders.size();
		faces = new_faces.size();
		vertices = new_vertices.size();
	}
	state.counters["holes"] = double(holes);
	state.counters["faces_added"] = double(faces);
	state.counters["vertices_added"] = double(vertices);
}

} // namespace

void register_cgal_benchmarks()
{
	for (const HoleMesh& h : hole_meshes)
	{
		const std::string path = data_file(h.file);
		if (!std::filesystem::exists(path))
			continue;
		for (const bool delaunay : {true, false})
		{
			const std::string space = delaunay ? "cgal_delaunay/" : "cgal_full/";
			benchmark::RegisterBenchmark(("fill_holes/triangulate/" + space + h.name).c_str(), cgal_fill_holes, path,
										 false, delaunay)
				->Unit(benchmark::kMillisecond);
			benchmark::RegisterBenchmark(("fill_holes/refine_fair/" + space + h.name).c_str(), cgal_fill_holes, path,
										 true, delaunay)
				->Unit(benchmark::kMillisecond);
		}
	}
}

} // namespace cgogn::bench_holes
