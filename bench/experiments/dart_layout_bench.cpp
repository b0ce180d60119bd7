// SPDX-License-Identifier: MIT
// Which dart layout makes the vertex walk fast: the surface suite's smoothing
// (one Gauss-Seidel pass, boundary vertices skipped) over the same map and
// the same positions, with the relations stored in several ways:
//   soa          one plain array per relation (phi1, phi2, vertex index) and a
//                boundary bit array: the limit for this walk
//   aos16        one 16-byte record per dart {phi1, phi2, vertex, face}
//   aos8         one 8-byte record per dart {phi1, phi2}, the vertex index
//                in its own array
//   soa_prefetch soa, prefetching phi2's cache line at phi2(d) as soon as it
//                is known (the next step reads phi2 in that dart's face)
//   block_table  the plain arrays reached through a table of 4096-element
//                blocks (cgogn's storage before LineStorage)
//   range_check  the plain arrays behind a `i < size ? base[i] : block(i)`
//                test (LineStorage's access)
//   lib_memory   the range_check walk over the library's own storages (the
//                map's phi1, phi2, vertex index and positions) through
//                pointers held in locals: where the values live
//   lib_access   the same walk through the library's accessors (phi1(m, d),
//                phi2(m, d), is_boundary, the index attribute, value):
//                how the compiler handles them in a loop
//   cgogn        the library's accessors and traversal (bench_suite's
//                surface/smoothing/cgogn)
//   paired_explicit  soa with the darts renumbered so that the two darts of
//                an edge are 2k and 2k+1 (pairs in order of first use by the
//                original dart order), phi2 still read from its array
//   paired_checked  the same numbering, phi2 read but the walk goes on with
//                d ^ 1 and only checks the value (a predicted branch instead
//                of a data dependency): what a builder numbering edges in
//                pairs would give without dropping the stored phi2
//   paired       the same numbering with phi2(d) = d ^ 1 computed, not read:
//                one dependent load per step around a vertex (phi1 of d ^ 1)
//                instead of two (phi2, then phi1), as a half-edge structure
// Same input as bench_suite (--input=data|generated|small); the numbers are
// in docs/performance.md.
#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>

#include "harness.h"
#include "inputs.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <vector>

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Face = CMap2::Face;

namespace
{

constexpr uint32 BLOCK_SHIFT = 12, BLOCK_MASK = (1u << BLOCK_SHIFT) - 1u;

// One array per relation and a boundary bit array, indexed by dart.
struct DartArrays
{
	std::vector<uint32> phi1, phi2, vertex;
	std::vector<uint64> boundary_bits;
};

struct Layouts
{
	CMap2 map;
	std::shared_ptr<AttributeArray<Vec3>> position;
	uint32 nb_vertices = 0;
	std::vector<uint32> vertex_dart; // INVALID_INDEX for free lines
	std::vector<Vec3> initial;       // per vertex line
	// soa
	DartArrays plain;
	std::vector<Vec3> pos;
	// aos16
	struct Record
	{
		uint32 phi1, phi2, vertex, face;
	};
	std::vector<Record> records;
	// aos8: {phi1, phi2} interleaved, vertex index in its own array
	struct Links
	{
		uint32 phi1, phi2;
	};
	std::vector<Links> links;
	// block_table: block pointers into the soa arrays
	std::vector<uint32*> phi1_blocks, phi2_blocks, vertex_blocks;
	std::vector<uint64*> boundary_blocks;
	std::vector<Vec3*> pos_blocks;
	// paired: darts renumbered in edge pairs (see the header comment)
	DartArrays paired;
	std::vector<uint32> paired_vertex_dart;

