// SPDX-License-Identifier: MIT
// CGAL Surface_mesh's side of the surface suite: Surface_mesh<Point_3> of
// Simple_cartesian<double>, built with add_vertex / add_face from the shared
// soup, traversed with its circulator ranges (vertices_around_face,
// faces_around_target, vertices_around_target) and property maps, edited with
// Euler::add_center_vertex, Euler::flip_edge, Euler::collapse_edge and
// collect_garbage.
#include "harness.h"
#include "inputs.h"
#include "workload_rules.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>
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
using Mesh = CGAL::Surface_mesh<Point>;
using VI = Mesh::Vertex_index;
using FI = Mesh::Face_index;
using HI = Mesh::Halfedge_index;
using EI = Mesh::Edge_index;

struct SmSurface
{
	Mesh m;
	Mesh::Property_map<VI, Vector> vnormal;
	Mesh::Property_map<FI, Vector> fnormal;

	explicit SmSurface(const cgogn::SurfaceSoup& s)
	{
		m.reserve(s.nb_vertices, s.face_vertices.size() / 2, s.face_sizes.size());
		for (const auto& p : s.positions)
			m.add_vertex(Point(p[0], p[1], p[2]));
		std::vector<VI> fv;
		std::size_t k = 0;
		for (uint32_t n : s.face_sizes)
		{
			fv.clear();
			for (uint32_t i = 0; i < n; ++i)
				fv.push_back(VI(s.face_vertices[k + i]));
			m.add_face(fv);
			k += n;
		}
		vnormal = m.add_property_map<VI, Vector>("v:normal", Vector(0, 0, 0)).first;
		fnormal = m.add_property_map<FI, Vector>("f:normal", Vector(0, 0, 0)).first;
	}
};

SmSurface& mesh()
{
	return Cache::get<SmSurface>("cgal_sm/surface", [] { return std::make_unique<SmSurface>(surface_soup()); });
}

