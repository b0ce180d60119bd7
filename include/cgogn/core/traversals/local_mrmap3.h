// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mr_lines.h>
#include <cgogn/core/map/mrmap3.h>
#include <cgogn/core/marking/dart_marker.h>
#include <cgogn/core/parallel/thread_pool.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/parallel.h>

#include <type_traits>
#include <vector>

namespace cgogn
{

// Traversals of a multiresolution 3-map at its current level, or of a level
// view. They are those of a 3-map, read through phi1, phi2 and phi3 at the
// level: each step costs what the level's phi1 costs (see MRMap3), 1 finest
// step at the finest level, where the local traversals are the finest
// CMap3's own. Boundary volumes are never reported.

/// Calls f(Dart) on each dart of the orbit of c at the level read, in the
/// order of a 3-map (faces in phi1 order, edges around in cyclic order);
/// f may return false to stop. Returns false when stopped. O(size of the
/// orbit x cost of a level step); vertices, volumes and connected
/// components are flooded with a pooled mark.
template <MRMesh3 M, Orbit O, typename FUNC>
bool foreach_dart_of_orbit(const M& m, Cell<O> c, const FUNC& f)
{
	const MRLevelView3 v = detail::read_level(m);
	const detail::MRState3& s = v.state();
	if (detail::mr_is_finest(v))
		return foreach_dart_of_orbit(s.map, c, f); // the finest map's own walk
	const uint32 l = v.level();
	const Dart d = c.dart;
	const auto phi1_l = [&](Dart x) { return detail::mr_phi1(s, l, x); };
	const auto phi2_l = [&](Dart x) { return detail::mr_phi2(s, l, x); };
	const auto phi3_l = [&](Dart x) { return detail::mr_phi3(s, l, x); };
	const auto cycle = [&](Dart start, const auto& next) {
		Dart it = start;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = next(it);
		} while (it != start);
		return true;
	};
	if constexpr (O == Orbit::DART)
		return call_and_continue(f, d);
	else if constexpr (O == Orbit::PHI1)
		return cycle(d, phi1_l);
	else if constexpr (O == Orbit::PHI2)
		return call_and_continue(f, d) && call_and_continue(f, phi2_l(d));
	else if constexpr (O == Orbit::PHI21)
		return cycle(d, [&](Dart x) { return phi1_l(phi2_l(x)); });
	else if constexpr (O == Orbit::PHI1_PHI3)
		return cycle(d, phi1_l) && cycle(phi3_l(d), phi1_l);
	else if constexpr (O == Orbit::PHI2_PHI3)
	{
		// each volume around the edge holds two darts of it: x and phi2(x)
		Dart it = d;
		do
		{
			const Dart it2 = phi2_l(it);
			if (!call_and_continue(f, it) || !call_and_continue(f, it2))
				return false;
			it = phi3_l(it2);
		} while (it != d);
		return true;
	}
	else if constexpr (O == Orbit::PHI1_PHI2)
		return detail::foreach_dart_flood(s.map, d, f, phi1_l, phi2_l);
	else if constexpr (O == Orbit::PHI21_PHI31)
		return detail::foreach_dart_flood(
			s.map, d, f, [&](Dart x) { return phi1_l(phi2_l(x)); }, [&](Dart x) { return phi1_l(phi3_l(x)); });
	else
	{
		static_assert(O == Orbit::PHI1_PHI2_PHI3, "foreach_dart_of_orbit: not an orbit of a 3-map");
		return detail::foreach_dart_flood(s.map, d, f, phi1_l, phi2_l, phi3_l);
	}
}

