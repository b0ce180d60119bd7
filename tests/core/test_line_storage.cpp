#include <cgogn/core/attributes/line_storage.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace cgogn_test_line_storage
{

using namespace cgogn;

namespace
{

// 16 elements per block, so that small storages cross many blocks
using Small = LineStorage<uint32, 4>;

} // namespace

TEST(LineStorage, ElementsKeepTheirAddressAndValueWhileGrowing)
{
	for (uint64 contiguous : {uint64(1) << 20, uint64(64), uint64(0)})
	{
		Small s(contiguous);
		std::vector<const uint32*> addresses;
		for (uint32 n = 16; n <= 4096; n += 16)
		{
			s.resize(n, 7);
			for (uint32 i = n - 16; i < n; ++i)
			{
				ASSERT_EQ(s[i], 7u);
				s[i] = i;
				addresses.push_back(&s[i]);
			}
		}
		ASSERT_EQ(s.size(), 4096u);
		for (uint32 i = 0; i < 4096; ++i)
		{
			ASSERT_EQ(&s[i], addresses[i]) << "contiguous " << contiguous << " element " << i;
			ASSERT_EQ(s[i], i);
		}
	}
}

TEST(LineStorage, ViewsAndRunsReachEveryElement)
{
	// in the reserved range, in blocks, and across the border between them
	for (uint64 contiguous : {uint64(1) << 20, uint64(64), uint64(0)})
	{
		Small s(contiguous);
		s.resize(256, 0);
		for (uint32 i = 0; i < 256; ++i)
			s[i] = 3 * i + 1;
		const Small::View v = s.view();
		for (uint32 i = 0; i < 256; ++i)
			ASSERT_EQ(&v[i], &s[i]) << "contiguous " << contiguous << " element " << i;
		// a run holds consecutive addresses and ends where the next element is elsewhere
		for (uint32 i = 0; i < 256;)
		{
			const uint32 end = s.run_end(i);
			ASSERT_GT(end, i);
			ASSERT_LE(end, 256u);
			for (uint32 k = i; k < end; ++k)
				ASSERT_EQ(&s[k], &s[i] + (k - i));
			if (contiguous == 0 || i >= 64)
				EXPECT_EQ(end - i, Small::BLOCK_SIZE); // one block
			else
				EXPECT_EQ(end, contiguous == 64 ? 64u : 256u); // the reserved range
			i = end;
		}
	}
}

TEST(LineStorage, ShrinkingGivesMemoryBackAndGrowingAgainStartsFromTheValue)
{
	for (uint64 contiguous : {uint64(1) << 20, uint64(64), uint64(0)})
	{
		Small s(contiguous);
		s.resize(4096, 1);
		const std::size_t full = s.memory_bytes();
		EXPECT_GE(full, 4096 * sizeof(uint32));
		for (uint32 i = 0; i < 4096; ++i)
			s[i] = 2;
		s.resize(32, 0);
		EXPECT_LT(s.memory_bytes(), full);
		EXPECT_EQ(s[0], 2u); // kept elements keep their values
		EXPECT_EQ(s[31], 2u);
		s.resize(4096, 3);
		EXPECT_EQ(s[32], 3u); // recreated elements get the new value
		EXPECT_EQ(s[4095], 3u);
		EXPECT_EQ(s.memory_bytes(), full);
		s.resize(0, 0);
		EXPECT_EQ(s.memory_bytes(), 0u);
	}
}

// Elements that own memory are constructed and destroyed exactly once (the
// sanitizer run reports a leak or a double free otherwise).
TEST(LineStorage, OwningElementsAreConstructedAndDestroyed)
{
	for (uint64 contiguous : {uint64(1) << 20, uint64(32), uint64(0)})
	{
		LineStorage<std::string, 4> s(contiguous);
		const std::string long_value(100, 'x'); // beyond the small-string buffer
		s.resize(128, long_value);
		for (uint32 i = 0; i < 128; ++i)
			ASSERT_EQ(s[i], long_value);
		s[100] = std::string(200, 'y');
		s.resize(64, long_value);
		s.resize(256, std::string(150, 'z'));
		EXPECT_EQ(s[63], long_value);
		EXPECT_EQ(s[64], std::string(150, 'z'));
		EXPECT_EQ(s[100], std::string(150, 'z'));
	}
}

// The default range holds 2^28 small values or 2 GiB of larger ones.
TEST(LineStorage, DefaultRangeIsBoundedInBytesAndLines)
{
	EXPECT_EQ((LineStorage<uint32, 12>::default_contiguous()), uint64(1) << 28);
	EXPECT_EQ((LineStorage<double, 12>::default_contiguous()), uint64(1) << 28);
	struct Big
	{
		double v[8];
	};
	EXPECT_EQ((LineStorage<Big, 12>::default_contiguous()), (uint64(1) << 31) / sizeof(Big));
}

// The pages a storage commits are counted process-wide (the allocator does
// not see them) and given back when it shrinks or dies.
TEST(LineStorage, CommittedPagesAreCountedUntilGivenBack)
{
	const std::size_t before = committed_storage_bytes();
	{
		LineStorage<double, 12> s;
		s.resize(16 * 4096, 1.0);
		EXPECT_EQ(s.memory_bytes(), 16 * 4096 * sizeof(double));
		EXPECT_EQ(committed_storage_bytes(), before + s.memory_bytes());
		s.resize(4096, 1.0);
		EXPECT_EQ(committed_storage_bytes(), before + 4096 * sizeof(double));
	}
	EXPECT_EQ(committed_storage_bytes(), before);
}

TEST(LineStorage, ReservedRangesStartAtStaggeredOffsets)
{
	// storages walked together must not start at the same offset modulo a
	// large power of two (see reserve_address_space); each range is usable
	// over its whole length
	const std::size_t page = detail::page_size();
	const std::size_t bytes = 64 * page;
	std::vector<char*> ranges;
	for (int i = 0; i < 8; ++i)
	{
		char* p = static_cast<char*>(detail::reserve_address_space(bytes));
		ASSERT_NE(p, nullptr);
		ASSERT_EQ(reinterpret_cast<std::uintptr_t>(p) % page, 0u);
		detail::commit_pages(p, bytes);
		p[0] = 1;
		p[bytes - 1] = 2;
		EXPECT_EQ(p[0] + p[bytes - 1], 3);
		ranges.push_back(p);
	}
	const std::uintptr_t two_mib = 512 * page;
	std::set<std::uintptr_t> offsets;
	for (char* p : ranges)
		offsets.insert(reinterpret_cast<std::uintptr_t>(p) % two_mib);
	EXPECT_EQ(offsets.size(), ranges.size());
	for (char* p : ranges)
	{
		detail::decommit_pages(p, bytes);
		detail::release_address_space(p, bytes);
	}
}

} // namespace cgogn_test_line_storage
