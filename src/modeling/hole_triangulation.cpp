// SPDX-License-Identifier: MIT
// Minimal-weight triangulation of a hole's boundary loop (Liepa 2003).
#include <cgogn/core/functions/traversals/local_cmap2.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/geometry/algos/normal.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <limits>
#include <unordered_map>
#include <utility>

#include "hole_filling_steps.h"

namespace cgogn::modeling::detail
{

namespace
{

constexpr double INFINITE_WEIGHT = std::numeric_limits<double>::infinity();
constexpr uint32 NO_APEX = std::numeric_limits<uint32>::max();
// dihedral terms closer than this count as equal, so that rounding noise on
// (nearly) planar holes does not hide the area criterion
constexpr double ANGLE_TOLERANCE = 1e-9;

/// 1 - cos of the angle between two unit normals: 0 when the triangles are
/// coplanar, 2 when folded back; a degenerate triangle (zero normal) is worse
/// than any fold (a hole filled on the back of a flat disk is folded 180
/// degrees everywhere along its boundary, and degenerate triangles would win
/// there on area).
double dihedral_term(const Vec3 &a, const Vec3 &b)
{
	if (a.isZero(0.0) || b.isZero(0.0))
		return 4.0;
	return 1.0 - a.dot(b);
}

Vec3 unit_or_zero(const Vec3 &v)
{
	const double l = v.norm();
	return l > 0.0 ? Vec3(v / l) : Vec3::Zero();
}

/// Pairs of non-consecutive corners that must not be joined: already adjacent
/// in the mesh (the new edge would double an edge) or the same vertex (a loop
/// through a pinched vertex).
std::vector<char> forbidden_diagonals(const CMap2 &m, const std::vector<Dart> &loop)
{
	const uint32 n = uint32(loop.size());
	std::unordered_multimap<uint32, uint32> corners_of_vertex;
	for (uint32 i = 0; i < n; ++i)
		corners_of_vertex.emplace(index_of(m, CMap2::Vertex(loop[i])), i);
	std::vector<char> forbidden(std::size_t(n) * n, 0);
	const auto forbid = [&](uint32 i, uint32 k)
	{
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
		foreach_dart_of_orbit(m, CMap2::Vertex(loop[i]),
		                      [&](Dart d)
		                      {
			                      auto range = corners_of_vertex.equal_range(index_of(m, CMap2::Vertex(phi1(m, d))));
			                      for (auto it = range.first; it != range.second; ++it)
				                      forbid(i, it->second);
		                      });
	}
	return forbidden;
}

} // namespace

bool optimal_hole_triangulation(const CMap2 &m, const Attribute<Vec3> &pos, const std::vector<Dart> &loop,
                                ProgressReporter &reporter, double from, double to, HoleTriangulation &out)
{
	const uint32 n = uint32(loop.size());
	std::vector<Vec3> p(n), outside(n);
	for (uint32 i = 0; i < n; ++i)
	{
		p[i] = pos[index_of(m, CMap2::Vertex(loop[i]))];
		// the face across loop edge i, oriented like the triangles that will fill the hole
		outside[i] = unit_or_zero(geometry::newell_vector(m, pos, phi2(m, loop[i])));
	}
	const std::vector<char> forbidden = forbidden_diagonals(m, loop);
	const auto at = [n](uint32 i, uint32 j) { return std::size_t(i) * n + j; };

	out.n = n;
	std::vector<double> angle(std::size_t(n) * n), area(std::size_t(n) * n);
	// first with the forbidden diagonals avoided; when no triangulation avoids
	// them (rare: a loop whose vertices are all joined outside), with them
	for (const bool avoid : {true, false})
	{
		out.split.assign(std::size_t(n) * n, NO_APEX);
		std::fill(angle.begin(), angle.end(), 0.0);
		std::fill(area.begin(), area.end(), 0.0);
		const auto top_normal = [&](uint32 i, uint32 j)
		{
			if (j == i + 1)
				return outside[i];
			const uint32 k = out.apex(i, j);
			return unit_or_zero((p[k] - p[i]).cross(p[j] - p[i]));
		};
		for (uint32 len = 2; len < n; ++len)
		{
			if (!reporter.report(from + (to - from) * double(len) / double(n)))
				return false;
			for (uint32 i = 0; i + len < n; ++i)
			{
				const uint32 j = i + len;
				double best_angle = INFINITE_WEIGHT, best_area = INFINITE_WEIGHT;
				uint32 best_k = NO_APEX;
				const bool closing = i == 0 && j == n - 1;
				if (!(avoid && !closing && forbidden[at(i, j)]))
				{
					for (uint32 k = i + 1; k < j; ++k)
					{
						if ((k > i + 1 && out.split[at(i, k)] == NO_APEX) ||
						    (j > k + 1 && out.split[at(k, j)] == NO_APEX))
							continue;
						const Vec3 nt_area = (p[k] - p[i]).cross(p[j] - p[i]);
						const Vec3 nt = unit_or_zero(nt_area);
						double a = std::max({angle[at(i, k)], angle[at(k, j)], dihedral_term(nt, top_normal(i, k)),
						                     dihedral_term(nt, top_normal(k, j))});
						if (closing)
							a = std::max(a, dihedral_term(nt, outside[n - 1]));
						const double s = area[at(i, k)] + area[at(k, j)] + 0.5 * nt_area.norm();
						if (a < best_angle - ANGLE_TOLERANCE || (a <= best_angle + ANGLE_TOLERANCE && s < best_area))
						{
							best_angle = a;
							best_area = s;
							best_k = k;
						}
					}
				}
				out.split[at(i, j)] = best_k;
				angle[at(i, j)] = best_angle;
				area[at(i, j)] = best_area;
			}
		}
		if (out.split[at(0, n - 1)] != NO_APEX)
			break;
	}
	return true;
}

void cut_hole(CMap2 &m, const std::vector<Dart> &loop, const HoleTriangulation &t)
{
	// each entry is a sub-polygon i..j, the face of loop[i], closed by phi_1(loop[i])
	std::vector<std::pair<uint32, uint32>> todo = {{0u, t.n - 1}};
	while (!todo.empty())
	{
		const auto [i, j] = todo.back();
		todo.pop_back();
		const uint32 k = t.apex(i, j);
		const Dart closing = phi_1(m, loop[i]);
		if (k > i + 1)
		{
			cut_face(m, CMap2::Vertex(loop[i]), CMap2::Vertex(loop[k]));
			todo.emplace_back(i, k);
		}
		if (j > k + 1)
		{
			cut_face(m, CMap2::Vertex(loop[k]), CMap2::Vertex(closing));
			todo.emplace_back(k, j);
		}
	}
}

} // namespace cgogn::modeling::detail
