// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/nmap_builder.h>
#include <cgogn/core/build/nmap_generators.h>
#include <cgogn/core/utils/error.h>

#include <algorithm>
#include <numeric>
#include <string>

namespace cgogn
{

namespace
{

// The vertices of the grid n^D: id i_1 + i_2 (n + 1) + ..., at (i_1 / n, ...).
template <uint32 D>
std::vector<PointD<D>> grid_points(uint32 n)
{
	uint32 nb = 1;
	for (uint32 a = 0; a < D; ++a)
		nb *= n + 1;
	std::vector<PointD<D>> p(nb);
	for (uint32 id = 0; id < nb; ++id)
		for (uint32 a = 0, r = id; a < D; ++a, r /= n + 1)
			p[id][a] = double(r % (n + 1)) / double(n);
	return p;
}

// The ids of the 2^D corners of each cube of the grid n^D, in the order of
// build_cubical_complex (corner k at the cube's origin + the bits of k).
std::vector<uint32> grid_cubes(uint32 D, uint32 n)
{
	std::vector<uint32> stride(D, 1);
	for (uint32 a = 1; a < D; ++a)
		stride[a] = stride[a - 1] * (n + 1);
	uint32 nb = 1;
	for (uint32 a = 0; a < D; ++a)
		nb *= n;
	std::vector<uint32> ids;
	ids.reserve(std::size_t(nb) << D);
	for (uint32 c = 0; c < nb; ++c)
	{
		uint32 origin = 0;
		for (uint32 a = 0, r = c; a < D; ++a, r /= n)
			origin += (r % n) * stride[a];
		for (uint32 k = 0; k < (1u << D); ++k)
		{
			uint32 id = origin;
			for (uint32 a = 0; a < D; ++a)
				if (k >> a & 1u)
					id += stride[a];
			ids.push_back(id);
		}
	}
	return ids;
}

// Sets the positions of the built vertices.
template <typename MAP>
void set_positions(MAP& m, const std::vector<CellD<0>>& vertices, const std::vector<PointD<MAP::dimension>>& p,
				   const char* what)
{
	auto position = add_attribute<PointD<MAP::dimension>, CellD<0>>(m, "position");
	if (!position)
		throw Error(std::string(what) + ": the map already has a vertex attribute named position");
	for (std::size_t id = 0; id < vertices.size(); ++id)
		if (vertices[id].is_valid())
			(*position)[vertices[id]] = p[id];
}

template <typename MAP>
void require_empty(const MAP& m, const char* what)
{
	if (nb_darts(m) != 0)
		throw Error(std::string(what) + ": the map is not empty");
	if (get_attribute<PointD<MAP::dimension>, CellD<0>>(m, "position"))
		throw Error(std::string(what) + ": the map already has a vertex attribute named position");
}

} // namespace

template <typename MAP>
requires is_nmap_v<MAP>
void generate_simplex(MAP& m)
{
	constexpr uint32 D = MAP::dimension;
	require_empty(m, "generate_simplex");
	std::vector<uint32> ids(D + 1);
	std::iota(ids.begin(), ids.end(), 0u);
	std::vector<PointD<D>> p(D + 1, PointD<D>{});
	for (uint32 a = 0; a < D; ++a)
		p[a + 1][a] = 1.0;
	set_positions(m, build_simplicial_complex(m, D + 1, ids), p, "generate_simplex");
}

template <typename MAP>
requires is_nmap_v<MAP>
void generate_cube(MAP& m)
{
	generate_cube_grid(m, 1);
}

template <typename MAP>
requires is_nmap_v<MAP>
void generate_cube_grid(MAP& m, uint32 n)
{
	constexpr uint32 D = MAP::dimension;
	require_empty(m, "generate_cube_grid");
	if (n == 0)
		throw Error("generate_cube_grid: the grid needs at least one cube per axis");
	const std::vector<PointD<D>> p = grid_points<D>(n);
	set_positions(m, build_cubical_complex(m, uint32(p.size()), grid_cubes(D, n)), p, "generate_cube_grid");
}

template <typename MAP>
requires is_nmap_v<MAP>
void generate_freudenthal_grid(MAP& m, uint32 n)
{
	constexpr uint32 D = MAP::dimension;
	require_empty(m, "generate_freudenthal_grid");
	if (n == 0)
		throw Error("generate_freudenthal_grid: the grid needs at least one cube per axis");
	const std::vector<PointD<D>> p = grid_points<D>(n);
	const std::vector<uint32> cubes = grid_cubes(D, n);
	std::vector<uint32> simplices;
	std::array<uint32, D> axes;
	for (std::size_t c = 0; c < cubes.size(); c += std::size_t(1) << D)
	{
		std::iota(axes.begin(), axes.end(), 0u);
		do
		{
			uint32 corner = 0; // the corner reached so far, as the bits of its axes
			simplices.push_back(cubes[c]);
			for (uint32 a : axes)
			{
				corner |= 1u << a;
				simplices.push_back(cubes[c + corner]);
			}
		} while (std::next_permutation(axes.begin(), axes.end()));
	}
	set_positions(m, build_simplicial_complex(m, uint32(p.size()), simplices), p, "generate_freudenthal_grid");
}

#define CGOGN_NMAP_GENERATORS(MAP)                                                                                     \
	template void generate_simplex(MAP&);                                                                              \
	template void generate_cube(MAP&);                                                                                 \
	template void generate_cube_grid(MAP&, uint32);                                                                    \
	template void generate_freudenthal_grid(MAP&, uint32);
CGOGN_NMAP_GENERATORS(CMapN<1>)
CGOGN_NMAP_GENERATORS(CMapN<2>)
CGOGN_NMAP_GENERATORS(CMapN<3>)
CGOGN_NMAP_GENERATORS(CMapN<4>)
CGOGN_NMAP_GENERATORS(CMapN<5>)
CGOGN_NMAP_GENERATORS(CMapN<6>)
CGOGN_NMAP_GENERATORS(CMapN<7>)
CGOGN_NMAP_GENERATORS(GMapN<1>)
CGOGN_NMAP_GENERATORS(GMapN<2>)
CGOGN_NMAP_GENERATORS(GMapN<3>)
CGOGN_NMAP_GENERATORS(GMapN<4>)
CGOGN_NMAP_GENERATORS(GMapN<5>)
CGOGN_NMAP_GENERATORS(GMapN<6>)
CGOGN_NMAP_GENERATORS(GMapN<7>)
#undef CGOGN_NMAP_GENERATORS

} // namespace cgogn
