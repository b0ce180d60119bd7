// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/darts.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/map/mr_common.h>

#include <array>
#include <memory>
#include <utility>
#include <vector>

namespace cgogn
{

class MRMap2;

namespace detail
{

/// The lines of one orbit of a multiresolution map, in the container of that
/// orbit in the finest map (whose own indexing of the orbit is off: its
/// operators run with set_indices = false). A cell has a line at every level
/// where it differs from the level below: a vertex at every level from its
/// creation on, an edge or face from its creation until it is refined (its
/// children get lines of their own), a connected component once. Each dart
/// holds the line of its cell at the finest level; `down` leads from a line
/// to the line of the same place one version coarser.
struct MRCellIndex
{
	AttributeArray<uint32>* index = nullptr;         ///< Per dart: its finest cell's line; nullptr while not indexed.
	std::shared_ptr<AttributeArray<uint32>> down;    ///< Per line: the line it refines (INVALID_INDEX: none).
	std::shared_ptr<AttributeArray<uint8>> level;    ///< Per line: the level from which the line holds.
	std::shared_ptr<AttributeArray<uint8>> replaced; ///< Per line: the level from which it does not (255: never).
};

/// The replaced level of a line that holds up to the finest level.
inline constexpr uint8 MR_NOT_REPLACED = 255;

/// The slot of an orbit in MRState2::cells: vertex, edge, face, component.
constexpr uint32 mr_slot(Orbit o)
{
	return o == Orbit::PHI21 ? 0 : o == Orbit::PHI2 ? 1 : o == Orbit::PHI1 ? 2 : 3;
}
/// Whether the orbit can carry attributes on a multiresolution 2-map.
constexpr bool is_mr2_orbit(Orbit o)
{
	return o == Orbit::PHI21 || o == Orbit::PHI2 || o == Orbit::PHI1 || o == Orbit::PHI1_PHI2;
}
/// The orbits of the slots of MRState2::cells.
inline constexpr Orbit MR2_ORBITS[4] = {Orbit::PHI21, Orbit::PHI2, Orbit::PHI1, Orbit::PHI1_PHI2};

/// What a multiresolution 2-map holds (see MRMap2): the finest map and the
/// labels of its darts. Not part of the API.
struct MRState2
{
	CMap2 map;                                    ///< The finest map: the darts of every level.
	std::shared_ptr<AttributeArray<uint8>> level; ///< Per dart: the level at which it was created.
	/// Per dart: the id of its edge, shared by the pieces of a cut edge and
	/// different from the ids of the edges that the edge's later midpoints are
	/// the middle of (see mr_phi1).
	std::shared_ptr<AttributeArray<uint8>> edge_id;
	/// darts_per_level[l]: the live darts created at level l. Its size is
	/// max_level + 1.
	std::vector<uint32> darts_per_level;
	uint32 current_level = 0;
	/// The lines of vertices, edges, faces and connected components (see mr_slot).
	std::array<MRCellIndex, 4> cells;
};

MRState2& mr_state_of(MRMap2& m);
const MRState2& mr_state_of(const MRMap2& m);

} // namespace detail

/// A multiresolution 2-map in the compact primal hierarchy (CPH) model: only
/// the finest map is stored, with per-dart labels (a creation level and an
/// edge id, 2 bytes per dart). The mesh at level l is made of the darts of
/// level <= l: phi1 at level l walks the finest map, turning around the
/// vertices born after level l until the edge id matches; phi2 at level l
/// follows from it. Every generic function (phi1, phi2, foreach_cell, the
/// local traversals, nb_cells, degree, check_integrity, ...) works at the
/// map's current level; level_view(m, l) reads another level at the same
/// time. Levels are added by add_level and removed by remove_finest_level.
///
/// Maps can be moved, not copied. The finest map is read-only from outside
/// (finest_map): its connectivity is changed only through the operators of
/// MRMap2, which keep the labels right.
class MRMap2
{
public:
	static constexpr uint32 dimension = 2; ///< The dimension of the map.

	using HalfEdge = CMap2::HalfEdge; ///< A dart of level <= the level read.
	using Vertex = CMap2::Vertex;     ///< A vertex: the darts leaving it, at the level read.
	using Edge = CMap2::Edge;         ///< An edge: its two darts at the level read.
	using Face = CMap2::Face;         ///< A face: a phi1 cycle at the level read.
	using Volume = CMap2::Volume;     ///< A connected component.

	/// Makes `base` the level 0 of a new hierarchy: every dart gets level 0
	/// and edge id 0. The map keeps its attributes. Precondition: `base` is
	/// closed (check_integrity passes). O(number of darts).
	explicit MRMap2(CMap2&& base);

