// SPDX-License-Identifier: MIT
// sqrt3 subdivision of triangle meshes (Kobbelt 2000).
#include <cgogn/core/operators/cmap2.h>

#include "subdivision_common.h"

#include <cmath>
#include <numbers>

namespace cgogn::modeling
{

using namespace detail;

namespace
{

/// True when the vertex of d has at least k edges. O(k).
bool has_degree_at_least(const CMap2& m, Dart d, uint32 k)
{
	Dart x = d;
	for (uint32 i = 1; i < k; ++i)
	{
		x = phi<2, 1>(m, x);
		if (x == d)
			return false;
	}
	return true;
}

/// can_flip_edge for an old edge d between two split triangles, in O(degree)
/// instead of O(degree^2): the new edge would join the centroids c1, c2 of
/// the two triangles, which fails only when they are already joined (two
/// triangles sharing two edges: the first flip joined them) or when an end
/// of d would be left with fewer than 2 edges.
bool can_flip_old_edge(const CMap2& m, Dart d)
{
	const Dart d2 = phi2(m, d);
	if (!has_degree_at_least(m, d, 3) || !has_degree_at_least(m, d2, 3))
		return false;
	const Dart c1 = phi<1, 1>(m, d);
	const uint32 c2 = index_of(m, Vertex(phi<1, 1>(m, d2)));
	bool joined = index_of(m, Vertex(c1)) == c2;
	foreach_dart_of_orbit(m, Vertex(c1), [&](Dart x) { return !(joined = index_of(m, Vertex(phi2(m, x))) == c2); });
	return !joined;
}

/// True when the triangles on both sides of d share another edge than d's.
/// O(1).
bool shares_another_edge(const CMap2& m, Dart d)
{
	const Dart d2 = phi2(m, d);
	const Dart e1 = phi1(m, d2), e2 = phi1(m, e1);
	for (Dart x : {phi1(m, d), phi<1, 1>(m, d)})
	{
		const Dart y = phi2(m, x);
		if (y == d2 || y == e1 || y == e2)
			return true;
	}
	return false;
}

} // namespace

SubdivisionResult sqrt3_subdivision(CMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	const FaceSnapshot snapshot(m);
	const std::vector<Dart>& faces = snapshot.darts;
	if (!faces.empty() && (snapshot.min_degree != 3 || snapshot.max_degree != 3))
		throw SubdivisionError("sqrt3 subdivision: every face must be a triangle");
	StepProgress step(progress);
	VertexPositions vertices(m);
	const std::size_t total = vertices.vertices.size() + faces.size();

	// 1. the old vertices: interior ones are relaxed, boundary ones stay
	for (std::size_t i = 0; i < vertices.vertices.size(); ++i)
	{
		if (!step.computing(i, total))
			return step.cancelled_before_change();
		const Vertex v(vertices.vertices[i]);
		const Vec3& p = position(m, pos, v.dart);
		Vec3 sum = Vec3::Zero();
		uint32 n = 0;
		bool boundary = false;
		foreach_dart_of_orbit(m, v, [&](Dart d) {
			boundary = boundary || is_boundary(m, d);
			sum += position(m, pos, phi2(m, d));
			++n;
		});
		if (boundary)
		{
			vertices.positions[i] = p;
			continue;
		}
		const double alpha = (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / double(n))) / 9.0;
		vertices.positions[i] = (1.0 - alpha) * p + (alpha / double(n)) * sum;
	}
	// 2. the face centroids
	std::vector<Vec3> centroids(faces.size());
	for (std::size_t i = 0; i < faces.size(); ++i)
	{
		if (!step.computing(vertices.vertices.size() + i, total))
			return step.cancelled_before_change();
		const Dart d = faces[i];
		centroids[i] = (position(m, pos, d) + position(m, pos, phi1(m, d)) + position(m, pos, phi<1, 1>(m, d))) / 3.0;
	}
	// the interior edges, flipped once the faces are split
	// (those whose two triangles share another edge are checked before
	// their flip: see can_flip_old_edge)
	std::vector<Dart> interior_edges = edge_snapshot(m);
	std::erase_if(interior_edges, [&](Dart d) { return is_boundary_edge(m, d); });
	std::vector<Dart> guarded_edges;
	std::erase_if(interior_edges, [&](Dart d) {
		if (!shares_another_edge(m, d))
			return false;
		guarded_edges.push_back(d);
		return true;
	});

	// 3. the connectivity
	vertices.commit(m, pos);
	const std::size_t work = faces.size() + interior_edges.size();
	for (std::size_t i = 0; i < faces.size(); ++i)
	{
		step.changing(i, work);
		pos[index_of(m, triangulate_face(m, Face(faces[i])))] = centroids[i];
	}
	for (std::size_t i = 0; i < interior_edges.size(); ++i)
	{
		step.changing(faces.size() + i, work);
		flip_edge(m, Edge(interior_edges[i]));
	}
	for (Dart d : guarded_edges)
		if (can_flip_old_edge(m, d))
			flip_edge(m, Edge(d));
	return step.finish();
}

} // namespace cgogn::modeling
