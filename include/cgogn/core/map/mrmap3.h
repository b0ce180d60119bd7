// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/map/mr_common.h>
#include <cgogn/core/map/mrmap2.h>

#include <array>
#include <memory>
#include <vector>

namespace cgogn
{

class MRMap3;

namespace detail
{

/// What a multiresolution 3-map holds (see MRMap3): the finest map and the
/// labels of its darts. Not part of the API.
struct MRState3
{
	CMap3 map;                                    ///< The finest map: the darts of every level.
	std::shared_ptr<AttributeArray<uint8>> level; ///< Per dart: the level at which it was created.
	/// Per dart: the id of its finest edge (the same on all its darts), shared
	/// by the pieces of a cut edge and different from the ids of the edges
	/// that the edge's later midpoints are the middle of, in the faces around
	/// them (see mr_phi1).
	std::shared_ptr<AttributeArray<uint8>> edge_id;
	/// Per dart: the id of its finest face (the same on both sides), shared by
	/// the pieces of a cut face and different from the ids of the faces that a
	/// later cut of a volume puts around the face's inner edges (see
	/// mr_phi2_in_face).
	std::shared_ptr<AttributeArray<uint8>> face_id;
	/// darts_per_level[l]: the live darts created at level l. Its size is
	/// max_level + 1.
	std::vector<uint32> darts_per_level;
	uint32 current_level = 0;
	/// The lines of vertices, edges, faces, volumes and connected components
	/// (see MRDim<MRState3>::slot and MRCellIndex).
	std::array<MRCellIndex, 5> cells;
};

MRState3& mr_state_of(MRMap3& m);
const MRState3& mr_state_of(const MRMap3& m);

} // namespace detail

/// A multiresolution 3-map in the compact primal hierarchy (CPH) model
/// (Untereiner, Cazier and Bechmann): only the finest map is stored, with
/// per-dart labels (a creation level, an edge id and a face id, 3 bytes per
/// dart). The mesh at level l is made of the darts of level <= l: phi1 at
/// level l walks the finest map, turning around the vertices born after
/// level l (inside the coarse face) until the edge id matches; phi2 and phi3
/// at level l follow from it. Every generic function (phi1, phi2, phi3,
/// foreach_cell, the local traversals, nb_cells, degree, check_integrity,
/// ...) works at the map's current level; level_view(m, l) reads another
/// level at the same time. Levels are added by add_level and removed by
/// remove_finest_level.
///
/// Attributes (mrmap3_attributes.h) follow the rules of MRMap2: a vertex has
/// a value at every level from its creation on, an edge, face or volume
/// keeps its line while it exists and its children get new lines.
///
/// Maps can be moved, not copied. The finest map is read-only from outside
/// (finest_map): its connectivity is changed only through the operators of
/// MRMap3, which keep the labels right.
class MRMap3
{
public:
	static constexpr uint32 dimension = 3; ///< The dimension of the map.

	using HalfEdge = CMap3::HalfEdge; ///< A dart of level <= the level read.
	using Vertex = CMap3::Vertex;     ///< A vertex: the darts leaving it, at the level read.
	using Edge = CMap3::Edge;         ///< An edge: its darts in the faces and volumes around it.
	using Face = CMap3::Face;         ///< A face: both of its sides.
	using Volume = CMap3::Volume;     ///< A volume: a closed 2-map at the level read.
	using CC = CMap3::CC;             ///< A connected component.
	using Vertex2 = CMap3::Vertex2;   ///< A vertex of one volume.
	using Edge2 = CMap3::Edge2;       ///< An edge of one volume.
	using Face2 = CMap3::Face2;       ///< One side of a face.

	/// Makes `base` the level 0 of a new hierarchy: every dart gets level 0,
	/// edge id 0 and face id 0. The map keeps its attributes: the lines of
	/// its vertices, edges, faces, volumes and connected components become
	/// those of level 0. Throws std::invalid_argument, leaving `base`
	/// untouched, when `base` indexes the cells of one volume (Vertex2,
	/// Edge2, Face2), which a hierarchy does not carry. Precondition: `base`
	/// is closed (check_integrity passes). O(number of darts).
	explicit MRMap3(CMap3&& base);

