// SPDX-License-Identifier: MIT
// The input of the subdivision benchmark, shared by its translation units:
// nefertiti.obj as loaded by cgogn::io, as a soup (each peer builds its own
// mesh from the same vertices and faces).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace cgogn::bench
{

struct SubdivisionInput
{
	std::vector<std::array<double, 3>> points;
	std::vector<std::vector<std::uint32_t>> faces;
};

/// Loaded once; empty (and the benchmarks skip) when the file is missing.
const SubdivisionInput& subdivision_input();

/// Registers the CGAL benchmarks (defined in their own translation unit).
void register_cgal_subdivision_benchmarks();

} // namespace cgogn::bench
