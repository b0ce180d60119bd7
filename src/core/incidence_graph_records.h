// SPDX-License-Identifier: MIT
// Reading and relinking the records of an incidence graph (see
// IncidenceGraph): the rings of edge ends around vertices, the radial
// rings of uses around edges and the face cycles. Shared by its operators,
// queries, conversions and integrity check.
#pragma once

#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/incidence_graph.h>

#include <span>

namespace cgogn::detail
{

class IgRecords
{
public:
	explicit IgRecords(const IncidenceGraph& ig)
		: ig_(const_cast<IncidenceGraph&>(ig)), links_(ig.links()),
		  vertices_(*state_of(ig_).cells[orbit_index(Orbit::IG_VERTEX)]),
		  edges_(*state_of(ig_).cells[orbit_index(Orbit::IG_EDGE)]), phi1_(*state_of(ig_).phi1)
	{
	}

	AttributeContainer& vertices() const
	{
		return vertices_;
	}
	AttributeContainer& edges() const
	{
		return edges_;
	}

	// --- edge ends: 2 x edge + side
	uint32 end_vertex(uint32 end) const
	{
		return (end & 1u) == 0 ? edges_.key()[end >> 1] : (*links_.edge_v1)[end >> 1];
	}
	void set_end_vertex(uint32 end, uint32 v) const
	{
		if ((end & 1u) == 0)
			edges_.key()[end >> 1] = v;
		else
			(*links_.edge_v1)[end >> 1] = v;
	}
	uint32 next_end(uint32 end) const
	{
		return (*links_.edge_next[end & 1u])[end >> 1];
	}
	void set_next_end(uint32 end, uint32 n) const
	{
		(*links_.edge_next[end & 1u])[end >> 1] = n;
	}
	uint32 first_end(uint32 v) const
	{
		return vertices_.key()[v];
	}
	void set_first_end(uint32 v, uint32 end) const
	{
		vertices_.key()[v] = end;
	}
	/// Puts edge end `end` into the ring of vertex v.
	void ring_insert(uint32 v, uint32 end) const
	{
		const uint32 f = first_end(v);
		if (f == NO_EDGE_END)
		{
			set_first_end(v, end);
			set_next_end(end, end);
		}
		else
		{
			set_next_end(end, next_end(f));
			set_next_end(f, end);
		}
	}
	/// The end before `end` in its ring. O(degree).
	uint32 ring_previous(uint32 end) const
	{
		uint32 p = end;
		while (next_end(p) != end)
			p = next_end(p);
		return p;
	}
	/// Takes edge end `end` out of the ring of vertex v. O(degree of v).
	void ring_remove(uint32 v, uint32 end) const
	{
		const uint32 p = ring_previous(end);
		if (p == end)
			set_first_end(v, NO_EDGE_END);
		else
		{
			set_next_end(p, next_end(end));
			if (first_end(v) == end)
				set_first_end(v, p);
		}
	}
	/// Calls f(end) on each end of v's ring; f may return false to stop.
	template <typename FUNC>
	bool foreach_end(uint32 v, const FUNC& f) const
	{
		const uint32 first = first_end(v);
		if (first == NO_EDGE_END)
			return true;
		uint32 it = first;
		do
		{
			const uint32 next = next_end(it); // f may unlink it
			if (!call_and_continue(f, it))
				return false;
			it = next;
		} while (it != first);
		return true;
	}

	// --- uses (darts)
	uint32 use_edge_end(Dart u) const
	{
		return (*links_.use_edge)[u.index];
	}
	void set_use_edge_end(Dart u, uint32 ee) const
	{
		(*links_.use_edge)[u.index] = ee;
	}
	uint32 origin(Dart u) const
	{
		return end_vertex(use_edge_end(u));
	}
	uint32 target(Dart u) const
	{
		return end_vertex(use_edge_end(u) ^ 1u);
	}
	Dart next_in_face(Dart u) const
	{
		return Dart(phi1_[u.index]);
	}
	void set_next_in_face(Dart u, Dart n) const
	{
		phi1_[u.index] = n.index;
	}
	Dart previous_in_face(Dart u) const
	{
		Dart p = u;
		while (next_in_face(p) != u)
			p = next_in_face(p);
		return p;
	}
	uint32 first_use(uint32 e) const
	{
		return (*links_.edge_use)[e];
	}
	Dart next_radial(Dart u) const
	{
		return Dart((*links_.radial)[u.index]);
	}
	/// Puts use u into the radial ring of its edge (read from u).
	void radial_insert(Dart u) const
	{
		const uint32 e = use_edge_end(u) >> 1;
		uint32& f = (*links_.edge_use)[e];
		if (f == INVALID_INDEX)
		{
			f = u.index;
			(*links_.radial)[u.index] = u.index;
		}
		else
		{
			(*links_.radial)[u.index] = (*links_.radial)[f];
			(*links_.radial)[f] = u.index;
		}
	}
	/// Takes use u out of the radial ring of its edge. O(degree of the edge).
	void radial_remove(Dart u) const
	{
		const uint32 e = use_edge_end(u) >> 1;
		uint32 p = u.index;
		while ((*links_.radial)[p] != u.index)
			p = (*links_.radial)[p];
		uint32& f = (*links_.edge_use)[e];
		if (p == u.index)
			f = INVALID_INDEX;
		else
		{
			(*links_.radial)[p] = (*links_.radial)[u.index];
			if (f == u.index)
				f = p;
		}
	}
	/// Calls f(use) on each use of edge e; f may return false to stop.
	template <typename FUNC>
	bool foreach_use(uint32 e, const FUNC& f) const
	{
		const uint32 first = first_use(e);
		if (first == INVALID_INDEX)
			return true;
		uint32 it = first;
		do
		{
			const uint32 next = (*links_.radial)[it];
			if (!call_and_continue(f, Dart(it)))
				return false;
			it = next;
		} while (it != first);
		return true;
	}
	/// A new use of edge end ee (the side from that end's vertex), alone in
	/// its face cycle, in the edge's radial ring.
	Dart new_use(uint32 ee) const
	{
		const Dart u = add_dart(ig_);
		set_use_edge_end(u, ee);
		radial_insert(u);
		return u;
	}

private:
	IncidenceGraph& ig_;
	IncidenceGraph::Links links_;
	AttributeContainer& vertices_;
	AttributeContainer& edges_;
	AttributeArray<uint32>& phi1_;
};

/// A new face whose sides (edge ends, 2 x edge + side) are consecutive in
/// this order, indexed when faces are. Precondition: they form a simple
/// cycle of at least 3 sides. Returns its first use.
Dart ig_build_face(IncidenceGraph& ig, std::span<const uint32> sides);

} // namespace cgogn::detail
