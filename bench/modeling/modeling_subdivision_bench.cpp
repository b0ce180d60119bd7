// SPDX-License-Identifier: MIT
// One step of Loop, sqrt3 and Catmull-Clark on nefertiti.obj (100k
// triangles): cgogn::modeling against OpenMesh's uniform subdividers and
// CGAL's Subdivision_method_3 (each peer only when found). Building each
// library's mesh is outside the timed region; CPU time is the measure.
#include "modeling_subdivision_bench.h"

#include <cgogn/cgogn.h>

#include <benchmark/benchmark.h>

#ifdef CGOGN_BENCH_HAS_OPENMESH
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>
#endif

#include "cgogn_test_data.h"

#include <filesystem>
#include <string>

namespace cgogn::bench
{

const SubdivisionInput& subdivision_input()
{
	static const SubdivisionInput input = [] {
		SubdivisionInput in;
		const std::string path = cgogn_test_data::path("surface/nefertiti.obj");
		if (!std::filesystem::exists(path))
			return in;
		CMap2 m;
		io::load_surface(m, path);
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		std::vector<uint32> id(pos->container()->end_index(), 0);
		foreach_cell(m, [&](CMap2::Vertex v) {
			id[index_of(m, v)] = uint32(in.points.size());
			const Vec3& p = (*pos)[index_of(m, v)];
			in.points.push_back({p.x(), p.y(), p.z()});
		});
		foreach_cell(m, [&](CMap2::Face f) {
			std::vector<uint32> face;
			foreach_incident_vertex(m, f, [&](CMap2::Vertex v) { face.push_back(id[index_of(m, v)]); });
			in.faces.push_back(face);
		});
		return in;
	}();
	return input;
}

} // namespace cgogn::bench

using namespace cgogn;
using cgogn::bench::subdivision_input;

namespace
{

std::shared_ptr<AttributeArray<Vec3>> build_cgogn(CMap2& m)
{
	const auto& in = subdivision_input();
	std::vector<uint32> sizes, vertices;
	for (const auto& f : in.faces)
	{
		sizes.push_back(uint32(f.size()));
		vertices.insert(vertices.end(), f.begin(), f.end());
	}
	const BuildReport r = build_surface(m, uint32(in.points.size()), sizes, vertices);
	auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
	for (std::size_t i = 0; i < in.points.size(); ++i)
		(*pos)[r.vertex_offset + uint32(i)] = Vec3(in.points[i][0], in.points[i][1], in.points[i][2]);
	return pos;
}

/// Attributes with rules, as a loaded mesh with data has them: a colour per
/// vertex (interpolated), a region per face (copied), a texture coordinate
/// per corner (interpolated).
void add_ruled_attributes(CMap2& m, const AttributeArray<Vec3>& pos)
{
	auto colour = add_attribute<Vec3, CMap2::Vertex>(m, "colour");
	auto region = add_attribute<int32, CMap2::Face>(m, "region");
	auto uv = add_attribute<Vec2, CMap2::HalfEdge>(m, "uv");
	foreach_cell(m, [&](CMap2::Vertex v) { value<Vec3>(m, colour, v) = pos[index_of(m, v)]; });
	foreach_cell(m, [&](CMap2::Face f) { value<int32>(m, region, f) = int32(index_of(m, f) % 7); });
	foreach_dart(m, [&](Dart d) { (*uv)[d.index] = pos[index_of(m, CMap2::Vertex(d))].head<2>(); });
}

void cgogn_subdivision(benchmark::State& state, modeling::SurfaceScheme scheme, bool rules)
{
	if (subdivision_input().faces.empty())
	{
		state.SkipWithError("nefertiti.obj not found");
		return;
	}
	double faces = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		{
			CMap2 m;
			auto pos = build_cgogn(m);
			if (rules)
				add_ruled_attributes(m, *pos);
			state.ResumeTiming();
			modeling::subdivide(m, *pos, scheme, 1);
			state.PauseTiming();
			faces = nb_cells<CMap2::Face>(m);
		} // the map is destroyed outside the timed region
		state.ResumeTiming();
	}
	state.counters["faces"] = faces;
}

#ifdef CGOGN_BENCH_HAS_OPENMESH
struct DoubleTraits : OpenMesh::DefaultTraits
{
	using Point = OpenMesh::Vec3d;
	using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

template <typename MESH>
void build_openmesh(MESH& om)
{
	const auto& in = subdivision_input();
	std::vector<typename MESH::VertexHandle> vh;
	for (const auto& p : in.points)
		vh.push_back(om.add_vertex(typename MESH::Point(p[0], p[1], p[2])));
	std::vector<typename MESH::VertexHandle> fv;
	for (const auto& f : in.faces)
	{
		fv.clear();
		for (uint32 i : f)
			fv.push_back(vh[i]);
		om.add_face(fv);
	}
}

template <typename SUBDIVIDER, typename MESH>
void openmesh_subdivision(benchmark::State& state)
{
	if (subdivision_input().faces.empty())
	{
		state.SkipWithError("nefertiti.obj not found");
		return;
	}
	double faces = 0;
	for (auto _ : state)
	{
		state.PauseTiming();
		{
			MESH om;
			build_openmesh(om);
			SUBDIVIDER sub;
			state.ResumeTiming();
			sub.attach(om);
			sub(1);
			sub.detach();
			state.PauseTiming();
			faces = double(om.n_faces());
		}
		state.ResumeTiming();
	}
	state.counters["faces"] = faces;
}
#endif

const int registered = [] {
	const auto unit = benchmark::kMillisecond;
	benchmark::RegisterBenchmark("loop/cgogn", cgogn_subdivision, modeling::SurfaceScheme::Loop, false)->Unit(unit);
	benchmark::RegisterBenchmark("sqrt3/cgogn", cgogn_subdivision, modeling::SurfaceScheme::Sqrt3, false)->Unit(unit);
	benchmark::RegisterBenchmark("catmull_clark/cgogn", cgogn_subdivision, modeling::SurfaceScheme::CatmullClark, false)
		->Unit(unit);
	// the same with three attributes that follow the edit (rules)
	benchmark::RegisterBenchmark("loop/cgogn_rules", cgogn_subdivision, modeling::SurfaceScheme::Loop, true)
		->Unit(unit);
#ifdef CGOGN_BENCH_HAS_OPENMESH
	using namespace OpenMesh::Subdivider::Uniform;
	benchmark::RegisterBenchmark("loop/openmesh", openmesh_subdivision<LoopT<TriMesh, double>, TriMesh>)->Unit(unit);
	benchmark::RegisterBenchmark("sqrt3/openmesh", openmesh_subdivision<Sqrt3T<TriMesh, double>, TriMesh>)->Unit(unit);
	benchmark::RegisterBenchmark("catmull_clark/openmesh",
								 openmesh_subdivision<CatmullClarkT<PolyMesh, double>, PolyMesh>)
		->Unit(unit);
#endif
#ifdef CGOGN_BENCH_HAS_CGAL
	cgogn::bench::register_cgal_subdivision_benchmarks();
#endif
	return 0;
}();

} // namespace

BENCHMARK_MAIN();