	/// Takes the hierarchy of another map; the moved-from map may only be
	/// destroyed or assigned to. O(1).
	MRMap2(MRMap2&&) = default;
	/// Replaces this hierarchy by another one. O(size of the replaced map).
	MRMap2& operator=(MRMap2&&) = default;
	MRMap2(const MRMap2&) = delete;
	MRMap2& operator=(const MRMap2&) = delete;

	/// Implements foreach_cell(m, f) at the current level (see local_mrmap2.h).
	template <typename CELL, typename FUNC>
	void foreach_cell(const FUNC& f) const;
	/// Implements parallel_foreach_cell(m, f) at the current level (see local_mrmap2.h).
	template <typename CELL, typename FUNC>
	void parallel_foreach_cell(const FUNC& f) const;

private:
	friend detail::MRState2& detail::mr_state_of(MRMap2& m);
	friend const detail::MRState2& detail::mr_state_of(const MRMap2& m);

	detail::MRState2 state_;
};

namespace detail
{
inline MRState2& mr_state_of(MRMap2& m)
{
	return m.state_;
}
inline const MRState2& mr_state_of(const MRMap2& m)
{
	return m.state_;
}
} // namespace detail

/// A read-only view of a multiresolution 2-map at one level: every generic
/// function reads it as the map of that level. Views are cheap to copy (a
/// pointer and a level); any number of them, at any levels, can be read at
/// once, also from several threads, as long as the map is not changed
/// meanwhile. A view is invalidated by every change of the hierarchy that
/// removes its level.
class MRLevelView2
{
public:
	static constexpr uint32 dimension = 2; ///< The dimension of the map.

	using HalfEdge = MRMap2::HalfEdge; ///< See MRMap2::HalfEdge.
	using Vertex = MRMap2::Vertex;     ///< See MRMap2::Vertex.
	using Edge = MRMap2::Edge;         ///< See MRMap2::Edge.
	using Face = MRMap2::Face;         ///< See MRMap2::Face.
	using Volume = MRMap2::Volume;     ///< See MRMap2::Volume.

	/// The view of m at level l. Precondition: l <= max_level(m). O(1).
	MRLevelView2(const MRMap2& m, uint32 l) : state_(&detail::mr_state_of(m)), level_(l)
	{
	}

	/// The view of the hierarchy in state s at level l (core's
	/// implementation only, for a hierarchy being built). O(1).
	MRLevelView2(const detail::MRState2& s, uint32 l) : state_(&s), level_(l)
	{
	}

	/// The level read. O(1).
	uint32 level() const
	{
		return level_;
	}
	/// The hierarchy's state (core's implementation only). O(1).
	const detail::MRState2& state() const
	{
		return *state_;
	}

