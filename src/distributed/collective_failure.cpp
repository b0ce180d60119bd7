// SPDX-License-Identifier: MIT
#include "collective_failure.h"

#include <cgogn/distributed/partition.h>
#include <cgogn/io/error.h>

#include <climits>

#include <stdexcept>

namespace cgogn::dist::detail
{

Failure failure_of(std::exception_ptr e)
{
	try
	{
		std::rethrow_exception(e);
	}
	catch (const PartitionError& x)
	{
		return {Failure::Kind::Argument, x.what(), {}};
	}
	catch (const io::Error& x)
	{
		return {Failure::Kind::File, x.cause(), x.path()};
	}
	catch (const std::exception& x)
	{
		return {Failure::Kind::Other, x.what(), {}};
	}
	catch (...)
	{
		return {Failure::Kind::Other, "an exception of unknown type", {}};
	}
}

namespace
{
void broadcast(MPI_Comm comm, int from, std::string& s)
{
	int length = int(s.size());
	MPI_Bcast(&length, 1, MPI_INT, from, comm);
	s.resize(std::size_t(length));
	MPI_Bcast(s.data(), length, MPI_CHAR, from, comm);
}
} // namespace

void raise_if_any_failed(MPI_Comm comm, const Failure& mine)
{
	int rank = 0;
	MPI_Comm_rank(comm, &rank);
	const int candidate = mine.kind == Failure::Kind::None ? INT_MAX : rank;
	int first = INT_MAX;
	MPI_Allreduce(&candidate, &first, 1, MPI_INT, MPI_MIN, comm);
	if (first == INT_MAX)
		return;
	Failure f = mine;
	int kind = int(f.kind);
	MPI_Bcast(&kind, 1, MPI_INT, first, comm);
	broadcast(comm, first, f.message);
	broadcast(comm, first, f.path);
	switch (Failure::Kind(kind))
	{
	case Failure::Kind::Argument:
		throw PartitionError(f.message);
	case Failure::Kind::File:
		throw io::Error(f.path, f.message);
	default:
		throw std::runtime_error(f.message);
	}
}

} // namespace cgogn::dist::detail
