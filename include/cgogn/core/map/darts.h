// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/utils/function_traits.h>

#include <cassert>

namespace cgogn
{

/// Next dart in the face cycle. O(1).
CGOGN_INLINE Dart phi1(const CMap1& m, Dart d)
{
	return Dart((*detail::state_of(m).phi1)[d.index]);
}

/// Previous dart in the face cycle. phi_1 is not stored (see docs/performance.md:
/// it would cost 4 bytes per dart): O(degree of the face).
inline Dart phi_1(const CMap1& m, Dart d)
{
	Dart it = d;
	for (Dart n = phi1(m, it); n != d; n = phi1(m, it))
		it = n;
	return it;
}

/// The dart of the adjacent face along the same edge, opposite direction. O(1).
CGOGN_INLINE Dart phi2(const CMap2& m, Dart d)
{
	return Dart((*detail::state_of(m).phi2)[d.index]);
}

/// Previous dart in the face cycle, in a 2-map. A boundary face of a surface
/// is a hole, which can be as long as the whole border of the mesh: for a
/// boundary dart, the previous dart is found around the origin of d instead
/// (it is phi2 of the dart z before d there, phi1(phi2(z)) == d). O(degree of
/// the face) for a dart of a real face, O(degree of its origin) for a
/// boundary dart.
inline Dart phi_1(const CMap2& m, Dart d)
{
	if (!detail::state_of(m).boundary->test(d.index))
		return phi_1(static_cast<const CMap1&>(m), d);
	Dart z = d;
	for (Dart n = phi1(m, phi2(m, z)); n != d; n = phi1(m, phi2(m, z)))
		z = n;
	return phi2(m, z);
}

/// Previous dart in the face cycle, in a 3-map: the faces of a 3-map, boundary
/// ones included, are faces of volumes. O(degree of the face).
inline Dart phi_1(const CMap3& m, Dart d)
{
	return phi_1(static_cast<const CMap1&>(m), d);
}

/// The dart of the adjacent volume along the same face, opposite direction. O(1).
CGOGN_INLINE Dart phi3(const CMap3& m, Dart d)
{
	return Dart((*detail::state_of(m).phi3)[d.index]);
}

/// Next dart in the face cycle of a map of any dimension. O(1).
template <uint32 D>
CGOGN_INLINE Dart phi1(const CMapN<D>& m, Dart d)
{
	return Dart((*detail::state_of(m).phi1)[d.index]);
}

/// Previous dart in the face cycle of a map of any dimension. O(degree of the
/// face).
template <uint32 D>
Dart phi_1(const CMapN<D>& m, Dart d)
{
	Dart it = d;
	for (Dart n = phi1(m, it); n != d; n = phi1(m, it))
		it = n;
	return it;
}

/// phi2 of a map of any dimension (D >= 2): the dart of the adjacent face
/// along the same edge, opposite direction. O(1).
template <uint32 D>
requires(D >= 2) CGOGN_INLINE Dart phi2(const CMapN<D>& m, Dart d)
{
	return Dart((*detail::state_of(m).phi2)[d.index]);
}

/// phi3 of a map of any dimension (D >= 3): the dart of the adjacent volume
/// along the same face, opposite direction. O(1).
template <uint32 D>
requires(D >= 3) CGOGN_INLINE Dart phi3(const CMapN<D>& m, Dart d)
{
	return Dart((*detail::state_of(m).phi3)[d.index]);
}

/// Composition of relations applied left to right: phi<1, 2>(m, d) is
/// phi2(m, phi1(m, d)); -1 stands for phi_1. In a CMapN<D>, every phi_i,
/// i <= D, is available: phi<4>(m, d) glues 4-cells. O(number of relations)
/// (phi_1: O(degree of the face)).
template <int... N, typename MAP>
Dart phi(const MAP& m, Dart d)
{
	auto apply = [&](int n) {
		if (n == 1)
			d = phi1(m, d);
		else if (n == -1)
			d = phi_1(m, d);
		else if (n == 2)
		{
			if constexpr (MAP::dimension >= 2)
				d = phi2(m, d);
		}
		else if (n == 3)
		{
			if constexpr (MAP::dimension >= 3)
				d = phi3(m, d);
		}
		else
			d = Dart((*detail::state_of(m).relations[n - 1])[d.index]);
	};
	static_assert(((N == 1 || N == -1 || (N >= 2 && N <= int(MAP::dimension))) && ...),
				  "phi<...>: relation not available in this map");
	(apply(N), ...);
	return d;
}

/// Number of live darts, boundary darts included. O(1).
inline uint32 nb_darts(const CMapBase& m)
{
	return detail::state_of(m).darts->nb_lines();
}

/// True when the dart belongs to a boundary cell (a boundary face of a 2-map,
/// a boundary volume of a 3-map). O(1).
CGOGN_INLINE bool is_boundary(const CMapBase& m, Dart d)
{
	return detail::state_of(m).boundary->test(d.index);
}

/// True when the map has boundary cells (an open surface, a volume mesh with
/// an outside). O(1): the map counts its boundary darts.
CGOGN_INLINE bool has_boundary(const CMapBase& m)
{
	return detail::state_of(m).nb_boundary_darts != 0;
}

/// True when d is a live dart of m. O(1).
inline bool is_dart_valid(const CMapBase& m, Dart d)
{
	return d.is_valid() && detail::state_of(m).darts->is_live(d.index);
}

/// Calls f(Dart) on every live dart, boundary darts included; f may return
/// false to stop. O(number of darts).
template <typename FUNC>
void foreach_dart(const CMapBase& m, const FUNC& func)
{
	held_callable_t<FUNC> f = func; // see held_callable_t
	const AttributeContainer& c = *detail::state_of(m).darts;
	const AttributeArray<uint32>& key = c.key();
	for (uint32 i = 0, end = c.end_index(); i < end; ++i)
		if (key[i] != INVALID_INDEX)
			if (!call_and_continue(f, Dart(i)))
				return;
}

namespace detail
{

inline Dart add_dart(CMapBase& m)
{
	if (!detail::state_of(m).incidence_tables.empty())
		detail::state_of(m).incidence_tables.clear(); // see drop_incidence_caches
	uint32 i = detail::state_of(m).darts->new_line(0);
	for (AttributeArray<uint32>* r : detail::state_of(m).relations)
		(*r)[i] = i;
	return Dart(i);
}

/// Boundary marks, like relations and the set of darts, define the cells the
/// quick incidence caches hold: every change drops them.
inline void set_boundary(CMapBase& m, Dart d, bool b)
{
	if (detail::state_of(m).boundary->test(d.index) == b)
		return;
	if (!detail::state_of(m).incidence_tables.empty())
		detail::state_of(m).incidence_tables.clear(); // see drop_incidence_caches
	detail::state_of(m).boundary->set_value(d.index, b);
	if (b)
		++detail::state_of(m).nb_boundary_darts;
	else
		--detail::state_of(m).nb_boundary_darts;
}

inline void remove_dart(CMapBase& m, Dart d)
{
	if (!detail::state_of(m).incidence_tables.empty())
		detail::state_of(m).incidence_tables.clear(); // see drop_incidence_caches
	set_boundary(m, d, false);
	detail::state_of(m).darts->release_line(d.index);
}

// A generalized map's darts come in pairs (beta0 is implicit): they are
// added and removed by add_dart_pair and remove_dart_pair only.
Dart add_dart(GMap1& m) = delete;
void remove_dart(GMap1& m, Dart d) = delete;
template <uint32 D>
Dart add_dart(GMapN<D>& m) = delete;
template <uint32 D>
void remove_dart(GMapN<D>& m, Dart d) = delete;

/// A new edge side of a generalized map: the darts d (even) and d + 1, each
/// other's beta0 for their whole life, fixed points of the other betas until
/// sewn. Returns d. O(number of dart attributes).
template <typename MAP>
requires is_gmap_v<MAP> Dart add_dart_pair(MAP& m)
{
	if (!detail::state_of(m).incidence_tables.empty())
		detail::state_of(m).incidence_tables.clear(); // see drop_incidence_caches
	const uint32 i = detail::state_of(m).darts->new_line_pair();
	for (AttributeArray<uint32>* r : detail::state_of(m).relations)
	{
		(*r)[i] = i;
		(*r)[i + 1] = i + 1;
	}
	return Dart(i);
}

/// Removes the darts d and beta0(d) (the caller has unlinked them). O(1).
template <typename MAP>
requires is_gmap_v<MAP>
void remove_dart_pair(MAP& m, Dart d)
{
	if (!detail::state_of(m).incidence_tables.empty())
		detail::state_of(m).incidence_tables.clear(); // see drop_incidence_caches
	const uint32 i = d.index & ~1u;
	for (uint32 j : {i + 1, i})
	{
		set_boundary(m, Dart(j), false);
		detail::state_of(m).darts->release_line(j);
	}
}

/// Every change of a relation goes through these: a topological change makes
/// the quick incidence caches wrong, so they are dropped (one test of a
/// null pointer when there are none).
inline void drop_incidence_caches(CMapBase& m)
{
	if (!detail::state_of(m).incidence_tables.empty())
		detail::state_of(m).incidence_tables.clear();
}
/// Frees the pooled marks nobody holds in every container of m (see
/// AttributeContainer::release_idle_marks; builders call it at the end).
inline void release_idle_marks(CMapBase& m)
{
	detail::state_of(m).darts->release_idle_marks();
	for (auto& c : detail::state_of(m).cells)
		c->release_idle_marks();
}
inline void set_phi1(CMap1& m, Dart d, Dart e)
{
	drop_incidence_caches(m);
	(*detail::state_of(m).phi1)[d.index] = e.index;
}
inline void set_phi2(CMap2& m, Dart d, Dart e)
{
	drop_incidence_caches(m);
	(*detail::state_of(m).phi2)[d.index] = e.index;
}
inline void set_phi3(CMap3& m, Dart d, Dart e)
{
	drop_incidence_caches(m);
	(*detail::state_of(m).phi3)[d.index] = e.index;
}
/// Sets relation i (phi_i of a CMapN, beta_i of a GMapN, i >= 1) of d to e,
/// one side only. O(1).
inline void set_relation(CMapBase& m, uint32 i, Dart d, Dart e)
{
	drop_incidence_caches(m);
	(*detail::state_of(m).relations[i - 1])[d.index] = e.index;
}
/// Relation i (phi_i of a CMapN, beta_i of a GMapN, i >= 1) of d. O(1).
CGOGN_INLINE Dart relation(const CMapBase& m, uint32 i, Dart d)
{
	return Dart((*detail::state_of(m).relations[i - 1])[d.index]);
}

} // namespace detail

/// Exchanges phi1(d) and phi1(e): joins two cycles into one, or splits one
/// cycle into two (the CMap1 sew/unsew primitive). Low level: no indexing.
inline void phi1_sew(CMap1& m, Dart d, Dart e)
{
	Dart f = phi1(m, d);
	Dart g = phi1(m, e);
	detail::set_phi1(m, d, g);
	detail::set_phi1(m, e, f);
}

/// Detaches phi1(d) from its cycle, which it leaves as a fixed point. Low level.
inline void phi1_unsew(CMap1& m, Dart d)
{
	Dart e = phi1(m, d);
	Dart f = phi1(m, e);
	detail::set_phi1(m, d, f);
	detail::set_phi1(m, e, e);
}

/// Links d and e by phi2; both must be phi2 fixed points. Low level: the map is
/// not closed while fixed points remain (builders use it; operators keep maps closed).
inline void phi2_sew(CMap2& m, Dart d, Dart e)
{
	assert(phi2(m, d) == d && phi2(m, e) == e);
	detail::set_phi2(m, d, e);
	detail::set_phi2(m, e, d);
}

/// Unlinks d and phi2(d), leaving two fixed points. Low level.
inline void phi2_unsew(CMap2& m, Dart d)
{
	Dart e = phi2(m, d);
	detail::set_phi2(m, d, d);
	detail::set_phi2(m, e, e);
}

/// Links d and e by phi3; both must be phi3 fixed points. Low level.
inline void phi3_sew(CMap3& m, Dart d, Dart e)
{
	assert(phi3(m, d) == d && phi3(m, e) == e);
	detail::set_phi3(m, d, e);
	detail::set_phi3(m, e, d);
}

/// Unlinks d and phi3(d). Low level.
inline void phi3_unsew(CMap3& m, Dart d)
{
	Dart e = phi3(m, d);
	detail::set_phi3(m, d, d);
	detail::set_phi3(m, e, e);
}

/// Exchanges phi1(d) and phi1(e) in a map of any dimension (see phi1_sew
/// of a CMap1). Low level: no indexing. O(1).
template <uint32 D>
void phi1_sew(CMapN<D>& m, Dart d, Dart e)
{
	const Dart f = phi1(m, d);
	const Dart g = phi1(m, e);
	detail::set_relation(m, 1, d, g);
	detail::set_relation(m, 1, e, f);
}

/// Links d and e by phi_i (2 <= i <= D); both must be phi_i fixed points.
/// Low level: the map is not closed while fixed points remain. O(1).
template <uint32 I, uint32 D>
requires(I >= 2 && I <= D) void phi_sew(CMapN<D>& m, Dart d, Dart e)
{
	assert(phi<int(I)>(m, d) == d && phi<int(I)>(m, e) == e);
	detail::set_relation(m, I, d, e);
	detail::set_relation(m, I, e, d);
}

/// Unlinks d and phi_i(d) (2 <= i <= D), leaving two fixed points. Low level. O(1).
template <uint32 I, uint32 D>
requires(I >= 2 && I <= D) void phi_unsew(CMapN<D>& m, Dart d)
{
	const Dart e = phi<int(I)>(m, d);
	detail::set_relation(m, I, d, d);
	detail::set_relation(m, I, e, e);
}

} // namespace cgogn
