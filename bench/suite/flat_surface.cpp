// SPDX-License-Identifier: MIT
// The "physical limit" of the surface read-only workloads: static flat arrays
// (positions, face->vertex CSR, vertex->face and vertex->vertex CSR, boundary
// flags), no mesh data structure at all. Each visited id is loaded (the
// `>> 31` term is 0 for every id) so that counting loops cannot be reduced to
// differences of offsets.
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

struct FlatSurface
{
	std::vector<P3> pos;
	std::vector<uint32_t> f_off, f_v; // face -> vertices
	std::vector<uint32_t> vf_off, vf; // vertex -> faces
	std::vector<uint32_t> vv_off, vv; // vertex -> vertices
	std::vector<uint8_t> boundary;    // per vertex
	std::vector<P3> fnormal, vnormal;

	explicit FlatSurface(const cgogn::SurfaceSoup& s)
	{
		const uint32_t nv = s.nb_vertices, nf = uint32_t(s.face_sizes.size());
		pos = s.positions;
		f_off.resize(nf + 1, 0);
		for (uint32_t f = 0; f < nf; ++f)
			f_off[f + 1] = f_off[f] + s.face_sizes[f];
		f_v = s.face_vertices;
		// vertex -> faces
		vf_off.assign(nv + 1, 0);
		for (uint32_t v : f_v)
			++vf_off[v + 1];
		for (uint32_t v = 0; v < nv; ++v)
			vf_off[v + 1] += vf_off[v];
		vf.resize(f_v.size());
		std::vector<uint32_t> fill(vf_off.begin(), vf_off.end() - 1);
		for (uint32_t f = 0; f < nf; ++f)
			for (uint32_t k = f_off[f]; k < f_off[f + 1]; ++k)
				vf[fill[f_v[k]]++] = f;
		// vertex -> vertices and boundary: undirected edges with their face count
		std::vector<std::pair<uint64_t, uint32_t>> edges;
		edges.reserve(f_v.size());
		for (uint32_t f = 0; f < nf; ++f)
			for (uint32_t k = f_off[f]; k < f_off[f + 1]; ++k)
			{
				const uint32_t a = f_v[k], b = f_v[k + 1 < f_off[f + 1] ? k + 1 : f_off[f]];
				edges.push_back({(uint64_t(std::min(a, b)) << 32) | std::max(a, b), 1});
			}
		std::sort(edges.begin(), edges.end());
		boundary.assign(nv, 0);
		std::vector<std::vector<uint32_t>> nbr(nv);
		for (std::size_t i = 0; i < edges.size();)
		{
			std::size_t j = i;
			while (j < edges.size() && edges[j].first == edges[i].first)
				++j;
			const uint32_t a = uint32_t(edges[i].first >> 32), b = uint32_t(edges[i].first);
			nbr[a].push_back(b);
			nbr[b].push_back(a);
			if (j - i == 1)
				boundary[a] = boundary[b] = 1;
			i = j;
		}
		vv_off.assign(nv + 1, 0);
		for (uint32_t v = 0; v < nv; ++v)
			vv_off[v + 1] = vv_off[v] + uint32_t(nbr[v].size());
		vv.reserve(vv_off[nv]);
		for (auto& n : nbr)
			vv.insert(vv.end(), n.begin(), n.end());
		fnormal.resize(nf);
		vnormal.resize(nv);
	}
};

FlatSurface& mesh()
{
	return Cache::get<FlatSurface>("flat/surface", [] { return std::make_unique<FlatSurface>(surface_soup()); });
}

void reset_positions(FlatSurface& m)
{
	m.pos = surface_soup().positions;
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
	FlatSurface& m = mesh();
	int64_t c = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			const uint32_t nv = uint32_t(m.pos.size()), nf = uint32_t(m.f_off.size() - 1);
			for (uint32_t v = 0; v < nv; ++v)
				for (uint32_t k = m.vf_off[v]; k < m.vf_off[v + 1]; ++k)
					c += 1 + (m.vf[k] >> 31);
			for (uint32_t f = 0; f < nf; ++f)
				for (uint32_t k = m.f_off[f]; k < m.f_off[f + 1]; ++k)
					c -= 1 + (m.f_v[k] >> 31);
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
}

