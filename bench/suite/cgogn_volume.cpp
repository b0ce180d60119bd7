// SPDX-License-Identifier: MIT
// cgogn's side of the volume suite: a CMap3 with double positions (and a
// volume attribute for the stored barycenters), built from the shared tet
// soup. "plain" mode (library cgogn): no incidence cache; the local
// traversals of local_cmap3.h. "quick" mode (library cgogn_quick): the same
// workloads on a map holding the quick incidence caches vertex -> volumes,
// volume -> vertices, vertex -> vertices through volumes and through edges
// (IncidenceCache), read by the same local traversals; their build is timed
// separately (volume/cache_build/cgogn_quick).
#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "cgogn_reorder.h"
#include "cgogn_topology.h"
#include "harness.h"
#include "inputs.h"
#include "workload_rules.h"

#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace cgogn_bench
{

namespace
{

using namespace cgogn;
using Vertex = CMap3::Vertex;
using Edge = CMap3::Edge;
using Volume = CMap3::Volume;

struct CgognVolume
{
	CMap3 map;
	std::shared_ptr<AttributeArray<Vec3>> position, position2, barycenter;
	uint32 vertex_offset = 0;
	// with --reorder: the vertex line of each soup vertex (else vertex_offset + i)
	std::vector<uint32> line_of_soup_vertex;

	CgognVolume(const VolumeSoup& s, bool with_work_attributes)
	{
		vertex_offset = build_volume(map, s).vertex_offset;
		position = add_attribute<Vec3, Vertex>(map, "position");
		if (with_work_attributes)
		{
			position2 = add_attribute<Vec3, Vertex>(map, "position2");
			barycenter = add_attribute<Vec3, Volume>(map, "barycenter");
		}
		reset_positions(s);
		if (reorder_requested())
			line_of_soup_vertex = reorder_by_morton(map, *position, vertex_offset, s.nb_vertices);
	}
	void reset_positions(const VolumeSoup& s)
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

void build_quick_caches(CMap3& m)
{
	IncidenceCache<CMap3, Vertex, Volume>::build(m);
	IncidenceCache<CMap3, Volume, Vertex>::build(m);
	IncidenceCache<CMap3, Vertex, Vertex, Volume>::build(m);
	IncidenceCache<CMap3, Vertex, Vertex, Edge>::build(m);
}

void remove_quick_caches(CMap3& m)
{
	IncidenceCache<CMap3, Vertex, Volume>::remove(m);
	IncidenceCache<CMap3, Volume, Vertex>::remove(m);
	IncidenceCache<CMap3, Vertex, Vertex, Volume>::remove(m);
	IncidenceCache<CMap3, Vertex, Vertex, Edge>::remove(m);
}

std::size_t quick_cache_bytes(const CMap3& m)
{
	return IncidenceCache<CMap3, Vertex, Volume>::memory_bytes(m) +
		   IncidenceCache<CMap3, Volume, Vertex>::memory_bytes(m) +
		   IncidenceCache<CMap3, Vertex, Vertex, Volume>::memory_bytes(m) +
		   IncidenceCache<CMap3, Vertex, Vertex, Edge>::memory_bytes(m);
}

CgognVolume& mesh(Mode mode = Mode::plain)
{
	if (mode == Mode::plain)
		return Cache::get<CgognVolume>("cgogn/volume",
									   [] { return std::make_unique<CgognVolume>(volume_soup(), true); });
	return Cache::get<CgognVolume>("cgogn_quick/volume", [] {
		auto me = std::make_unique<CgognVolume>(volume_soup(), true);
		build_quick_caches(me->map);
		return me;
	});
}

void cache_build(benchmark::State& state, bool)
{
	CgognVolume& me = mesh(Mode::quick);
	double wall = 0;
	for (auto _ : state)
	{
		// the tables dropped, then built again: process CPU time (thread pool)
		remove_quick_caches(me.map);
		const double c0 = process_seconds();
		const auto t0 = std::chrono::steady_clock::now();
		build_quick_caches(me.map);
		const auto t1 = std::chrono::steady_clock::now();
		state.SetIterationTime(process_seconds() - c0);
		wall += std::chrono::duration<double>(t1 - t0).count();
	}
	state.counters["wall_ms"] = wall * 1e3;
	state.counters["cache_MB"] = double(quick_cache_bytes(me.map)) / 1e6;
}

void circulator(benchmark::State& state, bool first, Mode mode)
{
	const CMap3& m = mesh(mode).map;
	int64 c = 0, incidences = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			// each reported cell is read (as flat reads each id)
			foreach_cell(m, [&](Located<Vertex> v) {
				foreach_incident_volume(m, v, [&](Volume w) { c += 1 + (w.dart.index >> 31); });
			});
			incidences = c;
			foreach_cell(m, [&](Located<Volume> w) {
				foreach_incident_vertex(m, w, [&](Vertex v) { c -= 1 + (v.dart.index >> 31); });
			});
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
	set_check(state, "check_incidences", double(incidences));
}

void circulator2(benchmark::State& state, bool first, Mode mode)
{
	const CMap3& m = mesh(mode).map;
	int64 total = 0;
	timed(
		state, first, [] {},
		[&] {
			total = 0;
			foreach_cell(m, [&](Located<Vertex> v) {
				foreach_adjacent_vertex_through_volume(m, v, [&](Vertex u) { total += 1 + (u.dart.index >> 31); });
			});
			benchmark::DoNotOptimize(total);
		});
	set_check(state, "check", double(total));
	int64 naive = 0;
	foreach_cell(m, [&](Vertex v) {
		foreach_incident_volume(m, v, [&](Volume w) { foreach_incident_vertex(m, w, [&](Vertex) { ++naive; }); });
	});
	state.counters["naive_triples"] = double(naive);
}

void barycenter(benchmark::State& state, bool first, Mode mode)
{
	CgognVolume& me = mesh(mode);
	const CMap3& m = me.map;
	const AttributeArray<Vec3>& pos = *me.position;
	AttributeArray<Vec3>& bary = *me.barycenter;
	timed(
		state, first, [] {},
		[&] {
			foreach_cell(m, [&](Located<Volume> w) {
				Vec3 b = Vec3::Zero();
				uint32 n = 0;
				// `auto`: a cached traversal gives LocatedCell, read without index lookup
				foreach_incident_vertex(m, w, [&](auto v) {
					b += value<Vec3>(m, pos, v);
					++n;
				});
				bary[w] = b / double(n);
			});
		});
	double s = 0;
	foreach_cell(m, [&](Volume w) { s += value<Vec3>(m, bary, w).sum(); });
	set_check(state, "check", s);
}

void smoothing_pass(CgognVolume& me)
{
	const CMap3& m = me.map;
	const AttributeArray<Vec3>& pos = *me.position;
	AttributeArray<Vec3>& out = *me.position2;
	foreach_cell(m, [&](Located<Vertex> v) {
		Vec3 s = Vec3::Zero();
		uint32 n = 0;
		foreach_adjacent_vertex_through_edge(m, v, [&](auto w) {
			s += value<Vec3>(m, pos, w);
			++n;
		});
		out[v] = s / double(n);
	});
	std::swap(me.position, me.position2);
}

/// The sum of every vertex's coordinates (the checks of smoothing and split).
double position_sum(const CgognVolume& me)
{
	double s = 0;
	foreach_cell(me.map, [&](Vertex v) { s += value<Vec3>(me.map, *me.position, v).sum(); });
	return s;
}

void smoothing(benchmark::State& state, bool first, Mode mode)
{
	CgognVolume& me = mesh(mode);
	timed(
		state, first, [&] { me.reset_positions(volume_soup()); }, [&] { smoothing_pass(me); });
	me.reset_positions(volume_soup());
	for (uint32 i = 0; i < volume_smoothing_check_passes; ++i)
		smoothing_pass(me);
	set_check(state, "check", position_sum(me));
}

void memory(benchmark::State& state, bool)
{
	Cache::clear();
	const VolumeSoup& s = volume_soup();
	std::size_t bytes = 0;
	for (auto _ : state)
	{
		trim_heap();
		const std::size_t before = heap_bytes();
		auto me = std::make_unique<CgognVolume>(s, false);
		bytes = heap_bytes() - before;
		state.SetIterationTime(1e-9);
		benchmark::DoNotOptimize(me.get());
	}
	state.counters["bytes"] = double(bytes);
	state.counters["bytes_per_tet"] = double(bytes) / double(s.cell_sizes.size());
	state.counters["bytes_per_vertex"] = double(bytes) / double(s.nb_vertices);
	state.counters["peak_rss_MB"] = double(peak_resident_bytes()) / 1e6;
}

// ---- topology workloads, written against the planned operators (see cgogn_topology.h)

void split(benchmark::State& state, bool)
{
	std::unique_ptr<CgognVolume> me;
	timed(
		state, false, [&] { me = fresh_structure<CgognVolume>(volume_soup(), false); },
		[&] {
			CMap3& m = me->map;
			AttributeArray<Vec3>& pos = *me->position;
			std::vector<Volume> tets;
			foreach_cell(m, [&](Volume w) { tets.push_back(w); });
			for (Volume w : tets)
			{
				Vec3 b = Vec3::Zero();
				foreach_incident_vertex(m, w, [&](Vertex v) { b += value<Vec3>(m, pos, v); });
				value<Vec3>(m, pos, split_tetra(m, w)) = b / 4.0;
			}
		});
	set_check(state, "check_V", double(nb_cells<Vertex>(me->map)));
	set_check(state, "check_T", double(nb_cells<Volume>(me->map)));
	set_check(state, "check_position_sum", position_sum(*me)); // the new vertices at the barycenters
	set_check(state, "check_valid", check_integrity(me->map).ok() ? 1.0 : 0.0);
}

void collapse(benchmark::State& state, bool)
{
	std::unique_ptr<CgognVolume> me;
	std::vector<double> lengths;
	timed(
		state, false, [&] { me = fresh_structure<CgognVolume>(volume_soup(), false); },
		[&] {
			CMap3& m = me->map;
			AttributeArray<Vec3>& pos = *me->position;
			lengths.clear();
			// the edges indexed (timed): each scan then walks the edge container
			// instead of marking the darts of every edge
			index_cells<Edge>(m);
			// boundary status cached per vertex
			auto boundary = add_attribute<uint8, Vertex>(m, "boundary_cache");
			foreach_cell(m, [&](Vertex v) { value<uint8>(m, *boundary, v) = is_incident_to_boundary(m, v); });
			for (uint32 k = 0; k < volume_collapses; ++k)
			{
				Edge best;
				ShortestEdge shortest;
				foreach_cell(m, [&](Edge e) {
					const Vertex a(e.dart), b(phi1(m, e.dart));
					if (value<uint8>(m, *boundary, a) || value<uint8>(m, *boundary, b))
						return;
					const Vec3& pa = value<Vec3>(m, pos, a);
					const Vec3& pb = value<Vec3>(m, pos, b);
					if (shortest.offer((pa - pb).norm(), pa, pb))
						best = e;
				});
				lengths.push_back(shortest.length);
				const Vertex kept = collapse_edge(m, best);
				pos[kept] = Vec3(shortest.midpoint[0], shortest.midpoint[1], shortest.midpoint[2]);
				value<uint8>(m, *boundary, kept) = is_incident_to_boundary(m, kept);
			}
			remove_attribute(m, boundary);
		});
	for (uint32 k = 0; k < lengths.size(); ++k)
		set_check(state, "check_len" + std::to_string(k), lengths[k]);
	set_check(state, "check_V", double(nb_cells<Vertex>(me->map)));
	set_check(state, "check_T", double(nb_cells<Volume>(me->map)));
	set_check(state, "check_valid", check_integrity(me->map).ok() ? 1.0 : 0.0);
}

const bool registered = [] {
	// a workload with its last argument fixed, as the harness registers it
	const auto with = [](auto workload, auto last) {
		return [workload, last](benchmark::State& state, bool first) { workload(state, first, last); };
	};
	for (Mode mode : {Mode::plain, Mode::quick})
	{
		const std::string lib = mode == Mode::plain ? "/cgogn" : "/cgogn_quick";
		if (mode == Mode::quick)
			register_bench("volume/cache_build" + lib, Kind::read_only, cache_build);
		register_bench("volume/circulator" + lib, Kind::read_only, with(circulator, mode));
		register_bench("volume/circulator2" + lib, Kind::read_only, with(circulator2, mode));
		register_bench("volume/barycenter" + lib, Kind::read_only, with(barycenter, mode));
		register_bench("volume/smoothing" + lib, Kind::read_only, with(smoothing, mode));
	}
	register_bench("volume/split/cgogn", Kind::topology, split);
	register_bench("volume/collapse/cgogn", Kind::topology, collapse);
	register_bench("memory/volume/cgogn", Kind::single, memory);
	return true;
}();

} // namespace

} // namespace cgogn_bench
