// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/betas.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/ncell_walk.h>
#include <cgogn/core/marking/dart_marker.h>

namespace cgogn
{

namespace detail
{

/// Breadth-first visit of the darts reachable from d through the given
/// relations; the darts marked so far are the work list (DartMarkerStore:
/// pooled mark and buffer, no allocation once warm, cleared and given back on
/// every exit, a throwing f included). Returns false when f stopped the
/// traversal.
template <typename MAP, typename FUNC, typename... NEXT>
bool foreach_dart_flood(const MAP& m, Dart d, const FUNC& f, NEXT... next)
{
	DartMarkerStore<MAP> seen(m);
	const std::vector<Dart>& darts = seen.marked_darts();
	seen.mark(d);
	for (std::size_t i = 0; i < darts.size(); ++i)
	{
		const Dart x = darts[i];
		if (!call_and_continue(f, x))
			return false;
		(seen.mark(next(x)), ...);
	}
	return true;
}

/// The darts of a 3-D vertex, breadth first: phi1 o phi2 turns around the
/// vertex inside a volume, phi1 o phi3 crosses into the next volume, with the
/// relations read through views held in locals (see LineStorage::View). A
/// dart reached through phi3 lies in another volume, whose darts are
/// elsewhere in memory: its phi2 and phi3 lines, and the line f will read for
/// it (a callable with a member prefetch_line(uint32), see
/// detail::LineReport), are prefetched as soon as it is found, so that their
/// misses overlap the walk of the darts queued before it instead of stalling
/// the walk when its turn comes (volume smoothing of armadillo_tet_461k,
/// whose darts are in file order: 15-30% faster).
template <typename MAP, typename FUNC>
bool foreach_dart_of_vertex3(const MAP& m, Dart d, const FUNC& f)
{
	const auto phi1_of = detail::state_of(m).phi1->view();
	const auto phi2_of = detail::state_of(m).phi2->view();
	const auto phi3_of = detail::state_of(m).phi3->view();
	auto turn = [&](Dart x) { return Dart(phi1_of[phi2_of[x.index]]); };
	auto cross = [&](Dart x) {
		const uint32 y = phi1_of[phi3_of[x.index]];
		CGOGN_PREFETCH(&phi2_of[y]);
		CGOGN_PREFETCH(&phi3_of[y]);
		if constexpr (requires { f.prefetch_line(y); })
			f.prefetch_line(y);
		return Dart(y);
	};
	return foreach_dart_flood(m, d, f, turn, cross);
}

/// beta0 read as a relation view (see LineStorage::View): the other dart of
/// the pair.
struct Beta0View
{
	uint32 operator[](uint32 i) const
	{
		return i ^ 1u;
	}
};

/// True for the orbits that foreach_dart_of_orbit floods with a mark and a
/// work list (volumes, 3-D vertices, connected components); the others are
/// walked as one or two cycles. The cells of the maps of any dimension count
/// as flooded: the global traversals flood them with one mark for all, whatever
/// their walk (see flood_orbit_keep_marks).
constexpr bool orbit_is_flooded(Orbit o)
{
	return is_dimension_orbit(o) || o == Orbit::PHI1_PHI2 || o == Orbit::PHI21_PHI31 || o == Orbit::PHI1_PHI2_PHI3 ||
		   o == Orbit::BETA0_BETA1_BETA2 || o == Orbit::BETA0_BETA1_BETA3 || o == Orbit::BETA0_BETA2_BETA3 ||
		   o == Orbit::BETA1_BETA2_BETA3 || o == Orbit::BETA0_BETA1_BETA2_BETA3;
}

/// Breadth-first visit of the orbit O of d with a mark and a work list owned by
/// the caller: darts already set in `mark` are treated as visited, and the bits
/// of the visited darts stay set (the caller clears them, possibly much later
/// and all at once). Traversals that flood many cells use it to pay one mark
/// for all of them instead of one pooled mark per cell. Calls f on each dart.
template <Orbit O, typename MAP, typename FUNC>
void flood_orbit_keep_marks(const MAP& m, Dart d, MarkAttribute& mark, std::vector<Dart>& work, const FUNC& f)
{
	static_assert(orbit_is_flooded(O));
	[[maybe_unused]] const auto steps = [&] {
		if constexpr (is_dimension_orbit(O))
			return ncell_steps<MAP, dimension_of_orbit(O)>(state_of(m));
		else
			return 0;
	}();
	work.clear();
	work.push_back(d);
	mark.set(d.index);
	auto visit = [&](Dart y) {
		if (!mark.test(y.index))
		{
			mark.set(y.index);
			work.push_back(y);
		}
	};
	for (std::size_t i = 0; i < work.size(); ++i)
	{
		const Dart x = work[i];
		f(x);
		if constexpr (is_dimension_orbit(O))
		{
			for (const auto& next : steps)
				visit(Dart(next[x.index]));
		}
		else if constexpr (O == Orbit::PHI1_PHI2)
		{
			visit(phi1(m, x));
			visit(phi2(m, x));
		}
		else if constexpr (O == Orbit::PHI21_PHI31)
		{
			visit(phi1(m, phi2(m, x)));
			visit(phi1(m, phi3(m, x)));
		}
		else if constexpr (orbit_uses_beta(O, 0) || orbit_uses_beta(O, 1))
		{
			// a G-map orbit: its involutions
			if constexpr (orbit_uses_beta(O, 0))
				visit(beta0(m, x));
			if constexpr (orbit_uses_beta(O, 1))
				visit(beta1(m, x));
			if constexpr (orbit_uses_beta(O, 2))
				visit(beta2(m, x));
			if constexpr (orbit_uses_beta(O, 3))
				visit(beta3(m, x));
		}
		else
		{
			visit(phi1(m, x));
			visit(phi2(m, x));
			visit(phi3(m, x));
		}
	}
}

} // namespace detail

/// Calls f(Dart) on each dart of the orbit of cell c; f may return false to
/// stop. Returns false when stopped. O(size of the orbit). Faces, 2-D vertices
/// and edges are visited in their cyclic order; volumes and 3-D vertices by a
/// flood with a pooled mark (no allocation once warm). Around a 2-D vertex, a
/// callable with a member prefetch_line(uint32) is told each e = phi2(d)
/// before the walk reads phi1(e), the next dart it receives (a hint; see
/// detail::LineReport); around a 3-D vertex, of each dart found in the next
/// volume, which it receives later (see detail::foreach_dart_of_vertex3).
template <typename MAP, Orbit O, typename FUNC>
requires std::derived_from<MAP, CMapBase>
bool foreach_dart_of_orbit(const MAP& m, Cell<O> c, const FUNC& f)
{
	const Dart d = c.dart;
	if constexpr (O == Orbit::DART)
		return call_and_continue(f, d);
	else if constexpr (O == Orbit::PHI1 || O == Orbit::ALPHA1)
	{
		// a face's cycle; in a graph, the half-edges around a vertex (alpha1
		// is stored where the maps keep phi1)
		static_assert(O == Orbit::PHI1 || std::derived_from<MAP, Graph>, "ALPHA1: an orbit of the graphs only");
		const auto phi1_of = detail::state_of(m).phi1->view(); // see LineStorage::View
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = Dart(phi1_of[it.index]);
		} while (it != d);
		return true;
	}
	else if constexpr (O == Orbit::PHI2)
	{
		static_assert(MAP::dimension >= 2);
		return call_and_continue(f, d) && call_and_continue(f, phi2(m, d));
	}
	else if constexpr (O == Orbit::PHI21)
	{
		static_assert(MAP::dimension >= 2);
		// relations read through views held in locals (see LineStorage::View)
		const auto phi1_of = detail::state_of(m).phi1->view();
		const auto phi2_of = detail::state_of(m).phi2->view();
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			const uint32 e = phi2_of[it.index];
			// The next step reads phi2 at phi1(e), a dart of e's face; a
			// face's darts are usually consecutive lines, so phi2's cache line
			// at e holds it: loading it now overlaps that miss with phi1(e)'s
			// instead of waiting for phi1(e) first (bench_dart_layout
			// soa_prefetch: the walk 15-30% faster). Not in a 3-map: there
			// the walk stays among one volume's darts, allocated together.
			if constexpr (MAP::dimension == 2)
				CGOGN_PREFETCH(&phi2_of[e]);
			// the same for the line f reads at phi1(e) (detail::LineReport)
			if constexpr (requires { f.prefetch_line(e); })
				f.prefetch_line(e);
			it = Dart(phi1_of[e]);
		} while (it != d);
		return true;
	}
	else if constexpr (O == Orbit::PHI1_PHI2)
	{
		static_assert(MAP::dimension >= 2);
		return detail::foreach_dart_flood(
			m, d, f, [&](Dart x) { return phi1(m, x); }, [&](Dart x) { return phi2(m, x); });
	}
	else if constexpr (O == Orbit::PHI1_PHI3)
	{
		static_assert(MAP::dimension >= 3);
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = phi1(m, it);
		} while (it != d);
		const Dart e = phi3(m, d);
		it = e;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			it = phi1(m, it);
		} while (it != e);
		return true;
	}
	else if constexpr (O == Orbit::PHI2_PHI3)
	{
		static_assert(MAP::dimension >= 3);
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			const Dart it2 = phi2(m, it);
			if (!call_and_continue(f, it2))
				return false;
			it = phi3(m, it2);
		} while (it != d);
		return true;
	}
	else if constexpr (O == Orbit::PHI21_PHI31)
	{
		static_assert(MAP::dimension >= 3);
		return detail::foreach_dart_of_vertex3(m, d, f);
	}
	else if constexpr (O == Orbit::PHI1_PHI2_PHI3)
	{
		static_assert(MAP::dimension >= 3);
		return detail::foreach_dart_flood(
			m, d, f, [&](Dart x) { return phi1(m, x); }, [&](Dart x) { return phi2(m, x); },
			[&](Dart x) { return phi3(m, x); });
	}
	else if constexpr (O == Orbit::BETA0 || O == Orbit::BETA1 || O == Orbit::ALPHA0)
	{
		// one involution: d and its image (d alone at a fixed point: a free
		// side of an unfinished G-map, an isolated graph vertex)
		static_assert(O == Orbit::ALPHA0 ? std::derived_from<MAP, Graph> : is_gmap_v<MAP>,
					  "orbit not available in this map");
		const Dart e = [&] {
			if constexpr (O == Orbit::ALPHA0)
				return alpha0(m, d);
			else
				return O == Orbit::BETA0 ? beta0(m, d) : beta1(m, d);
		}();
		return call_and_continue(f, d) && (e == d || call_and_continue(f, e));
	}
	else if constexpr (O == Orbit::BETA0_BETA1 || O == Orbit::BETA1_BETA2)
	{
		// The orbit of two involutions a, b is one cycle d, a(d), b(a(d)), ...
		// when both are fixed-point free (a polygon, the corners around a
		// vertex); with fixed points (an unfinished map) it is a path, walked
		// from d in both directions.
		static_assert(is_gmap_v<MAP>, "orbit not available in combinatorial maps");
		constexpr uint32 B = O == Orbit::BETA0_BETA1 ? 1 : 2;
		const auto a_of = [&] {
			if constexpr (O == Orbit::BETA0_BETA1)
				return detail::Beta0View{};
			else
				return detail::state_of(m).beta[1]->view(); // see LineStorage::View
		}();
		const auto b_of = detail::state_of(m).beta[B]->view();
		Dart it = d;
		do
		{
			if (!call_and_continue(f, it))
				return false;
			const Dart e(a_of[it.index]);
			if (e == it)
				return detail::walk_path_back(d, f, b_of, a_of);
			if (!call_and_continue(f, e))
				return false;
			it = Dart(b_of[e.index]);
			if (it == e)
				return detail::walk_path_back(d, f, b_of, a_of);
		} while (it != d);
		return true;
	}
	else if constexpr (O == Orbit::BETA0_BETA2)
	{
		// an edge: d, beta0(d), beta2(d), beta0(beta2(d)) (beta0 o beta2 is an
		// involution), two darts on a free edge of an unfinished map
		static_assert(is_gmap_v<MAP> && MAP::dimension >= 2, "orbit not available in this map");
		const Dart d0 = beta0(m, d), d2 = beta2(m, d);
		if (!call_and_continue(f, d) || (d0 != d && !call_and_continue(f, d0)))
			return false;
		if (d2 == d)
			return true;
		const Dart d20 = beta0(m, d2);
		return call_and_continue(f, d2) && (d20 == d2 || call_and_continue(f, d20));
	}
	else if constexpr (O == Orbit::BETA0_BETA1_BETA2)
	{
		static_assert(is_gmap_v<MAP> && MAP::dimension >= 2, "orbit not available in this map");
		return detail::foreach_dart_flood(
			m, d, f, [&](Dart x) { return beta0(m, x); }, [&](Dart x) { return beta1(m, x); },
			[&](Dart x) { return beta2(m, x); });
	}
	else if constexpr (O == Orbit::BETA0_BETA1_BETA3)
	{
		// a face of a 3-G-map: its two sides (a polygon each), exchanged by beta3
		static_assert(is_gmap_v<MAP> && MAP::dimension >= 3, "orbit not available in this map");
		return detail::foreach_dart_flood(
			m, d, f, [&](Dart x) { return beta0(m, x); }, [&](Dart x) { return beta1(m, x); },
			[&](Dart x) { return beta3(m, x); });
	}
	else if constexpr (O == Orbit::BETA0_BETA2_BETA3)
	{
		// an edge of a 3-G-map: its four darts in each face around it
		static_assert(is_gmap_v<MAP> && MAP::dimension >= 3, "orbit not available in this map");
		return detail::foreach_dart_flood(
			m, d, f, [&](Dart x) { return beta0(m, x); }, [&](Dart x) { return beta2(m, x); },
			[&](Dart x) { return beta3(m, x); });
	}
	else if constexpr (O == Orbit::BETA1_BETA2_BETA3)
	{
		// a vertex of a 3-G-map: its corners in every volume around it
		static_assert(is_gmap_v<MAP> && MAP::dimension >= 3, "orbit not available in this map");
		return detail::foreach_dart_flood(
			m, d, f, [&](Dart x) { return beta1(m, x); }, [&](Dart x) { return beta2(m, x); },
			[&](Dart x) { return beta3(m, x); });
	}
	else if constexpr (O == Orbit::BETA0_BETA1_BETA2_BETA3)
	{
		static_assert(is_gmap_v<MAP> && MAP::dimension >= 3, "orbit not available in this map");
		return detail::foreach_dart_flood(
			m, d, f, [&](Dart x) { return beta0(m, x); }, [&](Dart x) { return beta1(m, x); },
			[&](Dart x) { return beta2(m, x); }, [&](Dart x) { return beta3(m, x); });
	}
	else if constexpr (is_dimension_orbit(O))
	{
		static_assert(is_nmap_v<MAP> && dimension_of_orbit(O) <= MAP::dimension,
					  "CellD<I>: the cells of the maps of any dimension (CMapN, GMapN), I <= dimension");
		return detail::foreach_dart_of_ncell<dimension_of_orbit(O)>(m, d, f);
	}
	else
	{
		static_assert(O == Orbit::DART, "orbit not available in combinatorial maps");
		return false;
	}
}

