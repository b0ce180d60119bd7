// SPDX-License-Identifier: MIT
// The 1-to-4 split of a tetrahedron, written directly on the darts: the
// generic cavity re-tetrahedralization (cmap3_cavity.cpp) builds hash maps per
// call, this one touches 48 darts and allocates nothing.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/utils/error.h>

#include <array>

namespace cgogn
{

namespace
{

// The darts of the tetrahedron, face by face: old[f] is the phi1 cycle of face
// f (old[f][i + 1] = phi1(old[f][i])), face 0 is the face of w.
using OldDarts = std::array<std::array<Dart, 3>, 4>;
// new_darts[f][i] is the inner triangle built on edge old[f][i] = x (A -> B)
// inside the new tet of face f: [0] goes B -> A (phi2 of x), [1] A -> N,
// [2] N -> B, where N is the new vertex.
using NewDarts = std::array<std::array<std::array<Dart, 3>, 3>, 4>;
// face and position of phi2 of each old dart, read before the rewiring
using Opposite = std::array<std::array<std::array<uint8, 2>, 3>, 4>;

// The twelve darts of the tet and where phi2 of each lands among them; false
// when the volume of w is not a tetrahedron (4 triangles glued pairwise).
bool collect(const CMap3& m, Dart w, OldDarts& old, Opposite& opp)
{
	auto triangle = [&](Dart d, std::array<Dart, 3>& t) {
		t = {d, phi1(m, d), phi1(m, phi1(m, d))};
		return phi1(m, t[2]) == d;
	};
	if (!triangle(w, old[0]))
		return false;
	for (uint32 i = 0; i < 3; ++i)
		if (!triangle(phi2(m, old[0][i]), old[i + 1]))
			return false;
	for (uint32 f = 0; f < 4; ++f)
		for (uint32 i = 0; i < 3; ++i)
		{
			const Dart t = phi2(m, old[f][i]);
			bool found = false;
			for (uint8 g = 0; g < 4 && !found; ++g)
				for (uint8 k = 0; k < 3 && !found; ++k)
					if (old[g][k] == t && g != f)
					{
						opp[f][i] = {g, k};
						found = true;
					}
			if (!found)
				return false;
		}
	return true;
}

// Index maintenance of split_tetra, orbit by orbit: the cells of the old tet
// that survive whole (vertices, edges, faces, the connected component) keep
// their lines on their new darts; a split cell (the volume, and within it its
// vertices and edges) keeps its line on the part holding the line's
// representative dart (for the volume, the tet of w: w becomes the
// representative); the new vertex, edges, faces and the parts without the
// representative get new lines.
class SplitIndexer
{
public:
	SplitIndexer(CMap3& m, const OldDarts& old, const Opposite& opp, const NewDarts& nd)
		: m_(m), old_(old), opp_(opp), nd_(nd)
	{
	}

	void apply(Dart centre)
	{
		vertices(centre);
		edges();
		faces();
		volumes();
		vertices_of_volumes();
		edges_of_volumes();
		faces_of_volumes();
		if (AttributeArray<uint32>* cc = index(Orbit::PHI1_PHI2_PHI3))
			for_new_darts([&](Dart d) { (*cc)[d.index] = (*cc)[old_[0][0].index]; });
	}

private:
	AttributeArray<uint32>* index(Orbit o)
	{
		return detail::state_of(m_).cell_index[orbit_index(o)];
	}
	uint32 new_line(Orbit o, Dart key)
	{
		return detail::state_of(m_).cells[orbit_index(o)]->new_line(key.index);
	}
	template <typename FUNC>
	void for_new_darts(const FUNC& f)
	{
		for (const auto& face : nd_)
			for (const auto& tri : face)
				for (Dart d : tri)
					f(d);
	}

	void vertices(Dart centre)
	{
		AttributeArray<uint32>* idx = index(Orbit::PHI21_PHI31);
		if (idx == nullptr)
			return;
		const uint32 n = new_line(Orbit::PHI21_PHI31, centre);
		for (uint32 f = 0; f < 4; ++f)
			for (uint32 i = 0; i < 3; ++i)
			{
				const auto& t = nd_[f][i];
				(*idx)[t[0].index] = (*idx)[old_[f][(i + 1) % 3].index];
				(*idx)[t[1].index] = (*idx)[old_[f][i].index];
				(*idx)[t[2].index] = n;
			}
	}

