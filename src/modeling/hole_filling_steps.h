// SPDX-License-Identifier: MIT
// The steps of modeling::fill_hole, one file each (internal).
#pragma once

#include <cgogn/core/marking/marker.h>
#include <cgogn/modeling/hole_filling.h>

#include <unordered_map>
#include <unordered_set>
#include <vector>

namespace cgogn::modeling::detail
{

/// The minimal-weight triangulation of a hole: for the sub-polygon of loop
/// corners i..j (i < j), split[i * n + j] is the apex k of its triangle on
/// the edge (i, j).
struct HoleTriangulation
{
	uint32 n = 0;
	std::vector<uint32> split;
	uint32 apex(uint32 i, uint32 j) const
	{
		return split[std::size_t(i) * n + j];
	}
};

/// Liepa's dynamic programming over the loop of boundary darts `loop` (the
/// origin of loop[i] is corner i). Returns false when the reporter cancelled
/// (nothing was changed). O(n^3).
bool optimal_hole_triangulation(const CMap2& m, const AttributeArray<Vec3>& pos, const std::vector<Dart>& loop,
								ProgressReporter& reporter, double from, double to, HoleTriangulation& out);

/// Cuts the polygon filling the hole of `loop` (already a real face) along the
/// triangulation t. O(n).
void cut_hole(CMap2& m, const std::vector<Dart>& loop, const HoleTriangulation& t);

/// The patch being refined: its darts (all darts of its faces, marked), and the
/// target edge length at its vertices (by vertex line).
struct Patch
{
	explicit Patch(const CMap2& m) : marker(m)
	{
	}
	DartMarker<CMap2> marker;
	std::vector<Dart> darts;
	std::unordered_map<uint32, double> target_length;
	/// Lines of the vertices inserted by the refinement (flips move darts
	/// from vertex to vertex, so the lines, not darts, identify them).
	std::vector<uint32> new_vertex_lines;

	/// Marks the darts of the faces inside the filled hole of `loop` (reached
	/// from loop[0] without crossing the loop). O(patch).
	void collect(const CMap2& m, const std::vector<Dart>& loop);
	/// Adds the darts of face d that are not in the patch yet. O(degree).
	void add_face(const CMap2& m, Dart d);
	/// One dart per face of the patch. O(patch).
	std::vector<Dart> faces(const CMap2& m) const;
	/// The inserted vertices, as they are now. O(patch).
	std::vector<CMap2::Vertex> new_vertices(const CMap2& m) const;
};

/// Liepa's refinement: centroid splits where the triangles are larger than the
/// target lengths, Delaunay flips in between. Returns false when cancelled
/// (the map is then consistent, refined partially).
bool refine_patch(CMap2& m, AttributeArray<Vec3>& pos, Patch& patch, double density, ProgressReporter& reporter,
				  double from, double to);

} // namespace cgogn::modeling::detail
