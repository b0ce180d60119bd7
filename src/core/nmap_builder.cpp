// SPDX-License-Identifier: MIT
// Maps of any dimension from simplicial and cubical complexes: every top cell
// becomes the flags of its shape (see nmap_shapes.h), cells sharing a facet
// are sewn by beta_D where their flags name the same vertices, and the free
// facets are closed by boundary D-cells. A CMapN is the orientation class of
// the G-map so built.
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/build/nmap_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/utils/error.h>

#include "nmap_close.h"
#include "nmap_shapes.h"

#include <algorithm>
#include <numeric>
#include <string>

namespace cgogn
{

namespace detail
{
template <typename CMAP, typename GMAP>
void cmap_into(const GMAP& g, CMAP& m, const char* name, std::vector<uint32>& c);
} // namespace detail

namespace
{

// The beta_D partner of every flag (cell * nb_flags + flag), INVALID_INDEX
// for the flags of a free facet; throws on a bad complex. Reads only the
// ids: nothing is built before the complex is known to be good.
std::vector<uint32> glued_flags(const detail::CellShape& s, uint32 nb_vertices, std::span<const uint32> ids,
								const std::string& what)
{
	const uint32 nv = s.nb_vertices, D = s.dimension, F = s.nb_flags;
	if (ids.size() % nv != 0)
		throw Error(what + ": " + std::to_string(ids.size()) + " vertex ids is not a whole number of cells of " +
					std::to_string(nv) + " vertices");
	const uint32 nb_cells = uint32(ids.size() / nv);
	std::vector<uint32> sorted(nv);
	for (uint32 c = 0; c < nb_cells; ++c)
	{
		std::copy_n(ids.begin() + std::size_t(c) * nv, nv, sorted.begin());
		std::sort(sorted.begin(), sorted.end());
		if (sorted.back() >= nb_vertices)
			throw Error(what + ": cell " + std::to_string(c) + " uses vertex " + std::to_string(sorted.back()) +
						", out of range (" + std::to_string(nb_vertices) + " vertices)");
		if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
			throw Error(what + ": cell " + std::to_string(c) + " uses a vertex twice");
	}
	// the facets of all cells, by their sorted vertex ids
	const uint32 nf = uint32(s.facet_vertices.size()), fv = uint32(s.facet_vertices[0].size());
	std::vector<uint32> keys(std::size_t(nb_cells) * nf * fv);
	for (uint32 c = 0; c < nb_cells; ++c)
		for (uint32 f = 0; f < nf; ++f)
		{
			uint32* k = &keys[(std::size_t(c) * nf + f) * fv];
			for (uint32 j = 0; j < fv; ++j)
				k[j] = ids[std::size_t(c) * nv + s.facet_vertices[f][j]];
			std::sort(k, k + fv);
		}
	std::vector<uint32> order(std::size_t(nb_cells) * nf);
	std::iota(order.begin(), order.end(), 0u);
	auto key = [&](uint32 i) { return &keys[std::size_t(i) * fv]; };
	auto less = [&](uint32 a, uint32 b) {
		return std::lexicographical_compare(key(a), key(a) + fv, key(b), key(b) + fv);
	};
	auto same = [&](uint32 a, uint32 b) { return std::equal(key(a), key(a) + fv, key(b)); };
	std::sort(order.begin(), order.end(), less);

	std::vector<uint32> partner(std::size_t(nb_cells) * F, INVALID_INDEX);
	// the flags of facet f of cell c, sorted by the ids their chains name
	auto chain_ids = [&](uint32 c, uint32 flag) {
		std::vector<uint32> r(D);
		for (uint32 k = 0; k < D; ++k)
			r[k] = ids[std::size_t(c) * nv + s.chain[flag * D + k]];
		return r;
	};
	auto sorted_flags = [&](uint32 c, uint32 f) {
		std::vector<std::pair<std::vector<uint32>, uint32>> r;
		for (uint32 flag : s.facet_flags[f])
			r.emplace_back(chain_ids(c, flag), flag);
		std::sort(r.begin(), r.end());
		return r;
	};
	for (std::size_t i = 0; i < order.size();)
	{
		std::size_t j = i + 1;
		while (j < order.size() && same(order[i], order[j]))
			++j;
		if (j - i > 2)
			throw Error(what + ": a facet is shared by " + std::to_string(j - i) + " cells (cells " +
						std::to_string(order[i] / nf) + ", " + std::to_string(order[i + 1] / nf) + ", " +
						std::to_string(order[i + 2] / nf) + "): the complex is not a manifold there");
		if (j - i == 2)
		{
			const uint32 c1 = order[i] / nf, f1 = order[i] % nf, c2 = order[i + 1] / nf, f2 = order[i + 1] % nf;
			const auto a = sorted_flags(c1, f1), b = sorted_flags(c2, f2);
			for (std::size_t k = 0; k < a.size(); ++k)
			{
				if (a[k].first != b[k].first)
					throw Error(what + ": cells " + std::to_string(c1) + " and " + std::to_string(c2) +
								" share the vertices of a facet, not its shape (vertex order?)");
				partner[std::size_t(c1) * F + a[k].second] = c2 * F + b[k].second;
				partner[std::size_t(c2) * F + b[k].second] = c1 * F + a[k].second;
			}
		}
		i = j;
	}
	return partner;
}

// Builds the complex into the G-map g (checked first, see glued_flags).
template <uint32 D>
std::vector<CellD<0>> build_gmap(GMapN<D>& g, const detail::CellShape& s, uint32 nb_vertices,
								 std::span<const uint32> ids, const std::string& what)
{
	if (nb_darts(g) != 0)
		throw Error(what + ": the map is not empty");
	const std::vector<uint32> partner = glued_flags(s, nb_vertices, ids, what);
	const uint32 F = s.nb_flags, nv = s.nb_vertices;
	std::vector<Dart> dart(partner.size());
	for (std::size_t f = 0; f < dart.size(); f += 2)
	{
		dart[f] = detail::add_dart_pair(g);
		dart[f + 1] = beta0(g, dart[f]);
	}
	for (std::size_t f = 0; f < dart.size(); ++f)
	{
		const std::size_t cell_first = f - f % F;
		for (uint32 i = 1; i < D; ++i)
			detail::set_relation(g, i, dart[f], dart[cell_first + s.beta[(i - 1) * F + f % F]]);
		if (partner[f] != INVALID_INDEX)
			detail::set_relation(g, D, dart[f], dart[partner[f]]);
	}
	detail::close_free_facets(g);
	std::vector<CellD<0>> vertices(nb_vertices);
	for (std::size_t c = 0; c < ids.size() / nv; ++c)
		for (uint32 v = 0; v < nv; ++v)
			if (!vertices[ids[c * nv + v]].is_valid())
				vertices[ids[c * nv + v]] = CellD<0>(dart[c * F + s.flag_at_vertex[v]]);
	return vertices;
}

// The cells of the orbits indexed before the build get their indices.
template <typename MAP>
void index_built_cells(MAP& m)
{
	[&]<std::size_t... K>(std::index_sequence<K...>)
	{
		((is_indexed<CellD<K>>(m) ? index_cells<CellD<K>>(m) : void()), ...);
	}
	(std::make_index_sequence<MAP::dimension + 1>{});
}

template <typename MAP>
std::vector<CellD<0>> build_complex(MAP& m, const detail::CellShape& s, uint32 nb_vertices, std::span<const uint32> ids,
									const std::string& what)
{
	std::vector<CellD<0>> vertices;
	if constexpr (is_gmap_v<MAP>)
		vertices = build_gmap(m, s, nb_vertices, ids, what);
	else
	{
		if (nb_darts(m) != 0)
			throw Error(what + ": the map is not empty");
		GMapN<MAP::dimension> g;
		vertices = build_gmap(g, s, nb_vertices, ids, what);
		std::vector<uint32> c;
		detail::cmap_into(g, m, what.c_str(), c);
		for (CellD<0>& v : vertices)
			if (v.is_valid())
				v = CellD<0>(Dart(c[v.dart.index] != INVALID_INDEX ? c[v.dart.index] : c[beta1(g, v.dart).index]));
	}
	index_built_cells(m);
	return vertices;
}

} // namespace

template <typename MAP>
requires is_nmap_v<MAP> std::vector<CellD<0>> build_simplicial_complex(MAP& m, uint32 nb_vertices,
																	   std::span<const uint32> cell_vertices)
{
	static const detail::CellShape shape = detail::simplex_shape(MAP::dimension);
	return build_complex(m, shape, nb_vertices, cell_vertices, "build_simplicial_complex");
}

template <typename MAP>
requires is_nmap_v<MAP> std::vector<CellD<0>> build_cubical_complex(MAP& m, uint32 nb_vertices,
																	std::span<const uint32> cell_vertices)
{
	static const detail::CellShape shape = detail::cube_shape(MAP::dimension);
	return build_complex(m, shape, nb_vertices, cell_vertices, "build_cubical_complex");
}

#define CGOGN_NMAP_BUILDERS(MAP)                                                                                       \
	template std::vector<CellD<0>> build_simplicial_complex(MAP&, uint32, std::span<const uint32>);                    \
	template std::vector<CellD<0>> build_cubical_complex(MAP&, uint32, std::span<const uint32>);
CGOGN_NMAP_BUILDERS(CMapN<1>)
CGOGN_NMAP_BUILDERS(CMapN<2>)
CGOGN_NMAP_BUILDERS(CMapN<3>)
CGOGN_NMAP_BUILDERS(CMapN<4>)
CGOGN_NMAP_BUILDERS(CMapN<5>)
CGOGN_NMAP_BUILDERS(CMapN<6>)
CGOGN_NMAP_BUILDERS(CMapN<7>)
CGOGN_NMAP_BUILDERS(GMapN<1>)
CGOGN_NMAP_BUILDERS(GMapN<2>)
CGOGN_NMAP_BUILDERS(GMapN<3>)
CGOGN_NMAP_BUILDERS(GMapN<4>)
CGOGN_NMAP_BUILDERS(GMapN<5>)
CGOGN_NMAP_BUILDERS(GMapN<6>)
CGOGN_NMAP_BUILDERS(GMapN<7>)
#undef CGOGN_NMAP_BUILDERS

} // namespace cgogn
