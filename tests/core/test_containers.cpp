#include <cgogn/core/attributes/attribute_container.h>

#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <iterator>
#include <set>
#include <stdexcept>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

namespace cgogn_test_containers
{

using namespace cgogn;

// The container tests that walk many lines run with the attributes' values in
// their reserved range (the default), with one chunk there and the rest in
// blocks, and with blocks only (LineStorage).
class AttributeContainerLayout : public ::testing::TestWithParam<uint64>
{
};
INSTANTIATE_TEST_SUITE_P(ReservedRangeAndBlocks, AttributeContainerLayout,
						 ::testing::Values(~uint64(0), uint64(CHUNK_SIZE), uint64(0)));

TEST_P(AttributeContainerLayout, GrowsAcrossChunksWithoutMovingElements)
{
	AttributeContainer c("key", GetParam());
	auto a = c.add_attribute<int>("a");
	const uint32 n = 3 * CHUNK_SIZE + 5;
	c.new_line(0);
	(*a)[0] = 42;
	const int* first = &(*a)[0];
	for (uint32 i = 1; i < n; ++i)
		(*a)[c.new_line(0)] = int(i);
	EXPECT_EQ(c.nb_lines(), n);
	EXPECT_EQ(&(*a)[0], first); // values never move
	EXPECT_EQ((*a)[0], 42);
	for (uint32 i = 1; i < n; ++i)
		ASSERT_EQ((*a)[i], int(i));
	EXPECT_EQ(a->memory_bytes(), 4 * CHUNK_SIZE * sizeof(int));
	// shrinking gives the memory back; growing again starts from defaults
	c.clear();
	EXPECT_EQ(a->memory_bytes(), 0u);
	c.new_line(0);
	EXPECT_EQ((*a)[0], 0);
}

TEST(AttributeContainer, RemovedLinesAreSkippedAndReusedFirstWithDefaultValues)
{
	AttributeContainer c("key");
	auto a = c.add_attribute<double>("a", 1.5);
	for (uint32 i = 0; i < 10; ++i)
		(*a)[c.new_line(i)] = double(i);
	c.release_line(3);
	c.release_line(7);
	EXPECT_EQ(c.nb_lines(), 8u);
	EXPECT_FALSE(c.is_live(3));
	double sum = 0;
	uint32 count = 0;
	for (double v : *a)
	{
		sum += v;
		++count;
	}
	EXPECT_EQ(count, 8u);
	EXPECT_DOUBLE_EQ(sum, 45.0 - 3.0 - 7.0);
	// last released first, reset to the default value
	EXPECT_EQ(c.new_line(0), 7u);
	EXPECT_DOUBLE_EQ((*a)[7], 1.5);
	EXPECT_EQ(c.new_line(0), 3u);
	EXPECT_EQ(c.new_line(0), 10u);
	EXPECT_EQ(c.end_index(), 11u);
}

TEST_P(AttributeContainerLayout, RangeForVisitsLiveLinesAcrossChunksInLineOrder)
{
	AttributeContainer c("key", GetParam());
	auto a = c.add_attribute<uint32>("a");
	const uint32 n = 3 * CHUNK_SIZE + 17;
	for (uint32 i = 0; i < n; ++i)
		(*a)[c.new_line(0)] = i;
	auto visited = [&]() {
		std::vector<uint32> lines;
		const AttributeArray<uint32>& ca = *a;
		for (auto it = ca.begin(); it != ca.end(); ++it)
		{
			EXPECT_EQ(*it, it.index()); // the value is the line's own
			lines.push_back(it.index());
		}
		return lines;
	};
	// dense: every line, in order
	std::vector<uint32> lines = visited();
	ASSERT_EQ(lines.size(), n);
	for (uint32 i = 0; i < n; ++i)
		ASSERT_EQ(lines[i], i);
	// holes: the first line, both sides of a chunk border, a run, the last lines
	const std::set<uint32> released = {
		0, CHUNK_SIZE - 1, CHUNK_SIZE, 2 * CHUNK_SIZE + 3, 2 * CHUNK_SIZE + 4, 2 * CHUNK_SIZE + 5, n - 2, n - 1};
	for (uint32 i : released)
		c.release_line(i);
	lines = visited();
	ASSERT_EQ(lines.size(), n - released.size());
	std::vector<uint32> expected;
	for (uint32 i = 0; i < n; ++i)
		if (!released.contains(i))
			expected.push_back(i);
	EXPECT_EQ(lines, expected);
	// writing through the mutable range reaches the live lines only
	for (uint32& v : *a)
		v += 1;
	for (uint32 i = 0; i < n; ++i)
		ASSERT_TRUE(!c.is_live(i) || (*a)[i] == i + 1) << "line " << i;
	// every line free: nothing
	for (uint32 i = 0; i < n; ++i)
		if (c.is_live(i))
			c.release_line(i);
	EXPECT_EQ(a->begin(), a->end());
}

TEST_P(AttributeContainerLayout, RangeForStopsAtTheLastLineWhenItEndsAChunk)
{
	// the walk steps with a pointer through runs of consecutive values; when
	// the last line ends a chunk (and a block), end() must still be where it stops
	AttributeContainer c("key", GetParam());
	auto a = c.add_attribute<std::array<double, 3>>("a");
	EXPECT_EQ(a->begin(), a->end()); // no line yet
	const uint32 n = 2 * CHUNK_SIZE;
	for (uint32 i = 0; i < n; ++i)
		(*a)[c.new_line(0)] = {double(i), 1.0, 0.0};
	auto count_and_sum = [&]() {
		std::pair<uint32, double> r{0, 0.0};
		for (const auto& v : std::as_const(*a))
			++r.first, r.second += v[0] * v[1];
		return r;
	};
	EXPECT_EQ(count_and_sum(), std::make_pair(n, double(n) * double(n - 1) / 2));
	c.release_line(n - 1);
	c.release_line(CHUNK_SIZE);
	EXPECT_EQ(count_and_sum(), std::make_pair(n - 2, double(n) * double(n - 1) / 2 - (n - 1) - CHUNK_SIZE));
	EXPECT_EQ(std::next(a->begin(), n - 2), a->end());
}

TEST(AttributeContainer, AttributesByNameAndType)
{
	AttributeContainer c("key");
	auto a = c.add_attribute<float>("weight");
	ASSERT_NE(a, nullptr);
	EXPECT_EQ(c.add_attribute<float>("weight"), nullptr); // exists
	EXPECT_EQ(c.add_attribute<int>("weight"), nullptr);   // exists, other type
	EXPECT_EQ(c.get_attribute<float>("weight"), a);
	EXPECT_EQ(c.get_attribute<double>("weight"), nullptr); // other type
	EXPECT_EQ(c.get_attribute<float>("nothing"), nullptr);
	c.new_line(0);
	(*a)[0] = 2.0f;
	EXPECT_TRUE(c.remove_attribute(a.get()));
	EXPECT_EQ(c.get_attribute<float>("weight"), nullptr);
	EXPECT_EQ(a->container(), nullptr);
	EXPECT_FLOAT_EQ((*a)[0], 2.0f);  // the handle keeps its values
	EXPECT_EQ(a->begin(), a->end()); // but iterates over nothing
	EXPECT_FALSE(c.remove_attribute(a.get()));
	EXPECT_FALSE(c.remove_attribute(&c.key())); // the key stays
	// a new attribute starts with the container's lines at their default
	auto b = c.add_attribute<int>("b", 7);
	EXPECT_EQ((*b)[0], 7);
}

TEST(AttributeContainer, IdleMarksAreCountedAndCanBeFreed)
{
	AttributeContainer c("key");
	for (uint32 i = 0; i < 2 * CHUNK_SIZE; ++i)
		c.new_line(i);
	const std::size_t bare = c.memory_bytes();
	MarkAttribute* a = c.acquire_mark();
	MarkAttribute* b = c.acquire_mark();
	const std::size_t one_mark = a->memory_bytes();
	EXPECT_GT(one_mark, 0u);
	EXPECT_EQ(c.memory_bytes(), bare + 2 * one_mark);
	a->set(5);
	a->reset(5);
	c.release_mark(a);
	// released but kept for reuse: still held, still counted
	EXPECT_EQ(c.memory_bytes(), bare + 2 * one_mark);
	c.release_idle_marks();
	// the idle one is freed, the held one stays usable
	EXPECT_EQ(c.memory_bytes(), bare + one_mark);
	b->set(7);
	EXPECT_TRUE(b->test(7));
	b->reset(7);
	c.release_mark(b);
	c.release_idle_marks();
	EXPECT_EQ(c.memory_bytes(), bare);
	// acquiring again allocates a cleared mark
	MarkAttribute* again = c.acquire_mark();
	EXPECT_EQ(c.memory_bytes(), bare + one_mark);
	for (uint32 i = 0; i < 2 * CHUNK_SIZE; ++i)
		ASSERT_FALSE(again->test(i));
	c.release_mark(again);
}

TEST(AttributeContainer, ManyMarksAtOnceAreIndependentAndComeBackCleared)
{
	AttributeContainer c("key");
	for (uint32 i = 0; i < 200; ++i)
		c.new_line(0);
	std::vector<MarkAttribute*> marks;
	for (uint32 k = 0; k < 100; ++k) // more than the 64 lock-free slots
		marks.push_back(c.acquire_mark());
	EXPECT_EQ(std::set<MarkAttribute*>(marks.begin(), marks.end()).size(), 100u);
	for (uint32 k = 0; k < 100; ++k)
		marks[k]->set(k);
	for (uint32 k = 0; k < 100; ++k)
		for (uint32 i = 0; i < 100; ++i)
			ASSERT_EQ(marks[k]->test(i), i == k);
	for (auto* m : marks)
	{
		m->clear_all();
		c.release_mark(m);
	}
	MarkAttribute* m = c.acquire_mark();
	EXPECT_TRUE(m->all_clear());
	c.release_mark(m);
}

TEST(AttributeContainer, ReservedMarkIsGivenBackAlsoWhenItsScopeThrows)
{
	AttributeContainer c("key");
	for (uint32 i = 0; i < 10; ++i)
		c.new_line(0);
	MarkAttribute* first = nullptr;
	{
		ReservedMark r(c);
		first = &*r;
		r->set(3);
		EXPECT_TRUE(first->test(3));
		r->reset(3);
	}
	// the lowest free slot comes back: the same mark, so it was given back
	MarkAttribute* m = c.acquire_mark();
	EXPECT_EQ(m, first);
	c.release_mark(m);
	EXPECT_THROW(
		{
			ReservedMark r(c);
			EXPECT_EQ(&*r, first);
			throw std::runtime_error("callable failed");
		},
		std::runtime_error);
	m = c.acquire_mark();
	EXPECT_EQ(m, first);
	MarkAttribute* other = c.acquire_mark();
	EXPECT_NE(other, first);
	c.release_mark(other);
	c.release_mark(m);
	static_assert(!std::is_copy_constructible_v<ReservedMark>);
}

TEST(AttributeContainer, MarkReservationIsThreadSafe)
{
	AttributeContainer c("key");
	for (uint32 i = 0; i < 100; ++i)
		c.new_line(0);
	std::atomic<int> clashes{0};
	std::vector<std::thread> threads;
	for (int t = 0; t < 8; ++t)
		threads.emplace_back([&, t] {
			for (int i = 0; i < 2000; ++i)
			{
				MarkAttribute* m = c.acquire_mark();
				// a mark held by one thread only: nobody else may see our bit
				if (m->test(uint32(t)))
					++clashes;
				m->set(uint32(t));
				if (m->test(uint32((t + 1) % 8)))
					++clashes;
				m->reset(uint32(t));
				c.release_mark(m);
			}
		});
	for (auto& th : threads)
		th.join();
	EXPECT_EQ(clashes.load(), 0);
}

} // namespace cgogn_test_containers
