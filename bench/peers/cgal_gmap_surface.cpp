// SPDX-License-Identifier: MIT
// CGAL Linear_cell_complex_for_generalized_map<2, 3>'s side of bench_gmap
// (bench/micro/gmap_bench.cpp), Simple_cartesian<double>: the same torus,
// built with Linear_cell_complex_incremental_builder_3. For the read-only
// workloads, vertex attributes with the point (the indexed vertices and their
// positions) and face attributes (2-attributes) with a double (the indexed
// faces); for "build", CGAL's minimal items (vertex attributes with the
// point, nothing else). Vertices and faces are visited through their
// attribute containers. Two ways around a cell: CGAL's cell ranges
// (one_dart_per_incident_cell, which marks each incident cell whole and
// unmarks it after), or alpha steps, the walk of cgogn's GMap2: alpha<1, 2>
// around a vertex, next (alpha<0, 1>) around a face.
#include <cgogn/core/build/generators.h>

#include "gmap_bench.h"
#include "harness.h"

#include <CGAL/Linear_cell_complex_for_generalized_map.h>
#include <CGAL/Linear_cell_complex_incremental_builder.h>
#include <CGAL/Simple_cartesian.h>
#include <cstdint>
#include <memory>

namespace
{

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Traits = CGAL::Linear_cell_complex_traits<3, K>;

struct Items
{
	template <class LCC>
	struct Dart_wrapper
	{
		using Vertex_attribute = CGAL::Cell_attribute_with_point<LCC>;
		using Face_attribute = CGAL::Cell_attribute<LCC, double>; // the "face_data" of cgogn's faces
		using Attributes = std::tuple<Vertex_attribute, void, Face_attribute>;
	};
};

using Lcc = CGAL::Linear_cell_complex_for_generalized_map<2, 3, Traits, Items>;
using LccMin = CGAL::Linear_cell_complex_for_generalized_map<2, 3, Traits, CGAL::Linear_cell_complex_min_items>;
using DH = Lcc::Dart_handle;

template <typename LCC>
void build_torus(LCC& m)
{
	const cgogn::SurfaceSoup& s = cgogn::bench::gmap_soup();
	CGAL::Linear_cell_complex_incremental_builder_3<LCC> b(m);
	for (const auto& p : s.positions)
		b.add_vertex(Point(p[0], p[1], p[2]));
	b.begin_surface();
	std::size_t k = 0;
	for (std::uint32_t n : s.face_sizes)
	{
		b.begin_facet();
		for (std::uint32_t i = 0; i < n; ++i)
			b.add_vertex_to_facet(s.face_vertices[k + i]);
		b.end_facet();
		k += n;
	}
	b.end_surface();
}

/// V + E + F, by CGAL's count of the cells (marks)
template <typename LCC>
double nb_cells(LCC& m)
{
	const std::vector<unsigned int> n = m.count_cells({0, 1, 2});
	return double(n[0]) + double(n[1]) + double(n[2]);
}

struct Mesh
{
	Lcc m;
	bool valid = false;
	Mesh()
	{
		build_torus(m);
		for (auto d = m.one_dart_per_cell<2>().begin(), end = m.one_dart_per_cell<2>().end(); d != end; ++d)
			m.set_attribute<2>(d, m.create_attribute<2>(0.0));
		valid = m.is_valid() && m.is_without_boundary() &&
				m.number_of_attributes<2>() == cgogn::bench::gmap_soup().face_sizes.size();
	}
};

Mesh& mesh()
{
	static Mesh me;
	return me;
}

double nb_corners()
{
	double n = 0;
	for (std::uint32_t s : cgogn::bench::gmap_soup().face_sizes)
		n += s;
	return n;
}

} // namespace