	/// Takes the hierarchy of another map; the moved-from map may only be
	/// destroyed or assigned to. O(1).
	MRMap3(MRMap3&&) = default;
	/// Replaces this hierarchy by another one. O(size of the replaced map).
	MRMap3& operator=(MRMap3&&) = default;
	MRMap3(const MRMap3&) = delete;
	MRMap3& operator=(const MRMap3&) = delete;

	/// Implements foreach_cell(m, f) at the current level (see local_mrmap3.h).
	template <typename CELL, typename FUNC>
	void foreach_cell(const FUNC& f) const;
	/// Implements parallel_foreach_cell(m, f) at the current level (see local_mrmap3.h).
	template <typename CELL, typename FUNC>
	void parallel_foreach_cell(const FUNC& f) const;

private:
	friend detail::MRState3& detail::mr_state_of(MRMap3& m);
	friend const detail::MRState3& detail::mr_state_of(const MRMap3& m);

	detail::MRState3 state_;
};

namespace detail
{
inline MRState3& mr_state_of(MRMap3& m)
{
	return m.state_;
}
inline const MRState3& mr_state_of(const MRMap3& m)
{
	return m.state_;
}
} // namespace detail

/// A read-only view of a multiresolution 3-map at one level: every generic
/// function reads it as the map of that level. Views are cheap to copy (a
/// pointer and a level); any number of them, at any levels, can be read at
/// once, also from several threads, as long as the map is not changed
/// meanwhile. A view is invalidated by every change of the hierarchy that
/// removes its level.
class MRLevelView3
{
public:
	static constexpr uint32 dimension = 3; ///< The dimension of the map.

	using HalfEdge = MRMap3::HalfEdge; ///< See MRMap3::HalfEdge.
	using Vertex = MRMap3::Vertex;     ///< See MRMap3::Vertex.
	using Edge = MRMap3::Edge;         ///< See MRMap3::Edge.
	using Face = MRMap3::Face;         ///< See MRMap3::Face.
	using Volume = MRMap3::Volume;     ///< See MRMap3::Volume.
	using CC = MRMap3::CC;             ///< See MRMap3::CC.
	using Vertex2 = MRMap3::Vertex2;   ///< See MRMap3::Vertex2.
	using Edge2 = MRMap3::Edge2;       ///< See MRMap3::Edge2.
	using Face2 = MRMap3::Face2;       ///< See MRMap3::Face2.

	/// The view of m at level l. Precondition: l <= max_level(m). O(1).
	MRLevelView3(const MRMap3& m, uint32 l) : state_(&detail::mr_state_of(m)), level_(l)
	{
	}

	/// The view of the hierarchy in state s at level l (core's
	/// implementation only, for a hierarchy being built). O(1).
	MRLevelView3(const detail::MRState3& s, uint32 l) : state_(&s), level_(l)
	{
	}

	/// The level read. O(1).
	uint32 level() const
	{
		return level_;
	}
	/// The hierarchy's state (core's implementation only). O(1).
	const detail::MRState3& state() const
	{
		return *state_;
	}