namespace detail
{

/// Whether cells of orbit O lie in one volume: they are boundary cells when
/// their volume is a boundary volume. The other cells (vertices, edges,
/// faces, connected components) are never boundary cells of a 3-map.
template <Orbit O>
constexpr bool mr3_cell_in_one_volume()
{
	return O == Orbit::DART || O == Orbit::PHI1 || O == Orbit::PHI2 || O == Orbit::PHI21 || O == Orbit::PHI1_PHI2;
}

/// Calls f(first dart) once per cell of type CELL among the darts that
/// `walk` gives (a callable that calls its argument on darts and stops when
/// it returns false), boundary cells skipped, at the level of v: each cell is
/// marked as a whole when met. O(darts walked + sizes of the cells met).
template <typename CELL, typename WALK, typename FUNC>
void mr3_foreach_cell_met(const MRLevelView3& v, const WALK& walk, const FUNC& f)
{
	const CMap3& map = v.state().map;
	DartMarkerStore<CMap3> met(map);
	walk([&](Dart d) {
		if (met.is_marked(d))
			return true;
		foreach_dart_of_orbit(v, CELL(d), [&](Dart x) { met.mark(x); });
		if constexpr (mr3_cell_in_one_volume<CELL::ORBIT>())
			if (is_boundary(map, d))
				return true;
		return call_and_continue(f, CELL(d));
	});
}

/// The cells of type CELL incident to cell c at the level of v (those that
/// share a dart with it), each once, boundary cells skipped.
template <typename CELL, Orbit O, typename FUNC>
void mr3_foreach_incident(const MRLevelView3& v, Cell<O> c, const FUNC& f)
{
	mr3_foreach_cell_met<CELL>(
		v, [&](const auto& g) { foreach_dart_of_orbit(v, c, g); }, f);
}

/// The cells of type X that share a cell of type Y with x, each once, x
/// excluded, at the level of v.
template <typename X, typename Y, typename FUNC>
void mr3_foreach_adjacent(const MRLevelView3& v, X x, const FUNC& f)
{
	const CMap3& map = v.state().map;
	DartMarkerStore<CMap3> met(map);
	foreach_dart_of_orbit(v, x, [&](Dart d) { met.mark(d); });
	bool go_on = true;
	mr3_foreach_incident<Y>(v, x, [&](Y y) {
		foreach_dart_of_orbit(v, y, [&](Dart d) {
			if (met.is_marked(d))
				return true;
			foreach_dart_of_orbit(v, X(d), [&](Dart e) { met.mark(e); });
			if constexpr (mr3_cell_in_one_volume<X::ORBIT>())
				if (is_boundary(map, d))
					return true;
			return go_on = call_and_continue(f, X(d));
		});
		return go_on;
	});
}

} // namespace detail

template <typename CELL, typename FUNC>
void MRLevelView3::foreach_cell(const FUNC& func) const
{
	static_assert(std::is_same_v<CELL, Cell<CELL::ORBIT>>, "foreach_cell on a multiresolution map: take a plain cell");
	held_callable_t<FUNC> f = func;
	constexpr uint32 slot = detail::MRDim<detail::MRState3>::slot(CELL::ORBIT);
	if constexpr (slot < detail::MRDim<detail::MRState3>::orbits.size())
		if (state_->cells[slot].index != nullptr)
		{
			// an indexed orbit: the lines that hold at the level
			const AttributeContainer& c = detail::mr_slot_container(*state_, slot);
			const auto key = c.key().view();
			detail::mr_foreach_line_holding(*state_, slot, level_, 0, c.end_index(),
											[&](uint32 i) { return call_and_continue(f, CELL(Dart(key[i]))); });
			return;
		}
	if (detail::mr_is_finest(*this))
	{
		// the cells of the finest map (which indexes none of its orbits)
		cgogn::foreach_cell(state_->map, [&](CELL c) { return call_and_continue(f, c); });
		return;
	}
	const auto level = state_->level->view();
	detail::mr3_foreach_cell_met<CELL>(
		*this,
		[&](const auto& g) {
			foreach_dart(state_->map, [&](Dart d) {
				// a cell is found from one of its darts of the level; a real cell
				// has a dart outside the boundary volumes
				return level[d.index] > level_ || is_boundary(state_->map, d) || g(d);
			});
		},
		f);
}

