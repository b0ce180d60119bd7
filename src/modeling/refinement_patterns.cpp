// SPDX-License-Identifier: MIT
#include <cgogn/core/map/orbits.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/modeling/refinement_patterns.h>

#include <Eigen/Geometry>

#include <tuple>

namespace cgogn::modeling
{

namespace
{

using TetList = std::array<std::array<uint32, 4>, 8>;

/// The 8 tetrahedra for each choice of diagonal, positively oriented: the
/// orientation is decided once on a reference tetrahedron, and carries over
/// to any tetrahedron through the affine map between them.
std::array<TetList, 3> make_tet_patterns()
{
	// corners 0..3, then the midpoints of 01, 02, 03, 12, 13, 23
	constexpr std::array<std::array<uint32, 4>, 4> corner_tets = {
		{{0, 4, 5, 6}, {4, 1, 7, 8}, {5, 7, 2, 9}, {6, 8, 9, 3}}};
	// the four other midpoints around each diagonal, as a ring
	constexpr std::array<std::array<uint32, 4>, 3> rings = {{{5, 6, 8, 7}, {4, 6, 9, 7}, {4, 5, 9, 8}}};
	const std::array<Vec3, 4> corner = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
	std::array<Vec3, 10> p;
	for (uint32 i = 0; i < 4; ++i)
		p[i] = corner[i];
	const std::array<std::array<uint32, 2>, 6> edges = {{{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}}};
	for (uint32 i = 0; i < 6; ++i)
		p[4 + i] = 0.5 * (p[edges[i][0]] + p[edges[i][1]]);
	auto oriented = [&](std::array<uint32, 4> t) {
		if ((p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).dot(p[t[3]] - p[t[0]]) < 0.0)
			std::swap(t[2], t[3]);
		return t;
	};
	std::array<TetList, 3> patterns;
	for (uint32 k = 0; k < 3; ++k)
	{
		for (uint32 i = 0; i < 4; ++i)
			patterns[k][i] = oriented(corner_tets[i]);
		const auto& diagonal = tet_octahedron_diagonals[k];
		for (uint32 i = 0; i < 4; ++i)
			patterns[k][4 + i] = oriented({diagonal[0], diagonal[1], rings[k][i], rings[k][(i + 1) % 4]});
	}
	return patterns;
}

/// The children of a hexahedron on its 3 x 3 x 3 grid of points: the
/// parent's corner cycle (0, 0), (0, 1), (1, 1), (1, 0) seen from the grid,
/// at each child's height, as the parent's bottom and top quads are listed.
std::array<std::array<uint32, 8>, 8> make_hex_children()
{
	std::array<std::array<uint32, 8>, 8> children;
	uint32 k = 0;
	for (uint32 a = 0; a < 2; ++a)
		for (uint32 b = 0; b < 2; ++b)
			for (uint32 c = 0; c < 2; ++c, ++k)
			{
				uint32 i = 0;
				for (uint32 z : {c, c + 1})
					for (const auto& q : {std::array<uint32, 2>{a, b}, {a, b + 1}, {a + 1, b + 1}, {a + 1, b}})
						children[k][i++] = q[0] + 3 * q[1] + 9 * z;
			}
	return children;
}

} // namespace

std::array<RefinementPoint, 10> tet_refinement_points(const CMap3& m, CMap3::Volume w)
{
	// outward face (d0, d1, d2) and the apex: VTK order (d0, d2, d1, apex)
	const Dart d0 = w.dart, d1 = phi1(m, d0), d2 = phi1(m, d1);
	return {{{0, d0},
			 {0, d2},
			 {0, d1},
			 {0, phi<2, 1, 1>(m, d0)},
			 {1, d2},
			 {1, d0},
			 {1, phi<2, 1>(m, d0)},
			 {1, d1},
			 {1, phi<2, 1>(m, d2)},
			 {1, phi<2, 1>(m, d1)}}};
}

uint32 tet_cut_diagonal(const std::array<Vec3, 10>& points)
{
	const auto key = [&](uint32 k) {
		const Vec3& a = points[tet_octahedron_diagonals[k][0]];
		const Vec3& b = points[tet_octahedron_diagonals[k][1]];
		const bool a_first = std::tie(a[0], a[1], a[2]) < std::tie(b[0], b[1], b[2]);
		const Vec3& lo = a_first ? a : b;
		const Vec3& hi = a_first ? b : a;
		return std::make_tuple((a - b).squaredNorm(), lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]);
	};
	uint32 best = 0;
	for (uint32 k = 1; k < 3; ++k)
		if (key(k) < key(best))
			best = k;
	return best;
}

const std::array<std::array<uint32, 4>, 8>& tet_children(uint32 diagonal)
{
	static const std::array<TetList, 3> patterns = make_tet_patterns();
	return patterns[diagonal];
}

std::array<RefinementPoint, 27> hex_refinement_points(const CMap3& m, CMap3::Volume w)
{
	// corner i of the outward face cycle sits at xy[i] of the grid, the
	// midpoint of its edge to corner i + 1 at mid[i]
	constexpr std::array<std::array<uint32, 2>, 4> xy = {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}};
	constexpr std::array<std::array<uint32, 2>, 4> mid = {{{1, 0}, {2, 1}, {1, 2}, {0, 1}}};
	std::array<RefinementPoint, 27> grid;
	const auto at = [&](const std::array<uint32, 2>& q, uint32 z) -> RefinementPoint& {
		return grid[q[0] + 3 * q[1] + 9 * z];
	};
	Dart d = w.dart;
	for (uint32 i = 0; i < 4; ++i, d = phi1(m, d))
	{
		// side face of d: (end of d, origin of d, top of origin, top of end)
		const Dart vertical = phi<2, 1>(m, d), top = phi1(m, vertical);
		at(xy[i], 0) = {0, d};
		at(xy[i], 1) = {1, vertical};
		at(xy[i], 2) = {0, top};
		at(mid[i], 0) = {1, d};
		at(mid[i], 1) = {2, phi2(m, d)};
		at(mid[i], 2) = {1, top};
		if (i == 0)
			at({1, 1}, 2) = {2, phi2(m, top)};
	}
	at({1, 1}, 0) = {2, w.dart};
	at({1, 1}, 1) = {3, w.dart};
	return grid;
}

const std::array<std::array<uint32, 8>, 8>& hex_children()
{
	static const std::array<std::array<uint32, 8>, 8> children = make_hex_children();
	return children;
}

} // namespace cgogn::modeling
