// SPDX-License-Identifier: MIT
// CGAL Polyhedron_3's side of the surface suite: the list-based halfedge data
// structure (CGAL::HalfedgeDS_list: the vector-based one cannot remove
// elements), Simple_cartesian<double>, items carrying the vertex and face
// normals. Built with Polyhedron_incremental_builder_3 from the shared soup,
// traversed with its circulators, edited with create_center_vertex,
// flip_edge and (through its BGL interface) Euler::collapse_edge. Memory is
// released at once by the list: no garbage collection.
#include "harness.h"
#include "inputs.h"
#include "workload_rules.h"

#include <CGAL/HalfedgeDS_list.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_incremental_builder_3.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
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

// vertices and faces with a normal
struct Items : CGAL::Polyhedron_items_3
{
	template <class Refs, class Traits>
	struct Vertex_wrapper
	{
		struct Vertex : CGAL::HalfedgeDS_vertex_base<Refs, CGAL::Tag_true, Point>
		{
			using Base = CGAL::HalfedgeDS_vertex_base<Refs, CGAL::Tag_true, Point>;
			Vertex() = default;
			explicit Vertex(const Point& p) : Base(p)
			{
			}
			Vector normal{0, 0, 0};
		};
	};
	template <class Refs, class Traits>
	struct Face_wrapper
	{
		struct Face : CGAL::HalfedgeDS_face_base<Refs, CGAL::Tag_true>
		{
			Vector normal{0, 0, 0};
		};
	};
};

using Mesh = CGAL::Polyhedron_3<K, Items, CGAL::HalfedgeDS_list>;
using VH = Mesh::Vertex_handle;
using HH = Mesh::Halfedge_handle;
using FH = Mesh::Facet_handle;

class Builder : public CGAL::Modifier_base<Mesh::HalfedgeDS>
{
public:
	explicit Builder(const cgogn::SurfaceSoup& s) : s_(s)
	{
	}
	void operator()(Mesh::HalfedgeDS& hds) override
	{
		CGAL::Polyhedron_incremental_builder_3<Mesh::HalfedgeDS> b(hds, false);
		b.begin_surface(s_.nb_vertices, s_.face_sizes.size(), s_.face_vertices.size());
		for (const auto& p : s_.positions)
			b.add_vertex(Point(p[0], p[1], p[2]));
		std::size_t k = 0;
		for (uint32_t n : s_.face_sizes)
		{
			b.begin_facet();
			for (uint32_t i = 0; i < n; ++i)
				b.add_vertex_to_facet(s_.face_vertices[k + i]);
			b.end_facet();
			k += n;
		}
		b.end_surface();
	}

private:
	const cgogn::SurfaceSoup& s_;
};

