// SPDX-License-Identifier: MIT
// Helpers shared by the operator tests.
#pragma once

#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <vector>

namespace cgogn::test
{

/// Every cell of type CELL, in traversal order.
template <typename CELL, typename MAP>
std::vector<CELL> all(const MAP& m)
{
	std::vector<CELL> v;
	foreach_cell(m, [&](CELL c) { v.push_back(c); });
	return v;
}

/// The first cell of type CELL satisfying pred (invalid when none does).
template <typename CELL, typename MAP, typename P>
CELL find(const MAP& m, P pred)
{
	CELL r;
	foreach_cell(m, [&](CELL c) {
		if (!pred(c))
			return true;
		r = c;
		return false;
	});
	return r;
}

} // namespace cgogn::test

/// check_integrity(m) is clean, or the test fails with the report.
#define EXPECT_INTEGRITY(m)                                                                                          \
	do                                                                                                                 \
	{                                                                                                                  \
		const ::cgogn::IntegrityReport r_ = ::cgogn::check_integrity(m);                                              \
		EXPECT_TRUE(r_.ok()) << r_.to_string();                                                                        \
	} while (0)
