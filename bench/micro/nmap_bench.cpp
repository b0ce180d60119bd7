// SPDX-License-Identifier: MIT
// The maps of any dimension, in one process: CMapN<2> and CMapN<3> against
// the tuned CMap2 and CMap3 on the same meshes (the generic incidence and
// adjacency functions against the tuned circulators, and the cell counts),
// and CMapN<4> against CGAL's Linear_cell_complex_for_combinatorial_map<4>
// on the same hypercube grid (peers/cgal_lcc4.cpp, when CGAL is found):
// vertex stars, adjacency of 4-cells through 3-cells, the f-vector, and the
// bytes per dart, with the 4-cells indexed (cgogn_indexed) and without.
// The generic traversals run in both forms: once per incidence (cgogn), the
// contract of the tuned circulators and of CGAL's adjacency loop, and each
// cell once (cgogn_each_once, cgogn_indexed).
// Targets: the generic maps within 1.5x of the tuned ones; at D = 4 at least
// 2x faster than CGAL, with no more bytes per dart. Each
// row has a check value that every model of its workload must share; the
// table of times and ratios follows the run.
#include "nmap_bench.h"

#include <cgogn/core.h>

#include "harness.h"
#include "row_table.h"

#include <array>
#include <string>

using namespace cgogn;

namespace
{

// ---- D = 2: a closed torus of 500,000 triangles, vertices and faces indexed

const CMap2& surface()
{
	static const CMap2 m = [] {
		CMap2 s;
		build_surface(s, torus_soup(1000, 250, true));
		add_attribute<double, CMap2::Vertex>(s, "vertex_data");
		add_attribute<double, CMap2::Face>(s, "face_data");
		return s;
	}();
	return m;
}

const CMapN<2>& surface_n()
{
	static const CMapN<2> m = to_nmap(surface()); // the same darts and indexed cells
	return m;
}

// ---- D = 3: the Freudenthal grid of 20^3 cubes (48,000 tetrahedra), vertices and volumes indexed

const CMapN<3>& volume_n()
{
	static const CMapN<3> m = [] {
		CMapN<3> v;
		generate_freudenthal_grid(v, 20);
		add_attribute<double, CellD<3>>(v, "volume_data");
		return v;
	}();
	return m;
}

const CMap3& volume()
{
	static const CMap3 m = to_fixed_map(volume_n());
	return m;
}

// How a workload walks the cells: the tuned circulators of CMap2 and CMap3,
// which report a cell once per incidence; the generic functions with
// `each_incidence`, the same contract; or the generic functions that report
// each cell once.
enum class Walk
{
	tuned,
	each_incidence,
	each_once
};

// every vertex's I-cells, then every I-cell's vertices
template <uint32 I, typename MAP>
void star(benchmark::State& state, const MAP& m, Walk walk)
{
	using Vertex = cell_of_dimension_t<MAP, 0>;
	using Top = cell_of_dimension_t<MAP, I>;
	int64 up = 0;
	for (auto _ : state)
	{
		int64 c = 0;
		if (walk == Walk::each_incidence)
		{
			foreach_cell(m, [&](Vertex v) {
				foreach_incident_cell<I>(
					m, v, [&](Top) { ++c; }, each_incidence);
			});
			up = c;
			foreach_cell(m, [&](Top t) {
				foreach_incident_cell<0>(
					m, t, [&](Vertex) { --c; }, each_incidence);
			});
		}
		else if (walk == Walk::each_once)
		{
			foreach_cell(m, [&](Vertex v) { foreach_incident_cell<I>(m, v, [&](Top) { ++c; }); });
			up = c;
			foreach_cell(m, [&](Top t) { foreach_incident_cell<0>(m, t, [&](Vertex) { --c; }); });
		}
		else if constexpr (is_nmap_v<MAP>)
			state.SkipWithError("no tuned circulators");
		else if constexpr (I == 2)
		{
			foreach_cell(m, [&](Vertex v) { foreach_incident_face(m, v, [&](Top) { ++c; }); });
			up = c;
			foreach_cell(m, [&](Top t) { foreach_incident_vertex(m, t, [&](Vertex) { --c; }); });
		}
		else
		{
			foreach_cell(m, [&](Vertex v) { foreach_incident_volume(m, v, [&](Top) { ++c; }); });
			up = c;
			foreach_cell(m, [&](Top t) { foreach_incident_vertex(m, t, [&](Vertex) { --c; }); });
		}
		if (c != 0)
			state.SkipWithError("incidence check failed");
		benchmark::DoNotOptimize(c);
	}
	state.counters["check"] = double(up);
}

// every vertex's neighbours through its edges (walked as in star)
template <typename MAP>
void neighbours(benchmark::State& state, const MAP& m, Walk walk)
{
	using Vertex = cell_of_dimension_t<MAP, 0>;
	int64 c = 0;
	for (auto _ : state)
	{
		c = 0;
		if (walk == Walk::each_incidence)
			foreach_cell(m, [&](Vertex v) {
				foreach_adjacent_cell<1>(
					m, v, [&](Vertex) { ++c; }, each_incidence);
			});
		else if (walk == Walk::each_once)
			foreach_cell(m, [&](Vertex v) { foreach_adjacent_cell<1>(m, v, [&](Vertex) { ++c; }); });
		else if constexpr (is_nmap_v<MAP>)
			state.SkipWithError("no tuned circulators");
		else
			foreach_cell(m, [&](Vertex v) { foreach_adjacent_vertex_through_edge(m, v, [&](Vertex) { ++c; }); });
		benchmark::DoNotOptimize(c);
	}
	state.counters["check"] = double(c);
}

// the f-vector (the indexed orbits in O(1), the others by a walk of the darts)
template <typename MAP>
void count(benchmark::State& state, const MAP& m)
{
	double n = 0;
	for (auto _ : state)
	{
		n = 0;
		for (uint32 k : f_vector(m))
			n += k;
		benchmark::DoNotOptimize(n);
	}
	state.counters["check"] = n;
}

// ---- D = 4: the grid of 8^4 hypercubes, its vertices indexed (positions),
// and the same grid with its 4-cells indexed too

const CMapN<4>& grid4_indexed()
{
	static const CMapN<4> m = [] {
		CMapN<4> g;
		generate_cube_grid(g, 8);
		index_cells<CellD<4>>(g);
		return g;
	}();
	return m;
}

// every vertex's 4-cells (each once, or once per incidence)
void star4(benchmark::State& state, const CMapN<4>& m, Walk walk = Walk::each_once)
{
	int64 c = 0;
	for (auto _ : state)
	{
		c = 0;
		if (walk == Walk::each_incidence)
			foreach_cell(m, [&](CellD<0> v) {
				foreach_incident_cell<4>(
					m, v, [&](CellD<4>) { ++c; }, each_incidence);
			});
		else
			foreach_cell(m, [&](CellD<0> v) { foreach_incident_cell<4>(m, v, [&](CellD<4>) { ++c; }); });
		benchmark::DoNotOptimize(c);
	}
	state.counters["check"] = double(c);
}

// every 4-cell's neighbours through its 3-cells (each once, or once per
// shared 3-cell)
void adjacency4(benchmark::State& state, const CMapN<4>& m, Walk walk = Walk::each_once)
{
	int64 c = 0;
	for (auto _ : state)
	{
		c = 0;
		if (walk == Walk::each_incidence)
			foreach_cell(m, [&](CellD<4> h) {
				foreach_adjacent_cell<3>(
					m, h, [&](CellD<4>) { ++c; }, each_incidence);
			});
		else
			foreach_cell(m, [&](CellD<4> h) { foreach_adjacent_cell<3>(m, h, [&](CellD<4>) { ++c; }); });
		benchmark::DoNotOptimize(c);
	}
	state.counters["check"] = double(c);
}

// the bytes of a copy of the grid (relations, marks, vertex indices and
// positions, and the 4-cell indices when asked), per dart of its cells (not
// counting the boundary darts, which CGAL's open map does not have)
void memory4(benchmark::State& state, bool index_4_cells)
{
	double bytes = 0, darts = 0;
	for (auto _ : state)
	{
		const std::size_t before = cgogn_bench::heap_bytes();
		CMapN<4> m;
		generate_cube_grid(m, 8);
		if (index_4_cells)
			index_cells<CellD<4>>(m);
		bytes = double(cgogn_bench::heap_bytes() - before);
		darts = 0;
		foreach_dart(m, [&](Dart d) { darts += !is_boundary(m, d); });
		benchmark::DoNotOptimize(m);
	}
	state.counters["bytes_per_dart"] = bytes / darts;
	state.counters["check"] = darts;
}

} // namespace

