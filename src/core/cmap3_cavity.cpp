// SPDX-License-Identifier: MIT
#include "cmap3_cavity.h"

#include <cgogn/core/map/orbits.h>
#include <cgogn/core/marking/marker.h>

#include "reindex.h"

#include <algorithm>
#include <map>

namespace cgogn::detail
{

namespace
{
using Triple = std::array<uint32, 3>;

Triple sorted(Triple t)
{
	std::sort(t.begin(), t.end());
	return t;
}

// the faces of tet (p, q, r, s), seen from outside
std::array<Triple, 4> tet_faces(const std::array<uint32, 4>& t)
{
	return {Triple{t[0], t[2], t[1]}, Triple{t[0], t[1], t[3]}, Triple{t[1], t[2], t[3]}, Triple{t[2], t[0], t[3]}};
}

// true when cyclic sequences a and b are equal up to rotation
bool same_cycle(const Triple& a, const Triple& b)
{
	for (int k = 0; k < 3; ++k)
		if (a[0] == b[k] && a[1] == b[(k + 1) % 3] && a[2] == b[(k + 2) % 3])
			return true;
	return false;
}
} // namespace

Cavity::Cavity(CMap3& m, const std::vector<Dart>& volumes) : m_(m)
{
	DartMarkerStore<CMap3> in(m);
	for (Dart w : volumes)
		if (!in.is_marked(w))
			foreach_dart_of_orbit(m, CMap3::Volume(w), [&](Dart d) {
				in.mark(d);
				darts_.push_back(d);
			});
	const AttributeArray<uint32>* vidx = detail::state_of(m).cell_index[orbit_index(Orbit::PHI21_PHI31)];
	for (Dart d : darts_)
	{
		if (labels_.count(d.index))
			continue;
		const uint32 l = uint32(alias_.size());
		alias_.push_back(l);
		line_.push_back(vidx ? (*vidx)[d.index] : INVALID_INDEX);
		foreach_dart_of_orbit(m, CMap3::Vertex(d), [&](Dart x) { labels_[x.index] = l; });
	}
}

uint32 Cavity::find(uint32 l) const
{
	while (alias_[l] != l)
		l = alias_[l];
	return l;
}

uint32 Cavity::label(Dart d) const
{
	return find(labels_.at(d.index));
}

uint32 Cavity::new_vertex()
{
	alias_.push_back(uint32(alias_.size()));
	line_.push_back(INVALID_INDEX);
	return alias_.back();
}

void Cavity::merge_vertices(uint32 keep, uint32 gone)
{
	alias_[find(gone)] = find(keep);
}

std::array<uint32, 4> Cavity::tetra_labels(Dart w) const
{
	// the face of w is (p, r, q) seen from outside: w goes p -> r
	const uint32 p = label(w), r = label(phi1(m_, w)), q = label(phi1(m_, phi1(m_, w)));
	const uint32 s = label(phi_1(m_, phi2(m_, w))); // apex: the third vertex of the face across w
	return {p, q, r, s};
}

std::vector<Dart> Cavity::fill(std::vector<std::array<uint32, 4>> tets, bool set_indices)
{
	CMap3& m = m_;
	for (auto& t : tets)
		for (auto& l : t)
			l = find(l);
	// 1. the cavity's boundary faces, seen from outside the cavity
	DartMarkerStore<CMap3> in(m);
	for (Dart d : darts_)
		in.mark(d);
	std::map<Triple, std::pair<Dart, Triple>> outer; // sorted labels -> (outer dart, labels in phi1 order)
	std::map<Triple, std::vector<Dart>> faces;       // sorted labels -> faces to sew pairwise
	std::vector<Dart> outer_darts;
	std::vector<Dart> degenerate; // boundary triangles on a collapsed edge: one dart each
	for (Dart d : darts_)
	{
		const Dart o = phi3(m, d);
		if (in.is_marked(o))
			continue;
		const Triple t{label(o), label(phi1(m, o)), label(phi1(m, phi1(m, o)))};
		if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
		{
			if (t[0] == t[1])
				degenerate.push_back(o);
			continue;
		}
		outer_darts.push_back(o);
		outer.emplace(sorted(t), std::make_pair(o, t));
		if (phi1(m, phi1(m, o)) != phi_1(m, o)) // not a triangle: cannot be matched
			continue;
		if (std::find_if(faces[sorted(t)].begin(), faces[sorted(t)].end(), [&](Dart x) {
				return same_orbit(m, CMap3::Face2(x), CMap3::Face2(o));
			}) == faces[sorted(t)].end())
			faces[sorted(t)].push_back(o);
	}
	// 2. orient each new tet so that its faces on the cavity boundary face the outer faces
	std::vector<bool> oriented(tets.size(), false);
	for (std::size_t k = 0; k < tets.size(); ++k)
		for (const Triple& f : tet_faces(tets[k]))
		{
			auto it = outer.find(sorted(f));
			if (it == outer.end())
				continue;
			const Triple& o = it->second.second;
			const Triple reversed{o[0], o[2], o[1]};
			if (!same_cycle(f, reversed))
				std::swap(tets[k][1], tets[k][2]);
			oriented[k] = true;
			break;
		}
	assert(std::all_of(oriented.begin(), oriented.end(), [](bool b) { return b; }) &&
		   "every new tetrahedron must touch the cavity's boundary");
	// 3. remove the cavity
	RegionReindexer<CMap3> reindexer;
	if (set_indices)
	{
		std::vector<Dart> recorded = darts_;
		recorded.insert(recorded.end(), outer_darts.begin(), outer_darts.end());
		for (Dart e0 : degenerate)
			recorded.insert(recorded.end(), {e0, phi1(m, e0), phi_1(m, e0)});
		reindexer.record(m, recorded);
	}
	for (Dart o : outer_darts)
		set_phi3(m, o, o);
	// a degenerate boundary triangle is contracted inside the boundary surface:
	// its two other edges become one
	for (Dart e0 : degenerate)
	{
		const Dart e1 = phi1(m, e0), e2 = phi1(m, e1);
		const Dart n1 = phi2(m, e1), n2 = phi2(m, e2);
		set_phi2(m, n1, n2);
		set_phi2(m, n2, n1);
		outer_darts.push_back(n1); // their cells are in the changed region
		outer_darts.push_back(n2);
	}
	for (Dart e0 : degenerate)
	{
		const Dart e1 = phi1(m, e0), e2 = phi1(m, e1);
		for (Dart x : {e0, e1, e2})
			remove_dart(m, x);
	}
	for (Dart d : darts_)
		remove_dart(m, d);
	// 4. build the tets, remember the label of each new dart's origin
	std::vector<Dart> created, firsts;
	std::unordered_map<uint32, uint32> origin; // new dart -> label
	for (const auto& t : tets)
	{
		std::vector<Dart> tet_darts;
		for (const Triple& f : tet_faces(t))
		{
			Dart first;
			Dart prev;
			for (uint32 i = 0; i < 3; ++i)
			{
				const Dart d = add_dart(m);
				origin[d.index] = f[i];
				tet_darts.push_back(d);
				created.push_back(d);
				if (i == 0)
					first = d;
				else
					set_phi1(m, prev, d);
				prev = d;
			}
			set_phi1(m, prev, first);
			faces[sorted(f)].push_back(first);
		}
		for (Dart d : tet_darts)
		{
			if (phi2(m, d) != d)
				continue;
			const uint32 a = origin[d.index], b = origin[phi1(m, d).index];
			for (Dart e : tet_darts)
				if (e != d && phi2(m, e) == e && origin[e.index] == b && origin[phi1(m, e).index] == a)
				{
					phi2_sew(m, d, e);
					break;
				}
		}
		firsts.push_back(tet_darts.front());
	}
	// 5. sew faces by labels, two by two: new faces between them or with outer
	// faces, and outer faces whose volume in between vanished
	auto label_of = [&](Dart d) { return origin.count(d.index) ? origin[d.index] : label(d); };
	auto sew_faces3 = [&](Dart a, Dart b) {
		// align b so that it goes from the end of a to its origin
		Dart y = b;
		for (int k = 0; k < 3 && !(label_of(y) == label_of(phi1(m, a)) && label_of(phi1(m, y)) == label_of(a)); ++k)
			y = phi1(m, y);
		Dart x = a;
		for (int k = 0; k < 3; ++k)
		{
			phi3_sew(m, x, y);
			x = phi1(m, x);
			y = phi_1(m, y);
		}
	};
	for (auto& [key, list] : faces)
	{
		assert(list.size() == 2 && "faces of the cavity do not pair up");
		if (list.size() == 2)
			sew_faces3(list[0], list[1]);
	}
	for (Dart d : created)
		created_.emplace_back(d, origin[d.index]);
	// 6. indices: vertices of new darts take their label's line, then the region claims its lines
	if (set_indices)
	{
		std::vector<Dart> region = created;
		region.insert(region.end(), outer_darts.begin(), outer_darts.end());
		if (AttributeArray<uint32>* vidx = detail::state_of(m).cell_index[orbit_index(Orbit::PHI21_PHI31)])
		{
			for (Dart d : created)
				(*vidx)[d.index] = line_[find(origin[d.index])];
			// a vertex whose labels merged keeps the line of the label kept: the
			// reindexer would take whichever line it met first, the removed
			// vertex's when no new dart reaches the survivor (all the removed
			// end's tets surrounded the collapsed edge)
			for (Dart d : outer_darts)
			{
				const auto it = labels_.find(d.index);
				if (it == labels_.end())
					continue;
				const uint32 l = line_[find(it->second)];
				if (l != INVALID_INDEX && (*vidx)[d.index] != l)
					write_index(m, CMap3::Vertex(d), l);
			}
		}
		reindexer.apply(m, region);
	}
	return firsts;
}

Dart Cavity::vertex_dart(uint32 l) const
{
	l = find(l);
	for (auto [d, o] : created_)
		if (find(o) == l)
			return d;
	for (auto [d, o] : labels_)
		if (find(o) == l && is_dart_valid(m_, Dart(d)))
			return Dart(d);
	return Dart();
}

Dart Cavity::dart_between(uint32 from, uint32 to) const
{
	from = find(from);
	to = find(to);
	for (auto [d, o] : created_)
		if (find(o) == from)
			for (auto [e, p] : created_)
				if (e == phi1(m_, d) && find(p) == to)
					return d;
	return Dart();
}

} // namespace cgogn::detail
