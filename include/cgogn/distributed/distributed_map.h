// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/cmap2.h>
#include <cgogn/core/map/cmap3.h>

#include <array>
#include <memory>
#include <mpi.h>
#include <string>
#include <type_traits>
#include <vector>

namespace cgogn::dist
{

/// How a halo plan moves its values between neighbouring ranks.
enum class Transport
{
	/// One MPI_Neighbor_alltoallv on the graph of the ranks that share cells.
	NeighborhoodCollective,
	/// MPI_Isend/MPI_Irecv to each neighbour, then MPI_Waitall: the same
	/// messages, for MPI libraries whose neighbourhood collectives fail.
	PointToPoint,
};

/// For the cells of one orbit of one rank: which owned lines each neighbour
/// holds as ghosts, and which ghost lines each neighbour owns. Both sides
/// list the cells in increasing global id, so they agree without a
/// handshake. Counts are per neighbour (DistributedMapBase::neighbours()).
struct HaloPlan
{
	std::vector<int> send_counts;    ///< Owned cells sent to each neighbour.
	std::vector<uint32> send_lines;  ///< Their lines, neighbour after neighbour.
	std::vector<int> recv_counts;    ///< Ghost cells received from each neighbour.
	std::vector<uint32> slot_starts; ///< Received value s goes to slot_lines[slot_starts[s], slot_starts[s + 1]).
	/// The local lines of each received cell: one, or several when the ghost
	/// layer's outer rim splits a cell into local copies (a vertex or an edge
	/// whose ghost volumes touch only there).
	std::vector<uint32> slot_lines;
};

/// The part of a distributed map that does not depend on the map type: the
/// communicators, this rank, and the halo plan of each orbit.
class DistributedMapBase
{
public:
	DistributedMapBase() = default;
	DistributedMapBase(const DistributedMapBase&) = delete;
	DistributedMapBase& operator=(const DistributedMapBase&) = delete;
	/// Takes other's communicators and plans; other is left empty.
	DistributedMapBase(DistributedMapBase&& other) noexcept;
	/// Frees this map's communicators, then takes other's.
	DistributedMapBase& operator=(DistributedMapBase&& other) noexcept;
	/// Frees the communicators: a distributed map must be destroyed before
	/// MPI_Finalize.
	~DistributedMapBase();

	/// The map's communicator (a duplicate of the one it was built on).
	MPI_Comm comm() const
	{
		return comm_;
	}
	/// This rank in comm().
	int rank() const
	{
		return rank_;
	}
	/// The number of ranks of comm().
	int nb_ranks() const
	{
		return nb_ranks_;
	}
	/// The ranks that share at least one cell with this one, increasing.
	const std::vector<int>& neighbours() const
	{
		return neighbours_;
	}
	/// The halo plan of the cells of dimension k (0 vertices ... the map's
	/// dimension).
	const HaloPlan& plan(uint32 k) const
	{
		return plans_[k];
	}

	/// Moves values of elem_size bytes: for each neighbour i, send_counts[i]
	/// values from send (neighbour after neighbour) and recv_counts[i] into
	/// recv. Collective over comm(). Internal to exchange and accumulate.
	void move_values(const std::vector<int>& send_counts, const void* send, const std::vector<int>& recv_counts,
					 void* recv, std::size_t elem_size, Transport transport) const;

protected:
	/// A cell of the local map, for build_plans.
	struct LocalCell
	{
		uint64 gid;  ///< Its global id.
		uint32 line; ///< Its line in its orbit's container.
		int32 owner; ///< Its owner rank.
	};
	/// Duplicates comm, builds the halo plans of the cells of dimension
	/// 0..D (cells[k]: the local cells of dimension k, reordered) and the
	/// graph communicator of the neighbouring ranks. Collective over comm.
	void build_plans(MPI_Comm comm, std::vector<std::vector<LocalCell>>& cells);

private:
	MPI_Comm comm_ = MPI_COMM_NULL;
	MPI_Comm graph_ = MPI_COMM_NULL;
	int rank_ = 0;
	int nb_ranks_ = 1;
	std::vector<int> neighbours_;
	std::vector<HaloPlan> plans_;
};

namespace detail
{
/// Calls f(CELL(), k) for the cell type CELL of each dimension k of MAP:
/// vertices, edges, faces (and volumes).
template <typename MAP, typename F>
void foreach_cell_type(const F& f)
{
	f(typename MAP::Vertex(), 0u);
	f(typename MAP::Edge(), 1u);
	f(typename MAP::Face(), 2u);
	if constexpr (MAP::dimension == 3)
		f(CMap3::Volume(), 3u);
}
} // namespace detail

/// A map split over the ranks of an MPI communicator: on each rank an
/// ordinary CMap3 (CMap2) holding the volumes (faces) the rank owns plus one
/// ghost layer, every volume that shares a vertex with an owned one. Every
/// cell of every dimension has a 64-bit global id and one owner rank that all
/// the ranks holding it agree on; a volume's owner is its part, a lower
/// cell's the smallest part among its volumes. So an owned cell's whole star
/// (the volumes around each of its vertices) is local, and any algorithm
/// that reads the star of the cells it writes runs on map() unchanged for
/// the owned cells. Made by distribute(). Boundary volumes have no global id.
template <typename MAP>
class DistributedMap : public DistributedMapBase
{
	static_assert(std::is_same_v<MAP, CMap2> || std::is_same_v<MAP, CMap3>,
				  "DistributedMap: MAP must be CMap2 or CMap3");

public:
	static constexpr uint32 dimension = MAP::dimension; ///< 3 for a CMap3, 2 for a CMap2.
	/// The top cells, partitioned: volumes of a CMap3, faces of a CMap2.
	using TopCell = std::conditional_t<dimension == 3, CMap3::Volume, CMap2::Face>;

