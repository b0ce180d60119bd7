// SPDX-License-Identifier: MIT
// A failure on one rank, raised on every rank: a rank that throws while the
// others go on to a collective call would leave them waiting forever.
#pragma once

#include <exception>
#include <mpi.h>
#include <string>

namespace cgogn::dist::detail
{

/// What one rank caught.
struct Failure
{
	enum class Kind : int
	{
		None,
		Argument, ///< a PartitionError
		File,     ///< an io::Error: path and cause kept apart
		Other     ///< any other std::exception
	};
	Kind kind = Kind::None;
	std::string message; ///< what(), or the io::Error's cause
	std::string path;    ///< the io::Error's path
};

/// The failure of the exception e (Kind::Other for a non-standard one).
Failure failure_of(std::exception_ptr e);

/// Collective over comm: when a rank failed, every rank throws the failure
/// of the lowest failing rank, with its type (PartitionError, io::Error,
/// std::runtime_error). O(log ranks) when no rank failed.
void raise_if_any_failed(MPI_Comm comm, const Failure& mine);

/// True on every rank of comm when `local` is true on every rank: for a
/// check that every rank must pass before a collective call. One
/// MPI_Allreduce.
inline bool on_all_ranks(MPI_Comm comm, bool local)
{
	int in = local, out = 0;
	MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MIN, comm);
	return out != 0;
}

/// Runs f on this rank (f may do nothing on some ranks), then raises on
/// every rank what any rank's f threw. Collective over comm.
template <typename F>
void on_every_rank(MPI_Comm comm, const F& f)
{
	Failure mine;
	try
	{
		f();
	}
	catch (...)
	{
		mine = failure_of(std::current_exception());
	}
	raise_if_any_failed(comm, mine);
}

} // namespace cgogn::dist::detail
