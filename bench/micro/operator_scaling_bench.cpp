// SPDX-License-Identifier: MIT
// Cost per call of each CMap2 and CMap3 operator on generated meshes of about
// 10^4, 10^5 and 10^6 cells, with every orbit indexed and with none. A local
// operator must cost the same whatever the size of the mesh: the program ends
// with a table of the 10^6 / 10^4 ratio per operator.
//
// Meshes: a triangulated square grid with one boundary loop (2-maps) and a
// grid of cubes split in 6 tetrahedra (3-maps), both with a boundary, so that
// an operator that walks a boundary face, the boundary of a 3-map or a whole
// connected component shows a growing cost. Each benchmark builds its own
// mesh, then times ROUNDS rounds of CALLS calls on darts drawn at random
// (fixed seed) in a window of the same size on every mesh, and reports the
// fastest round per call; the
// preparation of a call (for example the cut_edge that makes a quad before
// cut_face) is not timed, the operator's predicate is.
#include <cgogn/core.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace cgogn;

namespace
{

constexpr uint32 CALLS = 400;
constexpr uint32 ROUNDS = 5;
constexpr std::array<uint32, 3> SIZES = {10'000, 100'000, 1'000'000};

using Clock = std::chrono::steady_clock;

/// Accumulates the time of the timed parts of the calls; a call refused by
/// its predicate (the timed function returns false) is not counted.
struct Timer
{
	double seconds = 0;
	template <typename F>
	auto time(const F& f)
	{
		const auto t0 = Clock::now();
		if constexpr (std::is_void_v<decltype(f())>)
		{
			f();
			seconds += std::chrono::duration<double>(Clock::now() - t0).count();
		}
		else
		{
			const bool accepted = f();
			if (accepted)
				seconds += std::chrono::duration<double>(Clock::now() - t0).count();
			return accepted;
		}
	}
};

/// Targets are drawn among the first WINDOW dart lines (a corner of the mesh,
/// boundary included) whatever the mesh size: the memory the calls touch is
/// then alike on every mesh, so that the ratio measures the work of the
/// operator, not the cache misses of random access to a larger mesh.
constexpr uint32 WINDOW = 20'000;

// A live dart of the window for which `wanted` holds; removals can empty the
// window of such darts, it is then widened.
template <typename MAP, typename P>
Dart random_dart_where(const MAP& m, std::mt19937& rng, const P& wanted)
{
	uint32 window = std::min(WINDOW, cgogn::detail::state_of(m).darts->end_index());
	for (uint32 misses = 0;; ++misses)
	{
		if (misses == 1000)
		{
			window = std::min(2 * window, cgogn::detail::state_of(m).darts->end_index());
			misses = 0;
		}
		const uint32 i = uint32(rng() % window);
		if (cgogn::detail::state_of(m).darts->is_live(i) && wanted(Dart(i)))
			return Dart(i);
	}
}

template <typename MAP>
Dart random_dart(const MAP& m, std::mt19937& rng)
{
	return random_dart_where(m, rng, [](Dart) { return true; });
}

template <typename MAP>
Dart random_inner_dart(const MAP& m, std::mt19937& rng)
{
	return random_dart_where(m, rng, [&](Dart d) { return !is_boundary(m, d); });
}

// Times the predicate `can` and, when it accepts, the operator `apply`; a
// refused call is not counted.
template <typename CAN, typename APPLY>
bool guarded(Timer& t, const CAN& can, const APPLY& apply)
{
	return t.time([&] {
		if (!can())
			return false;
		apply();
		return true;
	});
}

// ---- meshes

template <typename MAP>
void index_every_orbit(MAP& m)
{
	[&]<typename... C>(std::tuple<C...>*) {
		(
			[&] {
				if constexpr (C::ORBIT != Orbit::DART)
					add_attribute<uint32, C>(m, "index_holder");
			}(),
			...);
	}(static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
}

CMap2 surface(uint32 nb_faces, bool indexed)
{
	const uint32 n = uint32(std::lround(std::sqrt(nb_faces / 2.0)));
	CMap2 m;
	build_surface(m, grid_soup(n, n, true));
	if (indexed)
		index_every_orbit(m);
	return m;
}

CMap3 volume(uint32 nb_volumes, bool indexed)
{
	const uint32 n = uint32(std::lround(std::cbrt(nb_volumes / 6.0)));
	CMap3 m;
	build_volume(m, tet_grid_soup(n, n, n));
	if (indexed)
		index_every_orbit(m);
	return m;
}

// ---- one call of each operator: draws its target, prepares it untimed,
// times predicate and operator; returns false when the target was refused

using M2 = CMap2;
using M3 = CMap3;

template <typename MAP>
using Call = std::function<bool(MAP&, std::mt19937&, Timer&)>;

// the dart after d around its vertex
Dart next_around(const CMap2& m, Dart d)
{
	return phi2(m, phi_1(m, d));
}

const std::vector<std::pair<std::string, Call<M2>>>& surface_operators()
{
	static const std::vector<std::pair<std::string, Call<M2>>> ops = {
		{"cut_edge",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_dart(m, r);
			 t.time([&] { cut_edge(m, M2::Edge(d)); });
			 return true;
		 }},
		{"flip_edge",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Edge e(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_flip_edge(m, e); }, [&] { flip_edge(m, e); });
		 }},
		{"flip_back_edge",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Edge e(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_flip_back_edge(m, e); }, [&] { flip_back_edge(m, e); });
		 }},
		{"collapse_edge",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Edge e(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_collapse_edge(m, e); }, [&] { collapse_edge(m, e); });
		 }},
		{"cut_face",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r);
			 const Dart v = cut_edge(m, M2::Edge(d)).dart; // the face of d becomes a quad
			 const Dart w = phi1(m, phi1(m, v));
			 return guarded(
				 t, [&] { return can_cut_face(m, M2::Vertex(v), M2::Vertex(w)); },
				 [&] { cut_face(m, M2::Vertex(v), M2::Vertex(w)); });
		 }},
		{"merge_incident_faces(edge)",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Edge e(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_merge_incident_faces(m, e); }, [&] { merge_incident_faces(m, e); });
		 }},
		{"merge_incident_faces(vertex)",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Vertex v(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_merge_incident_faces(m, v); }, [&] { merge_incident_faces(m, v); });
		 }},
		{"merge_incident_edges",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Vertex v = cut_edge(m, M2::Edge(random_inner_dart(m, r))); // a vertex of degree 2
			 return guarded(
				 t, [&] { return can_merge_incident_edges(m, v); }, [&] { merge_incident_edges(m, v); });
		 }},
		{"split_vertex",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const Dart d1 = random_dart(m, r);
			 const Dart d2 = next_around(m, next_around(m, d1));
			 return guarded(
				 t, [&] { return can_split_vertex(m, d1, d2); }, [&] { split_vertex(m, d1, d2); });
		 }},
		{"remove_face",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Face f(random_inner_dart(m, r));
			 t.time([&] { remove_face(m, f); });
			 return true;
		 }},
		{"fill_hole_with_face",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r);
			 if (is_incident_to_boundary(m, M2::Face(d)))
				 return false; // keep to holes of one face
			 remove_face(m, M2::Face(d));
			 return guarded(
				 t, [&] { return can_fill_hole_with_face(m, d); }, [&] { fill_hole_with_face(m, d); });
		 }},
		{"unsew_faces",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Edge e(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_unsew_faces(m, e); }, [&] { unsew_faces(m, e); });
		 }},
		{"sew_faces",
		 [](M2& m, std::mt19937& r, Timer& t) {
			 const M2::Edge e(random_dart(m, r));
			 if (!can_unsew_faces(m, e))
				 return false;
			 const Dart d = e.dart, d2 = phi2(m, d);
			 unsew_faces(m, e); // sew it back
			 return guarded(
				 t, [&] { return can_sew_faces(m, M2::Edge(d), M2::Edge(d2)); },
				 [&] { sew_faces(m, M2::Edge(d), M2::Edge(d2)); });
		 }},
	};
	return ops;
}

