// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/dart.h>

#include <memory>
#include <vector>

namespace cgogn::detail
{

/// A vector of darts borrowed from a per-thread pool, so that local
/// traversals that need a work list (3-D vertices, volumes) do not allocate
/// once the pool is warm. Nesting is fine: each scope borrows its own vector.
class DartBuffer
{
public:
	DartBuffer() : v_(acquire())
	{
	}
	~DartBuffer()
	{
		v_->clear();
		pool().push_back(std::move(v_));
	}
	DartBuffer(const DartBuffer&) = delete;
	DartBuffer& operator=(const DartBuffer&) = delete;

	std::vector<Dart>& operator*()
	{
		return *v_;
	}
	std::vector<Dart>* operator->()
	{
		return v_.get();
	}

private:
	static std::vector<std::unique_ptr<std::vector<Dart>>>& pool()
	{
		thread_local std::vector<std::unique_ptr<std::vector<Dart>>> p;
		return p;
	}
	static std::unique_ptr<std::vector<Dart>> acquire()
	{
		auto& p = pool();
		if (p.empty())
		{
			auto v = std::make_unique<std::vector<Dart>>();
			v->reserve(128);
			return v;
		}
		auto v = std::move(p.back());
		p.pop_back();
		return v;
	}

	std::unique_ptr<std::vector<Dart>> v_;
};

} // namespace cgogn::detail
