// SPDX-License-Identifier: MIT
// What the surface subdivision schemes share: position access by vertex
// line, the boundary rules, snapshots of the cells before the refinement and
// the two-phase progress of a step.
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/dart_geometry.h>
#include <cgogn/modeling/subdivision.h>

#include <algorithm>
#include <vector>

namespace cgogn::modeling::detail
{

using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

// The schemes run on CMap2 and GMap2. What differs is how a dart reaches its
// neighbours: the other end of its edge (origin of phi2 in a 2-map, beta0 in
// a G-map), the other side of its edge (phi2, beta2), the next dart along
// its face, and how many darts a vertex has per incident edge (1, or 2 in a
// G-map: one per side of the edge). Sums over a vertex's darts are divided
// by the latter.

/// A dart at the other end of d's edge.
template <typename MAP>
Dart across_edge(const MAP& m, Dart d)
{
	if constexpr (is_gmap_v<MAP>)
		return beta0(m, d);
	else
		return phi2(m, d);
}

/// The dart of d's edge on its other side (the other face).
template <typename MAP>
Dart other_side(const MAP& m, Dart d)
{
	if constexpr (is_gmap_v<MAP>)
		return beta2(m, d);
	else
		return phi2(m, d);
}

/// The next dart along d's face, at the next vertex in the direction of d's
/// edge: the geometry layer's oriented walk (phi1; beta1 o beta0 in a G-map).
template <typename MAP>
Dart next_in_face(const MAP& m, Dart d)
{
	return geometry::oriented_phi1(m, d);
}

/// A dart at the vertex opposite to d's edge in d's triangle.
template <typename MAP>
Dart opposite_in_triangle(const MAP& m, Dart d)
{
	return across_edge(m, next_in_face(m, d));
}

/// Whether cutting d's edge by its smallest dart (as the schemes cut the
/// edges of edge_snapshot) takes d to the new vertex. A G-map's cut_edge
/// moves beta0 of the darts at the vertex of e.dart to the new vertex, so
/// the darts at the other end go; those at the vertex of the smallest dart
/// (an even index, a pair's first) stay. Never in a 2-map, whose cut_edge
/// keeps the origins of the existing darts. O(1).
template <typename MAP>
bool moves_when_its_edge_is_cut(const MAP& m, Dart d)
{
	if constexpr (is_gmap_v<MAP>)
	{
		const Dart e(std::min(d.index & ~1u, other_side(m, d).index & ~1u));
		return d != e && d != other_side(m, e);
	}
	else
		return false;
}

/// The face snapshot's darts once the edges are cut: each at an old vertex
/// (a dart that moved to an edge point is replaced by the next one along its
/// face, at the old vertex its edge now leads to). `moved` was computed by
/// moves_when_its_edge_is_cut before the cuts. O(number of faces).
template <typename MAP>
std::vector<Dart> faces_at_old_vertices(const MAP& m, std::vector<Dart> faces, const std::vector<bool>& moved)
{
	for (std::size_t i = 0; i < faces.size(); ++i)
		if (moved[i])
			faces[i] = next_in_face(m, faces[i]);
	return faces;
}

/// Darts of a vertex per incident edge.
template <typename MAP>
inline constexpr uint32 darts_per_edge_at_vertex = is_gmap_v<MAP> ? 2 : 1;

/// The position of the vertex of d (the origin of d in a 2-map).
template <typename MAP>
const Vec3& position(const MAP& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return pos[index_of(m, typename mesh_traits<MAP>::Vertex(d))];
}

/// True when the edge of d has a boundary face on one side.
template <typename MAP>
bool is_boundary_edge(const MAP& m, Dart d)
{
	return is_boundary(m, d) || is_boundary(m, other_side(m, d));
}

/// The boundary rule shared by Loop and Catmull-Clark for a vertex whose
/// orbit touches the boundary: 1/8 q0 + 3/4 p + 1/8 q1 (q0, q1 the ends of
/// its two boundary edges); a vertex with another number of boundary edges
/// (a pinched vertex) stays. Returns false (and leaves `out`) when v is not
/// on the boundary.
template <typename MAP>
bool boundary_vertex_rule(const MAP& m, const AttributeArray<Vec3>& pos, typename mesh_traits<MAP>::Vertex v, Vec3& out)
{
	Vec3 sum = Vec3::Zero();
	uint32 n = 0;
	bool boundary = false;
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		if (is_boundary_edge(m, d))
		{
			boundary = true;
			sum += position(m, pos, across_edge(m, d));
			++n;
		}
	});
	if (!boundary)
		return false;
	const Vec3& p = position(m, pos, v.dart);
	constexpr uint32 k = darts_per_edge_at_vertex<MAP>;
	out = n == 2 * k ? Vec3(0.75 * p + 0.125 / double(k) * sum) : p;
	return true;
}