	void edges()
	{
		AttributeArray<uint32>* idx = index(Orbit::PHI2_PHI3);
		if (idx == nullptr)
			return;
		for (uint32 f = 0; f < 4; ++f)
			for (uint32 i = 0; i < 3; ++i)
				(*idx)[nd_[f][i][0].index] = (*idx)[old_[f][i].index];
		// the four edges from the corners to the centre, from the darts leaving
		// corners A, B, C of face 0 and the apex D (origin of old[1][2])
		for (Dart d : {nd_[0][0][1], nd_[0][1][1], nd_[0][2][1], nd_[1][2][1]})
		{
			const uint32 l = new_line(Orbit::PHI2_PHI3, d);
			Dart e = d;
			do
			{
				(*idx)[e.index] = l;
				const Dart e2 = phi2(m_, e);
				(*idx)[e2.index] = l;
				e = phi3(m_, e2);
			} while (e != d);
		}
	}

	void faces()
	{
		AttributeArray<uint32>* idx = index(Orbit::PHI1_PHI3);
		if (idx == nullptr)
			return;
		for (uint32 f = 0; f < 4; ++f)
			for (uint32 i = 0; i < 3; ++i)
			{
				const auto [g, k] = opp_[f][i];
				if (g < f)
					continue; // the inner face of this edge is done
				const uint32 l = new_line(Orbit::PHI1_PHI3, nd_[f][i][0]);
				for (uint32 j = 0; j < 3; ++j)
				{
					(*idx)[nd_[f][i][j].index] = l;
					(*idx)[nd_[g][k][j].index] = l;
				}
			}
	}

	void volumes()
	{
		AttributeArray<uint32>* idx = index(Orbit::PHI1_PHI2);
		if (idx == nullptr)
			return;
		AttributeContainer& cells = *detail::state_of(m_).cells[orbit_index(Orbit::PHI1_PHI2)];
		for (uint32 f = 0; f < 4; ++f)
		{
			uint32 l = f == 0 ? (*idx)[old_[0][0].index] : INVALID_INDEX;
			if (l == INVALID_INDEX)
				l = cells.new_line(old_[f][0].index);
			else
				cells.key()[l] = old_[0][0].index;
			for (uint32 i = 0; i < 3; ++i)
			{
				(*idx)[old_[f][i].index] = l;
				for (Dart d : nd_[f][i])
					(*idx)[d.index] = l;
			}
		}
	}

	// a cell of the old tet split in parts: the part whose darts include `own`
	// keeps own's line when own is its representative, else gets a new one
	uint32 keep_or_new(Orbit o, AttributeArray<uint32>& idx, Dart own)
	{
		AttributeContainer& cells = *detail::state_of(m_).cells[orbit_index(o)];
		const uint32 l = idx[own.index];
		if (l != INVALID_INDEX && cells.key()[l] == own.index)
			return l;
		return cells.new_line(own.index);
	}

	void vertices_of_volumes()
	{
		AttributeArray<uint32>* idx = index(Orbit::PHI21);
		if (idx == nullptr)
			return;
		for (uint32 f = 0; f < 4; ++f)
		{
			for (uint32 i = 0; i < 3; ++i)
			{
				// the corner of old[f][i] in the tet of face f
				const Dart own = old_[f][i];
				const uint32 l = keep_or_new(Orbit::PHI21, *idx, own);
				(*idx)[own.index] = l;
				(*idx)[nd_[f][i][1].index] = l;
				(*idx)[nd_[f][(i + 2) % 3][0].index] = l;
			}
			const uint32 n = new_line(Orbit::PHI21, nd_[f][0][2]);
			for (uint32 i = 0; i < 3; ++i)
				(*idx)[nd_[f][i][2].index] = n;
		}
	}

