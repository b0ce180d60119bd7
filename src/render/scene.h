// SPDX-License-Identifier: MIT
// What the rasterizer draws, taken out of a map once: triangles over a compact
// vertex numbering, normals, the scalar to colour by, edges and defects.
// Keeping the rasterizer on these flat arrays lets it serve CMap2 and CMap3
// alike and keeps the per-sample work free of map traversals.
#pragma once

#include <cgogn/render/render.h>

#include <cstdint>
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
};

/// Draws a scene (non-empty, finite positions) with the options. Throws
/// RenderError on bad options.
Image rasterize(const Scene& s, const RenderOptions& o);

} // namespace cgogn::render::detail
