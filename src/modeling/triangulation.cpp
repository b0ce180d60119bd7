// SPDX-License-Identifier: MIT
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/gmap2.h>
#include <cgogn/core/properties/gmap_properties.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/normal.h>
#include <cgogn/modeling/triangulation.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cassert>
#include <limits>
#include <vector>

namespace cgogn::modeling
{

namespace
{

using Vec2 = Eigen::Vector2d;

double cross(const Vec2& a, const Vec2& b, const Vec2& c)
{
	return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

/// Cosine of the smallest angle of triangle abc (the largest of its three
/// cosines), 1 for a degenerate one: ranking ears by it avoids acos.
double smallest_angle_cos(const Vec2& a, const Vec2& b, const Vec2& c)
{
	const auto cos_at = [](const Vec2& o, const Vec2& p, const Vec2& q) {
		const Vec2 u = p - o, v = q - o;
		const double nu = u.norm(), nv = v.norm();
		if (nu == 0.0 || nv == 0.0)
			return 1.0;
		return std::clamp(u.dot(v) / (nu * nv), -1.0, 1.0);
	};
	return std::max({cos_at(a, b, c), cos_at(b, c, a), cos_at(c, a, b)});
}

/// The polygon being clipped: its corners (darts of the face, whose origins
/// are the corners) in cyclic order, and their projections.
struct Polygon
{
	std::vector<Dart> darts;
	std::vector<Vec2> points;

	std::size_t prev(std::size_t i) const
	{
		return (i + darts.size() - 1) % darts.size();
	}
	std::size_t next(std::size_t i) const
	{
		return (i + 1) % darts.size();
	}

	/// True when corner i is convex and no other corner lies in (or on) the
	/// triangle (prev(i), i, next(i)).
	bool is_ear(std::size_t i) const
	{
		const std::size_t p = prev(i), n = next(i);
		const Vec2 &a = points[p], &b = points[i], &c = points[n];
		if (cross(a, b, c) <= 0.0)
			return false;
		for (std::size_t j = 0; j < points.size(); ++j)
		{
			if (j == p || j == i || j == n)
				continue;
			const Vec2& q = points[j];
			if (cross(a, b, q) >= 0.0 && cross(b, c, q) >= 0.0 && cross(c, a, q) >= 0.0)
				return false;
		}
		return true;
	}

	/// The ear of largest smallest angle, else the most convex corner.
	std::size_t best_corner() const
	{
		std::size_t best = 0;
		double best_score = -std::numeric_limits<double>::infinity();
		bool best_is_ear = false;
		for (std::size_t i = 0; i < darts.size(); ++i)
		{
			const bool ear = is_ear(i);
			if (best_is_ear && !ear)
				continue;
			const Vec2 &a = points[prev(i)], &b = points[i], &c = points[next(i)];
			// ears: the larger the smallest angle, the smaller its cosine
			const double score = ear ? -smallest_angle_cos(a, b, c) : cross(a, b, c);
			if ((ear && !best_is_ear) || score > best_score)
			{
				best = i;
				best_score = score;
				best_is_ear = ear;
			}
		}
		return best;
	}
};

} // namespace

namespace
{
// The corners of face f in cyclic order, one dart each, at the corner's
// vertex (the origin of a 2-map dart; a G-map dart whose edge goes on to
// the next corner).
template <typename MAP>
void collect_corners(const MAP& m, typename mesh_traits<MAP>::Face f, std::vector<Dart>& corners)
{
	Dart d = f.dart;
	do
	{
		corners.push_back(d);
		d = geometry::oriented_phi1(m, d);
	} while (d != f.dart);
}

// Cuts off the triangle (p, i, n) of the polygon; returns the new edge's
// dart at p's corner in the rest, whose edge goes on to n.
Dart cut_ear(CMap2& m, Dart at_p, Dart at_n)
{
	return cut_face(m, CMap2::Vertex(at_p), CMap2::Vertex(at_n)).dart;
}
Dart cut_ear(GMap2& m, Dart at_p, Dart at_n)
{
	// at p, the dart on the side of the rest is beta1 of the corner's
	return cut_face(m, GMap2::Vertex(beta1(m, at_p)), GMap2::Vertex(at_n)).dart;
}

// ear_clip_face with the caller's buffers (triangulate_faces reuses one
// Polygon for all faces: no allocation per face)
template <typename MAP>
uint32 ear_clip(MAP& m, const AttributeArray<Vec3>& pos, typename mesh_traits<MAP>::Face f, Polygon& poly)
{
	assert(!is_boundary(m, f.dart));
	poly.darts.clear();
	poly.points.clear();
	collect_corners(m, f, poly.darts);
	if (poly.darts.size() <= 3)
		return 0;

	// a frame (u, v, n) of the face's plane, counter-clockwise seen from n
	Vec3 n = geometry::newell_vector(m, pos, f.dart);
	if (n.squaredNorm() == 0.0)
		n = Vec3::UnitZ();
	n.normalize();
	const Vec3 u = n.unitOrthogonal();
	const Vec3 v = n.cross(u);
	for (Dart d : poly.darts)
	{
		const Vec3& p = pos[index_of(m, typename mesh_traits<MAP>::Vertex(d))];
		poly.points.emplace_back(p.dot(u), p.dot(v));
	}

	uint32 nb_triangles = 0;
	while (poly.darts.size() > 3)
	{
		const std::size_t i = poly.best_corner();
		const std::size_t p = poly.prev(i), nx = poly.next(i);
		// the triangle (p, i, nx) is cut off; the new edge's dart from p's
		// corner to nx's, in the rest, takes p's place
		poly.darts[p] = cut_ear(m, poly.darts[p], poly.darts[nx]);
		poly.darts.erase(poly.darts.begin() + std::ptrdiff_t(i));
		poly.points.erase(poly.points.begin() + std::ptrdiff_t(i));
		++nb_triangles;
	}
	return nb_triangles + 1;
}

template <typename MAP>
uint32 triangulate_all(MAP& m, const AttributeArray<Vec3>& pos)
{
	using F = typename mesh_traits<MAP>::Face;
	std::vector<F> polygons;
	foreach_cell(m, [&](F f) {
		if (codegree(m, f) > 3)
			polygons.push_back(f);
	});
	Polygon poly;
	for (F f : polygons)
		ear_clip(m, pos, f, poly);
	return uint32(polygons.size());
}
} // namespace

uint32 ear_clip_face(CMap2& m, const AttributeArray<Vec3>& pos, CMap2::Face f)
{
	Polygon poly;
	return ear_clip(m, pos, f, poly);
}

uint32 ear_clip_face(GMap2& m, const AttributeArray<Vec3>& pos, GMap2::Face f)
{
	Polygon poly;
	return ear_clip(m, pos, f, poly);
}

uint32 triangulate_faces(CMap2& m, const AttributeArray<Vec3>& pos)
{
	return triangulate_all(m, pos);
}

uint32 triangulate_faces(GMap2& m, const AttributeArray<Vec3>& pos)
{
	return triangulate_all(m, pos);
}

} // namespace cgogn::modeling
