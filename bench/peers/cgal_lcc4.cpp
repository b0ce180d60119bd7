// SPDX-License-Identifier: MIT
// CGAL Linear_cell_complex_for_combinatorial_map<4>'s side of bench_nmap
// (bench/micro/nmap_bench.cpp): the hypercube grid of cgogn's CMapN<4>,
// copied dart for dart (CGAL's beta1 is phi1, beta2 ... beta4 are phi2 ...
// phi4; the boundary darts are left out, so the facets on the boundary are
// 4-free), with a 0-attribute holding each vertex's point (Epick_d<4>).
// Cells are walked with CGAL's cell ranges, which mark each cell met whole.
#include <cgogn/core.h>

#include "harness.h"
#include "nmap_bench.h"

#include <CGAL/Epick_d.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <cstdint>
#include <vector>

namespace
{

using K = CGAL::Epick_d<CGAL::Dimension_tag<4>>;
using Traits = CGAL::Linear_cell_complex_traits<4, K>;
using Lcc = CGAL::Linear_cell_complex_for_combinatorial_map<4, 4, Traits>;
using DH = Lcc::Dart_handle;

// the grid's map, copied into m
void copy_grid(Lcc& m)
{
	using namespace cgogn;
	const CMapN<4>& g = cgogn::bench::grid4();
	std::vector<DH> dart(container_of<Orbit::DART>(g).end_index(), m.null_handle);
	foreach_dart(g, [&](Dart d) {
		if (!is_boundary(g, d))
			dart[d.index] = m.create_dart();
	});
	foreach_dart(g, [&](Dart d) {
		if (is_boundary(g, d))
			return;
		m.basic_link_beta_1(dart[d.index], dart[phi1(g, d).index]);
		for (uint32 i = 2; i <= 4; ++i)
		{
			const Dart e = cgogn::detail::relation(g, i, d);
			if (!is_boundary(g, e) && d.index < e.index)
			{
				if (i == 2)
					m.basic_link_beta_for_involution<2>(dart[d.index], dart[e.index]);
				else if (i == 3)
					m.basic_link_beta_for_involution<3>(dart[d.index], dart[e.index]);
				else
					m.basic_link_beta_for_involution<4>(dart[d.index], dart[e.index]);
			}
		}
	});
	const auto position = get_attribute<PointD<4>, CellD<0>>(g, "position");
	foreach_cell(g, [&](CellD<0> v) {
		const PointD<4>& p = (*position)[v];
		const auto a = m.create_vertex_attribute(K::Point_d(p.begin(), p.end()));
		foreach_dart_of_orbit(g, v, [&](Dart d) {
			if (!is_boundary(g, d))
				m.set_dart_attribute<0>(dart[d.index], a);
		});
	});
}

struct Mesh
{
	Lcc m;
	bool valid = false;
	Mesh()
	{
		copy_grid(m);
		valid = m.is_valid();
	}
};

Mesh& mesh()
{
	static Mesh me;
	return me;
}

} // namespace

namespace cgogn::bench::cgal_lcc4
{

// every vertex's 4-cells (the vertex stars)
void vertex_star(benchmark::State& state)
{
	Lcc& m = mesh().m;
	if (!mesh().valid)
	{
		state.SkipWithError("the CGAL map is not valid");
		return;
	}
	std::int64_t c = 0;
	for (auto _ : state)
	{
		c = 0;
		for (auto& v : m.vertex_attributes())
			for (auto it = m.one_dart_per_incident_cell<4, 0>(v.dart()).begin(),
					  end = m.one_dart_per_incident_cell<4, 0>(v.dart()).end();
				 it != end; ++it)
				++c;
		benchmark::DoNotOptimize(c);
	}
	state.counters["check"] = double(c);
}

// every 4-cell's neighbours through its 3-cells
void adjacency(benchmark::State& state)
{
	Lcc& m = mesh().m;
	std::int64_t c = 0;
	for (auto _ : state)
	{
		c = 0;
		for (auto h = m.one_dart_per_cell<4>().begin(), end = m.one_dart_per_cell<4>().end(); h != end; ++h)
			for (auto f = m.one_dart_per_incident_cell<3, 4>(h).begin(),
					  fend = m.one_dart_per_incident_cell<3, 4>(h).end();
				 f != fend; ++f)
				if (!m.is_free<4>(f))
					++c;
		benchmark::DoNotOptimize(c);
	}
	state.counters["check"] = double(c);
}

// the number of cells of each dimension
void f_vector(benchmark::State& state)
{
	Lcc& m = mesh().m;
	double n = 0;
	for (auto _ : state)
	{
		const std::vector<unsigned int> f = m.count_cells({0, 1, 2, 3, 4});
		n = double(f[0]) + double(f[1]) + double(f[2]) + double(f[3]) + double(f[4]);
		benchmark::DoNotOptimize(n);
	}
	state.counters["check"] = n;
}

// the bytes of a copy of the grid, per dart of the grid's cells
void memory(benchmark::State& state)
{
	double bytes = 0, darts = 0;
	for (auto _ : state)
	{
		const std::size_t before = cgogn_bench::heap_bytes();
		Lcc m;
		copy_grid(m);
		bytes = double(cgogn_bench::heap_bytes() - before);
		darts = double(m.number_of_darts());
		benchmark::DoNotOptimize(m);
	}
	state.counters["bytes_per_dart"] = bytes / darts;
	state.counters["check"] = darts;
}

} // namespace cgogn::bench::cgal_lcc4