	void edges_of_volumes()
	{
		AttributeArray<uint32>* idx = index(Orbit::PHI2);
		if (idx == nullptr)
			return;
		for (uint32 f = 0; f < 4; ++f)
			for (uint32 i = 0; i < 3; ++i)
			{
				const Dart own = old_[f][i];
				const uint32 l = keep_or_new(Orbit::PHI2, *idx, own);
				(*idx)[own.index] = l;
				(*idx)[nd_[f][i][0].index] = l;
				const Dart a = nd_[f][i][2], b = nd_[f][(i + 1) % 3][1];
				const uint32 n = new_line(Orbit::PHI2, a);
				(*idx)[a.index] = n;
				(*idx)[b.index] = n;
			}
	}

	void faces_of_volumes()
	{
		AttributeArray<uint32>* idx = index(Orbit::PHI1);
		if (idx == nullptr)
			return;
		for (uint32 f = 0; f < 4; ++f)
			for (uint32 i = 0; i < 3; ++i)
			{
				const uint32 n = new_line(Orbit::PHI1, nd_[f][i][0]);
				for (Dart d : nd_[f][i])
					(*idx)[d.index] = n;
			}
	}

	CMap3& m_;
	const OldDarts& old_;
	const Opposite& opp_;
	const NewDarts& nd_;
};

} // namespace

CMap3::Vertex split_tetra(CMap3& m, CMap3::Volume w, bool set_indices)
{
	OldDarts old;
	Opposite opp;
	// the check is a by-product of reading the darts: refuse rather than damage
	if (is_boundary(m, w.dart))
		throw TopologyError("split_tetra: the volume is a boundary volume (the outside of the mesh)");
	if (!collect(m, w.dart, old, opp))
		throw TopologyError("split_tetra: the volume is not a tetrahedron (four triangles glued pairwise)");
	// the four vertices (old darts keep their origins)
	const std::array<Dart, 4> corners{w.dart, phi1(m, w.dart), phi_1(m, w.dart), phi<2, 1, 1>(m, w.dart)};

	// The old darts stay, each on the outer face of the new tet of its face
	// (so phi3 to the outside, and every index of the outer faces, is kept);
	// 36 new darts make the 12 sides of the 6 inner triangles.
	NewDarts nd;
	for (auto& face : nd)
		for (auto& tri : face)
		{
			for (Dart& d : tri)
				d = detail::add_dart(m);
			detail::set_phi1(m, tri[0], tri[1]);
			detail::set_phi1(m, tri[1], tri[2]);
			detail::set_phi1(m, tri[2], tri[0]);
		}
	for (uint32 f = 0; f < 4; ++f)
		for (uint32 i = 0; i < 3; ++i)
		{
			const auto& t = nd[f][i];
			// phi2 inside the new tet of face f: the old edge to its inner
			// triangle, the inner triangles to each other around the centre
			detail::set_phi2(m, old[f][i], t[0]);
			detail::set_phi2(m, t[0], old[f][i]);
			const Dart next_from_centre = nd[f][(i + 1) % 3][1];
			detail::set_phi2(m, t[2], next_from_centre);
			detail::set_phi2(m, next_from_centre, t[2]);
			// phi3 across the inner face of edge old[f][i], shared with the
			// new tet of the face on the other side of that edge
			const auto [g, k] = opp[f][i];
			const auto& u = nd[g][k];
			detail::set_phi3(m, t[0], u[0]);
			detail::set_phi3(m, t[1], u[2]);
			detail::set_phi3(m, t[2], u[1]);
		}
	// goes from the centre to the origin of w, in the tet that keeps w
	const Dart centre = nd[0][2][2];
	if (set_indices)
	{
		SplitIndexer(m, old, opp, nd).apply(centre);
		// rules: the centre is the mean of the corners, each new tet a part
		// of the old one (which the tet of `centre` keeps)
		if (detail::has_rules(m))
			detail::inherit_mean<CMap3::Vertex::ORBIT>(m, centre, corners);
		if (detail::has_rules(m) && container_of<CMap3::Volume::ORBIT>(m).has_rules())
			for (uint32 f = 0; f < 4; ++f)
				if (index_of(m, CMap3::Volume(old[f][0])) != index_of(m, CMap3::Volume(centre)))
					detail::inherit<CMap3::Volume::ORBIT>(m, old[f][0], centre);
	}
	return CMap3::Vertex(centre);
}

} // namespace cgogn