	/// The cells' dimension (0 for vertices ... dimension for TopCell).
	template <typename CELL>
	static constexpr uint32 dimension_of()
	{
		if constexpr (std::is_same_v<CELL, typename MAP::Vertex>)
			return 0;
		else if constexpr (std::is_same_v<CELL, typename MAP::Edge>)
			return 1;
		else if constexpr (std::is_same_v<CELL, typename MAP::Face>)
			return 2;
		else
		{
			static_assert(dimension == 3 && std::is_same_v<CELL, CMap3::Volume>,
						  "DistributedMap: a vertex, an edge, a face or a volume of the map");
			return 3;
		}
	}

	/// An empty map on no communicator; distribute() makes the real ones.
	DistributedMap() : map_(std::make_unique<MAP>())
	{
	}

	/// This rank's map: owned cells and ghosts. Any algorithm runs on it;
	/// changing its relations invalidates the halo plans.
	MAP& map()
	{
		return *map_;
	}
	/// This rank's map, read-only.
	const MAP& map() const
	{
		return *map_;
	}

	/// The global ids of the cells of dimension k, by line (readable through
	/// global_id()).
	const AttributeArray<uint64>& global_ids(uint32 k) const
	{
		return *gids_[k];
	}
	/// The owner ranks of the cells of dimension k, by line.
	const AttributeArray<int32>& owners(uint32 k) const
	{
		return *owners_[k];
	}

	/// Internal to distribute(): the global id attributes of each dimension,
	/// for the builder to add and fill.
	std::array<std::shared_ptr<AttributeArray<uint64>>, dimension + 1>& gid_attributes()
	{
		return gids_;
	}
	/// Internal to distribute(): the owner attributes of each dimension.
	std::array<std::shared_ptr<AttributeArray<int32>>, dimension + 1>& owner_attributes()
	{
		return owners_;
	}
	/// Internal to distribute(): builds the halo plans from the filled ids.
	void finish(MPI_Comm comm);

	/// The attributes of the distributed map that distribute() did not bring
	/// to the ranks ("edge attribute 'crease'", ...), the same on every rank.
	const std::vector<std::string>& not_carried() const
	{
		return not_carried_;
	}
	/// Internal to distribute().
	void set_not_carried(std::vector<std::string> names)
	{
		not_carried_ = std::move(names);
	}

private:
	std::unique_ptr<MAP> map_;
	std::array<std::shared_ptr<AttributeArray<uint64>>, dimension + 1> gids_;
	std::array<std::shared_ptr<AttributeArray<int32>>, dimension + 1> owners_;
	std::vector<std::string> not_carried_;
};

using DistributedCMap2 = DistributedMap<CMap2>;
using DistributedCMap3 = DistributedMap<CMap3>;

/// The global id of cell c (a real cell: not a boundary volume). O(1).
template <typename MAP, typename CELL>
uint64 global_id(const DistributedMap<MAP>& dm, CELL c)
{
	return dm.global_ids(DistributedMap<MAP>::template dimension_of<CELL>())[index_of(dm.map(), c)];
}

/// The rank that owns cell c. O(1).
template <typename MAP, typename CELL>
int owner(const DistributedMap<MAP>& dm, CELL c)
{
	return dm.owners(DistributedMap<MAP>::template dimension_of<CELL>())[index_of(dm.map(), c)];
}

/// True when this rank owns cell c (false for a ghost). O(1).
template <typename MAP, typename CELL>
bool is_owned(const DistributedMap<MAP>& dm, CELL c)
{
	return owner(dm, c) == dm.rank();
}

} // namespace cgogn::dist
