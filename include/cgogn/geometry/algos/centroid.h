// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap2.h>
#include <cgogn/geometry/algos/dart_geometry.h>

namespace cgogn::geometry
{

/// Mean of the positions of the vertices of cell c (an edge, a face, a
/// volume, a 2-map component; any cell type with a vertex incidence). For
/// faces this is the vertex centroid, not the area centroid (they agree on
/// triangles and parallelograms). O(number of darts of c); for 3-map volumes
/// the traversal floods with pooled marks (no allocation once warm).
template <GeometricMesh MESH, typename CELL>
Vec3 centroid(const MESH& m, CELL c, const AttributeArray<Vec3>& pos)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	Vec3 s = Vec3::Zero();
	uint32 n = 0;
	foreach_incident_vertex(m, c, [&](Vertex v) {
		s += value<Vec3>(m, pos, v);
		++n;
	});
	return n > 0 ? Vec3(s / n) : s;
}

namespace detail
{
/// Adds the k values from p to four partial sums taken in turn (see
/// mean_position). The sums are copied into locals for the loop: through
/// the reference, the compiler would store them after every add, since p
/// might point into them.
inline void add_in_four_sums(Vec3 (&sums)[4], const Vec3* p, uint32 k)
{
	Vec3 s0 = sums[0], s1 = sums[1], s2 = sums[2], s3 = sums[3];
	for (; k >= 4; k -= 4, p += 4)
	{
		s0 += p[0];
		s1 += p[1];
		s2 += p[2];
		s3 += p[3];
	}
	for (; k > 0; --k, ++p)
		s0 += *p;
	sums[0] = s0;
	sums[1] = s1;
	sums[2] = s2;
	sums[3] = s3;
}
} // namespace detail

/// Mean of the positions of all the vertices of the mesh (its vertex
/// centroid); zero for a mesh without vertices. O(number of vertices).
/// Precondition: pos is a vertex attribute of m (checked in debug builds).
/// The values of the live lines are read as plain arrays
/// (Attribute::foreach_live_run) into four partial sums taken in turn: with
/// one running sum every add waits for the previous one, and that chain, not
/// the reads, bounds the loop (docs/performance.md, "Read attributes the simple way").
template <GeometricMesh MESH>
Vec3 mean_position([[maybe_unused]] const MESH& m, const AttributeArray<Vec3>& pos)
{
	assert(pos.container() == &container_of<mesh_traits<MESH>::Vertex::ORBIT>(m) &&
		   "mean_position: pos is not a vertex attribute of m");
	Vec3 s[4] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
	uint32 n = 0;
	pos.foreach_live_run([&](const Vec3* first, uint32 count) {
		detail::add_in_four_sums(s, first, count);
		n += count;
	});
	return n > 0 ? Vec3(((s[0] + s[1]) + (s[2] + s[3])) / double(n)) : Vec3::Zero();
}

/// Writes the vertex centroid of every cell of the attribute's cell type
/// CELL into `out`. O(number of darts).
template <typename CELL, GeometricMesh MESH>
void compute_centroids(const MESH& m, const AttributeArray<Vec3>& pos, AttributeArray<Vec3>& out)
{
	foreach_cell(m, [&](CELL c) { out[c] = centroid(m, c, pos); });
}

} // namespace cgogn::geometry
