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

void keep_live_lines_once(std::vector<uint32>& lines, const AttributeContainer& cells)
{
	std::sort(lines.begin(), lines.end());
	lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
	std::erase_if(lines, [&](uint32 l) { return !cells.is_live(l); });
}

void release_unclaimed_lines(AttributeContainer& cells, const std::vector<uint32>& olds,
							 const std::unordered_set<uint32>& claimed)
{
	for (uint32 l : olds)
		if (!claimed.count(l))
			cells.release_line(l);
}

} // namespace cgogn::detail
