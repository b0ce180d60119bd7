// SPDX-License-Identifier: MIT
// CGAL Linear_cell_complex_for_combinatorial_map<2, 3>'s side of the surface
// suite: vertex attributes with the point and the vertex normal (info), face
// attributes (2-attributes) with the face normal, Simple_cartesian<double>.
// Built with Linear_cell_complex_incremental_builder_3; cells walked through
// their attribute containers and darts_of_cell / darts_of_orbit ranges;
// edited with insert_point_in_cell<2>, remove_cell<1> +
// insert_cell_1_in_cell_2 (the flip of a combinatorial map) and
// contract_cell<1> + contract_cell<2> (edge collapse). The compact container
// reuses freed elements: no garbage collection.
#include "harness.h"
#include "inputs.h"
#include "workload_rules.h"

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Linear_cell_complex_incremental_builder.h>
#include <CGAL/Simple_cartesian.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace cgogn_bench
{

namespace
{

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Vector = K::Vector_3;

struct Items
{
	template <class LCC>
	struct Dart_wrapper
	{
		using Vertex_attribute = CGAL::Cell_attribute_with_point<LCC, Vector>; // info: the vertex normal
		using Face_attribute = CGAL::Cell_attribute<LCC, Vector>;              // info: the face normal
		using Attributes = std::tuple<Vertex_attribute, void, Face_attribute>;
	};
};

using Lcc = CGAL::Linear_cell_complex_for_combinatorial_map<2, 3, CGAL::Linear_cell_complex_traits<3, K>, Items>;
using DH = Lcc::Dart_handle;
using VAH = Lcc::Vertex_attribute_handle;

struct LccSurface
{
	Lcc m;
	std::vector<VAH> vertices; // in soup order, to reset positions

	explicit LccSurface(const cgogn::SurfaceSoup& s)
	{
		CGAL::Linear_cell_complex_incremental_builder_3<Lcc> b(m);
		for (const auto& p : s.positions)
			vertices.push_back(b.add_vertex(Point(p[0], p[1], p[2])));
		b.begin_surface();
		std::size_t k = 0;
		for (uint32_t n : s.face_sizes)
		{
			b.begin_facet();
			for (uint32_t i = 0; i < n; ++i)
				b.add_vertex_to_facet(s.face_vertices[k + i]);
			b.end_facet();
			k += n;
		}
		b.end_surface();
		for (auto d = m.one_dart_per_cell<2>().begin(); d != m.one_dart_per_cell<2>().end(); ++d)
			m.set_attribute<2>(d, m.create_attribute<2>(Vector(0, 0, 0)));
	}
	void reset_positions()
	{
		const auto& s = surface_soup();
		for (uint32_t i = 0; i < s.nb_vertices; ++i)
			vertices[i]->point() = Point(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	}
};

LccSurface& mesh()
{
	return Cache::get<LccSurface>("cgal_lcc/surface", [] { return std::make_unique<LccSurface>(surface_soup()); });
}

double position_sum(Lcc& m)
{
	double s = 0;
	for (auto& v : m.vertex_attributes())
		s += v.point().x() + v.point().y() + v.point().z();
	return s;
}

Vector normalized(const Vector& n)
{
	const double l = std::sqrt(n.squared_length());
	return l > 0 ? n / l : n;
}

bool is_border_vertex(Lcc& m, DH d)
{
	for (auto it = m.darts_of_cell<0>(d).begin(), end = m.darts_of_cell<0>(d).end(); it != end; ++it)
		if (m.is_free<2>(it))
			return true;
	return false;
}

void circulator(benchmark::State& state, bool first)
{
	Lcc& m = mesh().m;
	int64_t c = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			for (auto& v : m.vertex_attributes())
				for (auto it = m.darts_of_cell<0>(v.dart()).begin(), end = m.darts_of_cell<0>(v.dart()).end();
					 it != end; ++it)
					++c; // one dart of the vertex per incident face
			for (auto& f : m.attributes<2>())
				for (auto it = m.darts_of_orbit<1>(f.dart()).begin(), end = m.darts_of_orbit<1>(f.dart()).end();
					 it != end; ++it)
					--c;
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
}

void barycenter(benchmark::State& state, bool first)
{
	LccSurface& me = mesh();
	Lcc& m = me.m;
	timed(
		state, first, [&] { me.reset_positions(); },
		[&] {
			Vector b(0, 0, 0);
			for (auto& v : m.vertex_attributes())
				b = b + (v.point() - CGAL::ORIGIN);
			b = b / double(m.number_of_vertex_attributes());
			for (auto& v : m.vertex_attributes())
				v.point() = v.point() - b;
		});
	double s = 0;
	for (auto& v : m.vertex_attributes())
		s += std::abs(v.point().x()) + std::abs(v.point().y()) + std::abs(v.point().z());
	set_check(state, "check", s);
}

void normal(benchmark::State& state, bool first)
{
	Lcc& m = mesh().m;
	timed(
		state, first, [] {},
		[&] {
			for (auto& f : m.attributes<2>())
			{
				const DH d = f.dart();
				const Point& p0 = m.point(d);
				const Point& p1 = m.point(m.next(d));
				const Point& p2 = m.point(m.next(m.next(d)));
				f.info() = normalized(CGAL::cross_product(p1 - p0, p2 - p0));
			}
			for (auto& v : m.vertex_attributes())
			{
				Vector n(0, 0, 0);
				for (auto it = m.darts_of_cell<0>(v.dart()).begin(), end = m.darts_of_cell<0>(v.dart()).end();
					 it != end; ++it)
					n = n + m.info<2>(it);
				v.info() = normalized(n);
			}
		});
	double s = 0;
	for (auto& v : m.vertex_attributes())
		s += v.info().x() + v.info().y() + v.info().z();
	set_check(state, "check", s);
}

Point one_ring_mean(Lcc& m, DH d, uint32_t& n)
{
	Vector s(0, 0, 0);
	n = 0;
	for (auto it = m.darts_of_cell<0>(d).begin(), end = m.darts_of_cell<0>(d).end(); it != end; ++it)
	{
		s = s + (m.point(m.next(it)) - CGAL::ORIGIN);
		++n;
	}
	return CGAL::ORIGIN + s / double(n);
}

void smoothing(benchmark::State& state, bool first)
{
	LccSurface& me = mesh();
	Lcc& m = me.m;
	timed(
		state, first, [&] { me.reset_positions(); },
		[&] {
			for (auto& v : m.vertex_attributes())
			{
				if (is_border_vertex(m, v.dart()))
					continue;
				uint32_t n;
				v.point() = one_ring_mean(m, v.dart(), n);
			}
		});
	set_check(state, "check", position_sum(m));
}

void set_counts_and_checksum(benchmark::State& state, Lcc& m)
{
	set_check(state, "check_V", double(m.number_of_vertex_attributes()));
	set_check(state, "check_F", double(m.number_of_attributes<2>()));
	set_check(state, "check", position_sum(m));
}

Point centroid(Lcc& m, DH d)
{
	Vector c(0, 0, 0);
	int n = 0;
	for (auto it = m.darts_of_orbit<1>(d).begin(), end = m.darts_of_orbit<1>(d).end(); it != end; ++it, ++n)
		c = c + (m.point(it) - CGAL::ORIGIN);
	return CGAL::ORIGIN + c / double(n);
}

bool adjacent(Lcc& m, DH a, VAH b)
{
	for (auto it = m.darts_of_cell<0>(a).begin(), end = m.darts_of_cell<0>(a).end(); it != end; ++it)
		if (m.vertex_attribute(m.next(it)) == b)
			return true;
	return false;
}

// the dart d goes from x to y in triangle (x, y, z), its opposite from y to x
// in (y, x, w): remove the edge (a quad) and insert the diagonal z-w
void flip(Lcc& m, DH d)
{
	const DH dz = m.previous(d), dw = m.previous(m.opposite<2>(d));
	m.remove_cell<1>(d);
	m.insert_cell_1_in_cell_2(dz, dw);
}

// collapses the edge of new vertex v (dart dv leaves v): v disappears, its
// neighbour w keeps its position; the two triangles on the edge become 2-gons
// and are contracted too
void collapse_vertex(Lcc& m, DH dv)
{
	const Point p = m.point(m.next(dv));
	const DH a = m.next(dv), b = m.next(m.opposite<2>(dv));
	m.contract_cell<1>(dv);
	m.contract_cell<2>(a);
	m.contract_cell<2>(b);
	m.point(b) = p;
}

void subdivision(benchmark::State& state, bool)
{
	std::unique_ptr<LccSurface> me;
	timed(
		state, false, [&] { me = fresh_structure<LccSurface>(surface_soup()); },
		[&] {
			Lcc& m = me->m;
			std::vector<VAH> vertices;
			std::vector<Point> moved;
			for (auto v = m.vertex_attributes().begin(); v != m.vertex_attributes().end(); ++v)
			{
				vertices.push_back(v);
				if (is_border_vertex(m, v->dart()))
				{
					moved.push_back(v->point());
					continue;
				}
				uint32_t n;
				const Point q = one_ring_mean(m, v->dart(), n);
				const double a = sqrt3_alpha(n);
				moved.push_back(CGAL::ORIGIN + ((1 - a) * (v->point() - CGAL::ORIGIN) + a * (q - CGAL::ORIGIN)));
			}
			std::vector<DH> edges;
			for (auto d = m.one_dart_per_cell<1>().begin(); d != m.one_dart_per_cell<1>().end(); ++d)
				edges.push_back(d);
			std::vector<DH> faces;
			for (auto& f : m.attributes<2>())
				faces.push_back(f.dart());
			for (DH f : faces)
				m.insert_point_in_cell<2>(f, centroid(m, f));
			for (std::size_t i = 0; i < vertices.size(); ++i)
				vertices[i]->point() = moved[i];
			for (DH d : edges)
			{
				if (m.is_free<2>(d))
					continue;
				const DH z = m.previous(d), w = m.previous(m.opposite<2>(d));
				if (!adjacent(m, z, m.vertex_attribute(w)))
					flip(m, d);
			}
		});
	set_counts_and_checksum(state, me->m);
}

void collapse(benchmark::State& state, bool)
{
	std::unique_ptr<LccSurface> me;
	timed(
		state, false, [&] { me = fresh_structure<LccSurface>(surface_soup()); },
		[&] {
			Lcc& m = me->m;
			std::vector<DH> faces;
			for (auto& f : m.attributes<2>())
				faces.push_back(f.dart());
			std::vector<DH> added;
			added.reserve(faces.size());
			for (DH f : faces)
				added.push_back(m.insert_point_in_cell<2>(f, Point(0, 0, 0)));
			for (DH dv : added)
				collapse_vertex(m, dv);
		});
	set_counts_and_checksum(state, me->m);
}

void dynamic(benchmark::State& state, bool)
{
	std::unique_ptr<LccSurface> me = fresh_structure<LccSurface>(surface_soup());
	trim_heap();
	Lcc& m = me->m;
	for (auto _ : state)
	{
		double total = 0;
		std::vector<DH> faces, added;
		for (uint32_t b = 0; b < dynamic_batches; ++b)
		{
			const double t0 = thread_seconds();
			faces.clear();
			added.clear();
			uint32_t rank = 0;
			for (auto& f : m.attributes<2>())
				if (dynamic_selected(rank++, b))
					faces.push_back(f.dart());
			for (DH f : faces)
				added.push_back(m.insert_point_in_cell<2>(f, centroid(m, f)));
			for (DH dv : added)
				collapse_vertex(m, dv);
			const double dt = thread_seconds() - t0;
			total += dt;
			record_batch(state, b, dt);
		}
		state.SetIterationTime(total);
	}
	set_check(state, "check_V", double(m.number_of_vertex_attributes()));
	set_check(state, "check_F", double(m.number_of_attributes<2>()));
}

void memory(benchmark::State& state, bool)
{
	Cache::clear();
	const auto& s = surface_soup();
	std::size_t bytes = 0;
	for (auto _ : state)
	{
		trim_heap();
		const std::size_t before = heap_bytes();
		auto me = std::make_unique<LccSurface>(s);
		me->vertices = {};
		me->vertices.shrink_to_fit(); // the handle table is the benchmark's, not the structure's
		bytes = heap_bytes() - before;
		state.SetIterationTime(1e-9);
		benchmark::DoNotOptimize(me.get());
	}
	state.counters["bytes"] = double(bytes);
	state.counters["bytes_per_face"] = double(bytes) / double(s.face_sizes.size());
	state.counters["bytes_per_vertex"] = double(bytes) / double(s.nb_vertices);
	state.counters["peak_rss_MB"] = double(peak_resident_bytes()) / 1e6;
}

const bool registered = [] {
	register_bench("surface/circulator/cgal_lcc", Kind::read_only, circulator);
	register_bench("surface/barycenter/cgal_lcc", Kind::read_only, barycenter);
	register_bench("surface/normal/cgal_lcc", Kind::read_only, normal);
	register_bench("surface/smoothing/cgal_lcc", Kind::read_only, smoothing);
	register_bench("surface/subdivision/cgal_lcc", Kind::topology, subdivision);
	register_bench("surface/collapse/cgal_lcc", Kind::topology, collapse);
	register_bench("surface/dynamic/cgal_lcc", Kind::single, dynamic);
	register_bench("memory/surface/cgal_lcc", Kind::single, memory);
	return true;
}();

} // namespace

} // namespace cgogn_bench
