// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mr_lines.h>
#include <cgogn/core/map/mrmap2.h>
#include <cgogn/core/marking/dart_marker.h>
#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/parallel.h>

#include <optional>
#include <type_traits>
#include <utility>

namespace cgogn
{

// Traversals of a multiresolution 2-map at its current level, or of a level
// view. They are those of a 2-map, read through phi1 and phi2 at the level:
// each step costs what the level's phi1 costs (see MRMap2), 1 finest step
// at the finest level. Boundary faces are never reported.

namespace detail
{

/// The relations of the level at which m is read (see MRRelations). O(1).
template <MRMesh2 M>
CGOGN_INLINE MRRelations mr_relations(const M& m)
{
	const MRLevelView2 v = read_level(m);
	return MRRelations(v.state(), v.level());
}

/// foreach_dart_of_orbit through the relations r of a level.
template <Orbit O, typename FUNC>
CGOGN_INLINE bool mr_foreach_dart_of_orbit(const MRRelations& r, Cell<O> c, const FUNC& func)
{
	// f's captures in registers across the walk, and f called from one place
	// in it at every level (see MRRelations)
	held_callable_t<FUNC> f = func;
	const Dart d = c.dart;
	if constexpr (O == Orbit::DART)
		return call_and_continue(f, d);
	else if constexpr (O == Orbit::PHI1)
	{
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = r.phi1(it);
		} while (it != d);
		return true;
	}
	else if constexpr (O == Orbit::PHI2)
	{
		Dart it = d;
		for (bool other_side = false;; other_side = true)
		{
			if (!call_and_continue(f, it))
				return false;
			if (other_side)
				return true;
			it = r.phi2(d);
		}
	}
	else if constexpr (O == Orbit::PHI21)
	{
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = r.phi2_and_phi12(it).second;
		} while (it != d);
		return true;
	}
	else
	{
		static_assert(O == Orbit::PHI1_PHI2, "foreach_dart_of_orbit: not an orbit of a 2-map");
		return foreach_dart_flood(
			r.s.map, d, f, [&](Dart x) { return r.phi1(x); }, [&](Dart x) { return r.phi2(x); });
	}
}

} // namespace detail

/// Calls f(Dart) on each dart of the orbit of c at the level read, in the
/// order of a 2-map (faces and vertices in cyclic order); f may return false
/// to stop. Returns false when stopped. O(size of the orbit x cost of a
/// level step); a connected component is flooded with a pooled mark.
template <MRMesh2 M, Orbit O, typename FUNC>
CGOGN_INLINE bool foreach_dart_of_orbit(const M& m, Cell<O> c, const FUNC& f)
{
	return detail::mr_foreach_dart_of_orbit(detail::mr_relations(m), c, f);
}

namespace detail
{

/// Whether d, a live non-boundary dart of the level read, is the dart that
/// reports its cell in the traversals of a level: the smallest non-boundary
/// dart of its orbit at the level. Walks the orbit (no mark), so that
/// parallel traversals need no shared state. Not for connected components.
template <typename CELL>
bool mr_reports_cell(const MRLevelView2& v, Dart d)
{
	constexpr Orbit O = CELL::ORBIT;
	if constexpr (O == Orbit::DART)
		return true;
	else if constexpr (O == Orbit::PHI2)
	{
		const Dart e = mr_phi2(v.state(), v.level(), d);
		return d.index < e.index || is_boundary(v.state().map, e);
	}
	else
	{
		bool smallest = true;
		foreach_dart_of_orbit(v, CELL(d), [&](Dart x) {
			if (x.index < d.index && !is_boundary(v.state().map, x))
				smallest = false;
			return smallest;
		});
		return smallest;
	}
}

} // namespace detail

namespace detail
{
template <Orbit O>
constexpr bool mr_walks_lines()
{
	return O != Orbit::DART && is_mr2_orbit(O);
}
} // namespace detail

