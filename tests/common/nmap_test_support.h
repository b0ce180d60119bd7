// SPDX-License-Identifier: MIT
// What the tests of the maps of any dimension share: the binomial numbers
// of the closed-form cell counts, and cells named by their darts so that
// two traversals (or two maps with the same dart indices) can be compared.
#pragma once

#include <cgogn/core.h>

#include <algorithm>
#include <map>
#include <vector>

namespace cgogn::test
{

/// n choose k.
inline uint64 binomial(uint32 n, uint32 k)
{
	uint64 r = 1;
	for (uint32 i = 1; i <= k; ++i)
		r = r * (n - k + i) / i;
	return r;
}

/// A cell by the smallest index of its darts: the same in two maps whose
/// darts have the same indices.
template <typename MAP, typename CELL>
uint32 key_of(const MAP& m, CELL c)
{
	uint32 k = INVALID_INDEX;
	foreach_dart_of_orbit(m, c, [&](Dart d) { k = std::min(k, d.index); });
	return k;
}

/// The cells of type CELL, each with the sorted keys of what
/// `around(c, put)` reports for it (by calling put on each).
template <typename CELL, typename MAP, typename AROUND>
std::map<uint32, std::vector<uint32>> relation(const MAP& m, const AROUND& around)
{
	std::map<uint32, std::vector<uint32>> r;
	foreach_cell(m, [&](CELL c) {
		std::vector<uint32>& row = r[key_of(m, c)];
		around(c, [&](auto x) { row.push_back(key_of(m, x)); });
		std::sort(row.begin(), row.end());
	});
	return r;
}

} // namespace cgogn::test
