// SPDX-License-Identifier: MIT
// What the rasterizer draws, taken out of a map once: triangles over a compact
// vertex numbering, normals, the scalar to colour by, edges and defects.
// Keeping the rasterizer on these flat arrays lets it serve CMap2 and CMap3
// alike and keeps the per-sample work free of map traversals.
#pragma once

#include <cgogn/render/render.h>

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

namespace cgogn::render::detail
{

struct Scene
{
	std::vector<Vec3> points;                   ///< per rendered vertex
	std::vector<Eigen::Vector3f> vertex_normal; ///< unit or zero, per rendered vertex
	std::vector<uint32_t> triangles;            ///< 3 vertex numbers per triangle
	std::vector<uint32_t> triangle_face;        ///< the face each triangle comes from
	std::vector<Eigen::Vector3f> face_normal;   ///< unit or zero, per face

	enum class ScalarOn
	{
		None,
		Vertices,
		Faces
	};
	ScalarOn scalar_on = ScalarOn::None;
	std::vector<double> scalar; ///< per vertex or per face (non-finite: no value)

	std::vector<uint32_t> edges;          ///< 2 vertex numbers per edge, when asked
	std::vector<uint32_t> boundary_edges; ///< 2 vertex numbers per boundary edge, when asked
	std::vector<uint32_t> split_vertices; ///< vertex numbers, when asked

	/// Per triangle (a, b, c), when asked instead of the edge lists: which of
	/// its sides are polygon edges to draw, and which are boundary edges.
	std::vector<uint8_t> triangle_flags;
	static constexpr uint8_t EDGE_AB = 1, EDGE_BC = 2, EDGE_CA = 4;
	static constexpr uint8_t BOUNDARY_AB = 8, BOUNDARY_BC = 16, BOUNDARY_CA = 32;
};

/// Writes a file through body (returns an error text, empty on success) into
/// a temporary file next to path, renamed to path on success and removed
/// otherwise. Throws RenderError naming path.
void write_file(const std::string& path, const std::function<std::string(FILE*)>& body);

/// Draws a scene (non-empty, finite positions) with the options. Throws
/// RenderError on bad options.
Image rasterize(const Scene& s, const RenderOptions& o);

} // namespace cgogn::render::detail