template <typename CELL, typename FUNC>
void MRLevelView3::parallel_foreach_cell(const FUNC& f) const
{
	if (detail::run_sequentially())
	{
		foreach_cell<CELL>(f);
		return;
	}
	constexpr uint32 slot = detail::MRDim<detail::MRState3>::slot(CELL::ORBIT);
	if constexpr (slot < detail::MRDim<detail::MRState3>::orbits.size())
		if (state_->cells[slot].index != nullptr)
		{
			const AttributeContainer& c = detail::mr_slot_container(*state_, slot);
			const auto key = c.key().view();
			detail::parallel_for_chunks(c.end_index(), detail::PARALLEL_LINE_GRAIN,
										detail::ChunkBody([&](uint32 b, uint32 e) {
											held_callable_t<FUNC> fc = f; // see held_callable_t
											detail::mr_foreach_line_holding(*state_, slot, level_, b, e,
																			[&](uint32 i) { fc(CELL(Dart(key[i]))); });
										}));
			return;
		}
	if (detail::mr_is_finest(*this))
	{
		cgogn::parallel_foreach_cell(state_->map, [&](CELL c) { f(c); });
		return;
	}
	// the cells are found by one thread (their marks are shared), then
	// handed out in chunks
	std::vector<CELL> cells;
	foreach_cell<CELL>([&](CELL c) { cells.push_back(c); });
	detail::parallel_for_chunks(uint32(cells.size()), detail::PARALLEL_LINE_GRAIN,
								detail::ChunkBody([&](uint32 b, uint32 e) {
									held_callable_t<FUNC> fc = f; // see held_callable_t
									for (uint32 i = b; i < e; ++i)
										fc(cells[i]);
								}));
}

template <typename CELL, typename FUNC>
void MRMap3::foreach_cell(const FUNC& f) const
{
	detail::read_level(*this).foreach_cell<CELL>(f);
}

template <typename CELL, typename FUNC>
void MRMap3::parallel_foreach_cell(const FUNC& f) const
{
	detail::read_level(*this).parallel_foreach_cell<CELL>(f);
}

// ---- local traversals: those of a 3-map (see local_cmap3.h), at the level
// read. Incidences report each cell once (around an edge and along a face in
// the order of the orbit walk, elsewhere in no defined order); adjacencies
// report each cell once and never the starting cell.

/// Defines foreach_incident_NAME(m, c, f) for cells c of type FROM: the
/// cells of type TO at the level read. At the finest level, the finest
/// map's own traversal. O(size of c + sizes of the cells met) level steps.
#define CGOGN_MR3_INCIDENCE(NAME, FROM, TO)                                                                            \
	template <MRMesh3 M, typename FUNC>                                                                                \
	void foreach_incident_##NAME(const M& m, MRMap3::FROM c, const FUNC& f)                                            \
	{                                                                                                                  \
		const MRLevelView3 lv = detail::read_level(m);                                                                 \
		if (detail::mr_is_finest(lv))                                                                                  \
			return foreach_incident_##NAME(lv.state().map, c, f);                                                      \
		detail::mr3_foreach_incident<MRMap3::TO>(lv, c, f);                                                            \
	}

CGOGN_MR3_INCIDENCE(edge, Vertex, Edge)
CGOGN_MR3_INCIDENCE(face, Vertex, Face)
CGOGN_MR3_INCIDENCE(volume, Vertex, Volume)
CGOGN_MR3_INCIDENCE(vertex, Edge, Vertex)
CGOGN_MR3_INCIDENCE(face, Edge, Face)
CGOGN_MR3_INCIDENCE(volume, Edge, Volume)
CGOGN_MR3_INCIDENCE(vertex, Face, Vertex)
CGOGN_MR3_INCIDENCE(edge, Face, Edge)
CGOGN_MR3_INCIDENCE(volume, Face, Volume)
CGOGN_MR3_INCIDENCE(vertex, Volume, Vertex)
CGOGN_MR3_INCIDENCE(edge, Volume, Edge)
CGOGN_MR3_INCIDENCE(face, Volume, Face)
#undef CGOGN_MR3_INCIDENCE

/// Defines foreach_adjacent_X_through_Y(m, x, f): the cells of type X
/// sharing a cell of type Y with x, x excluded, at the level read. At the
/// finest level, the finest map's own traversal. O(sizes of the cells met)
/// level steps.
#define CGOGN_MR3_ADJACENCY(XNAME, YNAME, X, Y)                                                                        \
	template <MRMesh3 M, typename FUNC>                                                                                \
	void foreach_adjacent_##XNAME##_through_##YNAME(const M& m, MRMap3::X x, const FUNC& f)                            \
	{                                                                                                                  \
		const MRLevelView3 lv = detail::read_level(m);                                                                 \
		if (detail::mr_is_finest(lv))                                                                                  \
			return foreach_adjacent_##XNAME##_through_##YNAME(lv.state().map, x, f);                                   \
		detail::mr3_foreach_adjacent<MRMap3::X, MRMap3::Y>(lv, x, f);                                                  \
	}