const std::vector<std::pair<std::string, Call<M3>>>& volume_operators()
{
	static const std::vector<std::pair<std::string, Call<M3>>> ops = {
		{"cut_edge",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_dart(m, r);
			 t.time([&] { cut_edge(m, M3::Edge(d)); });
			 return true;
		 }},
		{"cut_face",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r);
			 const Dart v = phi1(m, d);
			 cut_edge(m, M3::Edge(d)); // the faces around the edge become quads
			 const Dart w = phi1(m, phi1(m, v));
			 return guarded(
				 t, [&] { return can_cut_face(m, v, w); }, [&] { cut_face(m, v, w); });
		 }},
		{"merge_incident_faces",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r);
			 const Dart v = phi1(m, d);
			 cut_edge(m, M3::Edge(d));
			 const M3::Edge e = cut_face(m, v, phi1(m, phi1(m, v)));
			 return guarded(
				 t, [&] { return can_merge_incident_faces(m, e); }, [&] { merge_incident_faces(m, e); });
		 }},
		{"cut_volume",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r);
			 const std::vector<Dart> path = {d, phi1(m, d), phi_1(m, d)}; // around one face
			 t.time([&] { cut_volume(m, path); });
			 return true;
		 }},
		{"merge_incident_volumes",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r);
			 const M3::Face f = cut_volume(m, {d, phi1(m, d), phi_1(m, d)});
			 return guarded(
				 t, [&] { return can_merge_incident_volumes(m, f); }, [&] { merge_incident_volumes(m, f); });
		 }},
		{"collapse_edge",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const M3::Edge e(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_collapse_edge(m, e); }, [&] { collapse_edge(m, e); });
		 }},
		{"flip_face",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const M3::Face f(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_flip_face(m, f); }, [&] { flip_face(m, f); });
		 }},
		{"flip_edge",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const M3::Edge e(random_dart(m, r));
			 return guarded(
				 t, [&] { return can_flip_edge(m, e); }, [&] { flip_edge(m, e); });
		 }},
		{"split_tetra",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const M3::Volume w(random_inner_dart(m, r));
			 t.time([&] { split_tetra(m, w); });
			 return true;
		 }},
		{"unsew_volumes",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r);
			 if (is_boundary(m, phi3(m, d)))
				 return false;
			 t.time([&] { unsew_volumes(m, M3::Face(d)); });
			 return true;
		 }},
		{"sew_volumes",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const Dart d = random_inner_dart(m, r), d3 = phi3(m, d);
			 if (is_boundary(m, d3))
				 return false;
			 unsew_volumes(m, M3::Face(d)); // sew it back
			 return guarded(
				 t, [&] { return can_sew_volumes(m, M3::Face(d), M3::Face(d3)); },
				 [&] { sew_volumes(m, M3::Face(d), M3::Face(d3)); });
		 }},
		{"remove_volume",
		 [](M3& m, std::mt19937& r, Timer& t) {
			 const M3::Volume w(random_inner_dart(m, r));
			 t.time([&] { remove_volume(m, w); });
			 return true;
		 }},
	};
	return ops;
}

