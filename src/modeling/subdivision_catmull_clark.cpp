// SPDX-License-Identifier: MIT
// Catmull-Clark subdivision of polygon meshes.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/operators/gmap2.h>

#include "subdivision_common.h"

namespace cgogn::modeling
{

using namespace detail;

namespace
{

/// Vertex centroid of the face of d (a G-map face has two darts per vertex:
/// the mean is the same).
template <typename MAP>
Vec3 face_point(const MAP& m, const AttributeArray<Vec3>& pos, Dart d)
{
	Vec3 sum = Vec3::Zero();
	uint32 n = 0;
	foreach_dart_of_orbit(m, typename mesh_traits<MAP>::Face(d), [&](Dart x) {
		sum += position(m, pos, x);
		++n;
	});
	return sum / double(n);
}

/// Cuts the face of d0 (a 2k-gon after the cut of its k edges; d0 starts at
/// an old vertex) into k quads around a new vertex, which is returned.
/// `midpoints` is scratch space.
Vertex cut_into_quads(CMap2& m, Dart d0, std::vector<Dart>& midpoints)
{
	midpoints.clear();
	Dart d = phi1(m, d0);
	do
	{
		midpoints.push_back(d); // starts at the vertex cut into an old edge
		d = phi<1, 1>(m, d);
	} while (d != phi1(m, d0));
	// the corner at the end of midpoints[0] is cut off; the new edge is cut
	// at the centre, which is then joined to the other midpoints in turn
	const Edge first = cut_face(m, Vertex(midpoints[0]), Vertex(midpoints[1]));
	// first.dart (midpoints[0] -> midpoints[1]) lies in the face left to cut:
	// the centre's dart follows it there
	const Vertex centre = cut_edge(m, first);
	Dart from_centre = centre.dart; // centre -> midpoints[1]
	for (std::size_t i = 2; i < midpoints.size(); ++i)
		from_centre = cut_face(m, Vertex(from_centre), Vertex(midpoints[i])).dart;
	return centre;
}

/// The same in a G-map. midpoints[i] is the dart at the i-th midpoint whose
/// edge goes on to the next old vertex (the walk from d0). Each cut takes,
/// at the centre, the dart on the side of the part still to cut.
GMap2::Vertex cut_into_quads(GMap2& m, Dart d0, std::vector<Dart>& midpoints)
{
	midpoints.clear();
	Dart d = next_in_face(m, d0);
	do
	{
		midpoints.push_back(d);
		d = next_in_face(m, next_in_face(m, d));
	} while (d != next_in_face(m, d0));
	using V = GMap2::Vertex;
	// cut off the corner after midpoints[0]: joined on the side of d0
	const GMap2::Edge first = cut_face(m, V(beta0(m, d0)), V(midpoints[1]));
	// the centre's dart lies in the part still to cut (the face of
	// first.dart), on the half towards midpoints[1]; beta1 of it is on the
	// half towards midpoints[0], which every cut leaves in the part still to
	// cut (each cut takes off the quad on the side of midpoints[1])
	const GMap2::Vertex centre = cut_edge(m, first);
	const Dart from_centre = beta1(m, centre.dart);
	for (std::size_t i = 2; i < midpoints.size(); ++i)
		cut_face(m, V(from_centre), V(midpoints[i]));
	return centre;
}

template <typename MAP>
SubdivisionResult catmull_clark_step(MAP& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	using V = typename mesh_traits<MAP>::Vertex;
	using E = typename mesh_traits<MAP>::Edge;
	using F = typename mesh_traits<MAP>::Face;
	StepProgress step(progress);
	VertexPositions vertices(m);
	const std::vector<Dart> edges = edge_snapshot(m);
	const FaceSnapshot snapshot(m);
	if (!snapshot.darts.empty() && snapshot.min_degree < 3)
		throw SubdivisionError("Catmull-Clark subdivision: a face has fewer than 3 edges");
	const std::vector<Dart>& faces = snapshot.darts;
	const std::size_t total = vertices.vertices.size() + edges.size() + faces.size();

	// 1. the face points, and for each dart the slot of its face's point
	// (boundary darts have none), so that edges and vertices read them
	std::vector<Vec3> face_points(faces.size());
	std::vector<uint32> face_of_dart(container_of<Orbit::DART>(m).end_index(), INVALID_INDEX);
	for (std::size_t i = 0; i < faces.size(); ++i)
	{
		if (!step.computing(i, total))
			return step.cancelled_before_change();
		face_points[i] = face_point(m, pos, faces[i]);
		foreach_dart_of_orbit(m, F(faces[i]), [&](Dart d) { face_of_dart[d.index] = uint32(i); });
	}
	// 2. the old vertices: (Q + 2R + (n - 3) p) / n (the sums over the
	// vertex's darts: their means are the same whatever the darts per edge)
	for (std::size_t i = 0; i < vertices.vertices.size(); ++i)
	{
		if (!step.computing(faces.size() + i, total))
			return step.cancelled_before_change();
		const V v(vertices.vertices[i]);
		if (boundary_vertex_rule(m, pos, v, vertices.positions[i]))
			continue;
		const Vec3& p = position(m, pos, v.dart);
		Vec3 q = Vec3::Zero(), r = Vec3::Zero();
		uint32 darts = 0;
		foreach_dart_of_orbit(m, v, [&](Dart d) {
			q += face_points[face_of_dart[d.index]];
			r += position(m, pos, across_edge(m, d));
			++darts;
		});
		// R, the mean of the edge midpoints, is (p + mean of the neighbours) / 2
		const double dd = double(darts), dn = dd / double(darts_per_edge_at_vertex<MAP>);
		vertices.positions[i] = (q / dd + (p + r / dd) + (dn - 3.0) * p) / dn;
	}
	// 3. the edge points
	std::vector<Vec3> edge_points(edges.size());
	for (std::size_t i = 0; i < edges.size(); ++i)
	{
		if (!step.computing(faces.size() + vertices.vertices.size() + i, total))
			return step.cancelled_before_change();
		const Dart d = edges[i], d2 = other_side(m, d);
		const Vec3 ends = position(m, pos, d) + position(m, pos, across_edge(m, d));
		if (is_boundary(m, d) || is_boundary(m, d2))
			edge_points[i] = 0.5 * ends;
		else
			edge_points[i] = 0.25 * (ends + face_points[face_of_dart[d.index]] + face_points[face_of_dart[d2.index]]);
	}

	// 4. the connectivity (the face snapshot's darts that cut_edge takes
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
	std::vector<Dart> midpoints;
	for (std::size_t i = 0; i < corners.size(); ++i)
	{
		step.changing(edges.size() + i, work);
		pos[index_of(m, cut_into_quads(m, corners[i], midpoints))] = face_points[i];
	}
	return step.finish();
}

} // namespace

SubdivisionResult catmull_clark_subdivision(CMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	return catmull_clark_step(m, pos, progress);
}

SubdivisionResult catmull_clark_subdivision(GMap2& m, AttributeArray<Vec3>& pos, const ProgressCallback& progress)
{
	return catmull_clark_step(m, pos, progress);
}

} // namespace cgogn::modeling
