// SPDX-License-Identifier: MIT
#include "harness.h"

#include <cgogn/core/attributes/line_storage.h>

#include <cstdio>
#include <cstdlib>
#include <malloc.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

namespace cgogn_bench
{

namespace
{
int env_int(const char* name, int fallback)
{
	const char* s = std::getenv(name);
	if (s == nullptr || *s == '\0')
		return fallback;
	const int v = std::atoi(s);
	return v > 0 ? v : fallback;
}
} // namespace

void register_bench(const std::string& name, Kind kind, std::function<void(benchmark::State&, bool)> fn)
{
	auto first = std::make_shared<bool>(true);
	auto* b = benchmark::RegisterBenchmark(name.c_str(), [fn, first](benchmark::State& state) {
		const bool f = *first;
		*first = false;
		fn(state, f);
	});
	b->UseManualTime()->Iterations(1)->Unit(benchmark::kMillisecond);
	// R repetitions (env CGOGN_BENCH_REPS, default 5; topology workloads
	// CGOGN_BENCH_TOPO_REPS, default 3): report.py takes the median and min.
	if (kind == Kind::read_only)
		b->Repetitions(env_int("CGOGN_BENCH_REPS", 5));
	else if (kind == Kind::topology)
		b->Repetitions(env_int("CGOGN_BENCH_TOPO_REPS", 3));
	else
		b->Repetitions(1);
}

void record_batch(benchmark::State& state, unsigned b, double seconds)
{
	char key[32];
	std::snprintf(key, sizeof key, "batch%02u_ms", b);
	state.counters[key] = seconds * 1e3;
	std::snprintf(key, sizeof key, "batch%02u_rss_MB", b);
	state.counters[key] = double(resident_bytes()) / 1e6;
	std::snprintf(key, sizeof key, "batch%02u_heap_MB", b);
	state.counters[key] = double(heap_bytes()) / 1e6;
}

double thread_seconds()
{
	timespec ts;
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

double process_seconds()
{
	timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

std::size_t heap_bytes()
{
	// cgogn's attributes live in pages it commits itself (LineStorage), which
	// the allocator does not count
	const struct mallinfo2 mi = mallinfo2();
	return mi.uordblks + mi.hblkhd + cgogn::committed_storage_bytes();
}

std::size_t resident_bytes()
{
	std::FILE* f = std::fopen("/proc/self/statm", "r");
	if (f == nullptr)
		return 0;
	unsigned long size = 0, resident = 0;
	const int n = std::fscanf(f, "%lu %lu", &size, &resident);
	std::fclose(f);
	return n == 2 ? resident * std::size_t(sysconf(_SC_PAGESIZE)) : 0;
}

std::size_t peak_resident_bytes()
{
	struct rusage ru;
	getrusage(RUSAGE_SELF, &ru);
	return std::size_t(ru.ru_maxrss) * 1024u;
}

void trim_heap()
{
	malloc_trim(0);
}

} // namespace cgogn_bench
