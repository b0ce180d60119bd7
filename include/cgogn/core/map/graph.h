// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap_base.h>

namespace cgogn
{

/// A graph: vertices joined by edges, any number of edges per vertex,
/// self-loops and multiple edges allowed (skeletons, curve networks, vessel
/// trees, roads). A 1-dimensional map of half-edges (darts):
/// - alpha0, an involution, exchanges the two half-edges of an edge;
/// - alpha1, a permutation, turns around a vertex (alpha_1 is its inverse,
///   stored, so that inserting or removing a half-edge is O(1) whatever the
///   degree).
/// An isolated vertex is one dart with no edge: alpha0(d) = alpha1(d) = d.
/// It counts as a vertex of degree 0 and as no edge; a vertex with edges
/// holds only half-edges of edges (check_integrity checks both).
///
/// Attributes, markers, foreach_cell, parallel_foreach_cell and nb_cells work
/// as on the other maps; the operators are in <cgogn/core/operators/graph.h>,
/// the local traversals in <cgogn/core/traversals/local_graph.h>, the
/// queries (degree, components, cycle rank, branches) in
/// <cgogn/core/properties/graph_properties.h>.
class Graph : public CMapBase
{
public:
	static constexpr uint32 dimension = 1; ///< The dimension of the map.

	using Vertex = Cell<Orbit::ALPHA1>; ///< A vertex: the half-edges around it (one dart when isolated).
	using Edge = Cell<Orbit::ALPHA0>;   ///< An edge: its two half-edges, exchanged by alpha0.

	Graph() : CMapBase("__alpha1")
	{
		add_relation("__alpha0");  // stored where 2-maps keep phi2
		add_relation("__alpha_1"); // stored where 3-maps keep phi3
	}
};

/// The other half-edge of d's edge; d itself when d is an isolated vertex. O(1).
inline Dart alpha0(const Graph& g, Dart d)
{
	return Dart((*detail::state_of(g).phi2)[d.index]);
}

/// The next half-edge around d's vertex. O(1).
inline Dart alpha1(const Graph& g, Dart d)
{
	return Dart((*detail::state_of(g).phi1)[d.index]);
}

/// The previous half-edge around d's vertex (the inverse of alpha1). O(1).
inline Dart alpha_1(const Graph& g, Dart d)
{
	return Dart((*detail::state_of(g).phi3)[d.index]);
}

/// True when d is an isolated vertex: a dart with no edge. O(1).
inline bool is_isolated(const Graph& g, Dart d)
{
	return alpha0(g, d) == d;
}

} // namespace cgogn
