// SPDX-License-Identifier: MIT
#include <cgogn/distributed/distribute.h>

#include "collective_failure.h"
#include "rebuild_part.h"
#include "root_split.h"

#include <string>

namespace cgogn::dist
{

namespace
{

using detail::Top;

constexpr int MESSAGE_TAG = 8101;

template <typename MAP>
std::shared_ptr<CellAttribute<uint32, Top<MAP>::ORBIT>> root_parts(MAP& m, int nb_ranks,
																   const DistributeOptions& options)
{
	if (!options.use_existing_parts)
	{
		partition(m, uint32(nb_ranks), options.partition);
		return get_attribute<uint32, Top<MAP>>(m, options.partition.attribute);
	}
	auto parts = get_attribute<uint32, Top<MAP>>(m, options.partition.attribute);
	if (parts == nullptr)
		throw PartitionError("distribute: the map has no uint32 attribute '" + options.partition.attribute +
							 "' on its top cells");
	foreach_cell(m, [&](Top<MAP> t) {
		if ((*parts)[t] >= uint32(nb_ranks))
			throw PartitionError("distribute: part " + std::to_string((*parts)[t]) + " for " +
								 std::to_string(nb_ranks) + " ranks");
	});
	return parts;
}

// ------------------------------------------------------------ messages

void send_bytes(MPI_Comm comm, int to, const std::vector<std::byte>& bytes)
{
	const uint64 n = bytes.size();
	MPI_Send(&n, 1, MPI_UINT64_T, to, MESSAGE_TAG, comm);
	constexpr uint64 chunk = uint64(1) << 30;
	for (uint64 at = 0; at < n; at += chunk)
		MPI_Send(bytes.data() + at, int(std::min(chunk, n - at)), MPI_BYTE, to, MESSAGE_TAG, comm);
}

std::vector<std::byte> receive_bytes(MPI_Comm comm, int from)
{
	uint64 n = 0;
	MPI_Recv(&n, 1, MPI_UINT64_T, from, MESSAGE_TAG, comm, MPI_STATUS_IGNORE);
	std::vector<std::byte> bytes(n);
	constexpr uint64 chunk = uint64(1) << 30;
	for (uint64 at = 0; at < n; at += chunk)
		MPI_Recv(bytes.data() + at, int(std::min(chunk, n - at)), MPI_BYTE, from, MESSAGE_TAG, comm, MPI_STATUS_IGNORE);
	return bytes;
}

template <typename MAP>
DistributedMap<MAP> distribute_map(MPI_Comm comm, MAP* serial, const DistributeOptions& options, int root)
{
	int rank = 0, nb_ranks = 1;
	MPI_Comm_rank(comm, &rank);
	MPI_Comm_size(comm, &nb_ranks);
	std::shared_ptr<CellAttribute<uint32, Top<MAP>::ORBIT>> parts;
	detail::on_every_rank(comm, [&] {
		if (rank != root)
			return;
		if (serial == nullptr)
			throw PartitionError("distribute: the root has no map");
		parts = root_parts(*serial, nb_ranks, options);
	});
	detail::PartMessage own;
	if (rank == root)
	{
		const detail::RootSplit<MAP> split(*serial, *parts);
		const auto cells = split.cells_per_rank(nb_ranks);
		std::vector<uint32> local_vertex(split.count[0]);
		std::vector<uint64> stamp(split.count[0], detail::NO_GID);
		for (int r = 0; r < nb_ranks; ++r)
		{
			detail::PartMessage msg = split.message(cells[std::size_t(r)], local_vertex, stamp, uint64(r));
			if (r == root)
				own = std::move(msg);
			else
				send_bytes(comm, r, detail::serialize(msg));
		}
	}
	else
		own = detail::deserialize(receive_bytes(comm, root));
	DistributedMap<MAP> dm;
	detail::on_every_rank(comm, [&] { detail::build_part(dm, rank, own); });
	own = detail::PartMessage(); // the map holds it all now
	dm.finish(comm);
	return dm;
}

} // namespace

DistributedCMap3 distribute(MPI_Comm comm, CMap3* serial, const DistributeOptions& options, int root)
{
	return distribute_map(comm, serial, options, root);
}

DistributedCMap2 distribute(MPI_Comm comm, CMap2* serial, const DistributeOptions& options, int root)
{
	return distribute_map(comm, serial, options, root);
}

DistributedCMap3 distribute(MPI_Comm comm, CMap3* serial)
{
	return distribute_map(comm, serial, DistributeOptions(), 0);
}

DistributedCMap2 distribute(MPI_Comm comm, CMap2* serial)
{
	return distribute_map(comm, serial, DistributeOptions(), 0);
}

} // namespace cgogn::dist
