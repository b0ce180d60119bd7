// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/distributed/distributed_map.h>

#include <functional>
#include <type_traits>
#include <vector>

namespace cgogn::dist
{

/// Values a halo can carry: copied byte for byte between ranks of one
/// machine type. Arithmetic types, std::array and Eigen fixed-size vectors
/// and matrices (whose copy is a copy of their bytes).
template <typename T>
concept HaloValue = std::is_trivially_copyable_v<T> || requires
{
	typename T::Scalar;
	requires std::is_arithmetic_v<typename T::Scalar>;
	requires T::SizeAtCompileTime >
	0;
	requires sizeof(T) == sizeof(typename T::Scalar) * std::size_t(T::SizeAtCompileTime);
};

/// exchange() on values held by line: values[line] for every line of the
/// cells of dimension k (a cell attribute, or a std::vector with one value
/// per line). Collective over dm.comm(); cost as exchange().
template <typename MAP, typename LINES>
void exchange_lines(const DistributedMap<MAP>& dm, uint32 k, LINES& values,
					Transport transport = Transport::NeighborhoodCollective)
{
	using T = std::remove_cvref_t<decltype(values[uint32(0)])>;
	static_assert(HaloValue<T>, "exchange_lines: the values must be copyable byte for byte");
	const HaloPlan& plan = dm.plan(k);
	std::vector<T> send(plan.send_lines.size()), recv(plan.slot_starts.empty() ? 0 : plan.slot_starts.size() - 1);
	for (std::size_t i = 0; i < plan.send_lines.size(); ++i)
		send[i] = values[plan.send_lines[i]];
	dm.move_values(plan.send_counts, send.data(), plan.recv_counts, recv.data(), sizeof(T), transport);
	for (std::size_t s = 0; s < recv.size(); ++s)
		for (uint32 i = plan.slot_starts[s]; i < plan.slot_starts[s + 1]; ++i)
			values[plan.slot_lines[i]] = recv[s];
}

/// Sends the owners' values of attr to every ghost copy of their cells:
/// afterwards every rank holds the owner's value on each of its cells.
/// Collective over dm.comm(): every rank calls it with the same attribute.
/// Cost: one message per neighbouring rank, of the cells it shares
/// (O(ghost layer)), no global synchronisation.
template <typename MAP, typename T, Orbit O>
requires HaloValue<T>
void exchange(const DistributedMap<MAP>& dm, CellAttribute<T, O>& attr,
			  Transport transport = Transport::NeighborhoodCollective)
{
	exchange_lines(dm, DistributedMap<MAP>::template dimension_of<Cell<O>>(), attr, transport);
}

/// The same through the handle add_attribute returns.
template <typename MAP, typename T, Orbit O>
requires HaloValue<T>
void exchange(const DistributedMap<MAP>& dm, const std::shared_ptr<CellAttribute<T, O>>& attr,
			  Transport transport = Transport::NeighborhoodCollective)
{
	exchange(dm, *attr, transport);
}

/// Brings the ghosts' values of attr back to the owners: each owner's value
/// becomes op(op(value, c1), c2)... over the contributions c of the ranks
/// holding a ghost copy, in increasing rank order (the copies of one cell
/// on one rank are first combined with op). Ghost values are left as they
/// were; call exchange() after it to give them the result. op is any
/// callable T(T, T), the sum by default. Collective over dm.comm(); cost as
/// exchange().
template <typename MAP, typename T, Orbit O, typename OP = std::plus<>>
requires HaloValue<T>
void accumulate(const DistributedMap<MAP>& dm, CellAttribute<T, O>& attr, OP op = {},
				Transport transport = Transport::NeighborhoodCollective)
{
	const HaloPlan& plan = dm.plan(DistributedMap<MAP>::template dimension_of<Cell<O>>());
	const std::size_t nb_slots = plan.slot_starts.empty() ? 0 : plan.slot_starts.size() - 1;
	std::vector<T> contributions(nb_slots), received(plan.send_lines.size());
	for (std::size_t s = 0; s < nb_slots; ++s)
	{
		T v = attr[plan.slot_lines[plan.slot_starts[s]]];
		for (uint32 k = plan.slot_starts[s] + 1; k < plan.slot_starts[s + 1]; ++k)
			v = op(v, attr[plan.slot_lines[k]]);
		contributions[s] = v;
	}
	// the reverse of exchange: ghosts send, owners receive
	dm.move_values(plan.recv_counts, contributions.data(), plan.send_counts, received.data(), sizeof(T), transport);
	for (std::size_t k = 0; k < received.size(); ++k)
	{
		T& v = attr[plan.send_lines[k]];
		v = op(v, received[k]);
	}
}

/// The same through the handle add_attribute returns.
template <typename MAP, typename T, Orbit O, typename OP = std::plus<>>
requires HaloValue<T>
void accumulate(const DistributedMap<MAP>& dm, const std::shared_ptr<CellAttribute<T, O>>& attr, OP op = {},
				Transport transport = Transport::NeighborhoodCollective)
{
	accumulate(dm, *attr, op, transport);
}

} // namespace cgogn::dist