	/// Implements foreach_cell(view, f) (see local_mrmap3.h).
	template <typename CELL, typename FUNC>
	void foreach_cell(const FUNC& f) const;
	/// Implements parallel_foreach_cell(view, f) (see local_mrmap3.h).
	template <typename CELL, typename FUNC>
	void parallel_foreach_cell(const FUNC& f) const;

private:
	const detail::MRState3* state_;
	uint32 level_;
};

/// The multiresolution 3-map or one of its level views.
template <typename M>
concept MRMesh3 = std::same_as<M, MRMap3> || std::same_as<M, MRLevelView3>;

/// The finest map of m: the darts and attributes of every level, read as a
/// flat CMap3. O(1).
inline const CMap3& finest_map(const MRMap3& m)
{
	return detail::mr_state_of(m).map;
}

/// The finest level of m (0 for a map without refinement). O(1).
inline uint32 max_level(const MRMap3& m)
{
	return uint32(detail::mr_state_of(m).darts_per_level.size() - 1);
}

/// The level at which the generic functions read m. O(1).
inline uint32 current_level(const MRMap3& m)
{
	return detail::mr_state_of(m).current_level;
}

/// Makes the generic functions read m at level l. Throws std::out_of_range
/// when l > max_level(m). O(1).
void set_current_level(MRMap3& m, uint32 l);

/// The read-only view of m at level l (see MRLevelView3). Throws
/// std::out_of_range when l > max_level(m). O(1).
MRLevelView3 level_view(const MRMap3& m, uint32 l);

/// The level at which dart d was created. O(1).
inline uint32 dart_level(const MRMap3& m, Dart d)
{
	return (*detail::mr_state_of(m).level)[d.index];
}

/// The number of live darts created at level l (0 above max_level). A mesh
/// at level l has the darts created at levels 0 ... l. O(1).
inline uint32 nb_darts_at_level(const MRMap3& m, uint32 l)
{
	const auto& c = detail::mr_state_of(m).darts_per_level;
	return l < c.size() ? c[l] : 0;
}

namespace detail
{

/// The view at which the generic functions read an MR mesh: the view itself,
/// or a multiresolution map's current level. O(1).
inline MRLevelView3 read_level(const MRLevelView3& v)
{
	return v;
}
inline MRLevelView3 read_level(const MRMap3& m)
{
	return MRLevelView3(m, current_level(m));
}

/// Whether level l is the finest level of s (or above it), where the
/// relations and cells are those of the finest map. O(1).
CGOGN_INLINE bool mr_is_finest(const MRState3& s, uint32 l)
{
	return l + 1 >= s.darts_per_level.size();
}
/// Whether view v reads the finest level. O(1).
CGOGN_INLINE bool mr_is_finest(const MRLevelView3& v)
{
	return mr_is_finest(v.state(), v.level());
}

/// The dart across the edge of d in the same coarse face: phi2 of the finest
/// map, then, while that lands on a face that a later cut of the volume put
/// around the edge (another face id), on into the next finest volume
/// (phi2 o phi3). Used on the inner edges of a refined face only. O(number
/// of faces around the edge on d's side). INVALID when the budget runs out.
template <typename BUDGET>
CGOGN_INLINE Dart mr_phi2_in_face(const MRState3& s, Dart d, BUDGET& budget)
{
	const auto face_id = s.face_id->view();
	const uint8 f = face_id[d.index];
	Dart it = phi2(s.map, d);
	while (face_id[it.index] != f)
	{
		if (!budget.spend())
			return Dart();
		it = phi2(s.map, phi3(s.map, it));
	}
	return it;
}

/// phi1 at level l (the CPH model): from d, walk the finest face; at every
/// vertex born after level l, turn around it inside the coarse face (see
/// mr_phi2_in_face) to the piece of d's edge (the dart with d's edge id) and
/// go on, until a dart of level <= l. O(number of finest darts walked): 1 at
/// the finest level, about 2^(max_level - l) pieces of the edge below it.
/// With a limited budget, INVALID when it runs out.
template <typename BUDGET = MRNoStepLimit>
CGOGN_INLINE Dart mr_phi1(const MRState3& s, uint32 l, Dart d, BUDGET budget = {})
{
	Dart it = phi1(s.map, d);
	if (mr_is_finest(s, l))
		return it;
	const auto level = s.level->view();
	const auto edge_id = s.edge_id->view();
	const uint8 e = edge_id[d.index];
	while (level[it.index] > l)
	{
		while (edge_id[it.index] != e)
		{
			if (!budget.spend())
				return Dart();
			const Dart across = mr_phi2_in_face(s, it, budget);
			if (!across.is_valid())
				return Dart();
			it = phi1(s.map, across);
		}
		if (!budget.spend())
			return Dart();
		it = phi1(s.map, it);
	}
	return it;
}

/// phi_1 at level l: the inverse of mr_phi1, walking the finest face
/// backwards. O(degrees of the finest faces walked). Budget as mr_phi1.
template <typename BUDGET = MRNoStepLimit>
CGOGN_INLINE Dart mr_phi_1(const MRState3& s, uint32 l, Dart d, BUDGET budget = {})
{
	Dart it = phi_1(s.map, d);
	if (mr_is_finest(s, l))
		return it;
	const auto level = s.level->view();
	const auto edge_id = s.edge_id->view();
	const uint8 e = edge_id[it.index];
	while (level[it.index] > l)
	{
		if (!budget.spend())
			return Dart();
		it = phi_1(s.map, it);
		while (edge_id[it.index] != e)
		{
			if (!budget.spend())
				return Dart();
			const Dart across = mr_phi2_in_face(s, it, budget);
			if (!across.is_valid())
				return Dart();
			it = phi_1(s.map, across);
		}
	}
	return it;
}

/// The last finest piece of d's edge at level l, in d's coarse face: it ends
/// where phi1 at level l starts. Its phi2 and phi3 in the finest map are the
/// level's (no face of a refined volume holds a piece of the volume's
/// edges). INVALID when the budget runs out.
template <typename BUDGET = MRNoStepLimit>
CGOGN_INLINE Dart mr_last_piece(const MRState3& s, uint32 l, Dart d, BUDGET budget = {})
{
	const Dart next = mr_phi1(s, l, d, budget);
	return next.is_valid() ? phi_1(s.map, next) : Dart();
}

/// phi2 at level l: the dart of d's edge in the other face of d's volume at
/// level l, which leaves the end of d. O(cost of mr_phi1 + degree of a
/// finest face).
CGOGN_INLINE Dart mr_phi2(const MRState3& s, uint32 l, Dart d)
{
	if (mr_is_finest(s, l))
		return phi2(s.map, d);
	return phi2(s.map, mr_last_piece(s, l, d));
}

/// phi3 at level l: the dart of d's edge and face in the volume on the other
/// side of the face, which leaves the end of d. Cost as mr_phi2.
CGOGN_INLINE Dart mr_phi3(const MRState3& s, uint32 l, Dart d)
{
	if (mr_is_finest(s, l))
		return phi3(s.map, d);
	return phi3(s.map, mr_last_piece(s, l, d));
}

} // namespace detail

/// phi1 at the level read (see MRMap3). Precondition: dart_level(d) <= that
/// level. O(1) at the finest level, O(pieces of the edge walked) below.
template <MRMesh3 M>
CGOGN_INLINE Dart phi1(const M& m, Dart d)
{
	const MRLevelView3 v = detail::read_level(m);
	return detail::mr_phi1(v.state(), v.level(), d);
}

/// phi_1 at the level read: the inverse of phi1. Same precondition and cost.
template <MRMesh3 M>
CGOGN_INLINE Dart phi_1(const M& m, Dart d)
{
	const MRLevelView3 v = detail::read_level(m);
	return detail::mr_phi_1(v.state(), v.level(), d);
}

/// phi2 at the level read. Same precondition; costs one phi1 and one phi_1
/// of the finest map more.
template <MRMesh3 M>
CGOGN_INLINE Dart phi2(const M& m, Dart d)
{
	const MRLevelView3 v = detail::read_level(m);
	return detail::mr_phi2(v.state(), v.level(), d);
}

/// phi3 at the level read. Same precondition and cost as phi2.
template <MRMesh3 M>
CGOGN_INLINE Dart phi3(const M& m, Dart d)
{
	const MRLevelView3 v = detail::read_level(m);
	return detail::mr_phi3(v.state(), v.level(), d);
}

/// Whether d is a dart of a boundary volume (the same at every level). O(1).
template <MRMesh3 M>
CGOGN_INLINE bool is_boundary(const M& m, Dart d)
{
	return is_boundary(detail::read_level(m).state().map, d);
}

/// Whether d belongs to the mesh read: a live dart of level <= that level.
/// O(1).
template <MRMesh3 M>
bool is_dart_valid(const M& m, Dart d)
{
	const MRLevelView3 v = detail::read_level(m);
	return is_dart_valid(v.state().map, d) && (*v.state().level)[d.index] <= v.level();
}

/// The number of darts of the mesh read (levels 0 ... the level read). O(levels).
template <MRMesh3 M>
uint32 nb_darts(const M& m)
{
	const MRLevelView3 v = detail::read_level(m);
	uint32 n = 0;
	for (uint32 l = 0; l <= v.level(); ++l)
		n += v.state().darts_per_level[l];
	return n;
}

/// Calls f(Dart) on the darts of the mesh read (boundary darts included);
/// f may return false to stop. O(number of darts of the finest map).
template <MRMesh3 M, typename FUNC>
void foreach_dart(const M& m, const FUNC& f)
{
	const MRLevelView3 v = detail::read_level(m);
	const auto level = v.state().level->view();
	foreach_dart(v.state().map, [&](Dart d) { return level[d.index] > v.level() || call_and_continue(f, d); });
}

/// The traits of a multiresolution 3-map: those of a 3-map.
template <>
struct mesh_traits<MRMap3>
{
	static constexpr uint32 dimension = 3; ///< The dimension of the map.
	using MapType = MRMap3;                ///< The map type.
	using HalfEdge = MRMap3::HalfEdge;     ///< See MRMap3::HalfEdge.
	using Vertex = MRMap3::Vertex;         ///< See MRMap3::Vertex.
	using Edge = MRMap3::Edge;             ///< See MRMap3::Edge.
	using Face = MRMap3::Face;             ///< See MRMap3::Face.
	using Volume = MRMap3::Volume;         ///< See MRMap3::Volume.
	/// The cell types.
	using Cells = std::tuple<HalfEdge, Vertex, Edge, Face, Volume>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// A level view has the cells of its map.
template <>
struct mesh_traits<MRLevelView3> : mesh_traits<MRMap3>
{
};

namespace detail
{
template <typename M, uint32 I>
requires MRMesh3<M>
struct cell_of_dimension<M, I>
{
	using type = std::tuple_element_t<I, std::tuple<CMap3::Vertex, CMap3::Edge, CMap3::Face, CMap3::Volume>>;
};
} // namespace detail

namespace detail
{
/// What the code shared by the multiresolution maps of every dimension needs
/// to know of the 3-D one: its types and the orbits of its cell slots.
template <>
struct MRDim<MRState3>
{
	using Map = MRMap3;        ///< The multiresolution map.
	using View = MRLevelView3; ///< Its level views.
	using Flat = CMap3;        ///< Its finest map.
	/// The orbits of the slots of MRState3::cells.
	static constexpr std::array<Orbit, 5> orbits{Orbit::PHI21_PHI31, Orbit::PHI2_PHI3, Orbit::PHI1_PHI3,
												 Orbit::PHI1_PHI2, Orbit::PHI1_PHI2_PHI3};
	static constexpr uint32 vertex_slot = 0;    ///< The slot of the vertices.
	static constexpr uint32 edge_slot = 1;      ///< The slot of the edges.
	static constexpr uint32 face_slot = 2;      ///< The slot of the faces.
	static constexpr uint32 volume_slot = 3;    ///< The slot of the volumes.
	static constexpr uint32 component_slot = 4; ///< The slot of the connected components.
	/// The slot of orbit o (5 for an orbit without one).
	static constexpr uint32 slot(Orbit o)
	{
		for (uint32 i = 0; i < orbits.size(); ++i)
			if (orbits[i] == o)
				return i;
		return 5;
	}
};
} // namespace detail

} // namespace cgogn
