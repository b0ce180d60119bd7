// SPDX-License-Identifier: MIT
// Speed of the core alone: the surface "circulator" and "smoothing"
// workloads of the suite (bench/README.md) on a generated closed triangle mesh of 1M faces,
// with cells visited by walking darts with a marker ("plain") and by walking
// the indexed cell containers ("indexed"). Reports ns per visited incidence.
#include <cgogn/core.h>

#include <benchmark/benchmark.h>

#include <array>

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Face = CMap2::Face;
using Point3 = std::array<double, 3>;

namespace
{

struct Mesh
{
	CMap2 map;
	std::shared_ptr<AttributeArray<Point3>> position;
	uint64 nb_incidences = 0; // vertex-face incidences = 3F
	Mesh()
	{
		SurfaceSoup soup = torus_soup(1000, 500, true); // 1,000,000 triangles, closed
		BuildReport r = build_surface(map, soup);
		position = add_attribute<Point3, Vertex>(map, "position");
		for (uint32 i = 0; i < soup.nb_vertices; ++i)
			(*position)[r.vertex_offset + i] = soup.positions[i];
		nb_incidences = 3ull * soup.face_sizes.size();
	}
};

Mesh& mesh(bool index_faces)
{
	static Mesh plain;
	static Mesh indexed = [] {
		Mesh m;
		add_attribute<int, Face>(m.map, "face_index_holder");
		return m;
	}();
	return index_faces ? indexed : plain;
}

// the cells of an orbit found by walking the darts with a marker, as an
// unindexed orbit is traversed
template <typename CELL, typename F>
void foreach_cell_by_darts(const CMap2& m, const F& f)
{
	DartMarker<CMap2> dm(m);
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d) || dm.is_marked(d))
			return;
		dm.mark_orbit(CELL(d));
		f(CELL(d));
	});
}

void circulator(benchmark::State& state, bool indexed)
{
	Mesh& me = mesh(indexed);
	const CMap2& m = me.map;
	for (auto _ : state)
	{
		int64 c = 0;
		auto per_vertex = [&](Vertex v) { foreach_incident_face(m, v, [&](Face) { ++c; }); };
		auto per_face = [&](Face f) { foreach_incident_vertex(m, f, [&](Vertex) { --c; }); };
		if (indexed)
		{
			foreach_cell(m, per_vertex);
			foreach_cell(m, per_face);
		}
		else
		{
			foreach_cell_by_darts<Vertex>(m, per_vertex);
			foreach_cell_by_darts<Face>(m, per_face);
		}
		if (c != 0)
			state.SkipWithError("circulator check failed");
		benchmark::DoNotOptimize(c);
	}
	state.counters["ns_per_incidence"] = benchmark::Counter(double(2 * me.nb_incidences) * state.iterations(),
															benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void smoothing(benchmark::State& state, bool indexed)
{
	Mesh& me = mesh(indexed);
	const CMap2& m = me.map;
	AttributeArray<Point3>& pos = *me.position;
	uint64 incidences = 0;
	for (auto _ : state)
	{
		incidences = 0;
		// vertices in index order, in place (Gauss-Seidel), boundary skipped
		auto smooth = [&](Vertex v) {
			if (is_incident_to_boundary(m, v))
				return;
			Point3 sum = {0, 0, 0};
			uint32 n = 0;
			foreach_adjacent_vertex_through_edge(m, v, [&](Vertex w) {
				const Point3& q = value<Point3>(m, pos, w);
				sum[0] += q[0], sum[1] += q[1], sum[2] += q[2];
				++n;
			});
			Point3& p = pos[v];
			p = {sum[0] / n, sum[1] / n, sum[2] / n};
			incidences += n;
		};
		if (indexed)
			foreach_cell(m, smooth);
		else
			foreach_cell_by_darts<Vertex>(m, smooth);
	}
	state.counters["ns_per_incidence"] = benchmark::Counter(double(incidences) * state.iterations(),
															benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

} // namespace

// A vertex attribute read through value(m, pos, v) and through pos[v], from
// every dart in dart order: both read the dart's line from the map's index,
// then the value, so the two must time alike.
void attribute_read(benchmark::State& state, bool by_cell)
{
	Mesh& me = mesh(true);
	const CMap2& m = me.map;
	const AttributeArray<Point3>& pos = *me.position;
	double s = 0.0;
	uint64 reads = 0;
	for (auto _ : state)
	{
		reads = 0;
		if (by_cell)
			foreach_dart(m, [&](Dart d) {
				s += pos[Vertex(d)][0];
				++reads;
			});
		else
			foreach_dart(m, [&](Dart d) {
				s += value<Point3>(m, pos, Vertex(d))[0];
				++reads;
			});
		benchmark::DoNotOptimize(s);
	}
	state.counters["ns_per_read"] = benchmark::Counter(double(reads) * state.iterations(),
													   benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK_CAPTURE(circulator, plain, false)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(circulator, indexed, true)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(smoothing, plain, false)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(smoothing, indexed, true)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(attribute_read, value, false)->Unit(benchmark::kMillisecond)->MinTime(1.0);
BENCHMARK_CAPTURE(attribute_read, by_cell, true)->Unit(benchmark::kMillisecond)->MinTime(1.0);

BENCHMARK_MAIN();