	Layouts()
	{
		const SurfaceSoup& s = cgogn_bench::surface_soup();
		const uint32 offset = build_surface(map, s).vertex_offset;
		position = add_attribute<Vec3, Vertex>(map, "position");
		add_attribute<Vec3, Face>(map, "normal"); // indexes faces, as the suite's map
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*position)[offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		const uint32 nd = cgogn::detail::state_of(map).darts->end_index();
		const AttributeArray<uint32>& vidx = *cgogn::detail::state_of(map).cell_index[orbit_index(Orbit::PHI21)];
		const AttributeArray<uint32>& fidx = *cgogn::detail::state_of(map).cell_index[orbit_index(Orbit::PHI1)];
		auto& [phi1, phi2, vertex, boundary_bits] = plain;
		phi1.resize(nd);
		phi2.resize(nd);
		vertex.resize(nd);
		boundary_bits.assign(nd / 64 + 1 + 64, 0);
		records.resize(nd);
		links.resize(nd);
		for (uint32 d = 0; d < nd; ++d)
		{
			phi1[d] = (*cgogn::detail::state_of(map).phi1)[d];
			phi2[d] = (*cgogn::detail::state_of(map).phi2)[d];
			vertex[d] = vidx[d];
			if (is_boundary(map, Dart(d)))
				boundary_bits[d >> 6] |= uint64(1) << (d & 63u);
			records[d] = {phi1[d], phi2[d], vertex[d], fidx[d]};
			links[d] = {phi1[d], phi2[d]};
		}
		const AttributeContainer& vertices = *cgogn::detail::state_of(map).cells[orbit_index(Orbit::PHI21)];
		nb_vertices = vertices.end_index();
		vertex_dart.resize(nb_vertices);
		initial.resize(nb_vertices);
		for (uint32 v = 0; v < nb_vertices; ++v)
		{
			vertex_dart[v] = vertices.key()[v];
			initial[v] = (*position)[v];
		}
		pos = initial;
		for (uint32 b = 0; (b << BLOCK_SHIFT) < nd; ++b)
		{
			phi1_blocks.push_back(phi1.data() + (b << BLOCK_SHIFT));
			phi2_blocks.push_back(phi2.data() + (b << BLOCK_SHIFT));
			vertex_blocks.push_back(vertex.data() + (b << BLOCK_SHIFT));
			boundary_blocks.push_back(boundary_bits.data() + (b << (BLOCK_SHIFT - 6)));
		}
		for (uint32 b = 0; (b << BLOCK_SHIFT) < nb_vertices; ++b)
			pos_blocks.push_back(pos.data() + (b << BLOCK_SHIFT));
		pair_darts(nd);
	}

	void pair_darts(uint32 nd)
	{
		const auto& [phi1, phi2, vertex, boundary_bits] = plain;
		std::vector<uint32> renumber(nd, INVALID_INDEX);
		uint32 next = 0;
		for (uint32 d = 0; d < nd; ++d)
			if (phi1[d] != INVALID_INDEX && renumber[d] == INVALID_INDEX)
			{
				renumber[d] = next++;
				renumber[phi2[d]] = next++;
			}
		paired.phi1.assign(next, INVALID_INDEX);
		paired.phi2.assign(next, INVALID_INDEX);
		paired.vertex.assign(next, INVALID_INDEX);
		paired.boundary_bits.assign(next / 64 + 1 + 64, 0);
		for (uint32 d = 0; d < nd; ++d)
			if (renumber[d] != INVALID_INDEX)
			{
				const uint32 n = renumber[d];
				paired.phi1[n] = renumber[phi1[d]];
				paired.phi2[n] = renumber[phi2[d]];
				paired.vertex[n] = vertex[d];
				if ((boundary_bits[d >> 6] >> (d & 63u)) & 1u)
					paired.boundary_bits[n >> 6] |= uint64(1) << (n & 63u);
			}
		paired_vertex_dart.resize(nb_vertices);
		for (uint32 v = 0; v < nb_vertices; ++v)
			paired_vertex_dart[v] = vertex_dart[v] == INVALID_INDEX ? INVALID_INDEX : renumber[vertex_dart[v]];
	}

