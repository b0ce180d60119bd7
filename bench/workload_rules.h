// SPDX-License-Identifier: MIT
#pragma once

// Constants and selection rules shared by every library's implementation, so
// that all do exactly the same work (BENCHMARKS.md).

#include <cmath>
#include <cstdint>
#include <numbers>

namespace cgogn_bench
{

/// sqrt(3) subdivision weight of a vertex of valence n: (4 - 2 cos(2 pi / n)) / 9.
inline double sqrt3_alpha(uint32_t n)
{
	return (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / double(n))) / 9.0;
}

/// Dynamic editing: 50 batches; batch b splits the faces of rank r (in the
/// library's face iteration order) with r % 10 == b % 10, i.e. 10% of the
/// faces, then collapses the new vertices back.
inline constexpr uint32_t dynamic_batches = 50;
inline bool dynamic_selected(uint32_t face_rank, uint32_t batch)
{
	return face_rank % 10 == batch % 10;
}

/// Volume collapse: the number of shortest-interior-edge collapses.
inline constexpr uint32_t volume_collapses = 7;
/// Volume smoothing: the check is the coordinate sum after this many passes.
inline constexpr uint32_t volume_smoothing_check_passes = 7;

} // namespace cgogn_bench
