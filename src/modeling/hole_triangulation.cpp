// SPDX-License-Identifier: MIT
// Minimal-weight triangulation of a hole's boundary loop (Liepa 2003).
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/geometry/algos/normal.h>

#include "hole_filling_steps.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <unordered_map>
#include <utility>

namespace cgogn::modeling::detail
{

namespace
{

constexpr float INFINITE_ANGLE = std::numeric_limits<float>::infinity();
constexpr uint32 NO_APEX = std::numeric_limits<uint32>::max();
// dihedral terms closer than this count as equal, so that rounding noise on
// (nearly) planar holes does not hide the area criterion
constexpr float ANGLE_TOLERANCE = 1e-6f;

/// 1 - cos of the angle between two unit normals: 0 when the triangles are
/// coplanar, 2 when folded back; a degenerate triangle (zero normal) is worse
/// than any fold (a hole filled on the back of a flat disk is folded 180
/// degrees everywhere along its boundary, and degenerate triangles would win
/// there on area).
float dihedral_term(const Eigen::Vector3f& a, const Eigen::Vector3f& b)
{
	if (a.isZero(0.0f) || b.isZero(0.0f))
		return 4.0f;
	return 1.0f - a.dot(b);
}

Vec3 unit_or_zero(const Vec3& v)
{
	const double l = v.norm();
	return l > 0.0 ? Vec3(v / l) : Vec3::Zero();
}

/// Pairs of non-consecutive corners that must not be joined: already adjacent
/// in the mesh (the new edge would double an edge) or the same vertex (a loop
/// through a pinched vertex).
std::vector<char> forbidden_diagonals(const CMap2& m, const std::vector<Dart>& loop)
{
	const uint32 n = uint32(loop.size());
	std::unordered_multimap<uint32, uint32> corners_of_vertex;
	for (uint32 i = 0; i < n; ++i)
		corners_of_vertex.emplace(index_of(m, CMap2::Vertex(loop[i])), i);
	std::vector<char> forbidden(std::size_t(n) * n, 0);
	const auto forbid = [&](uint32 i, uint32 k) {
		forbidden[std::size_t(i) * n + k] = 1;
		forbidden[std::size_t(k) * n + i] = 1;
	};
	for (uint32 i = 0; i < n; ++i)
	{
		const uint32 vi = index_of(m, CMap2::Vertex(loop[i]));
		auto same = corners_of_vertex.equal_range(vi);
		for (auto it = same.first; it != same.second; ++it)
			if (it->second != i)
				forbid(i, it->second);
		foreach_dart_of_orbit(m, CMap2::Vertex(loop[i]), [&](Dart d) {
			auto range = corners_of_vertex.equal_range(index_of(m, CMap2::Vertex(phi1(m, d))));
			for (auto it = range.first; it != range.second; ++it)
				forbid(i, it->second);
		});
	}
	return forbidden;
}

} // namespace

bool optimal_hole_triangulation(const CMap2& m, const AttributeArray<Vec3>& pos, const std::vector<Dart>& loop,
								ProgressReporter& reporter, double from, double to, HoleTriangulation& out)
{
	const uint32 n = uint32(loop.size());
	// single precision, relative to the loop's centroid: the table below is
	// read n^3 / 3 times and memory traffic is the cost; float rounding stays
	// far below the angle tolerance
	Vec3 center = Vec3::Zero();
	for (Dart d : loop)
		center += pos[index_of(m, CMap2::Vertex(d))];
	center /= double(n);
	std::vector<Eigen::Vector3f> p(n), outside(n);
	for (uint32 i = 0; i < n; ++i)
	{
		p[i] = (pos[index_of(m, CMap2::Vertex(loop[i]))] - center).cast<float>();
		// the face across loop edge i, oriented like the triangles that will fill the hole
		outside[i] = unit_or_zero(geometry::newell_vector(m, pos, phi2(m, loop[i]))).cast<float>();
	}
	const std::vector<char> forbidden = forbidden_diagonals(m, loop);
	const auto at = [n](uint32 i, uint32 j) { return std::size_t(i) * n + j; };

	out.n = n;
	// the best triangulation of each sub-polygon i..j: its weight and the unit
	// normal of its triangle on (i, j), stored at (i, j) and (j, i) so that
	// the inner loop reads rows i and j contiguously
	struct Sub
	{
		float angle;
		float area;
		Eigen::Vector3f normal;
	};
	std::vector<Sub> sub(std::size_t(n) * n);
	// first with the forbidden diagonals avoided; when no triangulation avoids
	// them (rare: a loop whose vertices are all joined outside), with them
	for (const bool avoid : {true, false})
	{
		out.split.assign(std::size_t(n) * n, NO_APEX);
		std::fill(sub.begin(), sub.end(), Sub{INFINITE_ANGLE, INFINITE_ANGLE, Eigen::Vector3f::Zero()});
		for (uint32 i = 0; i + 1 < n; ++i)
			sub[at(i, i + 1)] = sub[at(i + 1, i)] = Sub{0.0f, 0.0f, outside[i]};
		for (uint32 len = 2; len < n; ++len)
		{
			if (!reporter.report(from + (to - from) * double(len) / double(n)))
				return false;
			for (uint32 i = 0; i + len < n; ++i)
			{
				const uint32 j = i + len;
				const bool closing = i == 0 && j == n - 1;
				if (avoid && !closing && forbidden[at(i, j)])
					continue;
				const Sub* row_i = &sub[at(i, 0)];
				const Sub* row_j = &sub[at(j, 0)];
				const Eigen::Vector3f pi = p[i], ij = p[j] - p[i];
				Sub best{INFINITE_ANGLE, INFINITE_ANGLE, Eigen::Vector3f::Zero()};
				uint32 best_k = NO_APEX;
				for (uint32 k = i + 1; k < j; ++k)
				{
					const Sub &left = row_i[k], &right = row_j[k];
					const float inherited = std::max(left.angle, right.angle);
					// also skips the sub-polygons without a triangulation (infinite)
					if (inherited > best.angle + ANGLE_TOLERANCE)
						continue;
					const Eigen::Vector3f twice_area = (p[k] - pi).cross(ij);
					const float norm = twice_area.norm();
					const Eigen::Vector3f nt =
						norm > 0.0f ? Eigen::Vector3f(twice_area / norm) : Eigen::Vector3f::Zero();
					float a = std::max({inherited, dihedral_term(nt, left.normal), dihedral_term(nt, right.normal)});
					if (closing)
						a = std::max(a, dihedral_term(nt, outside[n - 1]));
					const float s = left.area + right.area + 0.5f * norm;
					if (a < best.angle - ANGLE_TOLERANCE || (a <= best.angle + ANGLE_TOLERANCE && s < best.area))
					{
						best = Sub{a, s, nt};
						best_k = k;
					}
				}
				out.split[at(i, j)] = best_k;
				sub[at(i, j)] = sub[at(j, i)] = best;
			}
		}
		if (out.split[at(0, n - 1)] != NO_APEX)
			break;
	}
	return true;
}

void cut_hole(CMap2& m, const std::vector<Dart>& loop, const HoleTriangulation& t)
{
	// each entry is a sub-polygon i..j, the face of loop[i], closed by phi_1(loop[i])
	std::vector<std::pair<uint32, uint32>> pending = {{0u, t.n - 1}};
	while (!pending.empty())
	{
		const auto [i, j] = pending.back();
		pending.pop_back();
		const uint32 k = t.apex(i, j);
		const Dart closing = phi_1(m, loop[i]);
		if (k > i + 1)
		{
			cut_face(m, CMap2::Vertex(loop[i]), CMap2::Vertex(loop[k]));
			pending.emplace_back(i, k);
		}
		if (j > k + 1)
		{
			cut_face(m, CMap2::Vertex(loop[k]), CMap2::Vertex(closing));
			pending.emplace_back(k, j);
		}
	}
}

} // namespace cgogn::modeling::detail
