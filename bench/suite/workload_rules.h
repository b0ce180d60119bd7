// SPDX-License-Identifier: MIT
#pragma once

// Constants and selection rules shared by every library's implementation, so
// that all do exactly the same work (bench/README.md).

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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

/// Volume collapse: the shortest edge of a scan. Ties (a regular grid has
/// many edges of one length) go to the smallest midpoint in lexicographic
/// order, so that every library picks the same edge whatever its edge order.
struct ShortestEdge
{
	double length = std::numeric_limits<double>::max();
	std::array<double, 3> midpoint{};

	/// Whether the edge from a to b, of length l, is shorter than the best so
	/// far; if so it becomes the best. P: any point type with operator[].
	template <typename P>
	bool offer(double l, const P& a, const P& b)
	{
		if (l > length)
			return false;
		const std::array<double, 3> m{(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0, (a[2] + b[2]) / 2.0};
		if (l == length && !(m < midpoint))
			return false;
		length = l;
		midpoint = m;
		return true;
	}
};
/// Volume smoothing: the check is the coordinate sum after this many passes.
inline constexpr uint32_t volume_smoothing_check_passes = 7;

} // namespace cgogn_bench
