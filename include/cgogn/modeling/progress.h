// SPDX-License-Identifier: MIT
// Progress reporting and cancellation of the long modeling algorithms.
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <functional>

namespace cgogn::modeling
{

/// Called by long algorithms with the fraction of the work done, in [0, 1].
/// Returning false asks the algorithm to stop: it stops at the next
/// consistent state (the map always passes check_integrity) and reports it
/// through its result's `cancelled` flag. An empty callback costs nothing.
using ProgressCallback = std::function<bool(double fraction)>;

/// Throttles a ProgressCallback: the callback is called when the fraction
/// grew by at least 1/256 since the last call (and at the end), so tight loops
/// can report every step without paying a std::function call per step.
class ProgressReporter
{
public:
	/// A reporter to callback (possibly empty), which must outlive it: it is
	/// held by reference.
	explicit ProgressReporter(const ProgressCallback& callback) : callback_(callback)
	{
	}

	/// Reports `done` out of `total`; returns false once the callback asked to stop.
	bool report(uint64 done, uint64 total)
	{
		return report(total == 0 ? 1.0 : double(done) / double(total));
	}

	/// Reports the fraction of a phase-structured algorithm directly.
	bool report(double fraction)
	{
		if (!callback_ || cancelled_)
			return !cancelled_;
		if (fraction < next_ && fraction < 1.0)
			return true;
		next_ = fraction + 1.0 / 256.0;
		cancelled_ = !callback_(fraction);
		return !cancelled_;
	}

	/// Whether the callback asked to stop (then every report returns false).
	bool cancelled() const
	{
		return cancelled_;
	}

private:
	const ProgressCallback& callback_;
	double next_ = 0.0;
	bool cancelled_ = false;
};

} // namespace cgogn::modeling
