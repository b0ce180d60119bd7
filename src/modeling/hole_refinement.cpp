// SPDX-License-Identifier: MIT
// Refinement of a hole's patch to the density of the surface around it
// (Liepa 2003): centroid splits and Delaunay flips.
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/geometry/algos/dart_geometry.h>

#include "hole_filling_steps.h"

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>

namespace cgogn::modeling::detail
{

namespace
{

// bounds that only pathological input reaches: each refinement pass at least
// triples the triangles that are still too large
constexpr uint32 MAX_REFINEMENT_PASSES = 64;
constexpr uint32 MAX_RELAXATION_PASSES = 64;

const Vec3& origin(const CMap2& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return pos[index_of(m, CMap2::Vertex(d))];
}

double angle_at(const Vec3& apex, const Vec3& a, const Vec3& b)
{
	const Vec3 u = a - apex, v = b - apex;
	return std::atan2(u.cross(v).norm(), u.dot(v));
}

/// True when the edge of dart d (between two patch triangles) is not locally
/// Delaunay: the angles opposite to it sum to more than pi.
bool should_flip(const CMap2& m, const AttributeArray<Vec3>& pos, Dart d)
{
	const Dart e = phi2(m, d);
	const Vec3 &a = origin(m, pos, d), &b = origin(m, pos, e);
	const Vec3& c = origin(m, pos, phi_1(m, d));
	const Vec3& o = origin(m, pos, phi_1(m, e));
	if (angle_at(c, a, b) + angle_at(o, a, b) <= std::numbers::pi + 1e-10)
		return false;
	// the new edge (c, o) must lie inside the quad (a, o, b, c): both new
	// triangles face the way the old ones did (no fold, no sliver of zero area)
	const Vec3 before = (b - a).cross(c - a) + (a - b).cross(o - b);
	return (o - a).cross(c - a).dot(before) > 0.0 && (b - o).cross(c - o).dot(before) > 0.0;
}

bool is_inner_edge(const CMap2& m, const Patch& patch, Dart d)
{
	return patch.marker.is_marked(d) && patch.marker.is_marked(phi2(m, d));
}

bool relax_edge(CMap2& m, const AttributeArray<Vec3>& pos, const Patch& patch, Dart d)
{
	if (!is_inner_edge(m, patch, d) || !should_flip(m, pos, d) || !can_flip_edge(m, CMap2::Edge(d)))
		return false;
	flip_edge(m, CMap2::Edge(d));
	return true;
}

void relax_all(CMap2& m, const AttributeArray<Vec3>& pos, const Patch& patch)
{
	for (uint32 pass = 0; pass < MAX_RELAXATION_PASSES; ++pass)
	{
		bool flipped = false;
		for (Dart d : patch.darts)
			if (d.index < phi2(m, d).index)
				flipped |= relax_edge(m, pos, patch, d);
		if (!flipped)
			return;
	}
}

} // namespace

void Patch::add_face(const CMap2& m, Dart d)
{
	foreach_dart_of_orbit(m, CMap2::Face(d), [&](Dart x) {
		if (!marker.is_marked(x))
		{
			marker.mark(x);
			darts.push_back(x);
		}
	});
}

void Patch::collect(const CMap2& m, const std::vector<Dart>& loop)
{
	DartMarkerStore<CMap2> on_loop(m);
	for (Dart d : loop)
		on_loop.mark(d);
	add_face(m, loop[0]);
	for (std::size_t q = 0; q < darts.size(); ++q)
	{
		const Dart y = darts[q];
		if (!on_loop.is_marked(y) && !marker.is_marked(phi2(m, y)))
			add_face(m, phi2(m, y));
	}
}

std::vector<Dart> Patch::faces(const CMap2& m) const
{
	DartMarkerStore<CMap2> seen(m);
	std::vector<Dart> result;
	for (Dart d : darts)
		if (!seen.is_marked(d))
		{
			seen.mark_orbit(CMap2::Face(d));
			result.push_back(d);
		}
	return result;
}

std::vector<CMap2::Vertex> Patch::new_vertices(const CMap2& m) const
{
	std::unordered_set<uint32> pending(new_vertex_lines.begin(), new_vertex_lines.end());
	std::vector<CMap2::Vertex> result;
	for (Dart d : darts)
		if (pending.erase(index_of(m, CMap2::Vertex(d))) > 0)
			result.emplace_back(d);
	return result;
}

bool refine_patch(CMap2& m, AttributeArray<Vec3>& pos, Patch& patch, double density, ProgressReporter& reporter,
				  double from, double to)
{
	for (uint32 pass = 0; pass < MAX_REFINEMENT_PASSES; ++pass)
	{
		if (!reporter.report(from + (to - from) * (1.0 - std::pow(0.5, pass))))
			return false;
		bool split = false;
		for (Dart f : patch.faces(m))
		{
			const Dart corners[3] = {f, phi1(m, f), phi_1(m, f)};
			Vec3 center = Vec3::Zero();
			double target = 0.0;
			for (Dart c : corners)
			{
				center += origin(m, pos, c);
				target += patch.target_length.at(index_of(m, CMap2::Vertex(c)));
			}
			center /= 3.0;
			target /= 3.0;
			bool too_large = true;
			for (Dart c : corners)
			{
				const double l = density * (center - origin(m, pos, c)).norm();
				too_large = too_large && l > target && l > patch.target_length.at(index_of(m, CMap2::Vertex(c)));
			}
			if (!too_large)
				continue;
			const CMap2::Vertex v = triangulate_face(m, CMap2::Face(f));
			pos[index_of(m, v)] = center;
			patch.target_length[index_of(m, v)] = target;
			patch.new_vertex_lines.push_back(index_of(m, v));
			foreach_dart_of_orbit(m, v, [&](Dart d) { patch.add_face(m, d); });
			for (Dart c : corners)
				relax_edge(m, pos, patch, c);
			split = true;
		}
		if (!split)
			break;
		relax_all(m, pos, patch);
	}
	return true;
}

} // namespace cgogn::modeling::detail
