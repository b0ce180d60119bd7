// SPDX-License-Identifier: MIT
// sqrt3 subdivision of triangle meshes (Kobbelt 2000).
#include "subdivision_common.h"

#include <cgogn/core/operators/cmap2.h>

#include <cmath>
#include <numbers>

namespace cgogn::modeling
{

using namespace detail;

SubdivisionResult sqrt3_subdivision(CMap2& m, Attribute<Vec3>& pos, const ProgressCallback& progress)
{
	uint32 max_degree = 0;
	const std::vector<Dart> faces = face_snapshot(m, max_degree);
	if (max_degree > 3)
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
	std::vector<Dart> interior_edges = edge_snapshot(m);
	std::erase_if(interior_edges, [&](Dart d) { return is_boundary_edge(m, d); });

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
	return step.finish();
}

} // namespace cgogn::modeling
