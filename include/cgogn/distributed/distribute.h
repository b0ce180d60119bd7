// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/distributed/distributed_map.h>
#include <cgogn/distributed/partition.h>

#include <string>

namespace cgogn::dist
{

/// The options of distribute().
struct DistributeOptions
{
	/// How the root partitions its map (METIS; see partition()). The part
	/// attribute is left on the root's map.
	PartitionOptions partition;
	/// Use the root map's uint32 top-cell attribute `partition.attribute` as
	/// it is (values in [0, number of ranks)) instead of calling METIS.
	bool use_existing_parts = false;
};

/// Splits the root's map over the ranks of comm: the root partitions its
/// volumes (faces of a CMap2) into one part per rank, and each rank gets a
/// DistributedMap of its part plus one vertex ghost layer, with global ids,
/// owners and halo plans. The vertex and top-cell attributes of the root's
/// map whose type is an arithmetic type or Vec2/3/4 come along, under their
/// names, on owned and ghost cells alike; the others (and the edge and
/// face attributes of a volume map) are listed by not_carried(). Global ids are the cells' ranks in
/// the root map's foreach_cell order (vertex k of that order has global id
/// k, and so on for each dimension). Collective over comm; `serial` is read
/// on the root only (other ranks may pass nullptr) and must be a manifold
/// map with at least as many volumes as ranks. Throws PartitionError (on
/// every rank) for bad partition arguments, std::runtime_error when a rank
/// cannot rebuild its part. Cost on the root O(size of the map), on each
/// rank O(size of its part).
DistributedCMap3 distribute(MPI_Comm comm, CMap3* serial, const DistributeOptions& options, int root = 0);

/// The same for the faces of a surface: each rank gets the faces it owns
/// plus every face that shares a vertex with one of them.
DistributedCMap2 distribute(MPI_Comm comm, CMap2* serial, const DistributeOptions& options, int root = 0);

/// distribute() with the default options, from rank 0. (Separate overloads
/// rather than default arguments: g++ 12 warns wrongly about the strings
/// of a defaulted options argument.)
DistributedCMap3 distribute(MPI_Comm comm, CMap3* serial);
DistributedCMap2 distribute(MPI_Comm comm, CMap2* serial);

} // namespace cgogn::dist