namespace cgogn::bench::cgal_gmap
{

// every vertex's faces, then every face's vertices
void circulator(benchmark::State& state, bool alpha_walk)
{
	Mesh& me = mesh();
	Lcc& m = me.m;
	if (!me.valid)
	{
		state.SkipWithError("the CGAL map is not a valid closed surface");
		return;
	}
	std::int64_t up = 0;
	for (auto _ : state)
	{
		std::int64_t c = 0;
		if (alpha_walk)
		{
			for (auto& v : m.vertex_attributes())
			{
				const DH d = v.dart();
				DH x = d;
				do
				{
					++c;
					x = m.alpha<1, 2>(x);
				} while (x != d);
			}
			up = c;
			for (auto& f : m.attributes<2>())
			{
				const DH d = f.dart();
				DH x = d;
				do
				{
					--c;
					x = m.next(x);
				} while (x != d);
			}
		}
		else
		{
			for (auto& v : m.vertex_attributes())
				for (auto it = m.one_dart_per_incident_cell<2, 0>(v.dart()).begin(),
						  end = m.one_dart_per_incident_cell<2, 0>(v.dart()).end();
					 it != end; ++it)
					++c;
			up = c;
			for (auto& f : m.attributes<2>())
				for (auto it = m.one_dart_per_incident_cell<0, 2>(f.dart()).begin(),
						  end = m.one_dart_per_incident_cell<0, 2>(f.dart()).end();
					 it != end; ++it)
					--c;
		}
		if (c != 0)
			state.SkipWithError("circulator check failed");
		benchmark::DoNotOptimize(c);
	}
	state.counters["ns_per_incidence"] = benchmark::Counter(2.0 * nb_corners() * double(state.iterations()),
															benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
	state.counters["check"] = double(up);
}

// one in-place pass of umbrella smoothing over the vertices
void smoothing(benchmark::State& state, bool alpha_walk)
{
	Mesh& me = mesh();
	Lcc& m = me.m;
	if (!me.valid)
	{
		state.SkipWithError("the CGAL map is not a valid closed surface");
		return;
	}
	std::uint64_t incidences = 0;
	for (auto _ : state)
	{
		incidences = 0;
		for (auto& v : m.vertex_attributes())
		{
			double sum[3] = {0, 0, 0};
			std::uint32_t n = 0;
			const auto add = [&](DH other) {
				const Point& q = m.point(other);
				sum[0] += q.x(), sum[1] += q.y(), sum[2] += q.z();
				++n;
			};
			if (alpha_walk)
			{
				const DH d = v.dart();
				DH x = d;
				do
				{
					add(m.alpha<0>(x));
					x = m.alpha<1, 2>(x);
				} while (x != d);
			}
			else
				for (auto it = m.one_dart_per_incident_cell<1, 0>(v.dart()).begin(),
						  end = m.one_dart_per_incident_cell<1, 0>(v.dart()).end();
					 it != end; ++it)
					add(m.alpha<0>(it));
			v.point() = Point(sum[0] / n, sum[1] / n, sum[2] / n);
			incidences += n;
		}
	}
	state.counters["ns_per_incidence"] = benchmark::Counter(double(incidences) * double(state.iterations()),
															benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
	state.counters["check"] = double(incidences);
}

// counting the cells of every kind: vertices and faces have attributes (their
// containers' counts), edges do not (a walk of the darts with a mark)
void count_cells(benchmark::State& state)
{
	Lcc& m = mesh().m;
	std::uint64_t n = 0;
	for (auto _ : state)
	{
		n = m.number_of_vertex_attributes() + m.number_of_attributes<2>();
		for (auto it = m.one_dart_per_cell<1>().begin(), end = m.one_dart_per_cell<1>().end(); it != end; ++it)
			++n;
		benchmark::DoNotOptimize(n);
	}
	state.counters["check"] = double(n);
}

// building the map from the soup, and its memory once built (the builder's
// tables freed)
void build(benchmark::State& state)
{
	double bytes = 0, cells = 0;
	for (auto _ : state)
	{
		const std::size_t before = cgogn_bench::heap_bytes();
		{
			LccMin m;
			build_torus(m);
			bytes = double(cgogn_bench::heap_bytes() - before);
			state.PauseTiming();
			cells = nb_cells(m);
			state.ResumeTiming();
			benchmark::DoNotOptimize(m.number_of_darts());
		}
	}
	state.counters["bytes_per_face"] = bytes / double(gmap_soup().face_sizes.size());
	state.counters["check"] = cells;
}

} // namespace cgogn::bench::cgal_gmap
