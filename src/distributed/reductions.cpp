// SPDX-License-Identifier: MIT
#include <cgogn/distributed/reductions.h>

#include <vector>

namespace cgogn::dist
{

uint64 global_sum(MPI_Comm comm, uint64 local)
{
	uint64 total = 0;
	MPI_Allreduce(&local, &total, 1, MPI_UINT64_T, MPI_SUM, comm);
	return total;
}

double global_sum(MPI_Comm comm, double local)
{
	int nb_ranks = 1;
	MPI_Comm_size(comm, &nb_ranks);
	std::vector<double> parts(std::size_t(nb_ranks), 0.0);
	MPI_Allgather(&local, 1, MPI_DOUBLE, parts.data(), 1, MPI_DOUBLE, comm);
	double total = 0;
	for (double x : parts)
		total += x;
	return total;
}

BoundingBox global_union(MPI_Comm comm, const BoundingBox& local)
{
	BoundingBox box;
	MPI_Allreduce(local.min.data(), box.min.data(), 3, MPI_DOUBLE, MPI_MIN, comm);
	MPI_Allreduce(local.max.data(), box.max.data(), 3, MPI_DOUBLE, MPI_MAX, comm);
	return box;
}

} // namespace cgogn::dist
