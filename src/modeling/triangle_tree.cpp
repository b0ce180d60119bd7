// SPDX-License-Identifier: MIT
#include <cgogn/core/traversals/global.h>
#include <cgogn/modeling/triangle_tree.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace cgogn::modeling
{

namespace
{

constexpr uint32 LEAF_SIZE = 4;

double squared_distance_to_box(const Vec3& p, const Vec3& lo, const Vec3& hi)
{
	double d = 0.0;
	for (int k = 0; k < 3; ++k)
	{
		const double e = p[k] < lo[k] ? lo[k] - p[k] : (p[k] > hi[k] ? p[k] - hi[k] : 0.0);
		d += e * e;
	}
	return d;
}

} // namespace

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c)
{
	// the Voronoi regions of the corners, then of the edges, then the face
	const Vec3 ab = b - a, ac = c - a, ap = p - a;
	const double d1 = ab.dot(ap), d2 = ac.dot(ap);
	if (d1 <= 0.0 && d2 <= 0.0)
		return a;
	const Vec3 bp = p - b;
	const double d3 = ab.dot(bp), d4 = ac.dot(bp);
	if (d3 >= 0.0 && d4 <= d3)
		return b;
	const double vc = d1 * d4 - d3 * d2;
	if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
		return a + ab * (d1 / (d1 - d3));
	const Vec3 cp = p - c;
	const double d5 = ab.dot(cp), d6 = ac.dot(cp);
	if (d6 >= 0.0 && d5 <= d6)
		return c;
	const double vb = d5 * d2 - d1 * d6;
	if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
		return a + ac * (d2 / (d2 - d6));
	const double va = d3 * d6 - d5 * d4;
	if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
		return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
	const double denom = va + vb + vc;
	if (!(denom > 0.0)) // degenerate triangle: the nearest of its edges' ends
	{
		const Vec3* best = &a;
		for (const Vec3* q : {&b, &c})
			if ((*q - p).squaredNorm() < (*best - p).squaredNorm())
				best = q;
		return *best;
	}
	return a + ab * (vb / denom) + ac * (vc / denom);
}

TriangleTree::TriangleTree(const CMap2& m, const AttributeArray<Vec3>& pos)
{
	foreach_cell(m, [&](CMap2::Face f) {
		const Dart d0 = f.dart;
		const Vec3& p0 = pos[index_of(m, CMap2::Vertex(d0))];
		for (Dart d = phi1(m, d0); phi1(m, d) != d0; d = phi1(m, d))
			triangles_.push_back({p0, pos[index_of(m, CMap2::Vertex(d))], pos[index_of(m, CMap2::Vertex(phi1(m, d)))]});
	});
	build();
}

TriangleTree::TriangleTree(std::vector<Triangle> triangles) : triangles_(std::move(triangles))
{
	build();
}

void TriangleTree::build()
{
	nodes_.clear();
	if (triangles_.empty())
		return;
	nodes_.reserve(2 * triangles_.size() / LEAF_SIZE + 2);
	build_node(0, uint32(triangles_.size()));
}

uint32 TriangleTree::build_node(uint32 begin, uint32 end)
{
	const uint32 id = uint32(nodes_.size());
	nodes_.push_back({});
	Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
	Vec3 clo = lo, chi = hi; // bounds of the centroids
	for (uint32 i = begin; i < end; ++i)
	{
		Vec3 centroid = Vec3::Zero();
		for (const Vec3& p : triangles_[i])
		{
			lo = lo.cwiseMin(p);
			hi = hi.cwiseMax(p);
			centroid += p;
		}
		centroid /= 3.0;
		clo = clo.cwiseMin(centroid);
		chi = chi.cwiseMax(centroid);
	}
	nodes_[id].lo = lo;
	nodes_[id].hi = hi;
	nodes_[id].begin = begin;
	nodes_[id].end = end;
	nodes_[id].right = 0;
	if (end - begin <= LEAF_SIZE)
		return id;
	int axis = 0;
	(chi - clo).maxCoeff(&axis);
	const uint32 mid = begin + (end - begin) / 2;
	std::nth_element(triangles_.begin() + begin, triangles_.begin() + mid, triangles_.begin() + end,
					 [axis](const Triangle& s, const Triangle& t) {
						 return s[0][axis] + s[1][axis] + s[2][axis] < t[0][axis] + t[1][axis] + t[2][axis];
					 });
	build_node(begin, mid);
	const uint32 right = build_node(mid, end);
	nodes_[id].right = right;
	return id;
}

TriangleTree::Hit TriangleTree::closest_point(const Vec3& p) const
{
	assert(!nodes_.empty());
	Hit best{p, std::numeric_limits<double>::infinity(), 0};
	uint32 stack[64];
	uint32 top = 0;
	stack[top++] = 0;
	while (top > 0)
	{
		const Node& n = nodes_[stack[--top]];
		if (squared_distance_to_box(p, n.lo, n.hi) >= best.squared_distance)
			continue;
		if (n.right == 0)
		{
			for (uint32 i = n.begin; i < n.end; ++i)
			{
				const Triangle& t = triangles_[i];
				const Vec3 q = closest_point_on_triangle(p, t[0], t[1], t[2]);
				const double d = (q - p).squaredNorm();
				if (d < best.squared_distance)
					best = {q, d, i};
			}
			continue;
		}
		// visit the nearer child first: push it last
		const uint32 left = uint32(&n - nodes_.data()) + 1, right = n.right;
		const double dl = squared_distance_to_box(p, nodes_[left].lo, nodes_[left].hi);
		const double dr = squared_distance_to_box(p, nodes_[right].lo, nodes_[right].hi);
		if (dl < dr)
		{
			stack[top++] = right;
			stack[top++] = left;
		}
		else
		{
			stack[top++] = left;
			stack[top++] = right;
		}
	}
	return best;
}

SurfaceDistance vertex_distance_to_surface(const CMap2& m, const AttributeArray<Vec3>& pos,
										   const TriangleTree& reference)
{
	SurfaceDistance r;
	uint64 n = 0;
	double sum = 0.0, sum2 = 0.0;
	foreach_cell(m, [&](CMap2::Vertex v) {
		const double d2 = reference.closest_point(pos[index_of(m, v)]).squared_distance;
		const double d = std::sqrt(d2);
		r.max = std::max(r.max, d);
		sum += d;
		sum2 += d2;
		++n;
	});
	if (n > 0)
	{
		r.mean = sum / double(n);
		r.rms = std::sqrt(sum2 / double(n));
	}
	return r;
}

} // namespace cgogn::modeling