template <typename CELL, typename FUNC>
void MRLevelView2::foreach_cell(const FUNC& func) const
{
	static_assert(std::is_same_v<CELL, Cell<CELL::ORBIT>>, "foreach_cell on a multiresolution map: take a plain cell");
	held_callable_t<FUNC> f = func;
	constexpr Orbit O = CELL::ORBIT;
	const detail::MRState2& s = *state_;
	const uint32 l = level_;
	// f called at one place, whatever the way the cells are found (see
	// MRRelations): the lines that hold at the level for an indexed orbit
	// (see MRCellIndex), the finest map's darts otherwise, each asked whether
	// it starts a cell of the level.
	const detail::MRCellIndex* lines = nullptr;
	if constexpr (detail::mr_walks_lines<O>())
		if (s.cells[detail::mr_slot(O)].index != nullptr)
			lines = &s.cells[detail::mr_slot(O)];
	const bool indexed = lines != nullptr;
	const AttributeContainer& walked =
		indexed ? *detail::state_of(s.map).cells[orbit_index(O)] : *detail::state_of(s.map).darts;
	// the finest level unindexed: the finest map's cells (which indexes none of
	// its orbits); below it: the darts of the level, a component's flooded
	// with a mark, the other cells from the dart that reports them
	const bool finest = detail::mr_is_finest(*this);
	const bool finest_cells = O != Orbit::DART && !indexed && finest;
	std::optional<detail::UnindexedCellStarts<O, CMap2>> starts;
	std::optional<DartMarkerStore<CMap2>> seen;
	if (finest_cells)
		starts.emplace(s.map);
	else if (O == Orbit::PHI1_PHI2 && !indexed)
		seen.emplace(s.map);
	const auto dart_level = s.level->view();
	// the lines' levels, held in locals (the darts' levels in their place, unread, when not indexed)
	const auto line_level = indexed ? lines->level->view() : dart_level;
	const auto replaced = indexed ? lines->replaced->view() : dart_level;
	const auto key = walked.key().view(); // a line's dart, or a dart's phi1: INVALID_INDEX on free lines
	const uint32 end = walked.end_index();
	const bool finest_lines = indexed && finest;
	uint32 i = 0;
	// the next cell from line or dart i on (INVALID at the end), each way of
	// finding them with its own loop; the finest level's lines first, the
	// common case, with their views in registers
	auto next_cell = [&]() -> Dart {
		if (finest_lines) [[likely]]
		{
			for (; i < end; ++i)
				if (replaced[i] > l && key[i] != INVALID_INDEX)
					return Dart(key[i++]);
			return Dart();
		}
		if (indexed)
		{
			for (; i < end; ++i)
				if (replaced[i] > l && line_level[i] <= l && key[i] != INVALID_INDEX)
					return Dart(key[i++]);
			return Dart();
		}
		for (; i < end; ++i)
		{
			const Dart d(i);
			if (key[i] == INVALID_INDEX)
				continue;
			if (finest_cells)
			{
				if (starts->starts_cell(d))
					return Dart(i++);
				continue;
			}
			if (dart_level[i] > l || is_boundary(s.map, d))
				continue;
			if constexpr (O == Orbit::PHI1_PHI2)
			{
				if (seen->is_marked(d))
					continue;
				foreach_dart_of_orbit(*this, CELL(d), [&](Dart x) { seen->mark(x); });
				return Dart(i++);
			}
			else if (detail::mr_reports_cell<CELL>(*this, d))
				return Dart(i++);
		}
		return Dart();
	};
	for (;;)
	{
		const Dart d = next_cell();
		if (!d.is_valid() || !call_and_continue(f, CELL(d)))
			return;
	}
}

template <typename CELL, typename FUNC>
void MRLevelView2::parallel_foreach_cell(const FUNC& f) const
{
	constexpr Orbit O = CELL::ORBIT;
	if (detail::run_sequentially() || (O == Orbit::PHI1_PHI2 && state_->cells[3].index == nullptr))
	{
		foreach_cell<CELL>(f);
		return;
	}
	if constexpr (detail::mr_walks_lines<O>())
	{
		constexpr uint32 slot = detail::mr_slot(O);
		if (state_->cells[slot].index != nullptr)
		{
			const AttributeContainer& c = *detail::state_of(state_->map).cells[orbit_index(O)];
			const auto key = c.key().view();
			detail::parallel_for_chunks(c.end_index(), detail::PARALLEL_LINE_GRAIN,
										detail::ChunkBody([&](uint32 b, uint32 e) {
											held_callable_t<FUNC> fc = f; // see held_callable_t
											detail::mr_foreach_line_holding(*state_, slot, level_, b, e,
																			[&](uint32 i) { fc(CELL(Dart(key[i]))); });
										}));
			return;
		}
	}
	if (detail::mr_is_finest(*this))
	{
		cgogn::parallel_foreach_cell(state_->map, [&](CELL c) { f(c); });
		return;
	}
	const auto level = state_->level->view();
	const auto key = detail::state_of(state_->map).darts->key().view();
	detail::parallel_for_chunks(detail::state_of(state_->map).darts->end_index(), detail::PARALLEL_LINE_GRAIN,
								detail::ChunkBody([&](uint32 b, uint32 e) {
									held_callable_t<FUNC> fc = f; // see held_callable_t
									for (uint32 i = b; i < e; ++i)
									{
										const Dart d(i);
										if (key[i] == INVALID_INDEX || level[i] > level_ ||
											is_boundary(state_->map, d) || !detail::mr_reports_cell<CELL>(*this, d))
											continue;
										fc(CELL(d));
									}
								}));
}