void reset_positions(Mesh& m)
{
	const auto& s = surface_soup();
	for (uint32_t i = 0; i < s.nb_vertices; ++i)
		m.point(VI(i)) = Point(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
}

double position_sum(const Mesh& m)
{
	double s = 0;
	for (VI v : m.vertices())
	{
		const Point& p = m.point(v);
		s += p.x() + p.y() + p.z();
	}
	return s;
}

Vector normalized(const Vector& n)
{
	const double l = std::sqrt(n.squared_length());
	return l > 0 ? n / l : n;
}

void circulator(benchmark::State& state, bool first)
{
	const Mesh& m = mesh().m;
	int64_t c = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			for (VI v : m.vertices())
				for (FI f : m.faces_around_target(m.halfedge(v)))
					c += f != Mesh::null_face(); // faces_around_target reports border halfedges as null faces
			for (FI f : m.faces())
				for (VI v : m.vertices_around_face(m.halfedge(f)))
				{
					(void)v;
					--c;
				}
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
}

void barycenter(benchmark::State& state, bool first)
{
	Mesh& m = mesh().m;
	timed(
		state, first, [&] { reset_positions(m); },
		[&] {
			Vector b(0, 0, 0);
			for (VI v : m.vertices())
				b = b + (m.point(v) - CGAL::ORIGIN);
			b = b / double(m.number_of_vertices());
			for (VI v : m.vertices())
				m.point(v) = m.point(v) - b;
		});
	double s = 0;
	for (VI v : m.vertices())
	{
		const Point& p = m.point(v);
		s += std::abs(p.x()) + std::abs(p.y()) + std::abs(p.z());
	}
	set_check(state, "check", s);
}

void normal(benchmark::State& state, bool first)
{
	SmSurface& me = mesh();
	Mesh& m = me.m;
	timed(
		state, first, [] {},
		[&] {
			for (FI f : m.faces())
			{
				const HI h = m.halfedge(f);
				const Point& p0 = m.point(m.source(h));
				const Point& p1 = m.point(m.target(h));
				const Point& p2 = m.point(m.target(m.next(h)));
				me.fnormal[f] = normalized(CGAL::cross_product(p1 - p0, p2 - p0));
			}
			for (VI v : m.vertices())
			{
				Vector n(0, 0, 0);
				for (FI f : m.faces_around_target(m.halfedge(v)))
					if (f != Mesh::null_face())
						n = n + me.fnormal[f];
				me.vnormal[v] = normalized(n);
			}
		});
	double s = 0;
	for (VI v : m.vertices())
	{
		const Vector& n = me.vnormal[v];
		s += n.x() + n.y() + n.z();
	}
	set_check(state, "check", s);
}

void smoothing(benchmark::State& state, bool first)
{
	Mesh& m = mesh().m;
	timed(
		state, first, [&] { reset_positions(m); },
		[&] {
			for (VI v : m.vertices())
			{
				if (m.is_border(v))
					continue;
				Vector s(0, 0, 0);
				int n = 0;
				for (VI w : m.vertices_around_target(m.halfedge(v)))
				{
					s = s + (m.point(w) - CGAL::ORIGIN);
					++n;
				}
				m.point(v) = CGAL::ORIGIN + s / double(n);
			}
		});
	set_check(state, "check", position_sum(m));
}

void set_counts_and_checksum(benchmark::State& state, const Mesh& m)
{
	set_check(state, "check_V", double(m.number_of_vertices()));
	set_check(state, "check_F", double(m.number_of_faces()));
	set_check(state, "check", position_sum(m));
}

Point centroid(const Mesh& m, FI f)
{
	Vector c(0, 0, 0);
	int n = 0;
	for (VI v : m.vertices_around_face(m.halfedge(f)))
	{
		c = c + (m.point(v) - CGAL::ORIGIN);
		++n;
	}
	return CGAL::ORIGIN + c / double(n);
}

// splits f at a new vertex placed at p (Euler::add_center_vertex); returns it
VI split_face(Mesh& m, FI f, const Point& p)
{
	const HI h = CGAL::Euler::add_center_vertex(m.halfedge(f), m);
	const VI v = m.target(h);
	m.point(v) = p;
	return v;
}

// collapses an edge of v so that v disappears and its neighbour w stays.
// Euler::collapse_edge(e) removes the source of halfedge(e) and keeps its
// target; Surface_mesh orients the edges made by add_center_vertex towards the
// centre, so the centre's index survives: it takes w's position (the same
// connectivity and geometry, the kept index differs; collect_garbage renumbers
// anyway).
void collapse_vertex(Mesh& m, VI v)
{
	const EI e = m.edge(m.halfedge(v));
	const HI h = m.halfedge(e);
	const VI w = m.source(h) == v ? m.target(h) : m.source(h);
	const Point p = m.point(w);
	const VI kept = CGAL::Euler::collapse_edge(e, m);
	m.point(kept) = p;
}

void subdivision(benchmark::State& state, bool)
{
	std::unique_ptr<SmSurface> me;
	timed(
		state, false, [&] { me = fresh_structure<SmSurface>(surface_soup()); },
		[&] {
			Mesh& m = me->m;
			const uint32_t nv = uint32_t(m.number_of_vertices()), ne = uint32_t(m.number_of_edges()),
						   nf = uint32_t(m.number_of_faces());
			std::vector<Point> moved(nv);
			for (uint32_t i = 0; i < nv; ++i)
			{
				const VI v(i);
				if (m.is_border(v))
				{
					moved[i] = m.point(v);
					continue;
				}
				Vector s(0, 0, 0);
				uint32_t n = 0;
				for (VI w : m.vertices_around_target(m.halfedge(v)))
				{
					s = s + (m.point(w) - CGAL::ORIGIN);
					++n;
				}
				const double a = sqrt3_alpha(n);
				moved[i] = CGAL::ORIGIN + ((1 - a) * (m.point(v) - CGAL::ORIGIN) + (a / n) * s);
			}
			for (uint32_t i = 0; i < nf; ++i)
				split_face(m, FI(i), centroid(m, FI(i)));
			for (uint32_t i = 0; i < nv; ++i)
				m.point(VI(i)) = moved[i];
			for (uint32_t i = 0; i < ne; ++i)
			{
				const EI e(i);
				if (m.is_border(e))
					continue;
				const HI h = m.halfedge(e);
				const VI a = m.target(m.next(h)), b = m.target(m.next(m.opposite(h)));
				if (!m.halfedge(a, b).is_valid()) // the flipped edge must not exist already
					CGAL::Euler::flip_edge(h, m);
			}
		});
	set_counts_and_checksum(state, me->m);
}

void collapse(benchmark::State& state, bool)
{
	std::unique_ptr<SmSurface> me;
	timed(
		state, false, [&] { me = fresh_structure<SmSurface>(surface_soup()); },
		[&] {
			Mesh& m = me->m;
			const uint32_t nv = uint32_t(m.number_of_vertices()), nf = uint32_t(m.number_of_faces());
			for (uint32_t i = 0; i < nf; ++i)
				split_face(m, FI(i), Point(0, 0, 0));
			for (uint32_t i = nv, end = uint32_t(m.number_of_vertices()); i < end; ++i)
				collapse_vertex(m, VI(i));
			m.collect_garbage();
		});
	set_counts_and_checksum(state, me->m);
}

void dynamic(benchmark::State& state, bool)
{
	std::unique_ptr<SmSurface> me = fresh_structure<SmSurface>(surface_soup());
	trim_heap();
	Mesh& m = me->m;
	for (auto _ : state)
	{
		double total = 0;
		std::vector<VI> added;
		for (uint32_t b = 0; b < dynamic_batches; ++b)
		{
			const double t0 = thread_seconds();
			const uint32_t nf = uint32_t(m.number_of_faces());
			added.clear();
			for (uint32_t i = 0; i < nf; ++i)
				if (dynamic_selected(i, b))
					added.push_back(split_face(m, FI(i), centroid(m, FI(i))));
			for (VI v : added)
				collapse_vertex(m, v);
			m.collect_garbage();
			const double dt = thread_seconds() - t0;
			total += dt;
			record_batch(state, b, dt);
		}
		state.SetIterationTime(total);
	}
	set_check(state, "check_V", double(m.number_of_vertices()));
	set_check(state, "check_F", double(m.number_of_faces()));
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
		auto me = std::make_unique<SmSurface>(s);
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
	register_bench("surface/circulator/cgal_sm", Kind::read_only, circulator);
	register_bench("surface/barycenter/cgal_sm", Kind::read_only, barycenter);
	register_bench("surface/normal/cgal_sm", Kind::read_only, normal);
	register_bench("surface/smoothing/cgal_sm", Kind::read_only, smoothing);
	register_bench("surface/subdivision/cgal_sm", Kind::topology, subdivision);
	register_bench("surface/collapse/cgal_sm", Kind::topology, collapse);
	register_bench("surface/dynamic/cgal_sm", Kind::single, dynamic);
	register_bench("memory/surface/cgal_sm", Kind::single, memory);
	return true;
}();

} // namespace

} // namespace cgogn_bench
