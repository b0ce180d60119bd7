// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap_base.h>

namespace cgogn
{

/// A cell complex of vertices, edges and faces with no manifold and no
/// orientation constraint: an edge has any number of faces (a book of three
/// triangles on one spine, the 2-skeleton of a 4-polytope), a vertex any
/// number of fans, edges may have no face (wires) and vertices no edge.
///
/// Layout (radial-edge-like linked records, no std::vector per cell):
/// - a vertex is a record, its line in the vertex container: the first of
///   its edge ends;
/// - an edge is a record, its line in the edge container: its two vertices,
///   for each end the next edge end around that vertex (a singly linked
///   cycle), and its first face use;
/// - a face is a cycle of *uses*, the darts: one per side of the face, with
///   the next use in the face (phi1, the key), the next use around the
///   same edge (a singly linked radial cycle) and the edge with the side's
///   direction. A face is the PHI1 orbit of its uses, indexed lazily as in
///   the maps.
/// That is 12 bytes per use, 20 per edge and 4 per vertex: 68 bytes per face
/// of a triangle mesh, 1.8x a CMap2's 38 (phi1, phi2, the vertex index).
///
/// Vertex and Edge are records (see is_direct_orbit): their `dart` field
/// holds their line, they are always indexed, two handles of one cell are
/// equal. Face is an orbit of uses, as in a map: any use represents it, and
/// same_cell compares. Attributes, markers, foreach_cell and
/// parallel_foreach_cell work as on the maps. The operators are in
/// <cgogn/core/operators/incidence_graph.h>, the queries in
/// <cgogn/core/properties/incidence_graph_properties.h> and the local
/// traversals in <cgogn/core/traversals/local_incidence_graph.h>.
class IncidenceGraph : public CMapBase
{
public:
	static constexpr uint32 dimension = 2; ///< The dimension of the complex (its cells' largest).

	using Vertex = Cell<Orbit::IG_VERTEX>; ///< A vertex: its line.
	using Edge = Cell<Orbit::IG_EDGE>;     ///< An edge: its line.
	using Face = Cell<Orbit::PHI1>;        ///< A face: the cycle of its uses.

	IncidenceGraph() : CMapBase("__phi1")
	{
		radial_ = detail::state_of(*this).darts->add_attribute<uint32>("__radial", INVALID_INDEX).get();
		use_edge_ = detail::state_of(*this).darts->add_attribute<uint32>("__edge_end", INVALID_INDEX).get();
		AttributeContainer& edges = *detail::state_of(*this).cells[orbit_index(Orbit::IG_EDGE)];
		edge_v1_ = edges.add_attribute<uint32>("__v1", INVALID_INDEX).get();
		edge_next_[0] = edges.add_attribute<uint32>("__next_end0", INVALID_INDEX).get();
		edge_next_[1] = edges.add_attribute<uint32>("__next_end1", INVALID_INDEX).get();
		edge_use_ = edges.add_attribute<uint32>("__use", INVALID_INDEX).get();
	}

