// SPDX-License-Identifier: MIT
// sqrt3 subdivision of triangle meshes (Kobbelt 2000).
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/gmap2.h>

#include "subdivision_common.h"

#include <cmath>
#include <numbers>

namespace cgogn::modeling
{

using namespace detail;

namespace
{

/// True when the vertex of d has at least k edges. O(k).
template <typename MAP>
bool has_degree_at_least(const MAP& m, Dart d, uint32 k)
{
	Dart x = d;
	for (uint32 i = 1; i < k; ++i)
	{
		if constexpr (is_gmap_v<MAP>)
			x = beta<1, 2>(m, x);
		else
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
template <typename MAP>
bool can_flip_old_edge(const MAP& m, Dart d)
{
	using V = typename mesh_traits<MAP>::Vertex;
	const Dart d2 = other_side(m, d);
	if (!has_degree_at_least(m, d, 3) || !has_degree_at_least(m, across_edge(m, d), 3))
		return false;
	const Dart c1 = opposite_in_triangle(m, d);
	const uint32 c2 = index_of(m, V(opposite_in_triangle(m, d2)));
	bool joined = index_of(m, V(c1)) == c2;
	foreach_dart_of_orbit(m, V(c1), [&](Dart x) { return !(joined = index_of(m, V(across_edge(m, x))) == c2); });
	return !joined;
}

/// True when the triangles on both sides of d share another edge than d's.
/// O(1).
template <typename MAP>
bool shares_another_edge(const MAP& m, Dart d)
{
	using F = typename mesh_traits<MAP>::Face;
	const Dart d2 = other_side(m, d);
	bool shared = false;
	// the other sides of the darts of d's face that are not on d's edge
	foreach_dart_of_orbit(m, F(d), [&](Dart x) {
		if (same_orbit(m, typename mesh_traits<MAP>::Edge(x), typename mesh_traits<MAP>::Edge(d)))
			return true;
		const Dart y = other_side(m, x);
		foreach_dart_of_orbit(m, F(d2), [&](Dart z) { return !(shared = z == y); });
		return !shared;
	});
	return shared;
}

template <typename MAP>
SubdivisionResult sqrt3_step(MAP& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	using V = typename mesh_traits<MAP>::Vertex;
	using E = typename mesh_traits<MAP>::Edge;
	using F = typename mesh_traits<MAP>::Face;
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
		const V v(vertices.vertices[i]);
		const Vec3& p = position(m, pos, v.dart);
		Vec3 sum = Vec3::Zero();
		uint32 n = 0;
		bool boundary = false;
		foreach_dart_of_orbit(m, v, [&](Dart d) {
			boundary = boundary || is_boundary(m, d);
			sum += position(m, pos, across_edge(m, d));
			++n;
		});
		if (boundary)
		{
			vertices.positions[i] = p;
			continue;
		}
		n /= darts_per_edge_at_vertex<MAP>;
		sum /= double(darts_per_edge_at_vertex<MAP>);
		const double alpha = (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / double(n))) / 9.0;
		vertices.positions[i] = (1.0 - alpha) * p + (alpha / double(n)) * sum;
	}
	// 2. the face centroids
	std::vector<Vec3> centroids(faces.size());
	for (std::size_t i = 0; i < faces.size(); ++i)
	{
		if (!step.computing(vertices.vertices.size() + i, total))
			return step.cancelled_before_change();
		const Dart d = faces[i], d1 = next_in_face(m, d);
		centroids[i] = (position(m, pos, d) + position(m, pos, d1) + position(m, pos, next_in_face(m, d1))) / 3.0;
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

	// 3. the connectivity (flipping an old edge, in either direction, joins
	// the centroids of its two triangles)
	vertices.commit(m, pos);
	const std::size_t work = faces.size() + interior_edges.size();
	for (std::size_t i = 0; i < faces.size(); ++i)
	{
		step.changing(i, work);
		pos[index_of(m, triangulate_face(m, F(faces[i])))] = centroids[i];
	}
	for (std::size_t i = 0; i < interior_edges.size(); ++i)
	{
		step.changing(faces.size() + i, work);
		flip_edge(m, E(interior_edges[i]));
	}
	for (Dart d : guarded_edges)
		if (can_flip_old_edge(m, d))
			flip_edge(m, E(d));
	return step.finish();
}

} // namespace

SubdivisionResult sqrt3_subdivision(CMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	return sqrt3_step(m, pos, progress);
}

SubdivisionResult sqrt3_subdivision(GMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	return sqrt3_step(m, pos, progress);
}

} // namespace cgogn::modeling
