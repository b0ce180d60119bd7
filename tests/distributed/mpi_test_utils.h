// SPDX-License-Identifier: MIT
// What the tests under mpiexec share: this rank, the number of ranks, a
// check reduced over the ranks, and a gather of values on rank 0.
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <mpi.h>
#include <vector>

namespace cgogn_test_mpi
{

inline int world_rank()
{
	int r = 0;
	MPI_Comm_rank(MPI_COMM_WORLD, &r);
	return r;
}

inline int world_size()
{
	int p = 1;
	MPI_Comm_size(MPI_COMM_WORLD, &p);
	return p;
}

/// True on every rank when local is true on every rank.
inline bool everywhere(bool local)
{
	int in = local, out = 0;
	MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
	return out != 0;
}

/// The values of every rank, concatenated in rank order, on rank 0 (empty
/// elsewhere).
template <typename T>
std::vector<T> gather_on_root(const std::vector<T>& local)
{
	const int P = world_size();
	int n = int(local.size() * sizeof(T));
	std::vector<int> counts(static_cast<std::size_t>(P)), offsets(static_cast<std::size_t>(P), 0);
	MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
	for (std::size_t r = 1; r < counts.size(); ++r)
		offsets[r] = offsets[r - 1] + counts[r - 1];
	std::vector<T> all(world_rank() == 0 ? std::size_t(offsets.back() + counts.back()) / sizeof(T) : 0);
	MPI_Gatherv(local.data(), n, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
	return all;
}

} // namespace cgogn_test_mpi