/// True when cells of orbit O lie inside one top-dimension cell of MAP (a face
/// of a 2-map, a volume of a 3-map): such cells are boundary cells when their
/// darts are boundary darts. Other orbits straddle the boundary and are always
/// real cells.
template <typename MAP, Orbit O>
inline constexpr bool orbit_inside_top_cell_v =
	!orbit_uses_phi(O, MAP::dimension) && !orbit_uses_beta(O, MAP::dimension);

/// True when c is a boundary cell (not part of the mesh; skipped by
/// traversals); in a graph, the "edge" of an isolated vertex's dart. O(1).
template <typename MAP, Orbit O>
requires std::derived_from<MAP, CMapBase>
bool is_boundary_cell(const MAP& m, Cell<O> c)
{
	if constexpr (O == Orbit::ALPHA0)
		return is_isolated(m, c.dart); // an isolated graph vertex's dart: no edge
	else if constexpr ((MAP::dimension >= 2 || is_nmap_v<MAP>)&&orbit_inside_top_cell_v<MAP, O>)
		return is_boundary(m, c.dart);
	else
		return false;
}

namespace detail
{

/// Whether the global traversals that look for the cells of orbit O among
/// the darts pass over dart d. In the maps of dimension 1 to 3, the boundary
/// darts: each real cell has a dart that is not one. In the maps of any
/// dimension, the darts of boundary cells: a vertex of a CMapN<1> is a single
/// dart, and the last vertex of a path is the start of its boundary edge. In
/// a graph, an isolated vertex's dart for the edges (it has none). O(1).
template <Orbit O, typename MAP>
CGOGN_INLINE bool passed_over_by_traversals(const MAP& m, Dart d)
{
	if constexpr (is_nmap_v<MAP> || std::derived_from<MAP, Graph>)
		return is_boundary_cell(m, Cell<O>(d));
	else
		return is_boundary(m, d);
}

} // namespace detail

