// SPDX-License-Identifier: MIT
#include <cgogn/core/traversals/global.h>
#include <cgogn/distributed/distributed_map.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace cgogn::dist
{

namespace
{

constexpr int HALO_TAG = 8102;

void free_comm(MPI_Comm& c)
{
	if (c == MPI_COMM_NULL)
		return;
	int finalized = 0;
	MPI_Finalized(&finalized);
	if (!finalized)
		MPI_Comm_free(&c);
	c = MPI_COMM_NULL;
}

// Byte counts and offsets of values of elem_size bytes.
void to_bytes(const std::vector<int>& counts, std::size_t elem_size, std::vector<int>& bytes, std::vector<int>& offsets)
{
	bytes.resize(counts.size());
	offsets.resize(counts.size());
	std::size_t at = 0;
	for (std::size_t i = 0; i < counts.size(); ++i)
	{
		const std::size_t n = std::size_t(counts[i]) * elem_size;
		if (at + n > std::size_t(std::numeric_limits<int>::max()))
			throw std::length_error("dist: a halo message over 2 GiB");
		bytes[i] = int(n);
		offsets[i] = int(at);
		at += n;
	}
}

} // namespace

DistributedMapBase::DistributedMapBase(DistributedMapBase&& other) noexcept
	: comm_(std::exchange(other.comm_, MPI_COMM_NULL)), graph_(std::exchange(other.graph_, MPI_COMM_NULL)),
	  rank_(other.rank_), nb_ranks_(other.nb_ranks_), neighbours_(std::move(other.neighbours_)),
	  plans_(std::move(other.plans_))
{
}

DistributedMapBase& DistributedMapBase::operator=(DistributedMapBase&& other) noexcept
{
	if (this != &other)
	{
		free_comm(graph_);
		free_comm(comm_);
		comm_ = std::exchange(other.comm_, MPI_COMM_NULL);
		graph_ = std::exchange(other.graph_, MPI_COMM_NULL);
		rank_ = other.rank_;
		nb_ranks_ = other.nb_ranks_;
		neighbours_ = std::move(other.neighbours_);
		plans_ = std::move(other.plans_);
	}
	return *this;
}

DistributedMapBase::~DistributedMapBase()
{
	free_comm(graph_);
	free_comm(comm_);
}

void DistributedMapBase::build_plans(MPI_Comm comm, std::vector<std::vector<LocalCell>>& cells)
{
	free_comm(graph_);
	free_comm(comm_);
	MPI_Comm_dup(comm, &comm_);
	MPI_Comm_rank(comm_, &rank_);
	MPI_Comm_size(comm_, &nb_ranks_);
	const std::size_t P = std::size_t(nb_ranks_);

	// per orbit, per rank: what this rank sends and receives (before the
	// neighbours are known)
	std::vector<std::vector<int>> send_to(cells.size(), std::vector<int>(P, 0));
	std::vector<std::vector<int>> recv_from(cells.size(), std::vector<int>(P, 0));
	plans_.assign(cells.size(), HaloPlan());
	for (std::size_t k = 0; k < cells.size(); ++k)
	{
		std::vector<LocalCell>& c = cells[k];
		HaloPlan& plan = plans_[k];
		// ghosts by owner, then global id: one slot per distinct (owner, gid)
		auto ghosts_end = std::partition(c.begin(), c.end(), [&](const LocalCell& x) { return x.owner != rank_; });
		std::sort(c.begin(), ghosts_end, [](const LocalCell& a, const LocalCell& b) {
			return a.owner != b.owner ? a.owner < b.owner : a.gid != b.gid ? a.gid < b.gid : a.line < b.line;
		});
		std::vector<uint64> requests;
		std::vector<int> request_counts(P, 0);
		for (auto it = c.begin(); it != ghosts_end; ++it)
		{
			if (it->owner < 0 || std::size_t(it->owner) >= P)
				throw std::runtime_error("dist: a cell with owner " + std::to_string(it->owner));
			if (it == c.begin() || it->gid != (it - 1)->gid || it->owner != (it - 1)->owner)
			{
				plan.slot_starts.push_back(uint32(plan.slot_lines.size()));
				requests.push_back(it->gid);
				++request_counts[std::size_t(it->owner)];
			}
			plan.slot_lines.push_back(it->line);
		}
		plan.slot_starts.push_back(uint32(plan.slot_lines.size()));
		recv_from[k] = request_counts;

		// ask each owner for its cells; answer the requests for ours
		std::vector<int> incoming_counts(P, 0);
		MPI_Alltoall(request_counts.data(), 1, MPI_INT, incoming_counts.data(), 1, MPI_INT, comm_);
		std::vector<int> request_offsets(P, 0), incoming_offsets(P, 0);
		for (std::size_t r = 1; r < P; ++r)
		{
			request_offsets[r] = request_offsets[r - 1] + request_counts[r - 1];
			incoming_offsets[r] = incoming_offsets[r - 1] + incoming_counts[r - 1];
		}
		std::vector<uint64> incoming(std::size_t(incoming_offsets[P - 1] + incoming_counts[P - 1]));
		MPI_Alltoallv(requests.data(), request_counts.data(), request_offsets.data(), MPI_UINT64_T, incoming.data(),
					  incoming_counts.data(), incoming_offsets.data(), MPI_UINT64_T, comm_);

		std::sort(ghosts_end, c.end(), [](const LocalCell& a, const LocalCell& b) { return a.gid < b.gid; });
		plan.send_lines.reserve(incoming.size());
		for (uint64 g : incoming)
		{
			const auto it = std::lower_bound(ghosts_end, c.end(), g,
											 [](const LocalCell& x, uint64 value) { return x.gid < value; });
			if (it == c.end() || it->gid != g)
				throw std::runtime_error("dist: a rank asked for a cell this rank does not own");
			plan.send_lines.push_back(it->line);
		}
		send_to[k] = incoming_counts;
	}

	// the neighbours: the ranks this one sends to or receives from, any orbit
	neighbours_.clear();
	for (std::size_t r = 0; r < P; ++r)
	{
		bool shared = false;
		for (std::size_t k = 0; k < cells.size(); ++k)
			shared = shared || send_to[k][r] != 0 || recv_from[k][r] != 0;
		if (shared && int(r) != rank_)
			neighbours_.push_back(int(r));
	}
	for (std::size_t k = 0; k < cells.size(); ++k)
		for (int r : neighbours_)
		{
			plans_[k].send_counts.push_back(send_to[k][std::size_t(r)]);
			plans_[k].recv_counts.push_back(recv_from[k][std::size_t(r)]);
		}
	// reorder = 0: Open MPI's neighbourhood collectives have hung on reordered graphs
	const int degree = int(neighbours_.size());
	MPI_Dist_graph_create_adjacent(comm_, degree, neighbours_.data(), MPI_UNWEIGHTED, degree, neighbours_.data(),
								   MPI_UNWEIGHTED, MPI_INFO_NULL, 0, &graph_);
}

void DistributedMapBase::move_values(const std::vector<int>& send_counts, const void* send,
									 const std::vector<int>& recv_counts, void* recv, std::size_t elem_size,
									 Transport transport) const
{
	if (nb_ranks_ == 1)
		return;
	std::vector<int> send_bytes, send_offsets, recv_bytes, recv_offsets;
	to_bytes(send_counts, elem_size, send_bytes, send_offsets);
	to_bytes(recv_counts, elem_size, recv_bytes, recv_offsets);
	// MPI reads no byte of an empty message, but wants a valid address
	static std::byte none;
	const void* s = send != nullptr ? send : &none;
	void* r = recv != nullptr ? recv : &none;
	if (transport == Transport::NeighborhoodCollective)
	{
		MPI_Neighbor_alltoallv(s, send_bytes.data(), send_offsets.data(), MPI_BYTE, r, recv_bytes.data(),
							   recv_offsets.data(), MPI_BYTE, graph_);
		return;
	}
	std::vector<MPI_Request> requests;
	requests.reserve(2 * neighbours_.size());
	for (std::size_t i = 0; i < neighbours_.size(); ++i)
		if (recv_bytes[i] != 0)
			MPI_Irecv(static_cast<std::byte*>(r) + recv_offsets[i], recv_bytes[i], MPI_BYTE, neighbours_[i], HALO_TAG,
					  comm_, &requests.emplace_back());
	for (std::size_t i = 0; i < neighbours_.size(); ++i)
		if (send_bytes[i] != 0)
			MPI_Isend(static_cast<const std::byte*>(s) + send_offsets[i], send_bytes[i], MPI_BYTE, neighbours_[i],
					  HALO_TAG, comm_, &requests.emplace_back());
	MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
}

template <typename MAP>
void DistributedMap<MAP>::finish(MPI_Comm comm)
{
	std::vector<std::vector<LocalCell>> cells(dimension + 1);
	detail::foreach_cell_type<MAP>([&](auto cell, uint32 k) {
		foreach_cell(*map_, [&](decltype(cell) c) {
			const uint32 line = index_of(*map_, c);
			cells[k].push_back({(*gids_[k])[line], line, (*owners_[k])[line]});
		});
	});
	build_plans(comm, cells);
}

template class DistributedMap<CMap2>;
template class DistributedMap<CMap3>;

} // namespace cgogn::dist
