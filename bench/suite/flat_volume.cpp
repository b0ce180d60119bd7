// SPDX-License-Identifier: MIT
// The "physical limit" of the volume read-only workloads: static flat arrays
// (positions, tet->vertex list, vertex->tet and vertex->vertex CSR, boundary
// flags), no mesh data structure at all.
#include "harness.h"
#include "inputs.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace cgogn_bench
{

namespace
{

using P3 = std::array<double, 3>;

struct FlatVolume
{
	std::vector<P3> pos, pos2, bary;
	std::vector<uint32_t> t_v;        // 4 per tet
	std::vector<uint32_t> vt_off, vt; // vertex -> tets
	std::vector<uint32_t> vv_off, vv; // vertex -> vertices (edge neighbours)
	std::vector<uint8_t> boundary;    // per vertex: on a face with one tet

	explicit FlatVolume(const cgogn::VolumeSoup& s)
	{
		const uint32_t nv = s.nb_vertices, nt = uint32_t(s.cell_sizes.size());
		pos = s.positions;
		pos2.resize(nv);
		bary.resize(nt);
		t_v = s.cell_vertices;
		vt_off.assign(nv + 1, 0);
		for (uint32_t v : t_v)
			++vt_off[v + 1];
		for (uint32_t v = 0; v < nv; ++v)
			vt_off[v + 1] += vt_off[v];
		vt.resize(t_v.size());
		std::vector<uint32_t> fill(vt_off.begin(), vt_off.end() - 1);
		for (uint32_t t = 0; t < nt; ++t)
			for (uint32_t k = 0; k < 4; ++k)
				vt[fill[t_v[4 * t + k]]++] = t;
		std::vector<std::vector<uint32_t>> nbr(nv);
		for (uint32_t t = 0; t < nt; ++t)
			for (uint32_t i = 0; i < 4; ++i)
				for (uint32_t j = 0; j < 4; ++j)
					if (i != j)
						nbr[t_v[4 * t + i]].push_back(t_v[4 * t + j]);
		vv_off.assign(nv + 1, 0);
		for (uint32_t v = 0; v < nv; ++v)
		{
			std::sort(nbr[v].begin(), nbr[v].end());
			nbr[v].erase(std::unique(nbr[v].begin(), nbr[v].end()), nbr[v].end());
			vv_off[v + 1] = vv_off[v] + uint32_t(nbr[v].size());
		}
		for (auto& n : nbr)
			vv.insert(vv.end(), n.begin(), n.end());
		// boundary faces: sorted vertex triples seen once
		std::vector<std::array<uint32_t, 3>> faces;
		faces.reserve(4 * std::size_t(nt));
		for (uint32_t t = 0; t < nt; ++t)
			for (uint32_t skip = 0; skip < 4; ++skip)
			{
				std::array<uint32_t, 3> f;
				uint32_t n = 0;
				for (uint32_t k = 0; k < 4; ++k)
					if (k != skip)
						f[n++] = t_v[4 * t + k];
				std::sort(f.begin(), f.end());
				faces.push_back(f);
			}
		std::sort(faces.begin(), faces.end());
		boundary.assign(nv, 0);
		for (std::size_t i = 0; i < faces.size();)
		{
			std::size_t j = i;
			while (j < faces.size() && faces[j] == faces[i])
				++j;
			if (j - i == 1)
				for (uint32_t v : faces[i])
					boundary[v] = 1;
			i = j;
		}
	}
};

FlatVolume& mesh()
{
	return Cache::get<FlatVolume>("flat/volume", [] { return std::make_unique<FlatVolume>(volume_soup()); });
}

double coordinate_sum(const std::vector<P3>& v)
{
	double s = 0;
	for (const P3& p : v)
		s += p[0] + p[1] + p[2];
	return s;
}

void circulator(benchmark::State& state, bool first)
{
	FlatVolume& m = mesh();
	int64_t c = 0, incidences = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			incidences = 0;
			const uint32_t nv = uint32_t(m.pos.size()), nt = uint32_t(m.bary.size());
			for (uint32_t v = 0; v < nv; ++v)
				for (uint32_t k = m.vt_off[v]; k < m.vt_off[v + 1]; ++k)
					c += 1 + (m.vt[k] >> 31);
			incidences = c;
			for (uint32_t t = 0; t < nt; ++t)
				for (uint32_t k = 0; k < 4; ++k)
					c -= 1 + (m.t_v[4 * t + k] >> 31);
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
	set_check(state, "check_incidences", double(incidences));
}

void circulator2(benchmark::State& state, bool first)
{
	FlatVolume& m = mesh();
	int64_t total = 0;
	timed(
		state, first, [] {},
		[&] {
			total = 0;
			const uint32_t nv = uint32_t(m.pos.size());
			for (uint32_t v = 0; v < nv; ++v)
				for (uint32_t k = m.vv_off[v]; k < m.vv_off[v + 1]; ++k)
					total += 1 + (m.vv[k] >> 31);
			benchmark::DoNotOptimize(total);
		});
	set_check(state, "check", double(total));
	// the naive variant: every (v, tet, vertex of the tet) triple
	int64_t naive = 0;
	for (uint32_t v = 0; v < m.pos.size(); ++v)
		naive += 4 * int64_t(m.vt_off[v + 1] - m.vt_off[v]);
	state.counters["naive_triples"] = double(naive);
}

void barycenter(benchmark::State& state, bool first)
{
	FlatVolume& m = mesh();
	timed(
		state, first, [] {},
		[&] {
			const uint32_t nt = uint32_t(m.bary.size());
			for (uint32_t t = 0; t < nt; ++t)
			{
				P3 b{0, 0, 0};
				for (uint32_t k = 0; k < 4; ++k)
				{
					const P3& p = m.pos[m.t_v[4 * t + k]];
					b[0] += p[0], b[1] += p[1], b[2] += p[2];
				}
				m.bary[t] = {b[0] / 4, b[1] / 4, b[2] / 4};
			}
		});
	set_check(state, "check", coordinate_sum(m.bary));
}

void smoothing_pass(FlatVolume& m)
{
	const uint32_t nv = uint32_t(m.pos.size());
	for (uint32_t v = 0; v < nv; ++v)
	{
		P3 s{0, 0, 0};
		const uint32_t b = m.vv_off[v], e = m.vv_off[v + 1];
		for (uint32_t k = b; k < e; ++k)
		{
			const P3& q = m.pos[m.vv[k]];
			s[0] += q[0], s[1] += q[1], s[2] += q[2];
		}
		const double n = double(e - b);
		m.pos2[v] = {s[0] / n, s[1] / n, s[2] / n};
	}
	m.pos.swap(m.pos2);
}

void smoothing(benchmark::State& state, bool first)
{
	FlatVolume& m = mesh();
	timed(
		state, first, [&] { m.pos = volume_soup().positions; }, [&] { smoothing_pass(m); });
	// check: coordinate sum after 7 passes from the original positions
	m.pos = volume_soup().positions;
	for (int i = 0; i < 7; ++i)
		smoothing_pass(m);
	set_check(state, "check", coordinate_sum(m.pos));
}

const bool registered = [] {
	register_bench("volume/circulator/flat", Kind::read_only, circulator);
	register_bench("volume/circulator2/flat", Kind::read_only, circulator2);
	register_bench("volume/barycenter/flat", Kind::read_only, barycenter);
	register_bench("volume/smoothing/flat", Kind::read_only, smoothing);
	return true;
}();

} // namespace

} // namespace cgogn_bench