	/// Implements foreach_cell(view, f) (see local_mrmap2.h).
	template <typename CELL, typename FUNC>
	void foreach_cell(const FUNC& f) const;
	/// Implements parallel_foreach_cell(view, f) (see local_mrmap2.h).
	template <typename CELL, typename FUNC>
	void parallel_foreach_cell(const FUNC& f) const;

private:
	const detail::MRState2* state_;
	uint32 level_;
};

/// The multiresolution 2-map or one of its level views.
template <typename M>
concept MRMesh2 = std::same_as<M, MRMap2> || std::same_as<M, MRLevelView2>;

/// The finest map of m: the darts and attributes of every level, read as a
/// flat CMap2. O(1).
inline const CMap2& finest_map(const MRMap2& m)
{
	return detail::mr_state_of(m).map;
}

/// The finest level of m (0 for a map without refinement). O(1).
inline uint32 max_level(const MRMap2& m)
{
	return uint32(detail::mr_state_of(m).darts_per_level.size() - 1);
}

/// The level at which the generic functions read m. O(1).
inline uint32 current_level(const MRMap2& m)
{
	return detail::mr_state_of(m).current_level;
}

/// Makes the generic functions read m at level l. Throws std::out_of_range
/// when l > max_level(m). O(1).
void set_current_level(MRMap2& m, uint32 l);

/// The read-only view of m at level l (see MRLevelView2). Throws
/// std::out_of_range when l > max_level(m). O(1).
MRLevelView2 level_view(const MRMap2& m, uint32 l);

/// The level at which dart d was created. O(1).
inline uint32 dart_level(const MRMap2& m, Dart d)
{
	return (*detail::mr_state_of(m).level)[d.index];
}

/// The number of live darts created at level l (0 above max_level). A mesh
/// at level l has the darts created at levels 0 ... l. O(1).
inline uint32 nb_darts_at_level(const MRMap2& m, uint32 l)
{
	const auto& c = detail::mr_state_of(m).darts_per_level;
	return l < c.size() ? c[l] : 0;
}

namespace detail
{

/// The view at which the generic functions read an MR mesh: the view itself,
/// or a multiresolution map's current level. O(1).
inline MRLevelView2 read_level(const MRLevelView2& v)
{
	return v;
}
inline MRLevelView2 read_level(const MRMap2& m)
{
	return MRLevelView2(m, current_level(m));
}

/// Whether level l is the finest level of s (or above it), where the
/// relations and cells are those of the finest map. O(1).
CGOGN_INLINE bool mr_is_finest(const MRState2& s, uint32 l)
{
	return l + 1 >= s.darts_per_level.size();
}
/// Whether view v reads the finest level. O(1).
CGOGN_INLINE bool mr_is_finest(const MRLevelView2& v)
{
	return mr_is_finest(v.state(), v.level());
}

/// phi1 at level l (Untereiner et al., the CPH model): from d, walk the
/// finest face; at every vertex born after level l, turn around it to the
/// piece of d's edge (the dart with d's edge id) and go on, until a dart of
/// level <= l. O(number of finest darts walked): 1 at the finest level,
/// about 2^(max_level - l) pieces of the edge below it. With a limited
/// budget, INVALID when it runs out.
template <typename BUDGET = MRNoStepLimit>
CGOGN_INLINE Dart mr_phi1(const MRState2& s, uint32 l, Dart d, BUDGET budget = {})
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
			it = phi1(s.map, phi2(s.map, it));
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
CGOGN_INLINE Dart mr_phi_1(const MRState2& s, uint32 l, Dart d, BUDGET budget = {})
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
			it = phi_1(s.map, phi2(s.map, it));
		}
	}
	return it;
}

/// phi2 at level l: the dart of the other side of d's edge at level l, which
/// leaves the end of d. O(cost of mr_phi1 + degree of a finest face).
CGOGN_INLINE Dart mr_phi2(const MRState2& s, uint32 l, Dart d)
{
	if (mr_is_finest(s, l))
		return phi2(s.map, d);
	return phi2(s.map, phi_1(s.map, mr_phi1(s, l, d)));
}

/// mr_phi1 and mr_phi2 out of line, for the relations' walks below the
/// finest level: kept out of the finest level's loops, whose registers
/// they would otherwise take. O(cost of the walk) plus a call.
[[gnu::noinline, gnu::cold]] inline Dart mr_phi1_out_of_line(const MRState2& s, uint32 l, Dart d)
{
	return mr_phi1(s, l, d);
}
[[gnu::noinline, gnu::cold]] inline Dart mr_phi2_out_of_line(const MRState2& s, uint32 l, Dart d)
{
	return mr_phi2(s, l, d);
}

/// The relations of one level, held by a walk for its whole length: at the
/// finest level, the finest map's phi1 and phi2 through views held in the
/// walk's locals (see LineStorage::View); below it, the level walks. The
/// traversals step through them, so that each calls its callable from one
/// place whatever the level: called from two (the finest map's own traversal
/// and the level walk), the compilers keep the callable out of line, and
/// every dart then pays a call and reloads what the callable captured (the
/// circulator of bench_mr 1.6 times the flat map's at the finest level).
struct MRRelations
{
	using RelationView = decltype(std::declval<const AttributeArray<uint32>&>().view());

	const MRState2& s;
	uint32 l;
	bool finest;          ///< Whether l is the finest level (see mr_is_finest).
	RelationView phi1_of; ///< The finest map's phi1.
	RelationView phi2_of; ///< The finest map's phi2.

	CGOGN_INLINE MRRelations(const MRState2& state, uint32 level)
		: s(state), l(level), finest(mr_is_finest(state, level)), phi1_of(state_of(state.map).phi1->view()),
		  phi2_of(state_of(state.map).phi2->view())
	{
	}

