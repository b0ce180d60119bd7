// SPDX-License-Identifier: MIT
#include "nmap_shapes.h"

#include <algorithm>
#include <numeric>
#include <unordered_map>

namespace cgogn::detail
{

namespace
{

// A flag as a sequence of small numbers (a permutation, or a vertex then an
// order of the axes), packed into one key: the flags of a shape are found
// back from their sequences.
uint64 code_of(const std::vector<uint32>& seq)
{
	uint64 c = 0;
	for (uint32 x : seq)
		c = c * 256 + x;
	return c;
}

// Fills beta, facet_flags and flag_at_vertex of a shape whose flags are
// `flags` (sequences), with chain, facet_of_flag and facet_vertices set, and
// beta_i of a flag given by `swap_i` on its sequence.
template <typename SWAP>
void link_flags(CellShape& s, const std::vector<std::vector<uint32>>& flags, const SWAP& swap_i)
{
	std::unordered_map<uint64, uint32> index;
	for (uint32 f = 0; f < flags.size(); ++f)
		index.emplace(code_of(flags[f]), f);
	const uint32 D = s.dimension;
	s.nb_flags = uint32(flags.size());
	s.beta.assign(std::size_t(D > 1 ? D - 1 : 0) * s.nb_flags, 0);
	for (uint32 i = 1; i < D; ++i)
		for (uint32 f = 0; f < s.nb_flags; ++f)
			s.beta[(i - 1) * s.nb_flags + f] = index.at(code_of(swap_i(flags[f], i)));
	s.facet_flags.assign(s.facet_vertices.size(), {});
	s.flag_at_vertex.assign(s.nb_vertices, 0);
	for (uint32 f = s.nb_flags; f-- > 0;)
	{
		s.facet_flags[s.facet_of_flag[f]].push_back(f);
		s.flag_at_vertex[s.chain[f * D]] = f;
	}
}

} // namespace

CellShape simplex_shape(uint32 D)
{
	CellShape s;
	s.dimension = D;
	s.nb_vertices = D + 1;
	std::vector<uint32> p(D + 1);
	std::iota(p.begin(), p.end(), 0u);
	std::vector<std::vector<uint32>> flags;
	do
	{
		if (p[0] < p[1])
		{
			flags.push_back(p);
			std::vector<uint32> q = p;
			std::swap(q[0], q[1]);
			flags.push_back(q);
		}
	} while (std::next_permutation(p.begin(), p.end()));
	for (const auto& f : flags)
	{
		s.chain.insert(s.chain.end(), f.begin(), f.begin() + D);
		s.facet_of_flag.push_back(f[D]);
	}
	for (uint32 v = 0; v <= D; ++v)
	{
		s.facet_vertices.emplace_back();
		for (uint32 w = 0; w <= D; ++w)
			if (w != v)
				s.facet_vertices.back().push_back(w);
	}
	link_flags(s, flags, [](std::vector<uint32> f, uint32 i) {
		std::swap(f[i], f[i + 1]);
		return f;
	});
	return s;
}

CellShape cube_shape(uint32 D)
{
	CellShape s;
	s.dimension = D;
	s.nb_vertices = 1u << D;
	// a flag: (v, s_0, ..., s_{D-1})
	std::vector<uint32> axes(D);
	std::iota(axes.begin(), axes.end(), 0u);
	std::vector<std::vector<uint32>> flags;
	do
	{
		for (uint32 v = 0; v < s.nb_vertices; ++v)
			if ((v >> axes[0] & 1u) == 0)
				for (uint32 w : {v, v ^ (1u << axes[0])})
				{
					std::vector<uint32> f{w};
					f.insert(f.end(), axes.begin(), axes.end());
					flags.push_back(f);
				}
	} while (std::next_permutation(axes.begin(), axes.end()));
	for (const auto& f : flags)
	{
		const uint32 v = f[0];
		s.chain.push_back(v);
		for (uint32 k = 1; k < D; ++k)
			s.chain.push_back(v ^ (1u << f[k]));
		const uint32 last = f[D];
		s.facet_of_flag.push_back(2 * last + (v >> last & 1u));
	}
	for (uint32 a = 0; a < D; ++a)
		for (uint32 side = 0; side < 2; ++side)
		{
			s.facet_vertices.emplace_back();
			for (uint32 w = 0; w < s.nb_vertices; ++w)
				if ((w >> a & 1u) == side)
					s.facet_vertices.back().push_back(w);
		}
	link_flags(s, flags, [](std::vector<uint32> f, uint32 i) {
		std::swap(f[i], f[i + 1]); // s_{i-1} and s_i are f[i] and f[i + 1]
		return f;
	});
	return s;
}

} // namespace cgogn::detail
