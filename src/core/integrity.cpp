// SPDX-License-Identifier: MIT
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/properties/integrity.h>

#include "incidence_graph_records.h"
#include "integrity_quick.h"

#include <algorithm>
#include <array>
#include <sstream>

namespace cgogn
{

namespace
{

class Checker
{
public:
	explicit Checker(IntegrityReport& r) : report_(r)
	{
	}
	bool ok() const
	{
		return report_.nb_errors == 0;
	}
	void add(IntegrityError::Kind k, Orbit o, uint32 dart, uint32 index, const std::string& what)
	{
		++report_.nb_errors;
		if (report_.errors.size() >= 1000)
			return;
		std::ostringstream s;
		s << what;
		if (dart != INVALID_INDEX)
			s << " (dart " << dart << ")";
		if (index != INVALID_INDEX)
			s << " (line " << index << " of orbit " << orbit_name(o) << ")";
		report_.errors.push_back({k, o, dart, index, s.str()});
	}

private:
	IntegrityReport& report_;
};

using Kind = IntegrityError::Kind;

void check_container_free_list(const AttributeContainer& c, Orbit o, Checker& ck)
{
	std::vector<uint8> listed(c.end_index(), 0);
	for (uint32 i : c.free_lines())
	{
		if (c.key()[i] != INVALID_INDEX)
			ck.add(Kind::FreeLineLive, o, INVALID_INDEX, i, "a line of the free list is live");
		if (i < listed.size() && listed[i]++ == 1)
			ck.add(Kind::FreeLineDuplicate, o, INVALID_INDEX, i,
				   "a line is twice in the free list: it would be handed out twice");
	}
}

// Lines allocated past end_index() are handed out by new_line as they are:
// they must hold the default values (no key, no relation, no index), or new
// cells and darts would start with a deleted one's.
void check_unused_lines(const AttributeContainer& c, Orbit o,
						const std::vector<const AttributeArray<uint32>*>& attributes, Checker& ck)
{
	for (uint32 i = c.end_index(); i < c.capacity(); ++i)
		for (const AttributeArray<uint32>* a : attributes)
			if ((*a)[i] != INVALID_INDEX)
			{
				ck.add(Kind::StaleUnusedLine, o, INVALID_INDEX, i,
					   "an unused line past the end holds the value of attribute " + a->name() +
						   " of a deleted element");
				break;
			}
}

// The G-map relations: darts live in pairs (beta0, implicit), the stored
// betas fixed-point-free involutions, beta_j o beta_i an
// involution for i + 2 <= j, the boundary mark constant on faces (beta0,
// beta1) and never on both sides of beta_n, faces of 3 edges or more.
template <typename MAP>
void check_beta_relations(const MAP& m, Checker& ck)
{
	const auto& betas = detail::state_of(m).relations;
	bool relations_ok = true;
	foreach_dart(m, [&](Dart d) {
		if (!is_dart_valid(m, beta0(m, d)))
		{
			ck.add(Kind::DeadRelation, Orbit::DART, d.index, INVALID_INDEX,
				   "beta0 points to a dart that is not live (the other dart of its pair)");
			relations_ok = false;
		}
		for (std::size_t r = 0; r < betas.size(); ++r)
		{
			// built on an error only: a string per dart would cost more than the check
			const auto name = [r] { return "beta" + std::to_string(r + 1); }; // beta0 is not stored
			const Dart e((*betas[r])[d.index]);
			if (!is_dart_valid(m, e))
			{
				ck.add(Kind::DeadRelation, Orbit::DART, d.index, INVALID_INDEX,
					   name() + " points to a dart that is not live");
				relations_ok = false;
			}
			else if (e == d)
				ck.add(Kind::PhiFixedPoint, Orbit::DART, d.index, INVALID_INDEX,
					   name() + " has a fixed point: the map is not closed");
			else if (Dart((*betas[r])[e.index]) != d)
				ck.add(Kind::PhiNotInvolution, Orbit::DART, d.index, INVALID_INDEX, name() + " is not an involution");
		}
	});
	if (!relations_ok)
		return;
	if constexpr (MAP::dimension >= 2)
	{
		foreach_dart(m, [&](Dart d) {
			if (beta<0, 2, 0, 2>(m, d) != d)
				ck.add(Kind::BetaCompositionNotInvolution, Orbit::DART, d.index, INVALID_INDEX,
					   "beta2 o beta0 is not an involution");
			if constexpr (MAP::dimension >= 3)
			{
				if (beta<0, 3, 0, 3>(m, d) != d)
					ck.add(Kind::BetaCompositionNotInvolution, Orbit::DART, d.index, INVALID_INDEX,
						   "beta3 o beta0 is not an involution");
				if (beta<1, 3, 1, 3>(m, d) != d)
					ck.add(Kind::BetaCompositionNotInvolution, Orbit::DART, d.index, INVALID_INDEX,
						   "beta3 o beta1 is not an involution");
			}
		});
		// the boundary: faces (2-G-maps) or volumes (3-G-maps) whose darts
		// all carry the mark, never glued to each other by the last beta
		const auto top = [&](Dart d) {
			if constexpr (MAP::dimension >= 3)
				return beta3(m, d);
			else
				return beta2(m, d);
		};
		const std::string top_name = "beta" + std::to_string(MAP::dimension);
		uint32 marked = 0;
		foreach_dart(m, [&](Dart d) {
			const bool b = is_boundary(m, d);
			marked += b;
			if (b && is_boundary(m, top(d)))
				ck.add(Kind::BoundaryLinked, Orbit::DART, d.index, INVALID_INDEX,
					   top_name + " links two boundary darts");
			bool constant = is_boundary(m, beta0(m, d)) == b && is_boundary(m, beta1(m, d)) == b;
			if constexpr (MAP::dimension >= 3)
				constant = constant && is_boundary(m, beta2(m, d)) == b;
			if (!constant)
				ck.add(Kind::BoundaryMarkNotConstant, Orbit::DART, d.index, INVALID_INDEX,
					   "the boundary mark is not constant on a boundary cell");
			const Dart x = beta<0, 1>(m, d);
			if (!b && (x == d || beta<0, 1>(m, x) == d))
				ck.add(Kind::ShortFace, Orbit::BETA0_BETA1, d.index, INVALID_INDEX, "a face has fewer than 3 edges");
		});
		if (marked != detail::state_of(m).nb_boundary_darts)
			ck.add(Kind::BoundaryCountWrong, Orbit::DART, INVALID_INDEX, INVALID_INDEX,
				   "the map counts " + std::to_string(detail::state_of(m).nb_boundary_darts) + " boundary darts, " +
					   std::to_string(marked) + " are marked");
	}
}

// The graph relations: alpha0 an involution (a fixed point is a dart without
// edge, alone around its vertex), alpha1 a permutation and alpha_1 its
// inverse.
void check_graph_relations(const Graph& g, Checker& ck)
{
	const auto& st = detail::state_of(g);
	const std::array<std::pair<const AttributeArray<uint32>*, const char*>, 3> relations = {
		{{st.phi1, "alpha1"}, {st.phi2, "alpha0"}, {st.phi3, "alpha_1"}}};
	bool relations_ok = true;
	foreach_dart(g, [&](Dart d) {
		for (const auto& [r, name] : relations)
			if (!is_dart_valid(g, Dart((*r)[d.index])))
			{
				ck.add(Kind::DeadRelation, Orbit::DART, d.index, INVALID_INDEX,
					   std::string(name) + " points to a dart that is not live");
				relations_ok = false;
			}
	});
	if (!relations_ok)
		return;
	foreach_dart(g, [&](Dart d) {
		const Dart e = alpha0(g, d);
		if (alpha0(g, e) != d)
			ck.add(Kind::PhiNotInvolution, Orbit::DART, d.index, INVALID_INDEX, "alpha0 is not an involution");
		if (alpha_1(g, alpha1(g, d)) != d || alpha1(g, alpha_1(g, d)) != d)
			ck.add(Kind::InverseRelationWrong, Orbit::DART, d.index, INVALID_INDEX,
				   "alpha_1 is not the inverse of alpha1");
		if (e == d && alpha1(g, d) != d)
			ck.add(Kind::EdgelessDartNotAlone, Orbit::DART, d.index, INVALID_INDEX,
				   "a dart without edge (an isolated vertex) shares its vertex with other darts");
	});
}

// The records of an incidence graph (see IncidenceGraph): the rings of edge
// ends around vertices and of uses around edges, and the face cycles.
void check_incidence_graph_relations(const IncidenceGraph& ig, Checker& ck)
{
	const detail::IgRecords r(ig);
	const AttributeContainer& vertices = r.vertices();
	const AttributeContainer& edges = r.edges();
	check_container_free_list(vertices, Orbit::IG_VERTEX, ck);
	check_container_free_list(edges, Orbit::IG_EDGE, ck);
	// edges: two different live vertices
	bool ok = true;
	for (uint32 e = 0; e < edges.end_index(); ++e)
	{
		if (!edges.is_live(e))
			continue;
		const uint32 a = r.end_vertex(2 * e), b = r.end_vertex(2 * e + 1);
		if (!vertices.is_live(a) || !vertices.is_live(b) || a == b)
		{
			ck.add(Kind::DeadRelation, Orbit::IG_EDGE, INVALID_INDEX, e,
				   "an edge does not join two different live vertices");
			ok = false;
		}
	}
	if (!ok)
		return;
	// rings of ends: each end of a live edge once, in its vertex's ring
	std::vector<uint8> end_seen(2 * std::size_t(edges.end_index()), 0);
	for (uint32 v = 0; v < vertices.end_index(); ++v)
	{
		if (!vertices.is_live(v) || r.first_end(v) == detail::NO_EDGE_END)
			continue;
		uint32 it = r.first_end(v);
		for (uint32 steps = 0;; ++steps)
		{
			if (it >= end_seen.size() || !edges.is_live(it >> 1) || r.end_vertex(it) != v || end_seen[it] ||
				steps > end_seen.size())
			{
				ck.add(Kind::RingBroken, Orbit::IG_VERTEX, INVALID_INDEX, v,
					   "the ring of edge ends around a vertex is broken");
				return;
			}
			end_seen[it] = 1;
			it = r.next_end(it);
			if (it == r.first_end(v))
				break;
		}
	}
	for (uint32 e = 0; e < edges.end_index(); ++e)
		if (edges.is_live(e) && (!end_seen[2 * e] || !end_seen[2 * e + 1]))
			ck.add(Kind::RingBroken, Orbit::IG_EDGE, INVALID_INDEX, e, "an edge end is in no vertex's ring");
	// uses: on a live edge, each once in its edge's radial ring
	const AttributeContainer& darts = *detail::state_of(ig).darts;
	std::vector<uint8> use_seen(darts.end_index(), 0);
	bool uses_ok = true;
	foreach_dart(ig, [&](Dart u) {
		if (!edges.is_live(r.use_edge_end(u) >> 1) || !is_dart_valid(ig, r.next_in_face(u)))
		{
			ck.add(Kind::DeadRelation, Orbit::DART, u.index, INVALID_INDEX,
				   "a use is on a dead edge or its next use is dead");
			uses_ok = false;
		}
	});
	if (!uses_ok || !ck.ok())
		return;
	for (uint32 e = 0; e < edges.end_index(); ++e)
	{
		if (!edges.is_live(e) || r.first_use(e) == INVALID_INDEX)
			continue;
		Dart it(r.first_use(e));
		for (uint32 steps = 0;; ++steps)
		{
			if (!is_dart_valid(ig, it) || (r.use_edge_end(it) >> 1) != e || use_seen[it.index] ||
				steps > use_seen.size())
			{
				ck.add(Kind::RingBroken, Orbit::IG_EDGE, INVALID_INDEX, e, "the radial ring of an edge is broken");
				return;
			}
			use_seen[it.index] = 1;
			it = r.next_radial(it);
			if (it.index == r.first_use(e))
				break;
		}
	}
	foreach_dart(ig, [&](Dart u) {
		if (!use_seen[u.index])
			ck.add(Kind::RingBroken, Orbit::DART, u.index, INVALID_INDEX, "a use is in no edge's radial ring");
	});
	if (!ck.ok())
		return;
	// faces: phi1 a permutation, simple cycles of consecutive sides, 3 or more
	std::vector<uint8> preimages(darts.end_index(), 0);
	foreach_dart(ig, [&](Dart u) {
		if (preimages[r.next_in_face(u).index]++ == 1)
			ck.add(Kind::Phi1NotPermutation, Orbit::DART, r.next_in_face(u).index, INVALID_INDEX,
				   "phi1 is not a permutation: two uses have this use as next");
	});
	if (!ck.ok())
		return;
	std::vector<uint8> in_face(darts.end_index(), 0);
	std::vector<uint32> face_vertices;
	foreach_dart(ig, [&](Dart u) {
		if (in_face[u.index])
			return;
		face_vertices.clear();
		Dart it = u;
		bool consecutive = true;
		do
		{
			in_face[it.index] = 1;
			face_vertices.push_back(r.origin(it));
			consecutive = consecutive && r.target(it) == r.origin(r.next_in_face(it));
			it = r.next_in_face(it);
		} while (it != u);
		if (face_vertices.size() < 3)
			ck.add(Kind::ShortFace, Orbit::PHI1, u.index, INVALID_INDEX, "a face has fewer than 3 edges");
		std::sort(face_vertices.begin(), face_vertices.end());
		if (!consecutive || std::adjacent_find(face_vertices.begin(), face_vertices.end()) != face_vertices.end())
			ck.add(Kind::FaceNotSimpleCycle, Orbit::PHI1, u.index, INVALID_INDEX,
				   "a face is not a simple cycle of consecutive sides");
	});
}

template <typename MAP>
void check_phi_relations(const MAP& m, Checker& ck);
template <typename MAP>
void check_nmap_relations(const MAP& m, Checker& ck);

template <typename MAP>
void check_relations(const MAP& m, Checker& ck)
{
	const AttributeContainer& darts = *detail::state_of(m).darts;
	check_container_free_list(darts, Orbit::DART, ck);
	{
		std::vector<const AttributeArray<uint32>*> per_dart(detail::state_of(m).relations.begin(),
															detail::state_of(m).relations.end());
		for (const AttributeArray<uint32>* idx : detail::state_of(m).cell_index)
			if (idx != nullptr)
				per_dart.push_back(idx);
		check_unused_lines(darts, Orbit::DART, per_dart, ck);
		for (uint32 o = 0; o < NB_ORBITS; ++o)
			check_unused_lines(*detail::state_of(m).cells[o], Orbit(o), {&detail::state_of(m).cells[o]->key()}, ck);
	}
	if constexpr (std::is_same_v<MAP, Graph>)
		check_graph_relations(m, ck);
	else if constexpr (std::is_same_v<MAP, IncidenceGraph>)
		check_incidence_graph_relations(m, ck);
	else if constexpr (is_nmap_v<MAP>)
		check_nmap_relations(m, ck);
	else if constexpr (is_gmap_v<MAP>)
		check_beta_relations(m, ck);
	else
		check_phi_relations(m, ck);
}

// The combinatorial map relations: phi1 a permutation, phi_i fixed-point-free
// involutions (and phi3 o phi1 one), the boundary mark constant on boundary
// cells and never on both sides of phi_n, faces of 3 edges or more.
template <typename MAP>
void check_phi_relations(const MAP& m, Checker& ck)
{
	if (detail::phi_relations_hold(m))
		return;
	// the detailed check, which names what is wrong
	const AttributeContainer& darts = *detail::state_of(m).darts;
	std::vector<uint8> phi1_preimages(darts.end_index(), 0);
	bool relations_ok = true;
	foreach_dart(m, [&](Dart d) {
		for (std::size_t r = 0; r < detail::state_of(m).relations.size(); ++r)
		{
			const Dart e((*detail::state_of(m).relations[r])[d.index]);
			if (!is_dart_valid(m, e))
			{
				ck.add(Kind::DeadRelation, Orbit::DART, d.index, INVALID_INDEX,
					   "phi" + std::to_string(r + 1) + " points to a dart that is not live");
				relations_ok = false;
				continue;
			}
			if (r == 0)
			{
				if (phi1_preimages[e.index]++ == 1)
					ck.add(Kind::Phi1NotPermutation, Orbit::DART, e.index, INVALID_INDEX,
						   "phi1 is not a permutation: two darts have this dart as phi1");
			}
			else
			{
				// built on an error only: a string per dart would cost more than the check
				const auto name = [r] { return "phi" + std::to_string(r + 1); };
				if (e == d)
					ck.add(Kind::PhiFixedPoint, Orbit::DART, d.index, INVALID_INDEX,
						   name() + " has a fixed point: the map is not closed");
				else if (Dart((*detail::state_of(m).relations[r])[e.index]) != d)
					ck.add(Kind::PhiNotInvolution, Orbit::DART, d.index, INVALID_INDEX,
						   name() + " is not an involution");
			}
		}
	});
	if (!relations_ok)
		return;
	if constexpr (MAP::dimension == 3)
	{
		foreach_dart(m, [&](Dart d) {
			if (phi3(m, phi1(m, phi3(m, phi1(m, d)))) != d)
				ck.add(Kind::Phi1Phi3NotInvolution, Orbit::DART, d.index, INVALID_INDEX,
					   "phi3 o phi1 is not an involution");
		});
	}
	if constexpr (MAP::dimension >= 2)
	{
		uint32 marked = 0;
		foreach_dart(m, [&](Dart d) {
			const bool b = is_boundary(m, d);
			marked += b;
			if (b && is_boundary(m, detail::last_phi(m, d)))
				ck.add(Kind::BoundaryLinked, Orbit::DART, d.index, INVALID_INDEX,
					   "phi" + std::to_string(MAP::dimension) + " links two boundary darts");
			bool constant = is_boundary(m, phi1(m, d)) == b;
			if constexpr (MAP::dimension == 3)
				constant = constant && is_boundary(m, phi2(m, d)) == b;
			if (!constant)
				ck.add(Kind::BoundaryMarkNotConstant, Orbit::DART, d.index, INVALID_INDEX,
					   "the boundary mark is not constant on a boundary cell");
			// faces of 1 or 2 edges: no operator makes them (boundary faces
			// may have them: a hole of 1 or 2 edges)
			if (!b && phi1(m, phi1(m, d)) == d)
				ck.add(Kind::ShortFace, Orbit::PHI1, d.index, INVALID_INDEX, "a face has fewer than 3 edges");
		});
		if (marked != detail::state_of(m).nb_boundary_darts)
			ck.add(Kind::BoundaryCountWrong, Orbit::DART, INVALID_INDEX, INVALID_INDEX,
				   "the map counts " + std::to_string(detail::state_of(m).nb_boundary_darts) + " boundary darts, " +
					   std::to_string(marked) + " are marked");
	}
}

// The relations of a map of any dimension D. A CMapN: phi1 a permutation,
// phi_i (i >= 2) fixed-point-free involutions, phi1 o phi_j (j >= 3) and
// phi_i o phi_j (2 <= i, i + 2 <= j) involutions. A GMapN: darts in pairs,
// beta_i (i >= 1) fixed-point-free involutions, beta_i o beta_j involutions
// for i + 2 <= j. Both: the boundary mark constant on D-cells, never on both
// sides of the last relation. Faces of 1 or 2 edges are allowed (the
// contraction operators of any dimension make them).
template <typename MAP>
void check_nmap_relations(const MAP& m, Checker& ck)
{
	constexpr uint32 D = MAP::dimension;
	constexpr bool G = is_gmap_v<MAP>;
	const std::string r = G ? "beta" : "phi";
	std::vector<uint8> phi1_preimages(G ? 0 : detail::state_of(m).darts->end_index(), 0);
	bool relations_ok = true;
	foreach_dart(m, [&](Dart d) {
		if constexpr (G)
			if (!is_dart_valid(m, beta0(m, d)))
			{
				ck.add(Kind::DeadRelation, Orbit::DART, d.index, INVALID_INDEX,
					   "beta0 points to a dart that is not live (the other dart of its pair)");
				relations_ok = false;
			}
		for (uint32 i = 1; i <= D; ++i)
		{
			// built on an error only: a string per dart would cost more than the check
			const auto name = [&r, i] { return r + std::to_string(i); };
			const Dart e = detail::relation(m, i, d);
			if (!is_dart_valid(m, e))
			{
				ck.add(Kind::DeadRelation, Orbit::DART, d.index, INVALID_INDEX,
					   name() + " points to a dart that is not live");
				relations_ok = false;
			}
			else if (!G && i == 1)
			{
				if (phi1_preimages[e.index]++ == 1)
					ck.add(Kind::Phi1NotPermutation, Orbit::DART, e.index, INVALID_INDEX,
						   "phi1 is not a permutation: two darts have this dart as phi1");
			}
			else if (e == d)
				ck.add(Kind::PhiFixedPoint, Orbit::DART, d.index, INVALID_INDEX,
					   name() + " has a fixed point: the map is not closed");
			else if (detail::relation(m, i, e) != d)
				ck.add(Kind::PhiNotInvolution, Orbit::DART, d.index, INVALID_INDEX, name() + " is not an involution");
		}
	});
	if (!relations_ok)
		return;
	// relation i of d, beta0 included
	auto rel = [&](uint32 i, Dart d) { return G && i == 0 ? Dart(d.index ^ 1u) : detail::relation(m, i, d); };
	uint32 marked = 0;
	foreach_dart(m, [&](Dart d) {
		for (uint32 i = G ? 0 : 1; i + 2 <= D; ++i)
			for (uint32 j = i + 2; j <= D; ++j)
				if (rel(j, rel(i, rel(j, rel(i, d)))) != d)
				{
					const Kind k = G ? Kind::BetaCompositionNotInvolution : Kind::Phi1Phi3NotInvolution;
					ck.add(k, Orbit::DART, d.index, INVALID_INDEX,
						   r + std::to_string(j) + " o " + r + std::to_string(i) + " is not an involution");
				}
		const bool b = is_boundary(m, d);
		marked += b;
		if (b && is_boundary(m, rel(D, d)))
			ck.add(Kind::BoundaryLinked, Orbit::DART, d.index, INVALID_INDEX,
				   r + std::to_string(D) + " links two boundary darts");
		for (uint32 i = G ? 0 : 1; i < D; ++i)
			if (is_boundary(m, rel(i, d)) != b)
				ck.add(Kind::BoundaryMarkNotConstant, Orbit::DART, d.index, INVALID_INDEX,
					   "the boundary mark is not constant on a boundary cell");
	});
	if (marked != detail::state_of(m).nb_boundary_darts)
		ck.add(Kind::BoundaryCountWrong, Orbit::DART, INVALID_INDEX, INVALID_INDEX,
			   "the map counts " + std::to_string(detail::state_of(m).nb_boundary_darts) + " boundary darts, " +
				   std::to_string(marked) + " are marked");
}

// Local generators of orbit O: if all of them keep the index, the whole orbit does.
template <Orbit O, typename MAP, typename FUNC>
void foreach_orbit_neighbour(const MAP& m, Dart d, const FUNC& f)
{
	if constexpr (O == Orbit::PHI1)
		f(phi1(m, d));
	else if constexpr (O == Orbit::PHI2)
		f(phi2(m, d));
	else if constexpr (O == Orbit::PHI21)
		f(phi1(m, phi2(m, d)));
	else if constexpr (O == Orbit::PHI1_PHI2)
	{
		f(phi1(m, d));
		f(phi2(m, d));
	}
	else if constexpr (O == Orbit::PHI1_PHI3)
	{
		f(phi1(m, d));
		f(phi3(m, d));
	}
	else if constexpr (O == Orbit::PHI2_PHI3)
	{
		f(phi2(m, d));
		f(phi3(m, d));
	}
	else if constexpr (O == Orbit::PHI21_PHI31)
	{
		f(phi1(m, phi2(m, d)));
		f(phi1(m, phi3(m, d)));
	}
	else if constexpr (O == Orbit::PHI1_PHI2_PHI3)
	{
		f(phi1(m, d));
		f(phi2(m, d));
		f(phi3(m, d));
	}
	else if constexpr (O == Orbit::ALPHA0)
		f(alpha0(m, d));
	else if constexpr (O == Orbit::ALPHA1)
		f(alpha1(m, d));
	else if constexpr (is_dimension_orbit(O))
	{
		for (const auto& next : detail::ncell_steps<MAP, dimension_of_orbit(O)>(detail::state_of(m)))
			f(Dart(next[d.index]));
	}
	else if constexpr (O != Orbit::DART)
	{
		if constexpr (orbit_uses_beta(O, 0))
			f(beta0(m, d));
		if constexpr (orbit_uses_beta(O, 1))
			f(beta1(m, d));
		if constexpr (orbit_uses_beta(O, 2))
			f(beta2(m, d));
		if constexpr (orbit_uses_beta(O, 3))
			f(beta3(m, d));
	}
}

template <typename MAP, Orbit O>
void check_orbit_indexing(const MAP& m, Checker& ck)
{
	const AttributeArray<uint32>* idx = detail::state_of(m).cell_index[orbit_index(O)];
	if (idx == nullptr)
		return;
	const AttributeContainer& cells = *detail::state_of(m).cells[orbit_index(O)];
	check_container_free_list(cells, O, ck);
	if (detail::orbit_indexing_holds<O>(m, *idx, cells))
		return;
	// the detailed check, which names what is wrong
	std::vector<uint32> count(cells.end_index(), 0);
	foreach_dart(m, [&](Dart d) {
		const uint32 i = (*idx)[d.index];
		const bool boundary_cell = is_boundary_cell(m, Cell<O>(d));
		if (boundary_cell)
		{
			if (i != INVALID_INDEX)
				ck.add(Kind::BoundaryCellIndexed, O, d.index, i, "a boundary cell has an index");
			return;
		}
		if (i == INVALID_INDEX)
		{
			ck.add(Kind::MissingIndex, O, d.index, INVALID_INDEX, "a cell of an indexed orbit has no index");
			return;
		}
		if (!cells.is_live(i))
		{
			ck.add(Kind::DeadIndex, O, d.index, i, "a dart refers to a free line");
			return;
		}
		++count[i];
		foreach_orbit_neighbour<O>(m, d, [&](Dart e) {
			if ((*idx)[e.index] != i)
				ck.add(Kind::IndexNotConstant, O, d.index, i, "two darts of one cell have different indices");
		});
	});
	for (uint32 i = 0; i < cells.end_index(); ++i)
	{
		if (!cells.is_live(i))
			continue;
		const Dart rep(cells.key()[i]);
		if (!is_dart_valid(m, rep) || (*idx)[rep.index] != i)
		{
			ck.add(Kind::BadRepresentative, O, rep.index, i, "the representative dart of a line is not in its cell");
			continue;
		}
		uint32 orbit_size = 0;
		foreach_dart_of_orbit(m, Cell<O>(rep), [&](Dart) { ++orbit_size; });
		if (orbit_size != count[i])
			ck.add(Kind::IndexShared, O, rep.index, i,
				   "a line is used by " + std::to_string(count[i]) + " darts but its cell has " +
					   std::to_string(orbit_size) + ": several cells share it");
	}
}

// Each quick incidence cache against the relation recomputed from the darts.
void check_incidence_tables(const CMapBase& m, Checker& ck)
{
	for (const auto& t : detail::state_of(m).incidence_tables)
	{
		const AttributeContainer& from = *detail::state_of(m).cells[orbit_index(t->from)];
		const std::string what =
			std::string("incidence cache ") + std::string(orbit_name(t->from)) + " -> " +
			std::string(orbit_name(t->to)) +
			(t->through < NB_ORBITS ? std::string(" through ") + std::string(orbit_name(Orbit(t->through)))
									: std::string());
		if (detail::state_of(m).cell_index[orbit_index(t->from)] == nullptr ||
			t->offsets.size() != std::size_t(from.end_index()) + 1)
		{
			ck.add(Kind::IncidenceCacheStale, t->from, INVALID_INDEX, INVALID_INDEX,
				   what + ": the cells changed since it was built (call update)");
			continue;
		}
		for (uint32 r = 0; r + 1 < t->offsets.size(); ++r)
			if (!t->row_is_valid(m, *t, r))
				ck.add(Kind::IncidenceCacheStale, t->from, INVALID_INDEX, r,
					   what + ": the stored neighbours differ from the map's (call update)");
	}
}

template <typename MAP, Orbit... O>
IntegrityReport check_map(const MAP& m)
{
	IntegrityReport r;
	Checker ck(r);
	check_relations(m, ck);
	if (r.ok())
	{
		(check_orbit_indexing<MAP, O>(m, ck), ...);
		if (r.ok())
			check_incidence_tables(m, ck);
	}
	return r;
}

} // namespace

std::string IntegrityReport::to_string() const
{
	std::string s;
	for (const auto& e : errors)
		s += e.message + "\n";
	if (nb_errors > errors.size())
		s += "... and " + std::to_string(nb_errors - errors.size()) + " more\n";
	return s;
}

IntegrityReport check_integrity(const CMap1& m)
{
	return check_map<CMap1, Orbit::PHI1>(m);
}

IntegrityReport check_integrity(const CMap2& m)
{
	return check_map<CMap2, Orbit::PHI1, Orbit::PHI2, Orbit::PHI21, Orbit::PHI1_PHI2>(m);
}

IntegrityReport check_integrity(const CMap3& m)
{
	return check_map<CMap3, Orbit::PHI1, Orbit::PHI2, Orbit::PHI21, Orbit::PHI1_PHI2, Orbit::PHI1_PHI3,
					 Orbit::PHI2_PHI3, Orbit::PHI21_PHI31, Orbit::PHI1_PHI2_PHI3>(m);
}

IntegrityReport check_integrity(const Graph& g)
{
	return check_map<Graph, Orbit::ALPHA0, Orbit::ALPHA1>(g);
}

IntegrityReport check_integrity(const IncidenceGraph& ig)
{
	return check_map<IncidenceGraph, Orbit::PHI1>(ig);
}

IntegrityReport check_integrity(const GMap1& m)
{
	return check_map<GMap1, Orbit::BETA0, Orbit::BETA1, Orbit::BETA0_BETA1>(m);
}

IntegrityReport check_integrity(const GMap2& m)
{
	return check_map<GMap2, Orbit::BETA0_BETA1, Orbit::BETA0_BETA2, Orbit::BETA1_BETA2, Orbit::BETA0_BETA1_BETA2>(m);
}

template <typename MAP>
requires is_nmap_v<MAP> IntegrityReport check_integrity(const MAP& m)
{
	return [&]<std::size_t... K>(std::index_sequence<K...>)
	{
		return check_map<MAP, cell_orbit(K)...>(m);
	}
	(std::make_index_sequence<MAP::dimension + 1>{});
}

#define CGOGN_NMAP_INTEGRITY(D)                                                                                        \
	template IntegrityReport check_integrity(const CMapN<D>&);                                                         \
	template IntegrityReport check_integrity(const GMapN<D>&);
CGOGN_NMAP_INTEGRITY(1)
CGOGN_NMAP_INTEGRITY(2)
CGOGN_NMAP_INTEGRITY(3)
CGOGN_NMAP_INTEGRITY(4)
CGOGN_NMAP_INTEGRITY(5)
CGOGN_NMAP_INTEGRITY(6)
CGOGN_NMAP_INTEGRITY(7)
#undef CGOGN_NMAP_INTEGRITY

IntegrityReport check_integrity(const GMap3& m)
{
	return check_map<GMap3, Orbit::BETA0_BETA1, Orbit::BETA0_BETA2, Orbit::BETA1_BETA2, Orbit::BETA0_BETA1_BETA2,
					 Orbit::BETA0_BETA1_BETA3, Orbit::BETA0_BETA2_BETA3, Orbit::BETA1_BETA2_BETA3,
					 Orbit::BETA0_BETA1_BETA2_BETA3>(m);
}

} // namespace cgogn