template <typename CELL, typename FUNC>
void MRMap2::foreach_cell(const FUNC& f) const
{
	detail::read_level(*this).foreach_cell<CELL>(f);
}

template <typename CELL, typename FUNC>
void MRMap2::parallel_foreach_cell(const FUNC& f) const
{
	detail::read_level(*this).parallel_foreach_cell<CELL>(f);
}

namespace detail
{

/// What a vertex of level l >= 1 comes from at level l - 1 (see mr_vertex_origin).
enum class MRVertexOrigin
{
	Old,      ///< a vertex of level l - 1; the dart is one of its darts there
	Midpoint, ///< the midpoint of an edge of level l - 1; the dart is a dart of that edge
	Centre,   ///< the centre of a face of level l - 1; the dart is a dart of that face
	Unknown,  ///< none of these (a pattern that makes other vertices)
};

/// What vertex v (any of its darts) of level l >= 1 is at level l - 1, with
/// a dart of level <= l - 1 there: a piece of a cut edge has an old dart on
/// its other side at level l, a centre has an old corner in each of its
/// faces. O(degree of v + degree of one of its faces) level steps.
inline std::pair<MRVertexOrigin, Dart> mr_vertex_origin(const MRState2& s, uint32 l, Dart v)
{
	const MRLevelView2 f(s, l);
	const auto level = s.level->view();
	std::pair<MRVertexOrigin, Dart> r{MRVertexOrigin::Unknown, Dart()};
	foreach_dart_of_orbit(f, MRMap2::Vertex(v), [&](Dart d) {
		if (level[d.index] < l)
			r = {MRVertexOrigin::Old, d};
		else if (const Dart e = mr_phi2(s, l, d); level[e.index] < l)
			r = {MRVertexOrigin::Midpoint, e};
		return r.first != MRVertexOrigin::Old; // an old dart decides
	});
	if (r.first != MRVertexOrigin::Unknown)
		return r;
	foreach_dart_of_orbit(f, MRMap2::Face(v), [&](Dart d) {
		if (level[d.index] < l)
			r = {MRVertexOrigin::Centre, d};
		return r.first == MRVertexOrigin::Unknown;
	});
	return r;
}

} // namespace detail

// ---- local traversals: those of a 2-map (see local_cmap2.h), at the level read
//
// Each walks the darts through the relations of the level (detail::MRRelations)
// and calls its callable from one place, at every level: the finest level is
// not handed to the finest map's own traversals, which would make a second
// place (see detail::MRRelations).

/// Edges incident to vertex v, in cyclic order.
template <MRMesh2 M, typename FUNC>
CGOGN_INLINE void foreach_incident_edge(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	const detail::MRRelations r = detail::mr_relations(m);
	detail::mr_foreach_dart_of_orbit(r, v, [&](Dart d) { return call_and_continue(f, MRMap2::Edge(d)); });
}

/// Faces incident to vertex v, in cyclic order (boundary faces skipped).
template <MRMesh2 M, typename FUNC>
CGOGN_INLINE void foreach_incident_face(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	const detail::MRRelations r = detail::mr_relations(m);
	detail::mr_foreach_dart_of_orbit(
		r, v, [&](Dart d) { return is_boundary(r.s.map, d) || call_and_continue(f, MRMap2::Face(d)); });
}

/// Vertices joined to v by an edge, in cyclic order.
template <MRMesh2 M, typename FUNC>
CGOGN_INLINE void foreach_adjacent_vertex_through_edge(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	const detail::MRRelations r = detail::mr_relations(m);
	// the vertex walk written out: each step reads phi2 once, for the
	// neighbour and for the next step, and tests the level once
	held_callable_t<FUNC> fh = f;
	const Dart d = v.dart;
	Dart it = d;
	do
	{
		const auto [e, next] = r.phi2_and_phi12(it);
		if (!call_and_continue(fh, MRMap2::Vertex(e)))
			return;
		it = next;
	} while (it != d);
}

