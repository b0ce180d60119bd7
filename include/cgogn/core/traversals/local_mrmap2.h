// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mrmap2.h>
#include <cgogn/core/marking/dart_marker.h>
#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/parallel.h>

#include <type_traits>

namespace cgogn
{

// Traversals of a multiresolution 2-map at its current level, or of a level
// view. They are those of a 2-map, read through phi1 and phi2 at the level:
// each step costs what the level's phi1 costs (see MRMap2), 1 finest step
// at the finest level. Boundary faces are never reported.

/// Calls f(Dart) on each dart of the orbit of c at the level read, in the
/// order of a 2-map (faces and vertices in cyclic order); f may return false
/// to stop. Returns false when stopped. O(size of the orbit x cost of a
/// level step); a connected component is flooded with a pooled mark.
template <MRMesh2 M, Orbit O, typename FUNC>
bool foreach_dart_of_orbit(const M& m, Cell<O> c, const FUNC& f)
{
	const MRLevelView2 v = detail::read_level(m);
	const detail::MRState2& s = v.state();
	if (detail::mr_is_finest(v))
		return foreach_dart_of_orbit(s.map, c, f); // the finest map's own walk
	const uint32 l = v.level();
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
			it = detail::mr_phi1(s, l, it);
		} while (it != d);
		return true;
	}
	else if constexpr (O == Orbit::PHI2)
		return call_and_continue(f, d) && call_and_continue(f, detail::mr_phi2(s, l, d));
	else if constexpr (O == Orbit::PHI21)
	{
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = detail::mr_phi1(s, l, detail::mr_phi2(s, l, it));
		} while (it != d);
		return true;
	}
	else
	{
		static_assert(O == Orbit::PHI1_PHI2, "foreach_dart_of_orbit: not an orbit of a 2-map");
		return detail::foreach_dart_flood(
			s.map, d, f, [&](Dart x) { return detail::mr_phi1(s, l, x); },
			[&](Dart x) { return detail::mr_phi2(s, l, x); });
	}
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
/// Calls f(line) on every line of slot `slot` that holds at level l (see
/// MRCellIndex), for lines [b, e) of the container.
template <typename FUNC>
void mr_foreach_line_at_level(const MRState2& s, uint32 slot, uint32 l, uint32 b, uint32 e, const FUNC& f)
{
	const AttributeContainer& c = *state_of(s.map).cells[orbit_index(MR2_ORBITS[slot])];
	const auto key = c.key().view();
	const auto level = s.cells[slot].level->view();
	const auto replaced = s.cells[slot].replaced->view();
	for (uint32 i = b; i < e; ++i)
		if (key[i] != INVALID_INDEX && level[i] <= l && replaced[i] > l && !call_and_continue(f, i))
			return;
}
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
	if constexpr (detail::mr_walks_lines<O>())
	{
		// an indexed orbit: the lines that hold at the level
		constexpr uint32 slot = detail::mr_slot(O);
		if (state_->cells[slot].index != nullptr)
		{
			const AttributeContainer& c = *detail::state_of(state_->map).cells[orbit_index(O)];
			const auto key = c.key().view();
			detail::mr_foreach_line_at_level(*state_, slot, level_, 0, c.end_index(),
											 [&](uint32 i) { return call_and_continue(f, CELL(Dart(key[i]))); });
			return;
		}
	}
	if (detail::mr_is_finest(*this))
	{
		// the cells of the finest map (which indexes none of its orbits)
		cgogn::foreach_cell(state_->map, [&](CELL c) { return call_and_continue(f, c); });
		return;
	}
	const auto level = state_->level->view();
	if constexpr (O == Orbit::PHI1_PHI2)
	{
		DartMarkerStore<CMap2> seen(state_->map);
		foreach_dart(state_->map, [&](Dart d) {
			if (level[d.index] > level_ || is_boundary(state_->map, d) || seen.is_marked(d))
				return true;
			foreach_dart_of_orbit(*this, CELL(d), [&](Dart x) { seen.mark(x); });
			return call_and_continue(f, CELL(d));
		});
	}
	else
		foreach_dart(state_->map, [&](Dart d) {
			if (level[d.index] > level_ || is_boundary(state_->map, d) || !detail::mr_reports_cell<CELL>(*this, d))
				return true;
			return call_and_continue(f, CELL(d));
		});
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
											detail::mr_foreach_line_at_level(*state_, slot, level_, b, e,
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

/// Edges incident to vertex v, in cyclic order.
template <MRMesh2 M, typename FUNC>
void foreach_incident_edge(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_edge(lv.state().map, v, f); // the finest map's own traversal
	foreach_dart_of_orbit(m, v, [&](Dart d) { return call_and_continue(f, MRMap2::Edge(d)); });
}

/// Faces incident to vertex v, in cyclic order (boundary faces skipped).
template <MRMesh2 M, typename FUNC>
void foreach_incident_face(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_face(lv.state().map, v, f); // the finest map's own traversal
	foreach_dart_of_orbit(m, v, [&](Dart d) { return is_boundary(m, d) || call_and_continue(f, MRMap2::Face(d)); });
}

/// Vertices joined to v by an edge, in cyclic order.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_vertex_through_edge(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_adjacent_vertex_through_edge(lv.state().map, v, f); // the finest map's own traversal
	foreach_dart_of_orbit(m, v, [&](Dart d) { return call_and_continue(f, MRMap2::Vertex(phi2(m, d))); });
}

