// SPDX-License-Identifier: MIT
// Meshes of the geometry tests, built in code with the core generators.
#pragma once

#include <cgogn/cgogn.h>

#include <cmath>
#include <memory>
#include <vector>

namespace cgogn::test
{

using Pos = std::shared_ptr<AttributeArray<Vec3>>;

/// Builds the soup into m and gives its vertices a "position" attribute.
template <typename SOUP>
Pos build_with_positions(CMap2& m, const SOUP& s)
{
	const BuildReport r = build_surface(m, s);
	Pos pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	if (!pos)
		pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return pos;
}

inline Pos build_with_positions(CMap3& m, const VolumeSoup& s)
{
	const BuildReport r = build_volume(m, s);
	Pos pos = add_attribute<Vec3, CMap3::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return pos;
}

/// A soup from explicit polygons and positions.
inline SurfaceSoup polygon_soup(const std::vector<Vec3>& points, const std::vector<std::vector<uint32>>& faces)
{
	SurfaceSoup s;
	s.nb_vertices = uint32(points.size());
	for (const Vec3& p : points)
		s.positions.push_back({p.x(), p.y(), p.z()});
	for (const auto& f : faces)
	{
		s.face_sizes.push_back(uint32(f.size()));
		s.face_vertices.insert(s.face_vertices.end(), f.begin(), f.end());
	}
	return s;
}

/// The axis-aligned box [0, sx] x [0, sy] x [0, sz] as 6 quads oriented outwards.
inline SurfaceSoup box_soup(double sx = 1.0, double sy = 1.0, double sz = 1.0)
{
	return polygon_soup(
		{{0, 0, 0}, {sx, 0, 0}, {sx, sy, 0}, {0, sy, 0}, {0, 0, sz}, {sx, 0, sz}, {sx, sy, sz}, {0, sy, sz}},
		{{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}});
}

/// A deterministic pseudo-random value in [-1, 1] for integer i (an integer
/// hash, so that tests do not depend on a library's random generator).
inline double noise(uint32 i)
{
	uint32 x = i * 2654435761u + 0x9e3779b9u;
	x ^= x >> 16;
	x *= 0x7feb352du;
	x ^= x >> 15;
	x *= 0x846ca68bu;
	x ^= x >> 16;
	return double(x) / 4294967295.0 * 2.0 - 1.0;
}

/// The vertex of m whose position is closest to p.
template <typename MESH>
typename mesh_traits<MESH>::Vertex closest_vertex(const MESH& m, const AttributeArray<Vec3>& pos, const Vec3& p)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	Vertex best;
	double d = 1e300;
	foreach_cell(m, [&](Vertex v) {
		const double dv = (value<Vec3>(m, pos, v) - p).norm();
		if (dv < d)
		{
			d = dv;
			best = v;
		}
	});
	return best;
}

} // namespace cgogn::test