// ---- benchmarks and the ratio table

struct Row
{
	std::map<uint32, double> ns_per_call; // by mesh size
};
std::map<std::string, Row>& rows()
{
	static std::map<std::string, Row> r;
	return r;
}

template <typename MAP>
void run(benchmark::State& state, const std::string& row, const Call<MAP>& call, MAP (*make)(uint32, bool))
{
	const uint32 size = uint32(state.range(0));
	const bool indexed = state.range(1) != 0;
	MAP m = make(size, indexed);
	std::mt19937 rng(12345);
	// ROUNDS rounds of CALLS calls, the fastest counted: the first round runs
	// on memory that building the mesh left cold, which a large mesh evicts
	// from the caches and a small one does not (cache effects, not work)
	double best = 0;
	uint64 calls = 0;
	for (auto _ : state)
	{
		double total = 0;
		for (uint32 round = 0; round < ROUNDS; ++round)
		{
			Timer t;
			uint32 done = 0;
			for (uint32 attempts = 0; done < CALLS && attempts < 100 * CALLS; ++attempts)
				done += call(m, rng, t) ? 1 : 0;
			total += t.seconds;
			calls += done;
			if (done > 0 && (best == 0 || t.seconds / done < best))
				best = t.seconds / done;
		}
		state.SetIterationTime(total);
	}
	if (calls == 0)
	{
		state.SkipWithError("no call accepted by the predicate");
		return;
	}
	const double ns = 1e9 * best;
	state.counters["ns_per_call"] = ns;
	if (!check_integrity(m).ok())
		state.SkipWithError("the map is broken after the calls");
	rows()[row + (indexed ? " | all" : " | none")].ns_per_call[size] = ns;
}

template <typename MAP>
void register_all(const char* prefix, const std::vector<std::pair<std::string, Call<MAP>>>& ops,
				  MAP (*make)(uint32, bool))
{
	for (const auto& [name, call] : ops)
	{
		const std::string row = std::string(prefix) + " | " + name;
		auto* b =
			benchmark::RegisterBenchmark((std::string(prefix) + "/" + name).c_str(),
										 [row, call, make](benchmark::State& s) { run<MAP>(s, row, call, make); });
		for (uint32 size : SIZES)
			for (int indexed : {0, 1})
				b->Args({int64_t(size), indexed});
		b->UseManualTime()->Iterations(1)->Unit(benchmark::kMicrosecond);
	}
}

void print_table()
{
	std::printf("\n| map | operator | indexed orbits | ns/call 10^4 | ns/call 10^6 | 10^6 / 10^4 |\n");
	std::printf("|---|---|---|---:|---:|---:|\n");
	for (const auto& [row, r] : rows())
	{
		const auto small = r.ns_per_call.find(SIZES.front()), large = r.ns_per_call.find(SIZES.back());
		if (small == r.ns_per_call.end() || large == r.ns_per_call.end())
			continue;
		std::printf("| %s | %.0f | %.0f | %.2f |\n", row.c_str(), small->second, large->second,
					large->second / small->second);
	}
}

} // namespace

int main(int argc, char** argv)
{
	register_all<M2>("CMap2", surface_operators(), &surface);
	register_all<M3>("CMap3", volume_operators(), &volume);
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv))
		return 1;
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	print_table();
	return 0;
}
