// SPDX-License-Identifier: MIT
// Loop subdivision of triangle meshes.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/gmap2.h>

#include "subdivision_common.h"

#include <array>
#include <cmath>
#include <numbers>

namespace cgogn::modeling
{

using namespace detail;

bool is_triangle_mesh(const CMap2& m)
{
	bool ok = true;
	foreach_dart(m, [&](Dart d) {
		ok = is_boundary(m, d) || (phi<1, 1, 1>(m, d) == d && phi1(m, d) != d);
		return ok;
	});
	return ok;
}

bool is_triangle_mesh(const GMap2& m)
{
	bool ok = true;
	foreach_dart(m, [&](Dart d) {
		ok = is_boundary(m, d) ||
			 (beta<0, 1, 0, 1, 0, 1>(m, d) == d && beta<0, 1>(m, d) != d && beta<0, 1, 0, 1>(m, d) != d);
		return ok;
	});
	return ok;
}

namespace
{

/// Loop's weight beta of an interior vertex of valence n (n beta = 5/8 -
/// (3/8 + 1/4 cos(2 pi / n))^2, the original rule, which OpenMesh's LoopT
/// uses; Warren's 3/(8n) is a simplification of it).
double loop_beta(uint32 n)
{
	const double c = 3.0 + 2.0 * std::cos(2.0 * std::numbers::pi / double(n));
	return (40.0 - c * c) / 64.0 / double(n);
}

/// Cuts the hexagon (h0 .. h5) left by cutting the three edges of a triangle
/// (h0 starts at an old vertex) into four triangles; the middle one keeps the
/// face's line.
void cut_hexagon(CMap2& m, Dart h0)
{
	const Dart h1 = phi1(m, h0), h3 = phi<1, 1>(m, h1), h5 = phi<1, 1>(m, h3);
	// the corner at the end of h1, then at the end of h3, then at the end of h5
	const Dart x1 = phi2(m, cut_face(m, Vertex(h3), Vertex(h1)).dart); // mid(h0) -> mid(h2)
	cut_face(m, Vertex(h5), Vertex(h3));
	cut_face(m, Vertex(x1), Vertex(h5));
}

/// The same in a G-map: w0 .. w5 walk the hexagon from h0 (an old vertex),
/// each at the vertex where its edge starts. Each cut joins two midpoints by
/// their darts on the side of the middle triangle, which so keeps the line.
void cut_hexagon(GMap2& m, Dart h0)
{
	std::array<Dart, 6> w;
	w[0] = h0;
	for (uint32 k = 1; k < 6; ++k)
		w[k] = next_in_face(m, w[k - 1]);
	using V = GMap2::Vertex;
	const Dart e1 = cut_face(m, V(beta0(m, w[0])), V(w[3])).dart; // cuts off w[2]'s corner; e1 at w[1]'s vertex
	const Dart e2 = cut_face(m, V(beta0(m, e1)), V(w[5])).dart;   // w[4]'s corner; e2 at w[3]'s vertex
	cut_face(m, V(beta0(m, e2)), V(e1));                          // w[0]'s corner
}

template <typename MAP>
SubdivisionResult loop_step(MAP& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	using V = typename mesh_traits<MAP>::Vertex;
	using E = typename mesh_traits<MAP>::Edge;
	constexpr uint32 k = darts_per_edge_at_vertex<MAP>;
	const FaceSnapshot snapshot(m);
	const std::vector<Dart>& faces = snapshot.darts; // darts at old vertices
	if (!faces.empty() && (snapshot.min_degree != 3 || snapshot.max_degree != 3))
		throw SubdivisionError("Loop subdivision: every face must be a triangle");
	StepProgress step(progress);
	VertexPositions vertices(m);
	const std::vector<Dart> edges = edge_snapshot(m);
	const std::size_t total = vertices.vertices.size() + edges.size();

	// 1. the old vertices (the weights of the usual valences computed once)
	std::array<double, 16> betas;
	for (uint32 n = 1; n < betas.size(); ++n)
		betas[n] = loop_beta(n);
	for (std::size_t i = 0; i < vertices.vertices.size(); ++i)
	{
		if (!step.computing(i, total))
			return step.cancelled_before_change();
		const V v(vertices.vertices[i]);
		if (boundary_vertex_rule(m, pos, v, vertices.positions[i]))
			continue;
		Vec3 sum = Vec3::Zero();
		uint32 n = 0;
		foreach_dart_of_orbit(m, v, [&](Dart d) {
			sum += position(m, pos, across_edge(m, d));
			++n;
		});
		n /= k;
		sum /= double(k);
		const double beta = n < betas.size() ? betas[n] : loop_beta(n);
		vertices.positions[i] = (1.0 - double(n) * beta) * position(m, pos, v.dart) + beta * sum;
	}
	// 2. the edge vertices
	std::vector<Vec3> edge_points(edges.size());
	for (std::size_t i = 0; i < edges.size(); ++i)
	{
		if (!step.computing(vertices.vertices.size() + i, total))
			return step.cancelled_before_change();
		const Dart d = edges[i], d2 = other_side(m, d);
		const Vec3 ends = position(m, pos, d) + position(m, pos, across_edge(m, d));
		if (is_boundary(m, d) || is_boundary(m, d2))
			edge_points[i] = 0.5 * ends;
		else
			edge_points[i] = 0.375 * ends + 0.125 * (position(m, pos, opposite_in_triangle(m, d)) +
													 position(m, pos, opposite_in_triangle(m, d2)));
	}

	// 3. the connectivity (the face snapshot's darts that cut_edge takes
	// to edge points are replaced by darts at old vertices)
	vertices.commit(m, pos);
	std::vector<bool> moved(faces.size());
	for (std::size_t i = 0; i < faces.size(); ++i)
		moved[i] = moves_when_its_edge_is_cut(m, faces[i]);
	const std::size_t work = edges.size() + faces.size();
	for (std::size_t i = 0; i < edges.size(); ++i)
	{
		step.changing(i, work);
		pos[index_of(m, cut_edge(m, E(edges[i])))] = edge_points[i];
	}
	const std::vector<Dart> corners = faces_at_old_vertices(m, faces, moved);
	for (std::size_t i = 0; i < corners.size(); ++i)
	{
		step.changing(edges.size() + i, work);
		cut_hexagon(m, corners[i]);
	}
	return step.finish();
}

} // namespace

SubdivisionResult loop_subdivision(CMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	return loop_step(m, pos, progress);
}

SubdivisionResult loop_subdivision(GMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	return loop_step(m, pos, progress);
}

} // namespace cgogn::modeling