	// The same walk for every layout: ACCESS gives (boundary?, phi2, vertex,
	// phi1, position) for darts and vertex lines.
	template <typename A>
	void smooth(const A& access)
	{
		smooth(access, vertex_dart);
	}
	template <typename A>
	void smooth(const A& access, const std::vector<uint32>& starts)
	{
		for (uint32 v = 0; v < nb_vertices; ++v)
		{
			const uint32 d = starts[v];
			if (d == INVALID_INDEX)
				continue;
			Vec3 sum = Vec3::Zero();
			uint32 n = 0, it = d;
			bool inner = true;
			do
			{
				if (access.boundary(it))
				{
					inner = false;
					break;
				}
				const uint32 e = access.phi2(it);
				sum += access.pos(access.vertex(e));
				++n;
				it = access.phi1(e);
			} while (it != d);
			if (inner)
				access.pos(v) = sum / double(n);
		}
	}
};

Layouts& layouts()
{
	static Layouts l;
	return l;
}

// The plain arrays of one dart numbering (l.plain or l.paired).
struct Soa
{
	Layouts& l;
	const DartArrays& a;
	bool boundary(uint32 d) const
	{
		return (a.boundary_bits[d >> 6] >> (d & 63u)) & 1u;
	}
	uint32 phi1(uint32 d) const
	{
		return a.phi1[d];
	}
	uint32 phi2(uint32 d) const
	{
		return a.phi2[d];
	}
	uint32 vertex(uint32 d) const
	{
		return a.vertex[d];
	}
	Vec3& pos(uint32 v) const
	{
		return l.pos[v];
	}
};

// phi1 and phi2 read from the per-dart records l.*RECORDS
template <auto RECORDS>
struct Records : Soa
{
	uint32 phi1(uint32 d) const
	{
		return (l.*RECORDS)[d].phi1;
	}
	uint32 phi2(uint32 d) const
	{
		return (l.*RECORDS)[d].phi2;
	}
};

struct Aos16 : Records<&Layouts::records>
{
	uint32 vertex(uint32 d) const
	{
		return l.records[d].vertex;
	}
};

using Aos8 = Records<&Layouts::links>;

// soa, and as soon as phi2(d) = e is known, a prefetch of phi2's cache line
// at e: the next step reads phi2 at phi1(e), a dart of e's face, whose darts
// are usually consecutive (the builder allocates a face's darts together), so
// that miss overlaps the phi1(e) one instead of following it
struct SoaPrefetch : Soa
{
	uint32 phi2(uint32 d) const
	{
		const uint32 e = a.phi2[d];
		__builtin_prefetch(&a.phi2[e]);
		return e;
	}
};

// l.paired's numbering: phi2 computed, never read
struct Paired : Soa
{
	uint32 phi2(uint32 d) const
	{
		return d ^ 1u;
	}
};

// l.paired's numbering with phi2 still read, but only checked: the walk goes
// on with d ^ 1 while the load is in flight (a predicted branch, not a data
// dependency); the asm keeps the compiler from folding the test away
struct PairedChecked : Soa
{
	uint32 phi2(uint32 d) const
	{
		uint32 x = a.phi2[d];
		if (x != (d ^ 1u)) [[unlikely]]
		{
			asm volatile("" : "+r"(x));
			return x;
		}
		return d ^ 1u;
	}
};

struct BlockTable
{
	Layouts& l;
	bool boundary(uint32 d) const
	{
		return (l.boundary_blocks[d >> BLOCK_SHIFT][(d & BLOCK_MASK) >> 6] >> (d & 63u)) & 1u;
	}
	uint32 phi1(uint32 d) const
	{
		return l.phi1_blocks[d >> BLOCK_SHIFT][d & BLOCK_MASK];
	}
	uint32 phi2(uint32 d) const
	{
		return l.phi2_blocks[d >> BLOCK_SHIFT][d & BLOCK_MASK];
	}
	uint32 vertex(uint32 d) const
	{
		return l.vertex_blocks[d >> BLOCK_SHIFT][d & BLOCK_MASK];
	}
	Vec3& pos(uint32 v) const
	{
		return l.pos_blocks[v >> BLOCK_SHIFT][v & BLOCK_MASK];
	}
};

// An array whose elements past `limit` would live in blocks (never here: the
// limit is out of reach but unknown to the compiler, as in LineStorage)
template <typename T>
struct Checked
{
	T* base;
	uint32 limit;
	[[gnu::noinline]] T& in_block(uint32) const
	{
		std::abort();
	}
	T& operator[](uint32 i) const
	{
		if (i < limit) [[likely]]
			return base[i];
		return in_block(i);
	}
};

struct RangeCheck
{
	Checked<uint32> phi1_, phi2_, vertex_;
	Checked<uint64> bits_;
	Checked<Vec3> pos_;
	bool boundary(uint32 d) const
	{
		return (bits_[d >> 6] >> (d & 63u)) & 1u;
	}
	uint32 phi1(uint32 d) const
	{
		return phi1_[d];
	}
	uint32 phi2(uint32 d) const
	{
		return phi2_[d];
	}
	uint32 vertex(uint32 d) const
	{
		return vertex_[d];
	}
	Vec3& pos(uint32 v) const
	{
		return pos_[v];
	}
};

struct LibAccess
{
	const CMap2& m;
	AttributeArray<Vec3>& p;
	const AttributeArray<uint32>& vidx;
	bool boundary(uint32 d) const
	{
		return is_boundary(m, Dart(d));
	}
	uint32 phi1(uint32 d) const
	{
		return cgogn::phi1(m, Dart(d)).index;
	}
	uint32 phi2(uint32 d) const
	{
		return cgogn::phi2(m, Dart(d)).index;
	}
	uint32 vertex(uint32 d) const
	{
		return vidx[d];
	}
	Vec3& pos(uint32 v) const
	{
		return p[v];
	}
};

volatile uint32 far_limit = 0xF0000000u;

// Positions restored (untimed) from l.initial before each pass, then summed
// into the check value. POSITIONS: the soa vector or the library's attribute.
template <typename F, typename POSITIONS>
void run(benchmark::State& state, Layouts& l, F&& pass, POSITIONS& positions)
{
	for (auto _ : state)
	{
		state.PauseTiming();
		for (uint32 v = 0; v < l.nb_vertices; ++v)
			positions[v] = l.initial[v];
		state.ResumeTiming();
		pass();
	}
	double check = 0;
	for (const Vec3& p : positions)
		check += p.sum();
	state.counters["check"] = check;
}

void soa(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l,
		[&] {
			l.smooth(Soa{l, l.plain});
		},
		l.pos);
}
void aos16(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l,
		[&] {
			l.smooth(Aos16{{{l, l.plain}}});
		},
		l.pos);
}
void soa_prefetch(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l,
		[&] {
			l.smooth(SoaPrefetch{{l, l.plain}});
		},
		l.pos);
}
void aos8(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l,
		[&] {
			l.smooth(Aos8{{l, l.plain}});
		},
		l.pos);
}
void paired_explicit(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l,
		[&] {
			l.smooth(Soa{l, l.paired}, l.paired_vertex_dart);
		},
		l.pos);
}
void paired_checked(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l,
		[&] {
			l.smooth(PairedChecked{{l, l.paired}}, l.paired_vertex_dart);
		},
		l.pos);
}
void paired(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l,
		[&] {
			l.smooth(Paired{{l, l.paired}}, l.paired_vertex_dart);
		},
		l.pos);
}
void block_table(benchmark::State& state)
{
	Layouts& l = layouts();
	run(
		state, l, [&] { l.smooth(BlockTable{l}); }, l.pos);
}
void range_check(benchmark::State& state)
{
	Layouts& l = layouts();
	const uint32 lim = far_limit;
	run(
		state, l,
		[&] {
			l.smooth(RangeCheck{{l.plain.phi1.data(), lim},
								{l.plain.phi2.data(), lim},
								{l.plain.vertex.data(), lim},
								{l.plain.boundary_bits.data(), lim},
								{l.pos.data(), lim}});
		},
		l.pos);
}
void lib_access(benchmark::State& state)
{
	Layouts& l = layouts();
	const CMap2& m = l.map;
	run(
		state, l,
		[&] {
			l.smooth(LibAccess{m, *l.position, *cgogn::detail::state_of(m).cell_index[orbit_index(Orbit::PHI21)]});
		},
		*l.position);
}
void lib_memory(benchmark::State& state)
{
	Layouts& l = layouts();
	const CMap2& m = l.map;
	const uint32 lim = far_limit;
	run(
		state, l,
		[&] {
			l.smooth(RangeCheck{{&(*cgogn::detail::state_of(m).phi1)[0], lim},
								{&(*cgogn::detail::state_of(m).phi2)[0], lim},
								{&(*cgogn::detail::state_of(m).cell_index[orbit_index(Orbit::PHI21)])[0], lim},
								{l.plain.boundary_bits.data(), lim},
								{&(*l.position)[0], lim}});
		},
		*l.position);
}
void cgogn_library(benchmark::State& state)
{
	Layouts& l = layouts();
	const CMap2& m = l.map;
	AttributeArray<Vec3>& pos = *l.position;
	auto pass = [&] {
		foreach_cell(m, [&](Located<Vertex> v) {
			Vec3 s = Vec3::Zero();
			uint32 n = 0;
			const bool inner = foreach_dart_of_orbit(m, v, [&](Dart d) {
				if (is_boundary(m, d))
					return false;
				s += value<Vec3>(m, pos, Vertex(phi2(m, d)));
				++n;
				return true;
			});
			if (inner)
				pos[v] = s / double(n);
		});
	};
	run(state, l, pass, pos);
}

} // namespace

BENCHMARK(soa)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(aos16)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(block_table)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(range_check)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(lib_access)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(lib_memory)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(cgogn_library)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(soa_prefetch)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(aos8)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(paired_explicit)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(paired_checked)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);
BENCHMARK(paired)->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true);

int main(int argc, char** argv)
{
	std::vector<char*> args;
	try
	{
		args = cgogn_bench::take_input_options(argc, argv);
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "bench_dart_layout: %s\n", e.what());
		return 2;
	}
	int n = int(args.size());
	benchmark::Initialize(&n, args.data());
	if (benchmark::ReportUnrecognizedArguments(n, args.data()))
		return 1;
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}