struct PolySurface
{
	Mesh m;
	std::vector<VH> vertices; // in soup order, to reset positions
	explicit PolySurface(const cgogn::SurfaceSoup& s)
	{
		Builder b(s);
		m.delegate(b);
		for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
			vertices.push_back(v);
	}
	void reset_positions()
	{
		const auto& s = surface_soup();
		for (uint32_t i = 0; i < s.nb_vertices; ++i)
			vertices[i]->point() = Point(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	}
};

PolySurface& mesh()
{
	return Cache::get<PolySurface>("cgal_polyhedron/surface",
								   [] { return std::make_unique<PolySurface>(surface_soup()); });
}

double position_sum(Mesh& m)
{
	double s = 0;
	for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
		s += v->point().x() + v->point().y() + v->point().z();
	return s;
}

Vector normalized(const Vector& n)
{
	const double l = std::sqrt(n.squared_length());
	return l > 0 ? n / l : n;
}

bool is_border_vertex(VH v)
{
	Mesh::Halfedge_around_vertex_circulator h = v->vertex_begin(), end = h;
	do
		if (h->is_border())
			return true;
	while (++h != end);
	return false;
}

void circulator(benchmark::State& state, bool first)
{
	Mesh& m = mesh().m;
	int64_t c = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
			{
				Mesh::Halfedge_around_vertex_circulator h = v->vertex_begin(), end = h;
				do
					c += !h->is_border();
				while (++h != end);
			}
			for (FH f = m.facets_begin(); f != m.facets_end(); ++f)
			{
				Mesh::Halfedge_around_facet_circulator h = f->facet_begin(), end = h;
				do
					--c;
				while (++h != end);
			}
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
}

void barycenter(benchmark::State& state, bool first)
{
	PolySurface& me = mesh();
	Mesh& m = me.m;
	timed(
		state, first, [&] { me.reset_positions(); },
		[&] {
			Vector b(0, 0, 0);
			for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
				b = b + (v->point() - CGAL::ORIGIN);
			b = b / double(m.size_of_vertices());
			for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
				v->point() = v->point() - b;
		});
	double s = 0;
	for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
		s += std::abs(v->point().x()) + std::abs(v->point().y()) + std::abs(v->point().z());
	set_check(state, "check", s);
}

void normal(benchmark::State& state, bool first)
{
	Mesh& m = mesh().m;
	timed(
		state, first, [] {},
		[&] {
			for (FH f = m.facets_begin(); f != m.facets_end(); ++f)
			{
				const HH h = f->halfedge();
				const Point& p0 = h->prev()->vertex()->point();
				const Point& p1 = h->vertex()->point();
				const Point& p2 = h->next()->vertex()->point();
				f->normal = normalized(CGAL::cross_product(p1 - p0, p2 - p0));
			}
			for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
			{
				Vector n(0, 0, 0);
				Mesh::Halfedge_around_vertex_circulator h = v->vertex_begin(), end = h;
				do
					if (!h->is_border())
						n = n + h->facet()->normal;
				while (++h != end);
				v->normal = normalized(n);
			}
		});
	double s = 0;
	for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
		s += v->normal.x() + v->normal.y() + v->normal.z();
	set_check(state, "check", s);
}

Point one_ring_mean(VH v, uint32_t& n)
{
	Vector s(0, 0, 0);
	n = 0;
	Mesh::Halfedge_around_vertex_circulator h = v->vertex_begin(), end = h;
	do
	{
		s = s + (h->opposite()->vertex()->point() - CGAL::ORIGIN);
		++n;
	} while (++h != end);
	return CGAL::ORIGIN + s / double(n);
}

void smoothing(benchmark::State& state, bool first)
{
	PolySurface& me = mesh();
	Mesh& m = me.m;
	timed(
		state, first, [&] { me.reset_positions(); },
		[&] {
			for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
			{
				if (is_border_vertex(v))
					continue;
				uint32_t n;
				v->point() = one_ring_mean(v, n);
			}
		});
	set_check(state, "check", position_sum(m));
}

void set_counts_and_checksum(benchmark::State& state, Mesh& m)
{
	set_check(state, "check_V", double(m.size_of_vertices()));
	set_check(state, "check_F", double(m.size_of_facets()));
	set_check(state, "check", position_sum(m));
}

Point centroid(FH f)
{
	Vector c(0, 0, 0);
	int n = 0;
	Mesh::Halfedge_around_facet_circulator h = f->facet_begin(), end = h;
	do
	{
		c = c + (h->vertex()->point() - CGAL::ORIGIN);
		++n;
	} while (++h != end);
	return CGAL::ORIGIN + c / double(n);
}

VH split_face(Mesh& m, FH f, const Point& p)
{
	const HH h = m.create_center_vertex(f->halfedge());
	h->vertex()->point() = p;
	return h->vertex();
}

// collapses the edge from v to a neighbour w: v disappears, w stays
void collapse_vertex(Mesh& m, VH v)
{
	const HH h = v->halfedge()->opposite(); // source v
	CGAL::Euler::collapse_edge(CGAL::edge(h, m), m);
}

bool adjacent(VH a, VH b)
{
	Mesh::Halfedge_around_vertex_circulator h = a->vertex_begin(), end = h;
	do
		if (h->opposite()->vertex() == b)
			return true;
	while (++h != end);
	return false;
}

void subdivision(benchmark::State& state, bool)
{
	std::unique_ptr<PolySurface> me;
	timed(
		state, false, [&] { me = fresh_structure<PolySurface>(surface_soup()); },
		[&] {
			Mesh& m = me->m;
			std::vector<VH> vertices;
			std::vector<Point> moved;
			vertices.reserve(m.size_of_vertices());
			moved.reserve(m.size_of_vertices());
			for (VH v = m.vertices_begin(); v != m.vertices_end(); ++v)
			{
				vertices.push_back(v);
				if (is_border_vertex(v))
				{
					moved.push_back(v->point());
					continue;
				}
				uint32_t n;
				const Point q = one_ring_mean(v, n);
				const double a = sqrt3_alpha(n);
				moved.push_back(CGAL::ORIGIN + ((1 - a) * (v->point() - CGAL::ORIGIN) + a * (q - CGAL::ORIGIN)));
			}
			std::vector<HH> edges;
			edges.reserve(m.size_of_halfedges() / 2);
			for (auto e = m.edges_begin(); e != m.edges_end(); ++e)
				edges.push_back(e);
			std::vector<FH> faces;
			faces.reserve(m.size_of_facets());
			for (FH f = m.facets_begin(); f != m.facets_end(); ++f)
				faces.push_back(f);
			for (FH f : faces)
				split_face(m, f, centroid(f));
			for (std::size_t i = 0; i < vertices.size(); ++i)
				vertices[i]->point() = moved[i];
			for (HH h : edges)
			{
				if (h->is_border_edge())
					continue;
				if (!adjacent(h->next()->vertex(), h->opposite()->next()->vertex()))
					m.flip_edge(h);
			}
		});
	set_counts_and_checksum(state, me->m);
}

void collapse(benchmark::State& state, bool)
{
	std::unique_ptr<PolySurface> me;
	timed(
		state, false, [&] { me = fresh_structure<PolySurface>(surface_soup()); },
		[&] {
			Mesh& m = me->m;
			std::vector<FH> faces;
			faces.reserve(m.size_of_facets());
			for (FH f = m.facets_begin(); f != m.facets_end(); ++f)
				faces.push_back(f);
			std::vector<VH> added;
			added.reserve(faces.size());
			for (FH f : faces)
				added.push_back(split_face(m, f, Point(0, 0, 0)));
			for (VH v : added)
				collapse_vertex(m, v);
		});
	set_counts_and_checksum(state, me->m);
}

void dynamic(benchmark::State& state, bool)
{
	std::unique_ptr<PolySurface> me = fresh_structure<PolySurface>(surface_soup());
	trim_heap();
	Mesh& m = me->m;
	for (auto _ : state)
	{
		double total = 0;
		std::vector<FH> faces;
		std::vector<VH> added;
		for (uint32_t b = 0; b < dynamic_batches; ++b)
		{
			const double t0 = thread_seconds();
			faces.clear();
			added.clear();
			uint32_t rank = 0;
			for (FH f = m.facets_begin(); f != m.facets_end(); ++f)
				if (dynamic_selected(rank++, b))
					faces.push_back(f);
			for (FH f : faces)
				added.push_back(split_face(m, f, centroid(f)));
			for (VH v : added)
				collapse_vertex(m, v);
			const double dt = thread_seconds() - t0;
			total += dt;
			record_batch(state, b, dt);
		}
		state.SetIterationTime(total);
	}
	set_check(state, "check_V", double(m.size_of_vertices()));
	set_check(state, "check_F", double(m.size_of_facets()));
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
		auto me = std::make_unique<PolySurface>(s);
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
	register_bench("surface/circulator/cgal_polyhedron", Kind::read_only, circulator);
	register_bench("surface/barycenter/cgal_polyhedron", Kind::read_only, barycenter);
	register_bench("surface/normal/cgal_polyhedron", Kind::read_only, normal);
	register_bench("surface/smoothing/cgal_polyhedron", Kind::read_only, smoothing);
	register_bench("surface/subdivision/cgal_polyhedron", Kind::topology, subdivision);
	register_bench("surface/collapse/cgal_polyhedron", Kind::topology, collapse);
	register_bench("surface/dynamic/cgal_polyhedron", Kind::single, dynamic);
	register_bench("memory/surface/cgal_polyhedron", Kind::single, memory);
	return true;
}();

} // namespace

} // namespace cgogn_bench