	/// The relations of the records and uses (see the class comment); core's
	/// implementation reads them through the accessors below.
	struct Links
	{
		AttributeArray<uint32>* radial;       ///< per use: the next use around its edge
		AttributeArray<uint32>* use_edge;     ///< per use: 2 x its edge + 1 when it runs from v1 to v0
		AttributeArray<uint32>* edge_v1;      ///< per edge: its second vertex (the first is the key)
		AttributeArray<uint32>* edge_next[2]; ///< per edge and end: the next edge end around that end's vertex
		AttributeArray<uint32>* edge_use;     ///< per edge: a use of it, INVALID_INDEX without face
	};
	/// Not part of the API (see detail::state_of).
	Links links() const
	{
		return {radial_, use_edge_, edge_v1_, {edge_next_[0], edge_next_[1]}, edge_use_};
	}

private:
	AttributeArray<uint32>* radial_;
	AttributeArray<uint32>* use_edge_;
	AttributeArray<uint32>* edge_v1_;
	AttributeArray<uint32>* edge_next_[2];
	AttributeArray<uint32>* edge_use_;
};

namespace detail
{

/// The key of a vertex without edge: a valid key (the line is live) that is
/// no edge end.
inline constexpr uint32 NO_EDGE_END = INVALID_INDEX - 1;

/// The vertex at end s (0 or 1) of edge e. O(1).
inline uint32 ig_end_vertex(const IncidenceGraph& ig, uint32 e, uint32 s)
{
	return s == 0 ? state_of(ig).cells[orbit_index(Orbit::IG_EDGE)]->key()[e] : (*ig.links().edge_v1)[e];
}

/// The next edge end (2 x edge + side) around the vertex of edge end `end`. O(1).
inline uint32 ig_next_end(const IncidenceGraph& ig, uint32 end)
{
	return (*ig.links().edge_next[end & 1u])[end >> 1];
}

/// The first edge end of vertex v, NO_EDGE_END when it has none. O(1).
inline uint32 ig_first_end(const IncidenceGraph& ig, uint32 v)
{
	return state_of(ig).cells[orbit_index(Orbit::IG_VERTEX)]->key()[v];
}

} // namespace detail

/// The edge of use u (a dart: one side of a face). O(1).
inline IncidenceGraph::Edge edge_of_use(const IncidenceGraph& ig, Dart u)
{
	return IncidenceGraph::Edge(Dart((*ig.links().use_edge)[u.index] >> 1));
}

/// The vertex use u starts from (its face's vertex before the side). O(1).
inline IncidenceGraph::Vertex use_origin(const IncidenceGraph& ig, Dart u)
{
	const uint32 ee = (*ig.links().use_edge)[u.index];
	return IncidenceGraph::Vertex(Dart(detail::ig_end_vertex(ig, ee >> 1, ee & 1u)));
}

/// The vertex use u goes to. O(1).
inline IncidenceGraph::Vertex use_target(const IncidenceGraph& ig, Dart u)
{
	const uint32 ee = (*ig.links().use_edge)[u.index];
	return IncidenceGraph::Vertex(Dart(detail::ig_end_vertex(ig, ee >> 1, 1u - (ee & 1u))));
}

/// The next use in u's face. O(1).
inline Dart next_use_in_face(const IncidenceGraph& ig, Dart u)
{
	return Dart((*detail::state_of(ig).phi1)[u.index]);
}

/// The next use around u's edge (another face on the same edge; u itself
/// when the edge has one face). O(1).
inline Dart next_use_around_edge(const IncidenceGraph& ig, Dart u)
{
	return Dart((*ig.links().radial)[u.index]);
}

/// phi1 of an incidence graph: the next use in the face. O(1).
inline Dart phi1(const IncidenceGraph& ig, Dart u)
{
	return next_use_in_face(ig, u);
}

/// The two vertices of edge e: first (its first end) then second. O(1).
inline IncidenceGraph::Vertex first_vertex(const IncidenceGraph& ig, IncidenceGraph::Edge e)
{
	return IncidenceGraph::Vertex(Dart(detail::ig_end_vertex(ig, e.dart.index, 0)));
}
/// See first_vertex. O(1).
inline IncidenceGraph::Vertex second_vertex(const IncidenceGraph& ig, IncidenceGraph::Edge e)
{
	return IncidenceGraph::Vertex(Dart(detail::ig_end_vertex(ig, e.dart.index, 1)));
}

/// True when v is a live vertex of ig (its line is in use). O(1).
inline bool is_valid(const IncidenceGraph& ig, IncidenceGraph::Vertex v)
{
	return v.dart.is_valid() && detail::state_of(ig).cells[orbit_index(Orbit::IG_VERTEX)]->is_live(v.dart.index);
}
/// True when e is a live edge of ig. O(1).
inline bool is_valid(const IncidenceGraph& ig, IncidenceGraph::Edge e)
{
	return e.dart.is_valid() && detail::state_of(ig).cells[orbit_index(Orbit::IG_EDGE)]->is_live(e.dart.index);
}

} // namespace cgogn