CGOGN_MR3_ADJACENCY(vertex, face, Vertex, Face)
CGOGN_MR3_ADJACENCY(vertex, volume, Vertex, Volume)
CGOGN_MR3_ADJACENCY(edge, vertex, Edge, Vertex)
CGOGN_MR3_ADJACENCY(edge, face, Edge, Face)
CGOGN_MR3_ADJACENCY(edge, volume, Edge, Volume)
CGOGN_MR3_ADJACENCY(face, vertex, Face, Vertex)
CGOGN_MR3_ADJACENCY(face, edge, Face, Edge)
CGOGN_MR3_ADJACENCY(face, volume, Face, Volume)
CGOGN_MR3_ADJACENCY(volume, vertex, Volume, Vertex)
CGOGN_MR3_ADJACENCY(volume, edge, Volume, Edge)
CGOGN_MR3_ADJACENCY(volume, face, Volume, Face)
#undef CGOGN_MR3_ADJACENCY

/// The vertices joined to v by an edge, each once, v excluded, at the level
/// read. At the finest level, the finest map's own traversal, by the
/// vertices' lines when they have some. O(size of v + sizes of the edges
/// met) level steps.
template <MRMesh3 M, typename FUNC>
void foreach_adjacent_vertex_through_edge(const M& m, MRMap3::Vertex v, const FUNC& f)
{
	const MRLevelView3 lv = detail::read_level(m);
	const detail::MRState3& s = lv.state();
	if (detail::mr_is_finest(lv))
	{
		constexpr uint32 slot = detail::MRDim<detail::MRState3>::vertex_slot;
		if (s.cells[slot].index != nullptr &&
			detail::foreach_adjacent_vertex_by_line(s.map, v, detail::mr_slot_container(s, slot),
													s.cells[slot].index->view(), f))
			return;
		return foreach_adjacent_vertex_through_edge(s.map, v, f);
	}
	detail::mr3_foreach_adjacent<MRMap3::Vertex, MRMap3::Edge>(lv, v, f);
}

// ---- properties at the level read

/// Number of edges incident to v. O(size of v x cost of a level step).
template <MRMesh3 M>
uint32 degree(const M& m, MRMap3::Vertex v)
{
	uint32 n = 0;
	foreach_incident_edge(m, v, [&](MRMap3::Edge) { ++n; });
	return n;
}
/// Number of faces around edge e (boundary ones included). O(size of e x
/// cost of a level step).
template <MRMesh3 M>
uint32 degree(const M& m, MRMap3::Edge e)
{
	uint32 n = 0;
	foreach_dart_of_orbit(m, e, [&](Dart) { ++n; });
	return n / 2;
}
/// Number of edges of face f. O(codegree x cost of a level step).
template <MRMesh3 M>
uint32 codegree(const M& m, MRMap3::Face f)
{
	uint32 n = 0;
	foreach_dart_of_orbit(m, MRMap3::Face2(f.dart), [&](Dart) { ++n; });
	return n;
}
/// Number of faces of volume w. O(size of w x cost of a level step).
template <MRMesh3 M>
uint32 codegree(const M& m, MRMap3::Volume w)
{
	uint32 n = 0;
	foreach_incident_face(m, w, [&](MRMap3::Face) { ++n; });
	return n;
}
/// Whether v lies on the boundary of the mesh. O(size of v x cost of a level step).
template <MRMesh3 M>
bool is_incident_to_boundary(const M& m, MRMap3::Vertex v)
{
	bool b = false;
	foreach_dart_of_orbit(m, v, [&](Dart d) { return !(b = is_boundary(m, d)); });
	return b;
}
/// Whether face f lies on the boundary of the mesh. O(cost of a level step).
template <MRMesh3 M>
bool is_incident_to_boundary(const M& m, MRMap3::Face f)
{
	return is_boundary(m, f.dart) || is_boundary(m, phi3(m, f.dart));
}

} // namespace cgogn
