// SPDX-License-Identifier: MIT
#pragma once

// The measuring rules of the suite (bench/README.md) in one place: names
// `<suite>/<workload>/<library>`, one untimed warm-up for read-only
// workloads, R timed repetitions of one run each (manual timing, so that the
// untimed reset or rebuild of each repetition is excluded), check values as
// counters named "check*" (bench/suite/report.py compares them across libraries),
// one structure alive at a time, and the allocator and RSS probes.

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <utility>

namespace cgogn_bench
{

enum class Kind
{
	read_only, // warm-up then R repetitions
	topology,  // fresh copy each repetition (rebuild untimed), fewer repetitions
	single     // one run (memory, dynamic)
};

/// Registers a benchmark; fn(state, first) runs one repetition, `first` is true
/// on the first repetition (read-only workloads warm up then).
void register_bench(const std::string& name, Kind kind, std::function<void(benchmark::State&, bool)> fn);

/// CPU time of the calling thread, in seconds. The benchmarks report it
/// rather than wall time: the machine is shared, and descheduling would
/// otherwise be counted (wall time is kept in the counter "wall_ms").
double thread_seconds();
/// CPU time of all threads of the process, in seconds (for parallel work such
/// as the incidence caches' build, where the calling thread's time is a part).
double process_seconds();

/// Runs one repetition: reset() untimed, work() timed (thread CPU time, once
/// per benchmark iteration), warm-up first when asked.
template <typename Reset, typename Work>
void timed(benchmark::State& state, bool warm_up, Reset&& reset, Work&& work)
{
	if (warm_up)
	{
		reset();
		work();
	}
	double wall = 0;
	for (auto _ : state)
	{
		reset();
		const double c0 = thread_seconds();
		const auto t0 = std::chrono::steady_clock::now();
		work();
		const auto t1 = std::chrono::steady_clock::now();
		state.SetIterationTime(thread_seconds() - c0);
		wall += std::chrono::duration<double>(t1 - t0).count();
	}
	state.counters["wall_ms"] = wall * 1e3;
}

/// A check value (all libraries must report the same; compared by report.py).
inline void set_check(benchmark::State& state, const std::string& key, double v)
{
	state.counters[key] = benchmark::Counter(v);
}

/// Keeps one structure alive at a time (meshes of 1.6M faces for six
/// libraries would not fit comfortably): asking for another key destroys the
/// current structure first.
class Cache
{
public:
	template <typename T, typename MAKE>
	static T& get(const std::string& key, MAKE&& make)
	{
		if (key_ != key || !object_)
		{
			object_.reset();
			key_.clear();
			std::unique_ptr<T> p = make();
			object_ = std::shared_ptr<void>(p.release(), [](void* q) { delete static_cast<T*>(q); });
			key_ = key;
		}
		return *static_cast<T*>(object_.get());
	}
	static void clear()
	{
		object_.reset();
		key_.clear();
	}

private:
	static inline std::string key_;
	static inline std::shared_ptr<void> object_;
};

/// A structure built for one repetition of a topology workload (which
/// changes it): the cached structure is destroyed first, so that only one is
/// alive at a time.
template <typename T, typename... ARGS>
std::unique_ptr<T> fresh_structure(ARGS&&... args)
{
	Cache::clear();
	return std::make_unique<T>(std::forward<ARGS>(args)...);
}

/// Records batch b of the dynamic-editing workload: its time (ms), the
/// resident memory of the process and the bytes held by the allocator (MB).
void record_batch(benchmark::State& state, unsigned b, double seconds);

/// Bytes currently allocated by malloc (mallinfo2().uordblks + hblkhd) plus the
/// pages cgogn commits for its attributes (cgogn::committed_storage_bytes()).
std::size_t heap_bytes();
/// Resident set size of the process, in bytes (/proc/self/statm).
std::size_t resident_bytes();
/// Peak resident set size of the process, in bytes (getrusage).
std::size_t peak_resident_bytes();
/// Gives freed memory back to the system (malloc_trim) so RSS readings mean something.
void trim_heap();

} // namespace cgogn_bench
