// SPDX-License-Identifier: MIT
// OpenMesh's side of the surface suite: TriMesh_ArrayKernelT with double
// points and normals, built with add_vertex / add_face from the shared soup,
// traversed with its circulators (vf, fv, vv) and handle indices, edited with
// split(FaceHandle, Point), flip, collapse and garbage_collection.
#include "harness.h"
#include "inputs.h"
#include "workload_rules.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

namespace cgogn_bench
{

namespace
{

struct Traits : OpenMesh::DefaultTraits
{
	using Point = OpenMesh::Vec3d;
	using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;
using OpenMesh::Vec3d;

std::unique_ptr<Mesh> build(const cgogn::SurfaceSoup& s, bool with_status)
{
	auto m = std::make_unique<Mesh>();
	m->request_vertex_normals();
	m->request_face_normals();
	if (with_status)
	{
		m->request_vertex_status();
		m->request_edge_status();
		m->request_face_status();
		m->request_halfedge_status();
	}
	m->reserve(s.nb_vertices, s.face_vertices.size() / 2, s.face_sizes.size());
	for (const auto& p : s.positions)
		m->add_vertex(Vec3d(p[0], p[1], p[2]));
	std::vector<Mesh::VertexHandle> fv;
	std::size_t k = 0;
	for (uint32_t n : s.face_sizes)
	{
		fv.clear();
		for (uint32_t i = 0; i < n; ++i)
			fv.push_back(Mesh::VertexHandle(int(s.face_vertices[k + i])));
		m->add_face(fv);
		k += n;
	}
	return m;
}

Mesh& mesh()
{
	return Cache::get<Mesh>("openmesh/surface", [] { return build(surface_soup(), false); });
}

void reset_positions(Mesh& m)
{
	const auto& s = surface_soup();
	for (uint32_t i = 0; i < s.nb_vertices; ++i)
		m.point(Mesh::VertexHandle(int(i))) = Vec3d(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
}

double position_sum(const Mesh& m)
{
	double s = 0;
	for (auto v : m.vertices())
	{
		const Vec3d& p = m.point(v);
		s += p[0] + p[1] + p[2];
	}
	return s;
}

void circulator(benchmark::State& state, bool first)
{
	const Mesh& m = mesh();
	int64_t c = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			for (auto v : m.vertices())
				for (auto vf = m.cvf_iter(v); vf.is_valid(); ++vf)
					++c;
			for (auto f : m.faces())
				for (auto fv = m.cfv_iter(f); fv.is_valid(); ++fv)
					--c;
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
}

void barycenter(benchmark::State& state, bool first)
{
	Mesh& m = mesh();
	timed(
		state, first, [&] { reset_positions(m); },
		[&] {
			Vec3d b(0, 0, 0);
			for (auto v : m.vertices())
				b += m.point(v);
			b /= double(m.n_vertices());
			for (auto v : m.vertices())
				m.point(v) -= b;
		});
	double s = 0;
	for (auto v : m.vertices())
	{
		const Vec3d& p = m.point(v);
		s += std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]);
	}
	set_check(state, "check", s);
}

void normal(benchmark::State& state, bool first)
{
	Mesh& m = mesh();
	timed(
		state, first, [] {},
		[&] {
			for (auto f : m.faces())
			{
				auto fv = m.cfv_iter(f);
				const Vec3d& p0 = m.point(*fv);
				const Vec3d& p1 = m.point(*++fv);
				const Vec3d& p2 = m.point(*++fv);
				Vec3d n = OpenMesh::cross(p1 - p0, p2 - p0);
				const double l = n.norm();
				if (l > 0)
					n /= l;
				m.set_normal(f, n);
			}
			for (auto v : m.vertices())
			{
				Vec3d n(0, 0, 0);
				for (auto vf = m.cvf_iter(v); vf.is_valid(); ++vf)
					n += m.normal(*vf);
				const double l = n.norm();
				if (l > 0)
					n /= l;
				m.set_normal(v, n);
			}
		});
	double s = 0;
	for (auto v : m.vertices())
	{
		const Vec3d& n = m.normal(v);
		s += n[0] + n[1] + n[2];
	}
	set_check(state, "check", s);
}

void smoothing(benchmark::State& state, bool first)
{
	Mesh& m = mesh();
	timed(
		state, first, [&] { reset_positions(m); },
		[&] {
			for (auto v : m.vertices())
			{
				if (m.is_boundary(v))
					continue;
				Vec3d s(0, 0, 0);
				int n = 0;
				for (auto vv = m.cvv_iter(v); vv.is_valid(); ++vv)
				{
					s += m.point(*vv);
					++n;
				}
				m.point(v) = s / double(n);
			}
		});
	set_check(state, "check", position_sum(m));
}

std::unique_ptr<Mesh> fresh()
{
	Cache::clear();
	return build(surface_soup(), true);
}

void set_counts_and_checksum(benchmark::State& state, const Mesh& m)
{
	set_check(state, "check_V", double(m.n_vertices()));
	set_check(state, "check_F", double(m.n_faces()));
	set_check(state, "check", position_sum(m));
}

Vec3d centroid(const Mesh& m, Mesh::FaceHandle f)
{
	Vec3d c(0, 0, 0);
	int n = 0;
	for (auto fv = m.cfv_iter(f); fv.is_valid(); ++fv, ++n)
		c += m.point(*fv);
	return c / double(n);
}

void subdivision(benchmark::State& state, bool)
{
	std::unique_ptr<Mesh> mp;
	timed(
		state, false, [&] { mp = fresh(); },
		[&] {
			Mesh& m = *mp;
			const int nv = int(m.n_vertices()), ne = int(m.n_edges()), nf = int(m.n_faces());
			std::vector<Vec3d> moved(nv);
			for (int i = 0; i < nv; ++i)
			{
				const Mesh::VertexHandle v(i);
				if (m.is_boundary(v))
				{
					moved[i] = m.point(v);
					continue;
				}
				Vec3d s(0, 0, 0);
				uint32_t n = 0;
				for (auto vv = m.cvv_iter(v); vv.is_valid(); ++vv, ++n)
					s += m.point(*vv);
				const double a = sqrt3_alpha(n);
				moved[i] = (1 - a) * m.point(v) + (a / n) * s;
			}
			for (int i = 0; i < nf; ++i)
			{
				const Mesh::FaceHandle f(i);
				m.split(f, centroid(m, f));
			}
			for (int i = 0; i < nv; ++i)
				m.point(Mesh::VertexHandle(i)) = moved[i];
			for (int i = 0; i < ne; ++i)
			{
				const Mesh::EdgeHandle e(i);
				if (m.is_flip_ok(e))
					m.flip(e);
			}
		});
	set_counts_and_checksum(state, *mp);
}

void collapse(benchmark::State& state, bool)
{
	std::unique_ptr<Mesh> mp;
	timed(
		state, false, [&] { mp = fresh(); },
		[&] {
			Mesh& m = *mp;
			const int nv = int(m.n_vertices()), nf = int(m.n_faces());
			for (int i = 0; i < nf; ++i)
				m.split(Mesh::FaceHandle(i), Vec3d(0, 0, 0));
			for (int i = nv, end = int(m.n_vertices()); i < end; ++i)
				m.collapse(m.halfedge_handle(Mesh::VertexHandle(i))); // from the new vertex to a neighbour
			m.garbage_collection();
		});
	set_counts_and_checksum(state, *mp);
}

void dynamic(benchmark::State& state, bool)
{
	std::unique_ptr<Mesh> mp = fresh();
	trim_heap();
	Mesh& m = *mp;
	for (auto _ : state)
	{
		double total = 0;
		std::vector<Mesh::VertexHandle> added;
		for (uint32_t b = 0; b < dynamic_batches; ++b)
		{
			const double t0 = thread_seconds();
			const int nf = int(m.n_faces());
			added.clear();
			for (int i = 0; i < nf; ++i)
				if (dynamic_selected(uint32_t(i), b))
				{
					const Mesh::FaceHandle f(i);
					added.push_back(m.split(f, centroid(m, f)));
				}
			for (auto v : added)
				m.collapse(m.halfedge_handle(v));
			m.garbage_collection();
			const double dt = thread_seconds() - t0;
			total += dt;
			record_batch(state, b, dt);
		}
		state.SetIterationTime(total);
	}
	set_check(state, "check_V", double(m.n_vertices()));
	set_check(state, "check_F", double(m.n_faces()));
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
		auto m = build(s, false);
		bytes = heap_bytes() - before;
		state.SetIterationTime(1e-9);
		benchmark::DoNotOptimize(m.get());
	}
	state.counters["bytes"] = double(bytes);
	state.counters["bytes_per_face"] = double(bytes) / double(s.face_sizes.size());
	state.counters["bytes_per_vertex"] = double(bytes) / double(s.nb_vertices);
	state.counters["peak_rss_MB"] = double(peak_resident_bytes()) / 1e6;
}

const bool registered = [] {
	register_bench("surface/circulator/openmesh", Kind::read_only, circulator);
	register_bench("surface/barycenter/openmesh", Kind::read_only, barycenter);
	register_bench("surface/normal/openmesh", Kind::read_only, normal);
	register_bench("surface/smoothing/openmesh", Kind::read_only, smoothing);
	register_bench("surface/subdivision/openmesh", Kind::topology, subdivision);
	register_bench("surface/collapse/openmesh", Kind::topology, collapse);
	register_bench("surface/dynamic/openmesh", Kind::single, dynamic);
	register_bench("memory/surface/openmesh", Kind::single, memory);
	return true;
}();

} // namespace

} // namespace cgogn_bench
