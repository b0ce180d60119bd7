// SPDX-License-Identifier: MIT
// The side-by-side suites (workloads: bench/README.md): surface/<workload>/<library>,
// volume/<workload>/<library>, memory/<suite>/<library>. Libraries register
// their workloads from their own translation unit; peers not found at
// configure time are simply absent. Extra options: --input=data|generated|small,
// --permute=SEED (soups with randomly permuted vertex ids and face/cell order),
// --reorder (cgogn's maps reordered by Morton keys after building).
#include "inputs.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <vector>

int main(int argc, char** argv)
{
	std::vector<char*> args;
	try
	{
		args = cgogn_bench::take_input_options(argc, argv);
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "bench_suite: %s\n", e.what());
		return 2;
	}
	int n = int(args.size());
	benchmark::Initialize(&n, args.data());
	if (benchmark::ReportUnrecognizedArguments(n, args.data()))
		return 1;
	benchmark::AddCustomContext("compiler_flags", "-O3 -DNDEBUG (no -march=native)");
	benchmark::AddCustomContext("order", cgogn_bench::order_description());
	bool listing = false;
	for (int i = 0; i < n; ++i)
		listing = listing || std::strncmp(args[std::size_t(i)], "--benchmark_list_tests", 22) == 0;
	if (!listing) // describing the input loads it (the soups are shared by all benchmarks)
		benchmark::AddCustomContext("input", cgogn_bench::input_description());
	benchmark::RunSpecifiedBenchmarks();
	benchmark::Shutdown();
	return 0;
}