/// Vertices sharing a face with v (v excluded): the edge neighbours in cyclic
/// order, each followed by the other vertices of the next incident face.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_vertex_through_face(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	const detail::MRRelations r = detail::mr_relations(m);
	detail::mr_foreach_dart_of_orbit(r, v, [&](Dart d) {
		// the neighbour across d's edge, then the other vertices of d's face
		// but the one before v (the next edge neighbour): one call in a loop
		// (see detail::MRRelations)
		const bool inner = !is_boundary(r.s.map, d);
		Dart x = r.phi2(d);
		Dart y = inner ? r.phi1(r.phi1(d)) : d;
		for (;;)
		{
			if (!call_and_continue(f, MRMap2::Vertex(x)))
				return false;
			if (!inner)
				return true;
			const Dart z = r.phi1(y);
			if (z == d)
				return true;
			x = y;
			y = z;
		}
	});
}

/// The two vertices of edge e: the origin of e.dart first.
template <MRMesh2 M, typename FUNC>
void foreach_incident_vertex(const M& m, MRMap2::Edge e, const FUNC& f)
{
	foreach_dart_of_orbit(m, e, [&](Dart d) { return call_and_continue(f, MRMap2::Vertex(d)); });
}

/// The one or two faces incident to edge e (boundary faces skipped).
template <MRMesh2 M, typename FUNC>
void foreach_incident_face(const M& m, MRMap2::Edge e, const FUNC& f)
{
	const detail::MRState2& s = detail::read_level(m).state();
	foreach_dart_of_orbit(m, e, [&](Dart d) { return is_boundary(s.map, d) || call_and_continue(f, MRMap2::Face(d)); });
}

/// Edges sharing a vertex with e (e excluded): around the origin of e.dart,
/// then around the other end.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_edge_through_vertex(const M& m, MRMap2::Edge e, const FUNC& f)
{
	const detail::MRRelations r = detail::mr_relations(m);
	const Dart ends[2] = {e.dart, r.phi2(e.dart)};
	for (const Dart start : ends)
		for (Dart it = r.phi1(r.phi2(start)); it != start; it = r.phi1(r.phi2(it)))
			if (!call_and_continue(f, MRMap2::Edge(it)))
				return;
}

/// Edges sharing a (non-boundary) face with e, e excluded.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_edge_through_face(const M& m, MRMap2::Edge e, const FUNC& f)
{
	const detail::MRRelations r = detail::mr_relations(m);
	const Dart sides[2] = {e.dart, r.phi2(e.dart)};
	for (const Dart start : sides)
	{
		if (is_boundary(r.s.map, start))
			continue;
		for (Dart it = r.phi1(start); it != start; it = r.phi1(it))
			if (!call_and_continue(f, MRMap2::Edge(it)))
				return;
	}
}

/// Vertices of face f in phi1 order.
template <MRMesh2 M, typename FUNC>
CGOGN_INLINE void foreach_incident_vertex(const M& m, MRMap2::Face f, const FUNC& fn)
{
	foreach_dart_of_orbit(m, f, [&](Dart d) { return call_and_continue(fn, MRMap2::Vertex(d)); });
}

/// Edges of face f in phi1 order.
template <MRMesh2 M, typename FUNC>
CGOGN_INLINE void foreach_incident_edge(const M& m, MRMap2::Face f, const FUNC& fn)
{
	foreach_dart_of_orbit(m, f, [&](Dart d) { return call_and_continue(fn, MRMap2::Edge(d)); });
}

/// Faces across the edges of f (boundary faces skipped), in phi1 order.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_face_through_edge(const M& m, MRMap2::Face f, const FUNC& fn)
{
	const detail::MRRelations r = detail::mr_relations(m);
	detail::mr_foreach_dart_of_orbit(r, f, [&](Dart d) {
		const Dart d2 = r.phi2(d);
		return is_boundary(r.s.map, d2) || call_and_continue(fn, MRMap2::Face(d2));
	});
}

