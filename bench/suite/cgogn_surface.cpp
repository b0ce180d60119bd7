// SPDX-License-Identifier: MIT
// cgogn's side of the surface suite: a CMap2 with double positions and
// vertex and face normals (Vec3 attributes), built from the shared soup.
// "plain" mode (library cgogn): no incidence cache; cells are visited by
// walking the indexed containers (foreach_cell) and the local traversals of
// local_cmap2.h. "quick" mode (library cgogn_quick): the same workloads on a
// map holding the quick incidence caches vertex -> faces, face -> vertices and
// vertex -> vertices through edges (IncidenceCache), which the same local
// traversals then read; built untimed before the runs, their build timed
// separately (surface/cache_build/cgogn_quick).
#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "cgogn_reorder.h"
#include "cgogn_topology.h"
#include "harness.h"
#include "inputs.h"
#include "workload_rules.h"

#include <Eigen/Geometry> // cross(): vector_traits.h includes Eigen/Core only

#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <vector>

namespace cgogn_bench
{

namespace
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

struct CgognSurface
{
	CMap2 map;
	std::shared_ptr<AttributeArray<Vec3>> position, vnormal, fnormal;
	// quick mode: boundary flag per vertex (the flat arrays' boundary flags),
	// filled with the caches
	std::shared_ptr<AttributeArray<uint8>> boundary;
	uint32 vertex_offset = 0;
	// with --reorder: the vertex line of each soup vertex (else vertex_offset + i)
	std::vector<uint32> line_of_soup_vertex;

	explicit CgognSurface(const SurfaceSoup& s)
	{
		vertex_offset = build_surface(map, s).vertex_offset;
		position = add_attribute<Vec3, Vertex>(map, "position");
		vnormal = add_attribute<Vec3, Vertex>(map, "normal");
		fnormal = add_attribute<Vec3, Face>(map, "normal");
		reset_positions(s);
		if (reorder_requested())
			line_of_soup_vertex = reorder_by_morton(map, *position, vertex_offset, s.nb_vertices);
	}
	void reset_positions(const SurfaceSoup& s)
	{
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*position)[line_of_soup_vertex.empty() ? vertex_offset + i : line_of_soup_vertex[i]] =
				Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	}
};

enum class Mode
{
	plain,
	quick
};

// The caches of quick mode, and the boundary flags its smoothing reads.
void build_quick_caches(CgognSurface& me)
{
	CMap2& m = me.map;
	IncidenceCache<CMap2, Vertex, Face>::build(m);
	IncidenceCache<CMap2, Face, Vertex>::build(m);
	IncidenceCache<CMap2, Vertex, Vertex, Edge>::build(m);
	if (!me.boundary)
		me.boundary = add_attribute<uint8, Vertex>(m, "boundary");
	AttributeArray<uint8>& b = *me.boundary;
	parallel_foreach_cell(m, [&](Vertex v) { value<uint8>(m, b, v) = is_incident_to_boundary(m, v); });
}

std::size_t quick_cache_bytes(const CgognSurface& me)
{
	const CMap2& m = me.map;
	return IncidenceCache<CMap2, Vertex, Face>::memory_bytes(m) + IncidenceCache<CMap2, Face, Vertex>::memory_bytes(m) +
		   IncidenceCache<CMap2, Vertex, Vertex, Edge>::memory_bytes(m);
}

CgognSurface& mesh(Mode mode = Mode::plain)
{
	if (mode == Mode::plain)
		return Cache::get<CgognSurface>("cgogn/surface", [] { return std::make_unique<CgognSurface>(surface_soup()); });
	return Cache::get<CgognSurface>("cgogn_quick/surface", [] {
		auto me = std::make_unique<CgognSurface>(surface_soup());
		build_quick_caches(*me);
		return me;
	});
}

double position_sum(const CgognSurface& me)
{
	double s = 0;
	foreach_cell(me.map, [&](Vertex v) {
		const Vec3& p = value<Vec3>(me.map, *me.position, v);
		s += p[0] + p[1] + p[2];
	});
	return s;
}