/// Vertices sharing a face with v (v excluded): the edge neighbours in cyclic
/// order, each followed by the other vertices of the next incident face.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_vertex_through_face(const M& m, MRMap2::Vertex v, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_adjacent_vertex_through_face(lv.state().map, v, f); // the finest map's own traversal
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		if (!call_and_continue(f, MRMap2::Vertex(phi2(m, d))))
			return false;
		if (is_boundary(m, d))
			return true;
		for (Dart x = phi1(m, phi1(m, d)); phi1(m, x) != d; x = phi1(m, x))
			if (!call_and_continue(f, MRMap2::Vertex(x)))
				return false;
		return true;
	});
}

/// The two vertices of edge e: the origin of e.dart first.
template <MRMesh2 M, typename FUNC>
void foreach_incident_vertex(const M& m, MRMap2::Edge e, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_vertex(lv.state().map, e, f); // the finest map's own traversal
	if (call_and_continue(f, MRMap2::Vertex(e.dart)))
		call_and_continue(f, MRMap2::Vertex(phi2(m, e.dart)));
}

/// The one or two faces incident to edge e (boundary faces skipped).
template <MRMesh2 M, typename FUNC>
void foreach_incident_face(const M& m, MRMap2::Edge e, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_face(lv.state().map, e, f); // the finest map's own traversal
	if (!is_boundary(m, e.dart) && !call_and_continue(f, MRMap2::Face(e.dart)))
		return;
	const Dart d2 = phi2(m, e.dart);
	if (!is_boundary(m, d2))
		call_and_continue(f, MRMap2::Face(d2));
}

/// Edges sharing a vertex with e (e excluded): around the origin of e.dart,
/// then around the other end.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_edge_through_vertex(const M& m, MRMap2::Edge e, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_adjacent_edge_through_vertex(lv.state().map, e, f); // the finest map's own traversal
	for (Dart start : {e.dart, phi2(m, e.dart)})
		for (Dart it = phi1(m, phi2(m, start)); it != start; it = phi1(m, phi2(m, it)))
			if (!call_and_continue(f, MRMap2::Edge(it)))
				return;
}

/// Edges sharing a (non-boundary) face with e, e excluded.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_edge_through_face(const M& m, MRMap2::Edge e, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_adjacent_edge_through_face(lv.state().map, e, f); // the finest map's own traversal
	for (Dart start : {e.dart, phi2(m, e.dart)})
	{
		if (is_boundary(m, start))
			continue;
		for (Dart it = phi1(m, start); it != start; it = phi1(m, it))
			if (!call_and_continue(f, MRMap2::Edge(it)))
				return;
	}
}

