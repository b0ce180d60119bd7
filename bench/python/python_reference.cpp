// SPDX-License-Identifier: MIT
// The C++ side of bench/python/python_bench.py: times the bulk operations the
// Python bindings expose, called directly, on one mesh file. Prints one line
// per operation, "name milliseconds" (the median of `repeats` runs).
#include <cgogn/cgogn.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

using namespace cgogn;

namespace
{
double median_ms(int repeats, const std::function<void()>& setup, const std::function<void()>& run)
{
	std::vector<double> t;
	for (int i = 0; i < repeats; ++i)
	{
		setup();
		const auto start = std::chrono::steady_clock::now();
		run();
		t.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
	}
	std::sort(t.begin(), t.end());
	return t[t.size() / 2];
}
} // namespace

int main(int argc, char** argv)
{
	if (argc < 2)
	{
		std::fprintf(stderr, "usage: %s MESH [repeats]\n", argv[0]);
		return 2;
	}
	const std::string path = argv[1];
	const int repeats = argc > 2 ? std::stoi(argv[2]) : 5;
	std::unique_ptr<CMap2> m;
	std::shared_ptr<AttributeArray<Vec3>> pos;
	auto fresh = [&] {
		m = std::make_unique<CMap2>();
		io::load_surface(*m, path);
		pos = get_attribute<Vec3, CMap2::Vertex>(*m, "position");
	};
	std::printf("load %.3f\n", median_ms(
								   repeats, [&] { m.reset(); }, fresh));
	fresh();
	std::printf("vertex_normals %.3f\n", median_ms(
											 repeats, [] {},
											 [&] {
												 auto n = add_attribute<Vec3, CMap2::Vertex>(*m, "n");
												 geometry::compute_vertex_normals(*m, *pos, *n);
												 remove_attribute(*m, n);
											 }));
	std::printf("subdivide_loop %.3f\n",
				median_ms(repeats, fresh, [&] { modeling::subdivide(*m, *pos, modeling::SurfaceScheme::Loop, 1); }));
	modeling::DecimationOptions o;
	std::printf("decimate_quarter %.3f\n", median_ms(
											   repeats,
											   [&] {
												   fresh();
												   o.target_faces = nb_cells<CMap2::Face>(*m) / 4;
											   },
											   [&] { modeling::decimate(*m, *pos, o); }));
	return 0;
}
