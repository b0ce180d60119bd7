// SPDX-License-Identifier: MIT
// The peers' side of bench_modeling (OpenMesh, CGAL), each in its own
// translation unit: a triangle soup in, a triangle soup out, the thread CPU
// time of the operation alone (building and extracting the mesh excluded).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace cgogn_bench
{

struct TriangleSoup
{
	std::vector<std::array<double, 3>> points;
	std::vector<std::array<uint32_t, 3>> triangles;
};

/// Thread CPU time in seconds.
double modeling_thread_seconds();

/// OpenMesh Decimater with ModQuadricT (priority) and ModNormalFlippingT
/// (rejects fold-overs, as cgogn does) down to target_faces.
double openmesh_decimate(const TriangleSoup& in, uint32_t target_faces, TriangleSoup& out);

/// CGAL Surface_mesh_simplification::edge_collapse on a Surface_mesh with the
/// GarlandHeckbert_plane_policies (cost and placement), stopped at the edge
/// count of target_faces (3/2 per face on a closed mesh).
double cgal_decimate(const TriangleSoup& in, uint32_t target_faces, TriangleSoup& out);

/// CGAL Polygon_mesh_processing::isotropic_remeshing, target length L.
double cgal_remesh(const TriangleSoup& in, double length, uint32_t iterations, TriangleSoup& out);

} // namespace cgogn_bench
