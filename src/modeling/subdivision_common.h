// SPDX-License-Identifier: MIT
// What the surface subdivision schemes share: position access by vertex
// line, the boundary rules, snapshots of the cells before the refinement and
// the two-phase progress of a step.
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/modeling/subdivision.h>

#include <algorithm>
#include <vector>

namespace cgogn::modeling::detail
{

using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

/// The position of the origin of d.
inline const Vec3& position(const CMap2& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return pos[index_of(m, Vertex(d))];
}

/// True when the edge of d has a boundary face on one side.
inline bool is_boundary_edge(const CMap2& m, Dart d)
{
	return is_boundary(m, d) || is_boundary(m, phi2(m, d));
}

/// The boundary rule shared by Loop and Catmull-Clark for a vertex whose
/// orbit touches the boundary: 1/8 q0 + 3/4 p + 1/8 q1 (q0, q1 the ends of
/// its two boundary edges); a vertex with another number of boundary edges
/// (a pinched vertex) stays. Returns false (and leaves `out`) when v is not
/// on the boundary.
inline bool boundary_vertex_rule(const CMap2& m, const AttributeArray<Vec3>& pos, Vertex v, Vec3& out)
{
	Vec3 sum = Vec3::Zero();
	uint32 n = 0;
	bool boundary = false;
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		if (is_boundary_edge(m, d))
		{
			boundary = true;
			sum += position(m, pos, phi2(m, d));
			++n;
		}
	});
	if (!boundary)
		return false;
	const Vec3& p = position(m, pos, v.dart);
	out = n == 2 ? Vec3(0.75 * p + 0.125 * sum) : p;
	return true;
}

/// One dart per vertex, as the map is before a step (the operators create
/// cells while the snapshot is walked). Vertices are indexed (positions):
/// the container is walked. O(vertices).
inline std::vector<Dart> vertex_snapshot(const CMap2& m)
{
	std::vector<Dart> darts;
	darts.reserve(nb_cells<Vertex>(m));
	foreach_cell(m, [&](Vertex v) { darts.push_back(v.dart); });
	return darts;
}

/// One dart per edge: the one of smaller index (phi2 never joins two boundary
/// darts, so every edge is real). No marker, whether edges are indexed or
/// not. O(darts).
inline std::vector<Dart> edge_snapshot(const CMap2& m)
{
	std::vector<Dart> darts;
	darts.reserve(nb_darts(m) / 2);
	foreach_dart(m, [&](Dart d) {
		if (d.index < phi2(m, d).index)
			darts.push_back(d);
	});
	return darts;
}

/// One dart per non-boundary face (the one of smallest index, found by
/// walking the face until a smaller one shows up), with the smallest and
/// largest face degrees. No marker. O(sum of squared face degrees) in the
/// worst case, about 1.5 steps per dart on triangles.
struct FaceSnapshot
{
	std::vector<Dart> darts;
	uint32 min_degree = 0, max_degree = 0;

	explicit FaceSnapshot(const CMap2& m)
	{
		darts.reserve(nb_darts(m) / 3);
		min_degree = ~0u;
		foreach_dart(m, [&](Dart d) {
			if (is_boundary(m, d))
				return;
			uint32 degree = 1;
			for (Dart x = phi1(m, d); x != d; x = phi1(m, x), ++degree)
				if (x.index < d.index)
					return;
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

	explicit VertexPositions(const CMap2& m) : vertices(vertex_snapshot(m)), positions(vertices.size())
	{
	}
	void commit(const CMap2& m, AttributeArray<Vec3>& pos) const
	{
		for (std::size_t i = 0; i < vertices.size(); ++i)
			pos[index_of(m, Vertex(vertices[i]))] = positions[i];
	}
};

} // namespace cgogn::modeling::detail
