// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/graph.h>
#include <cgogn/core/properties/integrity.h>

#include <vector>

namespace cgogn
{

/// Number of edges incident to v, a self-loop counting twice; 0 for an
/// isolated vertex. O(degree of v).
uint32 degree(const Graph& g, Graph::Vertex v);

/// Number of vertices of edge e: 2 (a self-loop has its vertex twice). O(1).
inline uint32 degree(const Graph&, Graph::Edge)
{
	return 2;
}

/// Number of connected components, an isolated vertex being one. O(number of
/// darts).
uint32 nb_connected_components(const Graph& g);

/// The cycle rank (first Betti number) E - V + C: the number of independent
/// cycles; 0 for a forest, +1 per self-loop. O(number of darts).
uint32 cycle_rank(const Graph& g);

/// A branch: a maximal chain of edges whose inner vertices have degree 2.
struct GraphBranch
{
	Dart first;          ///< The half-edge of the first edge at the first vertex.
	Dart last;           ///< The half-edge of the last edge at the last vertex.
	uint32 nb_edges = 0; ///< The number of edges of the branch.
	/// True for a cycle through vertices of degree 2 only (a component that
	/// is a cycle): first and last are then at the same vertex, which is
	/// arbitrary. A branch from a junction back to itself (first and last at
	/// one vertex of degree other than 2) is not closed.
	bool closed = false;
};

/// Every branch of g, each once: the open ones from their ends (vertices of
/// degree other than 2), in dart order of their first half-edge, then the
/// closed ones. Isolated vertices are in no branch. Each edge is in exactly
/// one branch. O(number of darts).
std::vector<GraphBranch> branches(const Graph& g);

/// Checks every invariant of the graph: alpha0 an involution, alpha1 a
/// permutation and alpha_1 its inverse, all between live darts; a dart
/// without edge (alpha0(d) == d) alone around its vertex; and for every
/// indexed orbit the rules of the other maps (a dart without edge has no
/// edge line). O(number of darts x number of indexed orbits + lines).
IntegrityReport check_integrity(const Graph& g);

} // namespace cgogn