/// Faces sharing at least a vertex with f (f excluded), each once on a
/// manifold mesh: around each vertex of f in turn.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_face_through_vertex(const M& m, MRMap2::Face f, const FUNC& fn)
{
	const detail::MRRelations r = detail::mr_relations(m);
	detail::mr_foreach_dart_of_orbit(r, f, [&](Dart d) {
		for (Dart it = r.phi1(r.phi2(d)); it != d;)
		{
			const Dart next = r.phi1(r.phi2(it));
			if (next == d)
				break;
			if (!is_boundary(r.s.map, it) && !call_and_continue(fn, MRMap2::Face(it)))
				return false;
			it = next;
		}
		return true;
	});
}

/// The connected component of cell c.
template <MRMesh2 M, Orbit O, typename FUNC>
requires(O != Orbit::PHI1_PHI2) void foreach_incident_volume(const M&, Cell<O> c, const FUNC& f)
{
	call_and_continue(f, MRMap2::Volume(c.dart));
}

namespace detail
{
/// Calls f once per cell of type CELL of the connected component of `start`
/// at the level read, boundary cells skipped.
template <typename CELL, typename FUNC>
void mr_foreach_cell_of_volume(const MRLevelView2& v, Dart start, const FUNC& f)
{
	const MRRelations r(v.state(), v.level());
	const CMap2& map = v.state().map;
	DartMarkerStore<CMap2> done(map);
	mr_foreach_dart_of_orbit(r, MRMap2::Volume(start), [&](Dart d) {
		if (done.is_marked(d))
			return true;
		bool real = false; // a vertex is real when one of its darts is
		mr_foreach_dart_of_orbit(r, CELL(d), [&](Dart x) {
			done.mark(x);
			if constexpr (CELL::ORBIT == Orbit::PHI21)
				real = real || !is_boundary(map, x);
		});
		if constexpr (CELL::ORBIT == Orbit::PHI21)
			return !real || call_and_continue(f, CELL(d));
		else if constexpr (CELL::ORBIT == Orbit::PHI2)
			return (is_boundary(map, d) && is_boundary(map, r.phi2(d))) || call_and_continue(f, CELL(d));
		else
			return is_boundary(map, d) || call_and_continue(f, CELL(d));
	});
}
} // namespace detail

/// Vertices of connected component w (no defined order).
template <MRMesh2 M, typename FUNC>
void foreach_incident_vertex(const M& m, MRMap2::Volume w, const FUNC& f)
{
	detail::mr_foreach_cell_of_volume<MRMap2::Vertex>(detail::read_level(m), w.dart, f);
}
/// Edges of connected component w (no defined order).
template <MRMesh2 M, typename FUNC>
void foreach_incident_edge(const M& m, MRMap2::Volume w, const FUNC& f)
{
	detail::mr_foreach_cell_of_volume<MRMap2::Edge>(detail::read_level(m), w.dart, f);
}
/// Faces of connected component w, boundary faces skipped (no defined order).
template <MRMesh2 M, typename FUNC>
void foreach_incident_face(const M& m, MRMap2::Volume w, const FUNC& f)
{
	detail::mr_foreach_cell_of_volume<MRMap2::Face>(detail::read_level(m), w.dart, f);
}

// ---- properties at the level read

/// Number of edges incident to v. O(degree x cost of a level step).
template <MRMesh2 M>
uint32 degree(const M& m, MRMap2::Vertex v)
{
	uint32 n = 0;
	foreach_dart_of_orbit(m, v, [&](Dart) { ++n; });
	return n;
}
/// Number of non-boundary faces incident to e (1 or 2). O(1 level step).
template <MRMesh2 M>
uint32 degree(const M& m, MRMap2::Edge e)
{
	return uint32(!is_boundary(m, e.dart)) + uint32(!is_boundary(m, phi2(m, e.dart)));
}
/// Number of edges of face f. O(codegree x cost of a level step).
template <MRMesh2 M>
uint32 codegree(const M& m, MRMap2::Face f)
{
	uint32 n = 0;
	foreach_dart_of_orbit(m, f, [&](Dart) { ++n; });
	return n;
}
/// Whether v lies on the boundary. O(degree x cost of a level step).
template <MRMesh2 M>
bool is_incident_to_boundary(const M& m, MRMap2::Vertex v)
{
	bool b = false;
	foreach_dart_of_orbit(m, v, [&](Dart d) { return !(b = is_boundary(m, d)); });
	return b;
}
/// Whether e lies on the boundary. O(1 level step).
template <MRMesh2 M>
bool is_incident_to_boundary(const M& m, MRMap2::Edge e)
{
	return is_boundary(m, e.dart) || is_boundary(m, phi2(m, e.dart));
}

} // namespace cgogn
