// SPDX-License-Identifier: MIT
// Where cgogn's bytes go: builds the surface (CMap2 with position, vertex and
// face normals) and the volume (CMap3 with position) of the suites and prints
// the bytes of every attribute and mark of every container, per face (tet),
// next to the allocator's total. Reads the same inputs as bench_suite
// (--input=data|generated|small).
#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "harness.h"
#include "inputs.h"

#include <cstdio>
#include <cstring>

using namespace cgogn;

namespace
{

void print_map(const CMapBase& m, double per)
{
	auto print_container = [&](const char* what, const AttributeContainer& c) {
		if (c.end_index() == 0)
			return;
		std::printf("  %-10s lines %9u (live %9u)\n", what, c.end_index(), c.nb_lines());
		for (const auto& a : c.attributes())
			std::printf("    %-24s %8.2f B/unit\n", a->name().c_str(), double(a->memory_bytes()) / per);
		std::printf("    %-24s %8.2f B/unit (attributes + persistent marks + free list)\n", "container total",
					double(c.memory_bytes()) / per);
	};
	print_container("darts", *cgogn::detail::state_of(m).darts);
	for (uint32 o = 0; o < NB_ORBITS; ++o)
		print_container(orbit_name(Orbit(o)).data(), *cgogn::detail::state_of(m).cells[o]);
}

} // namespace

int main(int argc, char** argv)
{
	for (int i = 1; i < argc; ++i)
		if (std::strncmp(argv[i], "--input=", 8) == 0)
			cgogn_bench::set_input(argv[i] + 8);
	{
		const SurfaceSoup& s = cgogn_bench::surface_soup();
		cgogn_bench::trim_heap();
		const std::size_t before = cgogn_bench::heap_bytes();
		CMap2 m;
		build_surface(m, s);
		const std::size_t topo = cgogn_bench::heap_bytes() - before;
		add_attribute<Vec3, CMap2::Vertex>(m, "position");
		add_attribute<Vec3, CMap2::Vertex>(m, "normal");
		add_attribute<Vec3, CMap2::Face>(m, "normal");
		const std::size_t all = cgogn_bench::heap_bytes() - before;
		const double nf = double(s.face_sizes.size());
		std::printf("surface: %zu faces; after build_surface %.1f B/face; with position + 2 normals %.1f B/face\n",
					s.face_sizes.size(), double(topo) / nf, double(all) / nf);
		print_map(m, nf);
	}
	{
		const VolumeSoup& s = cgogn_bench::volume_soup();
		cgogn_bench::trim_heap();
		const std::size_t before = cgogn_bench::heap_bytes();
		CMap3 m;
		build_volume(m, s);
		add_attribute<Vec3, CMap3::Vertex>(m, "position");
		const std::size_t all = cgogn_bench::heap_bytes() - before;
		const double nt = double(s.cell_sizes.size());
		std::printf("volume: %zu tets; with position %.1f B/tet\n", s.cell_sizes.size(), double(all) / nt);
		print_map(m, nt);
	}
	return 0;
}