	/// phi1 at the level.
	CGOGN_INLINE Dart phi1(Dart d) const
	{
		if (finest) [[likely]]
			return Dart(phi1_of[d.index]);
		return mr_phi1_out_of_line(s, l, d);
	}
	/// phi2 at the level.
	CGOGN_INLINE Dart phi2(Dart d) const
	{
		if (finest) [[likely]]
			return Dart(phi2_of[d.index]);
		return mr_phi2_out_of_line(s, l, d);
	}
	/// phi2 and phi1 o phi2 at the level: the dart across d's edge and the
	/// next dart around d's vertex, with one test of the level. The next
	/// dart's phi2 is prefetched at the finest level, as in the finest
	/// map's vertex walk.
	CGOGN_INLINE std::pair<Dart, Dart> phi2_and_phi12(Dart d) const
	{
		if (finest) [[likely]]
		{
			const uint32 e = phi2_of[d.index];
			const uint32 n = phi1_of[e];
			CGOGN_PREFETCH(&phi2_of[n]);
			return {Dart(e), Dart(n)};
		}
		const Dart e = mr_phi2_out_of_line(s, l, d);
		return {e, mr_phi1_out_of_line(s, l, e)};
	}
};

} // namespace detail

/// phi1 at the level read (see MRMap2). Precondition: dart_level(d) <= that
/// level. O(1) at the finest level, O(pieces of the edge walked) below.
template <MRMesh2 M>
CGOGN_INLINE Dart phi1(const M& m, Dart d)
{
	const MRLevelView2 v = detail::read_level(m);
	return detail::mr_phi1(v.state(), v.level(), d);
}

/// phi_1 at the level read: the inverse of phi1. Same precondition and cost.
template <MRMesh2 M>
CGOGN_INLINE Dart phi_1(const M& m, Dart d)
{
	const MRLevelView2 v = detail::read_level(m);
	return detail::mr_phi_1(v.state(), v.level(), d);
}

/// phi2 at the level read. Same precondition; costs one phi1 and one phi_1
/// of the finest map more.
template <MRMesh2 M>
CGOGN_INLINE Dart phi2(const M& m, Dart d)
{
	const MRLevelView2 v = detail::read_level(m);
	return detail::mr_phi2(v.state(), v.level(), d);
}

/// Whether d is a boundary dart (the same at every level). O(1).
template <MRMesh2 M>
CGOGN_INLINE bool is_boundary(const M& m, Dart d)
{
	return is_boundary(detail::read_level(m).state().map, d);
}

/// Whether d belongs to the mesh read: a live dart of level <= that level.
/// O(1).
template <MRMesh2 M>
bool is_dart_valid(const M& m, Dart d)
{
	const MRLevelView2 v = detail::read_level(m);
	return is_dart_valid(v.state().map, d) && (*v.state().level)[d.index] <= v.level();
}

/// The number of darts of the mesh read (levels 0 ... the level read). O(levels).
template <MRMesh2 M>
uint32 nb_darts(const M& m)
{
	const MRLevelView2 v = detail::read_level(m);
	uint32 n = 0;
	for (uint32 l = 0; l <= v.level(); ++l)
		n += v.state().darts_per_level[l];
	return n;
}

/// Calls f(Dart) on the darts of the mesh read (boundary darts included);
/// f may return false to stop. O(number of darts of the finest map).
template <MRMesh2 M, typename FUNC>
void foreach_dart(const M& m, const FUNC& f)
{
	const MRLevelView2 v = detail::read_level(m);
	const auto level = v.state().level->view();
	foreach_dart(v.state().map, [&](Dart d) { return level[d.index] > v.level() || call_and_continue(f, d); });
}

/// The traits of a multiresolution 2-map: those of a 2-map.
template <>
struct mesh_traits<MRMap2>
{
	static constexpr uint32 dimension = 2; ///< The dimension of the map.
	using MapType = MRMap2;                ///< The map type.
	using HalfEdge = MRMap2::HalfEdge;     ///< See MRMap2::HalfEdge.
	using Vertex = MRMap2::Vertex;         ///< See MRMap2::Vertex.
	using Edge = MRMap2::Edge;             ///< See MRMap2::Edge.
	using Face = MRMap2::Face;             ///< See MRMap2::Face.
	using Volume = MRMap2::Volume;         ///< See MRMap2::Volume.
	/// The cell types.
	using Cells = std::tuple<HalfEdge, Vertex, Edge, Face, Volume>;
	template <typename T>
	using Attribute = cgogn::AttributeArray<T>; ///< An attribute of values of type T, of any orbit.
	using AttributeGen = AttributeBase;         ///< An attribute of any type (type-erased).
};

/// A level view has the cells of its map.
template <>
struct mesh_traits<MRLevelView2> : mesh_traits<MRMap2>
{
};

namespace detail
{
template <typename M, uint32 I>
requires MRMesh2<M>
struct cell_of_dimension<M, I>
{
	using type = std::tuple_element_t<I, std::tuple<CMap2::Vertex, CMap2::Edge, CMap2::Face, CMap2::Volume>>;
};
} // namespace detail

} // namespace cgogn
