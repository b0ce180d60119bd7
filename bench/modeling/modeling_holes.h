// SPDX-License-Identifier: MIT
// The hole-filling and triangulation benchmark (bench_modeling_holes): each
// peer registers its benchmarks from its own translation unit.
#pragma once

#include "cgogn_test_data.h"

#include <string>

namespace cgogn::bench_holes
{

/// Meshes with holes, by benchmark name.
struct HoleMesh
{
	const char* name;
	const char* file; // under surface/ of the data folders
};
inline constexpr HoleMesh hole_meshes[] = {{"bunny", "stanford-bunny.obj"}, {"elephant", "elephant-with-holes.off"}};
inline constexpr const char* quad_mesh = "spot_quadrangulated.obj";

inline std::string data_file(const char* file)
{
	return cgogn_test_data::path(std::string("surface/") + file);
}

void register_cgal_benchmarks();
void register_openmesh_benchmarks();

} // namespace cgogn::bench_holes