/// Number of darts of cell c. O(size of the orbit).
template <typename MAP, Orbit O>
requires std::derived_from<MAP, CMapBase> uint32 nb_darts_of_orbit(const MAP& m, Cell<O> c)
{
	uint32 n = 0;
	foreach_dart_of_orbit(m, c, [&](Dart) { ++n; });
	return n;
}

/// True when the darts of c1 and c2 are in the same orbit, by traversal (does
/// not look at indices: operators use it while indices are being rewritten).
/// O(size of the orbit).
template <typename MAP, Orbit O>
requires std::derived_from<MAP, CMapBase>
bool same_orbit(const MAP& m, Cell<O> c1, Cell<O> c2)
{
	bool found = false;
	foreach_dart_of_orbit(m, c1, [&](Dart d) {
		found = d == c2.dart;
		return !found;
	});
	return found;
}

/// True when c1 and c2 are the same cell. O(1) when the orbit is indexed,
/// O(size of the orbit) otherwise.
template <typename MAP, Orbit O>
requires std::derived_from<MAP, CMapBase>
bool same_cell(const MAP& m, Cell<O> c1, Cell<O> c2)
{
	if constexpr (is_direct_orbit(O))
		return c1.dart == c2.dart;
	else if constexpr (O != Orbit::DART)
	{
		if (const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(O)])
		{
			uint32 i1 = (*idx)[c1.dart.index];
			if (i1 != INVALID_INDEX)
				return i1 == (*idx)[c2.dart.index];
		}
	}
	return same_orbit(m, c1, c2);
}

} // namespace cgogn