void barycenter(benchmark::State& state, bool first)
{
	FlatSurface& m = mesh();
	timed(
		state, first, [&] { reset_positions(m); },
		[&] {
			// four partial sums, as geometry::mean_position: the limit of the
			// loop, not a chain of dependent adds
			P3 s[4] = {};
			const std::size_t nv = m.pos.size();
			std::size_t i = 0;
			for (; i + 4 <= nv; i += 4)
				for (std::size_t k = 0; k < 4; ++k)
					for (std::size_t c = 0; c < 3; ++c)
						s[k][c] += m.pos[i + k][c];
			for (; i < nv; ++i)
				for (std::size_t c = 0; c < 3; ++c)
					s[0][c] += m.pos[i][c];
			const double n = double(nv);
			P3 b;
			for (std::size_t c = 0; c < 3; ++c)
				b[c] = ((s[0][c] + s[1][c]) + (s[2][c] + s[3][c])) / n;
			for (P3& p : m.pos)
				p[0] -= b[0], p[1] -= b[1], p[2] -= b[2];
		});
	double s = 0;
	for (const P3& p : m.pos)
		s += std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]);
	set_check(state, "check", s);
}

void normal(benchmark::State& state, bool first)
{
	FlatSurface& m = mesh();
	timed(
		state, first, [] {},
		[&] {
			const uint32_t nv = uint32_t(m.pos.size()), nf = uint32_t(m.f_off.size() - 1);
			for (uint32_t f = 0; f < nf; ++f)
			{
				const uint32_t* fv = &m.f_v[m.f_off[f]];
				const P3 &p0 = m.pos[fv[0]], &p1 = m.pos[fv[1]], &p2 = m.pos[fv[2]];
				const double u[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
				const double w[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
				P3 n{u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
				const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
				if (l > 0)
					n = {n[0] / l, n[1] / l, n[2] / l};
				m.fnormal[f] = n;
			}
			for (uint32_t v = 0; v < nv; ++v)
			{
				P3 n{0, 0, 0};
				for (uint32_t k = m.vf_off[v]; k < m.vf_off[v + 1]; ++k)
				{
					const P3& q = m.fnormal[m.vf[k]];
					n[0] += q[0], n[1] += q[1], n[2] += q[2];
				}
				const double l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
				if (l > 0)
					n = {n[0] / l, n[1] / l, n[2] / l};
				m.vnormal[v] = n;
			}
		});
	set_check(state, "check", coordinate_sum(m.vnormal));
}

void smoothing(benchmark::State& state, bool first)
{
	FlatSurface& m = mesh();
	timed(
		state, first, [&] { reset_positions(m); },
		[&] {
			const uint32_t nv = uint32_t(m.pos.size());
			for (uint32_t v = 0; v < nv; ++v)
			{
				if (m.boundary[v])
					continue;
				P3 s{0, 0, 0};
				const uint32_t b = m.vv_off[v], e = m.vv_off[v + 1];
				for (uint32_t k = b; k < e; ++k)
				{
					const P3& q = m.pos[m.vv[k]];
					s[0] += q[0], s[1] += q[1], s[2] += q[2];
				}
				const double n = double(e - b);
				m.pos[v] = {s[0] / n, s[1] / n, s[2] / n};
			}
		});
	set_check(state, "check", coordinate_sum(m.pos));
}

const bool registered = [] {
	register_bench("surface/circulator/flat", Kind::read_only, circulator);
	register_bench("surface/barycenter/flat", Kind::read_only, barycenter);
	register_bench("surface/normal/flat", Kind::read_only, normal);
	register_bench("surface/smoothing/flat", Kind::read_only, smoothing);
	return true;
}();

} // namespace

} // namespace cgogn_bench
