// SPDX-License-Identifier: MIT
#include <cgogn/distributed/reductions.h>

#include <limits>
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

BoundingBox global_bounding_box(const DistributedMapBase& dm, const AttributeArray<Vec3>& pos,
								const std::vector<uint32>& vertex_lines)
{
	constexpr double inf = std::numeric_limits<double>::infinity();
	double low[3] = {inf, inf, inf}, high[3] = {-inf, -inf, -inf};
	for (uint32 line : vertex_lines)
		for (int i = 0; i < 3; ++i)
		{
			low[i] = std::min(low[i], pos[line][i]);
			high[i] = std::max(high[i], pos[line][i]);
		}
	BoundingBox box;
	MPI_Allreduce(low, box.min.data(), 3, MPI_DOUBLE, MPI_MIN, dm.comm());
	MPI_Allreduce(high, box.max.data(), 3, MPI_DOUBLE, MPI_MAX, dm.comm());
	return box;
}

} // namespace cgogn::dist
