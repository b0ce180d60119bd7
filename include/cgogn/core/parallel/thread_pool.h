// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <memory>

namespace cgogn
{

/// The library's only global state: the set of threads that run parallel
/// traversals (a oneTBB task arena). By default it has as many workers as the
/// hardware (and the process' affinity mask) allows. Not to be resized while
/// a parallel traversal runs.
class ThreadPool
{
public:
	/// A pool with the default number of workers (thread_pool() makes the
	/// process' one; other pools are not used by the library).
	ThreadPool();
	~ThreadPool();
	ThreadPool(const ThreadPool&) = delete;
	ThreadPool& operator=(const ThreadPool&) = delete;

	/// Number of threads that may run a parallel traversal at once (the
	/// calling thread included): per-thread arrays are sized with it. O(1).
	uint32 nb_workers() const
	{
		return nb_workers_;
	}

	/// Limits (or raises) the number of workers; 0 restores the default. With
	/// one worker, parallel traversals run sequentially on the calling thread.
	/// More workers than cores is allowed (useful in tests). Precondition: no
	/// parallel traversal is running. O(1) plus the arena's creation.
	void set_nb_workers(uint32 n);

	/// The default number of workers (hardware concurrency). O(1).
	static uint32 default_nb_workers();

private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
	uint32 nb_workers_ = 1;

	friend struct ThreadPoolAccess;
};

/// The process-wide pool used by parallel_foreach_cell. Thread-safe to call.
ThreadPool* thread_pool();

/// Shorthand for thread_pool()->set_nb_workers(n).
inline void set_nb_workers(uint32 n)
{
	thread_pool()->set_nb_workers(n);
}

/// Index of the calling thread in [0, thread_pool()->nb_workers()) while it
/// runs a callable of a parallel traversal: two callables running at the same
/// time never get the same index, so per-thread accumulators can be indexed by
/// it. 0 on a thread that runs no parallel traversal (and in a sequential
/// one). No registration needed. O(1).
uint32 current_thread_index();

namespace detail
{

/// A non-owning reference to a callable `void(uint32 begin, uint32 end)`.
class ChunkBody
{
public:
	template <typename F>
	explicit ChunkBody(const F& f)
		: obj_(&f), call_([](const void* o, uint32 b, uint32 e) { (*static_cast<const F*>(o))(b, e); })
	{
	}
	void operator()(uint32 b, uint32 e) const
	{
		call_(obj_, b, e);
	}

private:
	const void* obj_;
	void (*call_)(const void*, uint32, uint32);
};

/// Calls body(b, e) on disjoint chunks [b, e) covering [0, n), at least
/// `grain` items each (but the last), on the pool's workers (the calling
/// thread takes part) and returns when all are done. Chunks never overlap, so
/// a body may write to the items of its chunk without synchronisation.
/// Precondition: not called from inside a parallel region (see
/// in_parallel_region). The split is dynamic (work stealing).
void parallel_for_chunks(uint32 n, uint32 grain, ChunkBody body);

/// True on a thread that is running a chunk of a parallel traversal: nested
/// parallel traversals then run sequentially (keeping thread indices dense).
bool in_parallel_region();

/// True when a parallel traversal should run sequentially on this thread: one
/// worker, or already inside a parallel region. O(1).
inline bool run_sequentially()
{
	return thread_pool()->nb_workers() <= 1 || in_parallel_region();
}

} // namespace detail

} // namespace cgogn