void circulator(benchmark::State& state, bool first, Mode mode)
{
	const CMap2& m = mesh(mode).map;
	int64 c = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			// each reported cell is read (as flat reads each id), so that counting
			// does not reduce to a row length
			foreach_cell(m, [&](Located<Vertex> v) {
				foreach_incident_face(m, v, [&](Face f) { c += 1 + (f.dart.index >> 31); });
			});
			foreach_cell(m, [&](Located<Face> f) {
				foreach_incident_vertex(m, f, [&](Vertex v) { c -= 1 + (v.dart.index >> 31); });
			});
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
}

void barycenter(benchmark::State& state, bool first, Mode mode)
{
	CgognSurface& me = mesh(mode);
	const CMap2& m = me.map;
	AttributeArray<Vec3>& pos = *me.position;
	timed(
		state, first, [&] { me.reset_positions(surface_soup()); },
		[&] {
			// the mean in line order, in four partial sums (geometry::mean_position),
			// then the values of the live vertices, walked by the attribute's range
			const Vec3 b = geometry::mean_position(m, pos);
			for (Vec3& p : pos)
				p -= b;
		});
	double s = 0;
	foreach_cell(m, [&](Vertex v) { s += value<Vec3>(m, pos, v).cwiseAbs().sum(); });
	set_check(state, "check", s);
}

void normal(benchmark::State& state, bool first, Mode mode)
{
	CgognSurface& me = mesh(mode);
	const CMap2& m = me.map;
	const AttributeArray<Vec3>& pos = *me.position;
	AttributeArray<Vec3>& fn = *me.fnormal;
	AttributeArray<Vec3>& vn = *me.vnormal;
	timed(
		state, first, [] {},
		[&] {
			foreach_cell(m, [&](Located<Face> f) {
				const Dart d0 = f.dart, d1 = phi1(m, d0), d2 = phi1(m, d1);
				const Vec3& p0 = value<Vec3>(m, pos, Vertex(d0));
				fn[f] = (value<Vec3>(m, pos, Vertex(d1)) - p0).cross(value<Vec3>(m, pos, Vertex(d2)) - p0).normalized();
			});
			foreach_cell(m, [&](Located<Vertex> v) {
				Vec3 n = Vec3::Zero();
				// `auto`: the face comes with its line (LocatedCell), read without index lookup
				foreach_incident_face(m, v, [&](auto f) { n += value<Vec3>(m, fn, f); });
				vn[v] = n.normalized();
			});
		});
	double s = 0;
	foreach_cell(m, [&](Vertex v) { s += value<Vec3>(m, vn, v).sum(); });
	set_check(state, "check", s);
}

void smoothing_quick(benchmark::State& state, bool first)
{
	CgognSurface& me = mesh(Mode::quick);
	const CMap2& m = me.map;
	AttributeArray<Vec3>& pos = *me.position;
	const AttributeArray<uint8>& boundary = *me.boundary;
	timed(
		state, first, [&] { me.reset_positions(surface_soup()); },
		[&] {
			// the one-ring from the vertex -> vertex cache, the boundary from its flag
			foreach_cell(m, [&](Located<Vertex> v) {
				if (value<uint8>(m, boundary, v))
					return;
				Vec3 s = Vec3::Zero();
				uint32 n = 0;
				foreach_adjacent_vertex_through_edge(m, v, [&](auto w) {
					s += value<Vec3>(m, pos, w);
					++n;
				});
				pos[v] = s / double(n);
			});
		});
	set_check(state, "check", position_sum(me));
}

void cache_build(benchmark::State& state, bool)
{
	CgognSurface& me = mesh(Mode::quick);
	double wall = 0;
	for (auto _ : state)
	{
		// every table (and the flags) dropped, then built again: process CPU
		// time, the build runs on the thread pool
		IncidenceCache<CMap2, Vertex, Face>::remove(me.map);
		IncidenceCache<CMap2, Face, Vertex>::remove(me.map);
		IncidenceCache<CMap2, Vertex, Vertex, Edge>::remove(me.map);
		const double c0 = process_seconds();
		const auto t0 = std::chrono::steady_clock::now();
		build_quick_caches(me);
		const auto t1 = std::chrono::steady_clock::now();
		state.SetIterationTime(process_seconds() - c0);
		wall += std::chrono::duration<double>(t1 - t0).count();
	}
	state.counters["wall_ms"] = wall * 1e3;
	state.counters["cache_MB"] = double(quick_cache_bytes(me)) / 1e6;
}

