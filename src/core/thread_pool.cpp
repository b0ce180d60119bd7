// SPDX-License-Identifier: MIT
// Two back-ends share the interface of thread_pool.h: oneTBB (the default),
// and plain std::thread fork-join, used by the tsan preset only: Debian's
// libtbb is not instrumented, so ThreadSanitizer cannot see the
// synchronisation inside TBB's scheduler and reports TBB's own partitioner
// objects as races. The std back-end performs the same chunked split, so TSan
// checks what matters here: the sharing done by cgogn's code and callables.
#include <cgogn/core/parallel/thread_pool.h>

#ifdef CGOGN_STD_THREADS_BACKEND
#include <atomic>
#include <thread>
#include <vector>
#else
#include <tbb/blocked_range.h>
#include <tbb/global_control.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>

namespace cgogn
{

namespace
{
thread_local bool tl_in_parallel = false;
thread_local uint32 tl_index = 0;

// Marks the calling thread as running chunks with the given index; restores
// the previous state (nested regions run sequentially inside a chunk).
class RegionGuard
{
public:
	explicit RegionGuard(uint32 index) : was_in_(tl_in_parallel), old_index_(tl_index)
	{
		tl_in_parallel = true;
		tl_index = index;
	}
	~RegionGuard()
	{
		tl_in_parallel = was_in_;
		tl_index = old_index_;
	}
	RegionGuard(const RegionGuard&) = delete;
	RegionGuard& operator=(const RegionGuard&) = delete;

private:
	bool was_in_;
	uint32 old_index_;
};
} // namespace

#ifdef CGOGN_STD_THREADS_BACKEND

struct ThreadPool::Impl
{
};

uint32 ThreadPool::default_nb_workers()
{
	return std::max(1u, std::thread::hardware_concurrency());
}

void ThreadPool::set_nb_workers(uint32 n)
{
	nb_workers_ = n == 0 ? default_nb_workers() : n;
}

void detail::parallel_for_chunks(uint32 n, uint32 grain, ChunkBody body)
{
	grain = std::max(grain, 1u);
	const uint32 nb_chunks = uint32((uint64(n) + grain - 1) / grain);
	const uint32 nb_threads = std::min(thread_pool()->nb_workers(), nb_chunks);
	std::atomic<uint32> next{0};
	auto work = [&](uint32 index) {
		RegionGuard guard(index);
		for (uint32 c = next.fetch_add(1); c < nb_chunks; c = next.fetch_add(1))
			body(c * grain, uint32(std::min<uint64>(uint64(c) * grain + grain, n)));
	};
	std::vector<std::thread> threads;
	threads.reserve(nb_threads);
	for (uint32 t = 1; t < nb_threads; ++t)
		threads.emplace_back(work, t);
	work(0);
	for (auto& t : threads)
		t.join();
}

#else

struct ThreadPool::Impl
{
	// raises TBB's global worker limit when more workers than cores are asked
	std::unique_ptr<tbb::global_control> control;
	std::unique_ptr<tbb::task_arena> arena;
};

uint32 ThreadPool::default_nb_workers()
{
	return uint32(std::max(1, tbb::info::default_concurrency()));
}

void ThreadPool::set_nb_workers(uint32 n)
{
	n = n == 0 ? default_nb_workers() : n;
	impl_->arena.reset();
	impl_->control.reset();
	if (n > default_nb_workers())
		impl_->control = std::make_unique<tbb::global_control>(tbb::global_control::max_allowed_parallelism, n);
	impl_->arena = std::make_unique<tbb::task_arena>(int(n));
	nb_workers_ = n;
}

struct ThreadPoolAccess
{
	static tbb::task_arena& arena(ThreadPool& p)
	{
		return *p.impl_->arena;
	}
};

void detail::parallel_for_chunks(uint32 n, uint32 grain, ChunkBody body)
{
	tbb::task_arena& arena = ThreadPoolAccess::arena(*thread_pool());
	arena.execute([&] {
		tbb::parallel_for(tbb::blocked_range<uint32>(0, n, std::max(grain, 1u)),
						  [&](const tbb::blocked_range<uint32>& r) {
							  // the arena slot: dense in [0, arena concurrency)
							  RegionGuard guard{uint32(tbb::this_task_arena::current_thread_index())};
							  body(r.begin(), r.end());
						  });
	});
}

#endif

ThreadPool::ThreadPool() : impl_(std::make_unique<Impl>())
{
	set_nb_workers(0);
}

ThreadPool::~ThreadPool() = default;

ThreadPool* thread_pool()
{
	static ThreadPool pool;
	return &pool;
}

uint32 current_thread_index()
{
	return tl_in_parallel ? tl_index : 0;
}

bool detail::in_parallel_region()
{
	return tl_in_parallel;
}

} // namespace cgogn