/// One dart per vertex, as the map is before a step (the operators create
/// cells while the snapshot is walked). Vertices are indexed (positions):
/// the container is walked. O(vertices).
template <typename MAP>
std::vector<Dart> vertex_snapshot(const MAP& m)
{
	using V = typename mesh_traits<MAP>::Vertex;
	std::vector<Dart> darts;
	darts.reserve(nb_cells<V>(m));
	foreach_cell(m, [&](V v) { darts.push_back(v.dart); });
	return darts;
}

/// One dart per edge: the one of smallest index (phi2 never joins two
/// boundary darts, so every edge is real; a G-map edge's four darts are
/// compared). No marker, whether edges are indexed or not. O(darts).
template <typename MAP>
std::vector<Dart> edge_snapshot(const MAP& m)
{
	std::vector<Dart> darts;
	darts.reserve(nb_darts(m) / (2 * darts_per_edge_at_vertex<MAP>));
	foreach_dart(m, [&](Dart d) {
		const Dart d2 = other_side(m, d);
		if constexpr (is_gmap_v<MAP>)
		{
			if (d.index < beta0(m, d).index && d.index < d2.index && d.index < beta0(m, d2).index)
				darts.push_back(d);
		}
		else if (d.index < d2.index)
			darts.push_back(d);
	});
	return darts;
}

/// One dart per non-boundary face (the one of smallest index, found by
/// walking the face until a smaller one shows up), with the smallest and
/// largest face degrees. In a G-map only the darts whose edge goes forward
/// from them along next_in_face are walked (one per edge): the face's
/// smallest such dart is kept. No marker. O(sum of squared face degrees) in
/// the worst case, about 1.5 steps per dart on triangles.
struct FaceSnapshot
{
	std::vector<Dart> darts;
	uint32 min_degree = 0, max_degree = 0;

	template <typename MAP>
	explicit FaceSnapshot(const MAP& m)
	{
		darts.reserve(nb_darts(m) / (3 * darts_per_edge_at_vertex<MAP>));
		min_degree = ~0u;
		foreach_dart(m, [&](Dart d) {
			if (is_boundary(m, d))
				return;
			if constexpr (is_gmap_v<MAP>)
				if (beta0(m, d).index < d.index)
					return;
			uint32 degree = 1;
			for (Dart x = next_in_face(m, d); x != d; x = next_in_face(m, x), ++degree)
			{
				if (x.index < d.index)
					return;
				if constexpr (is_gmap_v<MAP>)
					if (beta0(m, x).index < d.index)
						return; // the other walk direction holds a smaller dart
			}
			darts.push_back(d);
			min_degree = std::min(min_degree, degree);
			max_degree = std::max(max_degree, degree);
		});
		if (darts.empty())
			min_degree = 0;
	}
};

/// Progress of one step: computing the positions is [0, 0.5) and may be
/// cancelled (the map is untouched), changing the connectivity is [0.5, 1]
/// and always runs to its end (a cancel request is kept for the result).
class StepProgress
{
public:
	explicit StepProgress(const ProgressCallback& callback) : reporter_(callback)
	{
	}
	/// False when the caller asked to stop.
	bool computing(std::size_t done, std::size_t total)
	{
		return (done & 1023u) != 0 || reporter_.report(0.5 * double(done) / double(total ? total : 1));
	}
	void changing(std::size_t done, std::size_t total)
	{
		if ((done & 1023u) == 0)
			reporter_.report(0.5 + 0.5 * double(done) / double(total ? total : 1));
	}
	SubdivisionResult finish()
	{
		if (!reporter_.cancelled())
			reporter_.report(1.0);
		return {reporter_.cancelled(), 1};
	}
	SubdivisionResult cancelled_before_change() const
	{
		return {true, 0};
	}

private:
	ProgressReporter reporter_;
};

/// New positions of the old vertices, stored by vertex line until the
/// connectivity changes, then written to `pos`.
struct VertexPositions
{
	std::vector<Dart> vertices;
	std::vector<Vec3> positions;

	template <typename MAP>
	explicit VertexPositions(const MAP& m) : vertices(vertex_snapshot(m)), positions(vertices.size())
	{
	}
	template <typename MAP>
	void commit(const MAP& m, AttributeArray<Vec3>& pos) const
	{
		for (std::size_t i = 0; i < vertices.size(); ++i)
			pos[index_of(m, typename mesh_traits<MAP>::Vertex(vertices[i]))] = positions[i];
	}
};

} // namespace cgogn::modeling::detail