void smoothing(benchmark::State& state, bool first)
{
	CgognSurface& me = mesh();
	const CMap2& m = me.map;
	AttributeArray<Vec3>& pos = *me.position;
	timed(
		state, first, [&] { me.reset_positions(surface_soup()); },
		[&] {
			// is_incident_to_boundary is O(1) on a closed map (the map counts its
			// boundary darts); on an open one it walks v's darts before the ring
			foreach_cell(m, [&](Located<Vertex> v) {
				if (is_incident_to_boundary(m, v))
					return;
				Vec3 s = Vec3::Zero();
				uint32 n = 0;
				// `auto`: the neighbour comes with its line, read without index lookup
				foreach_adjacent_vertex_through_edge(m, v, [&](auto w) {
					s += value<Vec3>(m, pos, w);
					++n;
				});
				pos[v] = s / double(n);
			});
		});
	set_check(state, "check", position_sum(me));
}

void memory(benchmark::State& state, bool)
{
	Cache::clear();
	const SurfaceSoup& s = surface_soup();
	std::size_t bytes = 0;
	for (auto _ : state)
	{
		trim_heap();
		const std::size_t before = heap_bytes();
		auto me = std::make_unique<CgognSurface>(s);
		bytes = heap_bytes() - before;
		state.SetIterationTime(1e-9);
		benchmark::DoNotOptimize(me.get());
	}
	const double nf = double(s.face_sizes.size()), nv = double(s.nb_vertices);
	state.counters["bytes"] = double(bytes);
	state.counters["bytes_per_face"] = double(bytes) / nf;
	state.counters["bytes_per_vertex"] = double(bytes) / nv;
	state.counters["peak_rss_MB"] = double(peak_resident_bytes()) / 1e6;
}

// ---- topology workloads, written against the planned operators (see cgogn_topology.h)

void set_counts_and_checksum(benchmark::State& state, const CgognSurface& me)
{
	set_check(state, "check_V", double(nb_cells<Vertex>(me.map)));
	set_check(state, "check_F", double(nb_cells<Face>(me.map)));
	set_check(state, "check", position_sum(me));
}

Vec3 centroid(const CMap2& m, const AttributeArray<Vec3>& pos, Face f)
{
	Vec3 c = Vec3::Zero();
	uint32 n = 0;
	foreach_incident_vertex(m, f, [&](Vertex v) {
		c += value<Vec3>(m, pos, v);
		++n;
	});
	return c / double(n);
}

void subdivision(benchmark::State& state, bool)
{
	std::unique_ptr<CgognSurface> me;
	timed(
		state, false, [&] { me = fresh_structure<CgognSurface>(surface_soup()); },
		[&] {
			CMap2& m = me->map;
			AttributeArray<Vec3>& pos = *me->position;
			// new positions of the original vertices, kept aside (by vertex line)
			std::vector<Vec3> moved(container_of<Vertex::ORBIT>(m).end_index());
			std::vector<Vertex> old_vertices;
			old_vertices.reserve(nb_cells<Vertex>(m));
			foreach_cell(m, [&](Vertex v) {
				old_vertices.push_back(v);
				// one walk around v for the boundary test and the neighbours' sum
				// (is_incident_to_boundary would walk the vertex's darts a second
				// time: cgogn has no O(1) boundary flag per vertex, unlike
				// Surface_mesh's border-halfedge invariant); phi2(d) starts at the
				// neighbour along d
				Vec3 s = Vec3::Zero();
				uint32 n = 0;
				bool boundary = false;
				foreach_dart_of_orbit(m, v, [&](Dart d) {
					boundary = boundary || is_boundary(m, d);
					s += value<Vec3>(m, pos, Vertex(phi2(m, d)));
					++n;
				});
				if (boundary)
				{
					moved[index_of(m, v)] = value<Vec3>(m, pos, v);
					return;
				}
				const double a = sqrt3_alpha(n);
				moved[index_of(m, v)] = (1 - a) * value<Vec3>(m, pos, v) + a / n * s;
			});
			std::vector<Face> faces;
			faces.reserve(nb_cells<Face>(m));
			foreach_cell(m, [&](Face f) { faces.push_back(f); });
			std::vector<Edge> edges;
			foreach_cell(m, [&](Edge e) { edges.push_back(e); });
			for (Face f : faces)
			{
				const Vec3 c = centroid(m, pos, f);
				value<Vec3>(m, pos, triangulate_face(m, f)) = c;
			}
			for (Vertex v : old_vertices)
				pos[v] = moved[index_of(m, v)];
			for (Edge e : edges)
				if (can_flip_edge(m, e))
					flip_edge(m, e);
		});
	set_counts_and_checksum(state, *me);
}

