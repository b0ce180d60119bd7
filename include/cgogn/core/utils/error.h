// SPDX-License-Identifier: MIT
#pragma once

#include <stdexcept>
#include <string>

namespace cgogn
{

/// Base of every exception the library throws for failures a user can cause
/// (bad files, impossible requests). Programming errors are asserted instead.
class Error : public std::runtime_error
{
public:
	using std::runtime_error::runtime_error;
};

/// A requested operation is not possible on the given cells (a `can_*`
/// predicate would have said no).
class TopologyError : public Error
{
public:
	using Error::Error;
};

} // namespace cgogn
