// SPDX-License-Identifier: MIT
#include "reindex.h"

namespace cgogn::detail
{

namespace
{
thread_local std::uint64_t reindexed_darts = 0;
}

std::uint64_t reindexed_dart_count()
{
	return reindexed_darts;
}

void reset_reindexed_dart_count()
{
	reindexed_darts = 0;
}

void count_reindexed_darts(std::uint64_t n)
{
	reindexed_darts += n;
}

} // namespace cgogn::detail
