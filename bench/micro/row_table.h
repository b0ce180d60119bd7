// SPDX-License-Identifier: MIT
// The table the side-by-side micro-benchmarks (bench_gmap, bench_nmap) print
// after their run: one row per workload, one column per model ("workload<model>"
// benchmarks), the fastest repetition's CPU time, then the ratios of one model
// against the others; rows whose check values differ are reported.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace cgogn::bench
{

class RowTable
{
public:
	/// `subject`: the model whose ratios to the others are printed; `memory_counter`:
	/// the counter of a memory row (e.g. "bytes_per_face"), printed under the
	/// workload that sets it.
	RowTable(std::string subject, std::string memory_counter)
		: subject_(std::move(subject)), memory_counter_(std::move(memory_counter))
	{
	}

	/// Registers the benchmark "workload<model>"; `iterations` > 0 fixes its
	/// iteration count (builds), else it runs for a second.
	void add(const std::string& workload, const std::string& model, std::function<void(benchmark::State&)> fn,
			 int iterations = 0)
	{
		auto* b =
			benchmark::RegisterBenchmark((workload + "<" + model + ">").c_str(), fn)->Unit(benchmark::kMillisecond);
		if (iterations > 0)
			b->Iterations(iterations);
		else
			b->MinTime(1.0);
		if (std::find(workloads_.begin(), workloads_.end(), workload) == workloads_.end())
			workloads_.push_back(workload);
		if (std::find(models_.begin(), models_.end(), model) == models_.end())
			models_.push_back(model);
	}

	/// Runs the benchmarks selected by the command line, then prints the
	/// table. Returns the process's exit code: 1 for a bad argument or when
	/// the rows of a workload disagree on their check value.
	int run(int argc, char** argv)
	{
		benchmark::Initialize(&argc, argv);
		if (benchmark::ReportUnrecognizedArguments(argc, argv))
			return 1;
		Collector collector(benchmark::CreateDefaultDisplayReporter(), *this);
		benchmark::RunSpecifiedBenchmarks(&collector);
		benchmark::Shutdown();
		return print() ? 0 : 1;
	}

private:
	struct Result
	{
		double ms = 0;
		double memory = 0;
		double check = 0;
	};

	class Collector : public benchmark::BenchmarkReporter
	{
	public:
		Collector(benchmark::BenchmarkReporter* display, RowTable& table) : display_(display), table_(table)
		{
		}
		bool ReportContext(const Context& context) override
		{
			return display_->ReportContext(context);
		}
		void ReportRuns(const std::vector<Run>& runs) override
		{
			display_->ReportRuns(runs);
			for (const Run& r : runs)
			{
				if (r.run_type != Run::RT_Iteration || r.error_occurred)
					continue;
				const std::string& name = r.run_name.function_name;
				const std::size_t open = name.find('<');
				if (open == std::string::npos || name.back() != '>')
					continue;
				auto& row = table_.results_[name.substr(0, open)];
				const std::string model = name.substr(open + 1, name.size() - open - 2);
				const bool first = row.find(model) == row.end();
				Result& res = row[model];
				const double ms = r.GetAdjustedCPUTime(); // in the row's unit, ms
				res.ms = first ? ms : std::min(res.ms, ms);
				const auto get = [&](const std::string& key) {
					const auto it = r.counters.find(key);
					return it == r.counters.end() ? 0.0 : double(it->second);
				};
				res.memory = get(table_.memory_counter_);
				res.check = get("check");
			}
		}
		void Finalize() override
		{
			display_->Finalize();
		}

	private:
		benchmark::BenchmarkReporter* display_;
		RowTable& table_;
	};

	bool print() const
	{
		bool same = true;
		std::printf("\n| workload |");
		for (const std::string& model : models_)
			std::printf(" %s |", model.c_str());
		for (const std::string& model : models_)
			if (model != subject_)
				std::printf(" %s / %s |", subject_.c_str(), model.c_str());
		std::printf("\n|---|");
		for (std::size_t i = 0; i + 1 < 2 * models_.size(); ++i)
			std::printf("---:|");
		std::printf("\n");
		const auto row = [&](const std::string& label, const std::map<std::string, Result>& r, const char* unit,
							 double (*get)(const Result&)) {
			std::printf("| %s |", label.c_str());
			for (const std::string& model : models_)
			{
				const auto it = r.find(model);
				if (it == r.end())
					std::printf(" - |");
				else
					std::printf(" %.1f %s |", get(it->second), unit);
			}
			const auto s = r.find(subject_);
			for (const std::string& model : models_)
			{
				if (model == subject_)
					continue;
				const auto it = r.find(model);
				if (s == r.end() || it == r.end() || get(it->second) == 0)
					std::printf(" - |");
				else
					std::printf(" %.2f |", get(s->second) / get(it->second));
			}
			std::printf("\n");
		};
		for (const std::string& w : workloads_)
		{
			const auto r = results_.find(w);
			if (r == results_.end())
				continue;
			if (r->second.begin()->second.ms > 0)
				row(w, r->second, "ms", [](const Result& x) { return x.ms; });
			if (r->second.begin()->second.memory > 0)
				row("memory, " + memory_counter_, r->second, "B", [](const Result& x) { return x.memory; });
			for (const auto& [model, res] : r->second)
				if (res.check != r->second.begin()->second.check)
				{
					std::printf("check of %s<%s>: %.0f, of %s<%s>: %.0f\n", w.c_str(), model.c_str(), res.check,
								w.c_str(), r->second.begin()->first.c_str(), r->second.begin()->second.check);
					same = false;
				}
		}
		return same;
	}

	std::string subject_, memory_counter_;
	std::vector<std::string> workloads_, models_;
	std::map<std::string, std::map<std::string, Result>> results_;
};

} // namespace cgogn::bench
