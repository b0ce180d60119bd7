// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/modeling/hole_filling.h>
#include <cgogn/modeling/triangulation.h>

#include "hole_filling_steps.h"

#include <string>

namespace cgogn::modeling
{

namespace
{

using Vertex = CMap2::Vertex;

std::vector<Dart> boundary_loop(const CMap2& m, Dart d)
{
	std::vector<Dart> loop;
	foreach_dart_of_orbit(m, CMap2::Face(d), [&](Dart x) { loop.push_back(x); });
	return loop;
}

/// Mean length of the edges at v: the target edge length of the patch there.
double mean_incident_length(const CMap2& m, const AttributeArray<Vec3>& pos, Vertex v)
{
	const Vec3& p = pos[index_of(m, v)];
	double sum = 0.0;
	uint32 count = 0;
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		sum += (pos[index_of(m, Vertex(phi2(m, d)))] - p).norm();
		++count;
	});
	return count == 0 ? 0.0 : sum / double(count);
}

/// Fills the hole of boundary loop `loop`, reporting progress in [from, to].
void fill_loop(CMap2& m, AttributeArray<Vec3>& pos, const std::vector<Dart>& loop, const HoleFillingOptions& options,
			   ProgressReporter& reporter, double from, double to, HoleFillingResult& result)
{
	const uint32 n = uint32(loop.size());
	if (n < 3 || n > options.max_hole_size)
	{
		++result.holes_skipped;
		return;
	}
	const auto at = [&](double fraction) { return from + (to - from) * fraction; };
	const bool optimal = n <= options.max_optimal_size;
	detail::HoleTriangulation triangulation;
	if (optimal && !detail::optimal_hole_triangulation(m, pos, loop, reporter, at(0.0), at(0.6), triangulation))
	{
		result.cancelled = true;
		return;
	}
	detail::Patch patch(m);
	for (Dart d : loop)
		patch.target_length[index_of(m, Vertex(d))] = mean_incident_length(m, pos, Vertex(d));

	cgogn::fill_hole_with_face(m, loop[0]);
	if (optimal)
		detail::cut_hole(m, loop, triangulation);
	else
	{
		ear_clip_face(m, pos, CMap2::Face(loop[0]));
		++result.holes_ear_clipped;
	}
	++result.holes_filled;
	result.faces_added += n - 2;

	if (!options.refine)
		return;
	patch.collect(m, loop);
	const bool refined = detail::refine_patch(m, pos, patch, options.density, reporter, at(0.6), at(0.8));
	const uint32 nb_new = uint32(patch.new_vertex_lines.size());
	result.faces_added += 2 * nb_new;
	result.vertices_added += nb_new;
	if (!refined || !reporter.report(at(0.8)))
	{
		result.cancelled = true;
		return;
	}
	if (options.fair && nb_new > 0 &&
		!fair_vertices(m, pos, patch.new_vertices(m), options.fairing_weights, options.fairing_continuity))
		++result.fairing_failures;
}

} // namespace

HoleFillingResult fill_hole(CMap2& m, AttributeArray<Vec3>& pos, Dart d, const HoleFillingOptions& options,
							const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	if (!is_dart_valid(m, d) || !is_boundary(m, d))
		throw TopologyError("modeling::fill_hole: dart " + std::to_string(d.index) +
							" is not on a hole (boundary face)");
	HoleFillingResult result;
	result.holes_found = 1;
	ProgressReporter reporter(progress);
	fill_loop(m, pos, boundary_loop(m, d), options, reporter, 0.0, 1.0, result);
	if (!result.cancelled)
		reporter.report(1.0); // the work is done: a stop asked now changes nothing
	return result;
}

HoleFillingResult fill_holes(CMap2& m, AttributeArray<Vec3>& pos, const HoleFillingOptions& options,
							 const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	// the loops first: filling one hole does not touch the darts of the others
	std::vector<Dart> holes;
	{
		DartMarker<CMap2> seen(m);
		foreach_dart(m, [&](Dart d) {
			if (is_boundary(m, d) && !seen.is_marked(d))
			{
				seen.mark_orbit(CMap2::Face(d));
				holes.push_back(d);
			}
		});
	}
	HoleFillingResult result;
	result.holes_found = uint32(holes.size());
	ProgressReporter reporter(progress);
	const double nb = double(holes.size());
	for (std::size_t h = 0; h < holes.size() && !result.cancelled; ++h)
	{
		if (!reporter.report(double(h) / nb))
		{
			result.cancelled = true;
			break;
		}
		fill_loop(m, pos, boundary_loop(m, holes[h]), options, reporter, double(h) / nb, double(h + 1) / nb, result);
	}
	if (!result.cancelled)
		reporter.report(1.0);
	return result;
}

} // namespace cgogn::modeling
