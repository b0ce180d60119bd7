// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/geometry/algos/dart_geometry.h>

#include <Eigen/Geometry> // cross()

#include <vector>

namespace cgogn::geometry
{

/// How the face normals around a vertex are combined into a vertex normal.
enum class NormalWeighting
{
	Uniform, ///< every incident face counts the same
	Area,    ///< faces weighted by their area
	Angle    ///< faces weighted by their corner angle at the vertex (Thuermer-Wuethrich)
};

/// Newell vector of the face cycle of dart d: twice the vector area of the
/// polygon (its direction is the face normal, its norm twice the area; for a
/// non-planar polygon, the normal of the best-fitting plane and the area of
/// the projection on it). Exact for any simple polygon, convex or not.
/// O(face degree). Works on the faces of 2-maps, 3-maps and 2-G-maps, in the
/// orientation of d (see oriented_phi1).
template <GeometricMesh MESH>
Vec3 newell_vector(const MESH& m, const AttributeArray<Vec3>& pos, Dart d)
{
	// relative to the first vertex: same value, better rounding far from the origin
	const Vec3& p0 = origin_position(m, pos, d);
	Vec3 n = Vec3::Zero();
	Dart it = oriented_phi1(m, d);
	Vec3 a = origin_position(m, pos, it) - p0;
	for (it = oriented_phi1(m, it); it != d; it = oriented_phi1(m, it))
	{
		const Vec3 b = origin_position(m, pos, it) - p0;
		n += a.cross(b);
		a = b;
	}
	return n;
}

/// Unit normal of face f by Newell's method (any polygon; counterclockwise
/// vertices give the normal pointing at the viewer). The zero vector for a
/// degenerate face (zero area). On a G-map, which has no orientation, the
/// normal is that of the face seen from f.dart (its vertices in the order
/// f.dart, beta0(f.dart), ...): the two darts of a face that beta0 exchanges
/// give opposite normals. O(face degree).
template <GeometricMesh MESH>
Vec3 face_normal(const MESH& m, typename mesh_traits<MESH>::Face f, const AttributeArray<Vec3>& pos)
{
	const Vec3 n = newell_vector(m, pos, f.dart);
	const double l = n.norm();
	return l > 0.0 ? Vec3(n / l) : Vec3::Zero();
}

/// Unit normal of vertex v of a surface: the weighted sum of the normals of
/// its incident faces (boundary faces excluded), normalized. Zero when every
/// incident face is degenerate. On a G-map, the faces are seen oriented as
/// the face of v.dart (see face_normal): the normal points to the side of
/// that face's normal. O(sum of the degrees of the incident faces).
template <SurfaceMesh MESH>
Vec3 vertex_normal(const MESH& m, typename mesh_traits<MESH>::Vertex v, const AttributeArray<Vec3>& pos,
				   NormalWeighting w = NormalWeighting::Angle)
{
	const Vec3& p = origin_position(m, pos, v.dart);
	Vec3 n = Vec3::Zero();
	// around v, the face of dart phi1(phi2(d)) has the edge d as its previous
	// edge: walking the orbit gives each corner's two edges in O(1)
	Dart prev = v.dart;
	Dart it = v.dart;
	do
	{
		prev = it;
		it = oriented_phi1(m, oriented_phi2(m, it));
		if (is_boundary(m, it))
			continue;
		const Vec3 nf = newell_vector(m, pos, it);
		switch (w)
		{
		case NormalWeighting::Area:
			n += nf;
			break;
		case NormalWeighting::Uniform:
			if (const double l = nf.norm(); l > 0.0)
				n += nf / l;
			break;
		case NormalWeighting::Angle:
			if (const double l = nf.norm(); l > 0.0)
			{
				const Vec3 next = origin_position(m, pos, oriented_phi1(m, it)) - p;
				const Vec3 before = origin_position(m, pos, oriented_phi1(m, prev)) - p;
				n += angle_between(next, before) * nf / l;
			}
			break;
		}
	} while (it != v.dart);
	const double l = n.norm();
	return l > 0.0 ? Vec3(n / l) : Vec3::Zero();
}

/// Writes the unit Newell normal of every face into the face attribute
/// `normal` (on a G-map, each face seen from its dart: see face_normal).
/// O(number of darts).
template <GeometricMesh MESH>
void compute_face_normals(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<Vec3>& normal)
{
	using Face = typename mesh_traits<MESH>::Face;
	foreach_cell(m, [&](Face f) { normal[f] = face_normal(m, f, pos); });
}

/// Writes the normal of every vertex of a surface into the vertex attribute
/// `normal`, in one pass over the faces (each face normal computed once).
/// Isolated or fully degenerate vertices get zero. O(number of darts).
/// On a G-map, whose faces need not agree on an orientation, each vertex is
/// computed on its own by vertex_normal (same values, its orientation
/// convention): O(number of darts times the face degree).
template <SurfaceMesh MESH>
void compute_vertex_normals(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<Vec3>& normal,
							NormalWeighting w = NormalWeighting::Angle)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	using Face = typename mesh_traits<MESH>::Face;
	if constexpr (is_gmap_v<MESH>)
	{
		foreach_cell(m, [&](Vertex v) { normal[v] = vertex_normal(m, v, pos, w); });
	}
	else
	{
		foreach_cell(m, [&](Vertex v) { normal[v] = Vec3::Zero(); });
		foreach_cell(m, [&](Face f) {
			const Vec3 nf = newell_vector(m, pos, f.dart);
			const double l = nf.norm();
			if (l <= 0.0)
				return;
			if (w == NormalWeighting::Area)
			{
				foreach_dart_of_orbit(m, f, [&](Dart d) { normal[Vertex(d)] += nf; });
				return;
			}
			const Vec3 u = nf / l;
			if (w == NormalWeighting::Uniform)
			{
				foreach_dart_of_orbit(m, f, [&](Dart d) { normal[Vertex(d)] += u; });
				return;
			}
			// corner angles: previous, current and next vertex along the face
			Dart prev = f.dart;
			while (phi1(m, prev) != f.dart)
				prev = phi1(m, prev);
			Dart cur = f.dart;
			do
			{
				const Dart next = phi1(m, cur);
				const Vec3& p = origin_position(m, pos, cur);
				const double a = angle_between(origin_position(m, pos, next) - p, origin_position(m, pos, prev) - p);
				normal[Vertex(cur)] += a * u;
				prev = cur;
				cur = next;
			} while (cur != f.dart);
		});
		foreach_cell(m, [&](Vertex v) {
			Vec3& n = normal[v];
			const double l = n.norm();
			n = l > 0.0 ? Vec3(n / l) : Vec3::Zero();
		});
	}
}

} // namespace cgogn::geometry
