// SPDX-License-Identifier: MIT
// The software renderer on a 1M-triangle sphere at 1920x1080: the target is
// under 2 s per picture, single-threaded.
#include <cgogn/cgogn.h>

#include <benchmark/benchmark.h>

namespace
{

using namespace cgogn;

struct Sphere
{
	CMap2 m;
	std::shared_ptr<CellAttribute<Vec3, CMap2::Vertex::ORBIT>> pos;
	Sphere()
	{
		// 2 x 1000 x 499 = 998000 triangles
		const SurfaceSoup s = sphere_soup(1000, 500, true);
		const BuildReport r = build_surface(m, s);
		pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	}
};

Sphere& sphere()
{
	static Sphere s;
	return s;
}

void BM_RenderSphere1M(benchmark::State& state)
{
	Sphere& s = sphere();
	render::RenderOptions o;
	o.width = 1920;
	o.height = 1080;
	o.supersampling = uint32_t(state.range(0));
	o.edges = state.range(1) != 0;
	o.color = state.range(2) != 0 ? render::ColorSource::Quality : render::ColorSource::Uniform;
	for (auto _ : state)
	{
		render::Image img = render::render_surface(s.m, *s.pos, o);
		benchmark::DoNotOptimize(img.rgb.data());
	}
	state.counters["triangles"] = double(nb_cells<CMap2::Face>(s.m));
}
BENCHMARK(BM_RenderSphere1M)
	->ArgNames({"ssaa", "edges", "color"})
	->Args({2, 0, 0})
	->Args({3, 0, 0})
	->Args({2, 1, 1})
	->Unit(benchmark::kMillisecond)
	->Iterations(3);

} // namespace

BENCHMARK_MAIN();