void collapse(benchmark::State& state, bool)
{
	std::unique_ptr<CgognSurface> me;
	timed(
		state, false, [&] { me = fresh_structure<CgognSurface>(surface_soup()); },
		[&] {
			CMap2& m = me->map;
			AttributeArray<Vec3>& pos = *me->position;
			std::vector<Face> faces;
			foreach_cell(m, [&](Face f) { faces.push_back(f); });
			std::vector<Vertex> added;
			added.reserve(faces.size());
			for (Face f : faces)
				added.push_back(triangulate_face(m, f));
			for (Vertex v : added)
			{
				// the edge from v to a neighbour w: v disappears, w stays where it was
				const Dart d = v.dart;
				const Vec3 keep = value<Vec3>(m, pos, Vertex(phi1(m, d)));
				value<Vec3>(m, pos, collapse_edge(m, Edge(d))) = keep;
			}
			compact(m);
		});
	set_counts_and_checksum(state, *me);
}

// with_compact (surface/dynamic_compact/cgogn): each batch ends with
// compact(m), timed, as the peers' batches end with their garbage collection
// (without it the freed lines are reused by the next batches)
void dynamic(benchmark::State& state, bool, bool with_compact)
{
	std::unique_ptr<CgognSurface> me = fresh_structure<CgognSurface>(surface_soup());
	trim_heap();
	CMap2& m = me->map;
	for (auto _ : state)
	{
		double total = 0;
		for (uint32 b = 0; b < dynamic_batches; ++b)
		{
			const double t0 = thread_seconds();
			std::vector<Face> faces;
			uint32 rank = 0;
			foreach_cell(m, [&](Face f) {
				if (dynamic_selected(rank++, b))
					faces.push_back(f);
			});
			std::vector<Vertex> added;
			for (Face f : faces)
				added.push_back(triangulate_face(m, f));
			for (Vertex v : added)
				collapse_edge(m, Edge(v.dart));
			if (with_compact)
				compact(m);
			const double dt = thread_seconds() - t0;
			total += dt;
			record_batch(state, b, dt);
		}
		state.SetIterationTime(total);
	}
	set_check(state, "check_V", double(nb_cells<Vertex>(m)));
	set_check(state, "check_F", double(nb_cells<Face>(m)));
}

const bool registered = [] {
	// a workload with its last argument fixed, as the harness registers it
	const auto with = [](auto workload, auto last) {
		return [workload, last](benchmark::State& state, bool first) { workload(state, first, last); };
	};
	register_bench("surface/circulator/cgogn", Kind::read_only, with(circulator, Mode::plain));
	register_bench("surface/barycenter/cgogn", Kind::read_only, with(barycenter, Mode::plain));
	register_bench("surface/normal/cgogn", Kind::read_only, with(normal, Mode::plain));
	register_bench("surface/smoothing/cgogn", Kind::read_only, smoothing);
	register_bench("surface/cache_build/cgogn_quick", Kind::read_only, cache_build);
	register_bench("surface/circulator/cgogn_quick", Kind::read_only, with(circulator, Mode::quick));
	register_bench("surface/barycenter/cgogn_quick", Kind::read_only, with(barycenter, Mode::quick));
	register_bench("surface/normal/cgogn_quick", Kind::read_only, with(normal, Mode::quick));
	register_bench("surface/smoothing/cgogn_quick", Kind::read_only, smoothing_quick);
	register_bench("surface/subdivision/cgogn", Kind::topology, subdivision);
	register_bench("surface/collapse/cgogn", Kind::topology, collapse);
	register_bench("surface/dynamic/cgogn", Kind::single, with(dynamic, false));
	register_bench("surface/dynamic_compact/cgogn", Kind::single, with(dynamic, true));
	register_bench("memory/surface/cgogn", Kind::single, memory);
	return true;
}();

} // namespace

} // namespace cgogn_bench