const CMapN<4>& cgogn::bench::grid4()
{
	static const CMapN<4> m = [] {
		CMapN<4> g;
		generate_cube_grid(g, 8);
		return g;
	}();
	return m;
}

int main(int argc, char** argv)
{
	cgogn::bench::RowTable table("cgogn", "bytes_per_dart");
	// D = 2 and 3: the generic map, each incidence as the tuned circulators
	// (cgogn) or each once (cgogn_each_once), against the tuned one (tuned,
	// and the generic functions on it: tuned_generic); the meshes are built
	// when a benchmark first asks for them
	const auto models = [&](const std::string& workload, auto run, auto fixed, auto generic) {
		table.add(workload, "tuned", [=](benchmark::State& s) { run(s, fixed(), Walk::tuned); });
		table.add(workload, "cgogn", [=](benchmark::State& s) { run(s, generic(), Walk::each_incidence); });
		table.add(workload, "cgogn_each_once", [=](benchmark::State& s) { run(s, generic(), Walk::each_once); });
		table.add(workload, "tuned_generic", [=](benchmark::State& s) { run(s, fixed(), Walk::each_incidence); });
	};
	models(
		"2d_vertex_faces", [](benchmark::State& s, const auto& m, Walk w) { star<2>(s, m, w); }, surface, surface_n);
	models(
		"2d_neighbours", [](benchmark::State& s, const auto& m, Walk w) { neighbours(s, m, w); }, surface, surface_n);
	table.add("2d_f_vector", "tuned", [](benchmark::State& s) { count(s, surface()); });
	table.add("2d_f_vector", "cgogn", [](benchmark::State& s) { count(s, surface_n()); });
	models(
		"3d_vertex_volumes", [](benchmark::State& s, const auto& m, Walk w) { star<3>(s, m, w); }, volume, volume_n);
	models(
		"3d_neighbours", [](benchmark::State& s, const auto& m, Walk w) { neighbours(s, m, w); }, volume, volume_n);
	table.add("3d_f_vector", "tuned", [](benchmark::State& s) { count(s, volume()); });
	table.add("3d_f_vector", "cgogn", [](benchmark::State& s) { count(s, volume_n()); });
	// D = 4: the generic map, each incidence (cgogn) or each once, with its
	// 4-cells indexed (cgogn_indexed) or not (cgogn_each_once)
	table.add("4d_vertex_star", "cgogn",
			  [](benchmark::State& s) { star4(s, cgogn::bench::grid4(), Walk::each_incidence); });
	table.add("4d_vertex_star", "cgogn_each_once", [](benchmark::State& s) { star4(s, cgogn::bench::grid4()); });
	table.add("4d_vertex_star", "cgogn_indexed", [](benchmark::State& s) { star4(s, grid4_indexed()); });
	table.add("4d_adjacency_through_3_cells", "cgogn",
			  [](benchmark::State& s) { adjacency4(s, cgogn::bench::grid4(), Walk::each_incidence); });
	table.add("4d_adjacency_through_3_cells", "cgogn_each_once",
			  [](benchmark::State& s) { adjacency4(s, cgogn::bench::grid4()); });
	table.add("4d_adjacency_through_3_cells", "cgogn_indexed",
			  [](benchmark::State& s) { adjacency4(s, grid4_indexed()); });
	table.add(
		"4d_memory", "cgogn", [](benchmark::State& s) { memory4(s, false); }, 1);
	table.add(
		"4d_memory", "cgogn_indexed", [](benchmark::State& s) { memory4(s, true); }, 1);
#ifdef CGOGN_BENCH_HAS_CGAL
	namespace peer = cgogn::bench::cgal_lcc4;
	table.add("4d_vertex_star", "CGAL_LCC", peer::vertex_star);
	table.add("4d_adjacency_through_3_cells", "CGAL_LCC", peer::adjacency);
	table.add("4d_f_vector", "CGAL_LCC", peer::f_vector);
	table.add("4d_memory", "CGAL_LCC", peer::memory, 1);
#endif
	table.add("4d_f_vector", "cgogn", [](benchmark::State& s) { count(s, cgogn::bench::grid4()); });
	table.add("4d_f_vector", "cgogn_indexed", [](benchmark::State& s) { count(s, grid4_indexed()); });
	return table.run(argc, argv);
}