/// Vertices of face f in phi1 order.
template <MRMesh2 M, typename FUNC>
void foreach_incident_vertex(const M& m, MRMap2::Face f, const FUNC& fn)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_vertex(lv.state().map, f, fn); // the finest map's own traversal
	foreach_dart_of_orbit(m, f, [&](Dart d) { return call_and_continue(fn, MRMap2::Vertex(d)); });
}

/// Edges of face f in phi1 order.
template <MRMesh2 M, typename FUNC>
void foreach_incident_edge(const M& m, MRMap2::Face f, const FUNC& fn)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_edge(lv.state().map, f, fn); // the finest map's own traversal
	foreach_dart_of_orbit(m, f, [&](Dart d) { return call_and_continue(fn, MRMap2::Edge(d)); });
}

/// Faces across the edges of f (boundary faces skipped), in phi1 order.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_face_through_edge(const M& m, MRMap2::Face f, const FUNC& fn)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_adjacent_face_through_edge(lv.state().map, f, fn); // the finest map's own traversal
	foreach_dart_of_orbit(m, f, [&](Dart d) {
		const Dart d2 = phi2(m, d);
		return is_boundary(m, d2) || call_and_continue(fn, MRMap2::Face(d2));
	});
}

/// Faces sharing at least a vertex with f (f excluded), each once on a
/// manifold mesh: around each vertex of f in turn.
template <MRMesh2 M, typename FUNC>
void foreach_adjacent_face_through_vertex(const M& m, MRMap2::Face f, const FUNC& fn)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_adjacent_face_through_vertex(lv.state().map, f, fn); // the finest map's own traversal
	foreach_dart_of_orbit(m, f, [&](Dart d) {
		for (Dart it = phi1(m, phi2(m, d)); it != d;)
		{
			const Dart next = phi1(m, phi2(m, it));
			if (next == d)
				break;
			if (!is_boundary(m, it) && !call_and_continue(fn, MRMap2::Face(it)))
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
	DartMarkerStore<CMap2> done(v.state().map);
	foreach_dart_of_orbit(v, MRMap2::Volume(start), [&](Dart d) {
		if (done.is_marked(d))
			return true;
		foreach_dart_of_orbit(v, CELL(d), [&](Dart x) { done.mark(x); });
		if constexpr (CELL::ORBIT == Orbit::PHI21)
		{
			// a vertex is real when one of its darts is
			bool real = false;
			foreach_dart_of_orbit(v, CELL(d), [&](Dart x) { return !(real = !is_boundary(v.state().map, x)); });
			return !real || call_and_continue(f, CELL(d));
		}
		else if constexpr (CELL::ORBIT == Orbit::PHI2)
			return (is_boundary(v.state().map, d) && is_boundary(v.state().map, mr_phi2(v.state(), v.level(), d))) ||
				   call_and_continue(f, CELL(d));
		else
			return is_boundary(v.state().map, d) || call_and_continue(f, CELL(d));
	});
}
} // namespace detail

/// Vertices of connected component w (no defined order).
template <MRMesh2 M, typename FUNC>
void foreach_incident_vertex(const M& m, MRMap2::Volume w, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_vertex(lv.state().map, w, f); // the finest map's own traversal
	detail::mr_foreach_cell_of_volume<MRMap2::Vertex>(detail::read_level(m), w.dart, f);
}
/// Edges of connected component w (no defined order).
template <MRMesh2 M, typename FUNC>
void foreach_incident_edge(const M& m, MRMap2::Volume w, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_edge(lv.state().map, w, f); // the finest map's own traversal
	detail::mr_foreach_cell_of_volume<MRMap2::Edge>(detail::read_level(m), w.dart, f);
}
/// Faces of connected component w, boundary faces skipped (no defined order).
template <MRMesh2 M, typename FUNC>
void foreach_incident_face(const M& m, MRMap2::Volume w, const FUNC& f)
{
	if (const MRLevelView2 lv = detail::read_level(m); detail::mr_is_finest(lv))
		return foreach_incident_face(lv.state().map, w, f); // the finest map's own traversal
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
