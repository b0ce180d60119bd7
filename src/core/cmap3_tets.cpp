// SPDX-License-Identifier: MIT
// Operators of tetrahedral 3-maps: edge collapse, flips (the 1-to-4 split is
// in cmap3_split_tetra.cpp).
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/properties/properties.h>

#include "cmap3_cavity.h"

#include <algorithm>
#include <map>
#include <set>
#include <unordered_map>

namespace cgogn
{

namespace
{
using Vertex = CMap3::Vertex;
using Volume = CMap3::Volume;

// Vertex identities for predicates, by flooding vertex orbits on demand.
class VertexLabels
{
public:
	explicit VertexLabels(const CMap3& m) : m_(m)
	{
	}
	uint32 operator()(Dart d)
	{
		auto it = labels_.find(d.index);
		if (it != labels_.end())
			return it->second;
		const uint32 l = next_++;
		foreach_dart_of_orbit(m_, Vertex(d), [&](Dart x) { labels_[x.index] = l; });
		return l;
	}

private:
	const CMap3& m_;
	std::unordered_map<uint32, uint32> labels_;
	uint32 next_ = 0;
};

// A tetrahedron: four triangles, three at each corner. Four triangles alone
// can also make a sphere with a double edge (corners of 4, 4, 2 and 2
// triangles, left by sewing a volume onto itself), which no tetrahedral
// operator can rebuild.
bool is_tetra(const CMap3& m, Dart w)
{
	uint32 darts = 0;
	bool tet = true;
	foreach_dart_of_orbit(m, Volume(w), [&](Dart d) {
		++darts;
		const Dart next = phi<2, 1>(m, d); // the next triangle around d's corner
		tet = tet && phi<1, 1, 1>(m, d) == d && next != d && phi<2, 1, 2, 1>(m, next) == d;
		return tet && darts <= 12;
	});
	return tet && darts == 12;
}

std::vector<Dart> volumes_around(const CMap3& m, Vertex v)
{
	std::vector<Dart> w;
	foreach_incident_volume(m, v, [&](Volume x) { w.push_back(x.dart); });
	return w;
}

using Tet = std::array<uint32, 4>;

bool all_distinct(std::vector<uint32> labels)
{
	std::sort(labels.begin(), labels.end());
	return std::adjacent_find(labels.begin(), labels.end()) == labels.end();
}

// the four corner labels of the tet of dart w (any order)
Tet corners(const CMap3& m, Dart w, VertexLabels& label)
{
	return {label(w), label(phi1(m, w)), label(phi_1(m, w)), label(phi_1(m, phi2(m, w)))};
}

// True when the link of a vertex (one triangle per incident tet, given by the
// labels of its three other corners) is a sphere (an interior vertex) or a
// disk (a boundary vertex): its star is a ball or a half-ball. A pinched
// vertex (left by unsew_volumes or remove_volume) has a link of several
// pieces, or a disk pinched at a vertex; a collapse there cannot rebuild the
// faces around it (phi3 would keep fixed points).
bool link_is_sphere_or_disk(const std::vector<std::array<uint32, 3>>& triangles)
{
	std::map<std::pair<uint32, uint32>, uint32> edge_count;
	std::map<uint32, uint32> parent; // union-find over the link's vertices
	const auto root = [&](uint32 x) {
		while (parent[x] != x)
			x = parent[x] = parent[parent[x]];
		return x;
	};
	for (const auto& t : triangles)
		for (uint32 x : t)
			parent.emplace(x, x);
	for (const auto& t : triangles)
		for (int k = 0; k < 3; ++k)
		{
			const uint32 x = t[k], y = t[(k + 1) % 3];
			++edge_count[{std::min(x, y), std::max(x, y)}];
			parent[root(x)] = root(y);
		}
	std::map<uint32, uint32> boundary_degree;
	for (const auto& [edge, count] : edge_count)
	{
		if (count > 2)
			return false;
		if (count == 1)
		{
			++boundary_degree[edge.first];
			++boundary_degree[edge.second];
		}
	}
	for (const auto& [x, deg] : boundary_degree)
		if (deg != 2)
			return false; // the link's boundary is pinched at x
	uint32 components = 0;
	for (const auto& [x, p] : parent)
		components += root(x) == x;
	const int64 chi = int64(parent.size()) - int64(edge_count.size()) + int64(triangles.size());
	return components == 1 && chi == (boundary_degree.empty() ? 2 : 1);
}
} // namespace

bool can_collapse_edge(const CMap3& m, CMap3::Edge e)
{
	const Dart d = e.dart;
	const Vertex a(d), b(phi1(m, d));
	VertexLabels label(m);
	const uint32 la = label(d), lb = label(phi1(m, d));
	if (la == lb)
		return false;
	std::set<uint32> va, vb, vab;
	std::set<std::pair<uint32, uint32>> ea, eb, eab, ba, bb;
	std::set<std::array<uint32, 3>> ta, tb;
	auto pair_of = [](uint32 x, uint32 y) { return std::make_pair(std::min(x, y), std::max(x, y)); };
	bool star_ok = true;
	std::vector<std::array<uint32, 3>> link_triangles; // of the last vertex given to link()
	auto link = [&](Vertex v, uint32 lv, std::set<uint32>& vs, std::set<std::pair<uint32, uint32>>& es,
					std::set<std::array<uint32, 3>>& ts) {
		link_triangles.clear();
		// The collapse rebuilds the star by vertex labels: two faces at v with the
		// same corners (the two sides of an unsewn face) or two tets with the same
		// corners cannot be told apart, so they are refused.
		DartMarkerStore<CMap3> face_seen(m);
		std::set<std::pair<uint32, uint32>> faces_at;
		for (Dart w : volumes_around(m, v))
		{
			if (!is_tetra(m, w))
			{
				star_ok = false;
				return;
			}
			bool repeated = false;
			foreach_dart_of_orbit(m, Volume(w), [&](Dart x) {
				if (label(x) != lv || face_seen.is_marked(x))
					return true;
				face_seen.mark_orbit(CMap3::Face(x));
				repeated = !faces_at.insert(pair_of(label(phi1(m, x)), label(phi_1(m, x)))).second;
				return !repeated;
			});
			const Tet t = corners(m, w, label);
			if (repeated || !all_distinct({t.begin(), t.end()})) // volumes sewn onto themselves repeat a corner
			{
				star_ok = false;
				return;
			}
			std::vector<uint32> others;
			for (uint32 x : t)
				if (x != lv)
					others.push_back(x);
			std::sort(others.begin(), others.end());
			vs.insert(others.begin(), others.end());
			es.insert({others[0], others[1]});
			es.insert({others[1], others[2]});
			es.insert({others[0], others[2]});
			if (!ts.insert({others[0], others[1], others[2]}).second)
			{
				star_ok = false; // two tets with the same corners
				return;
			}
			link_triangles.push_back({others[0], others[1], others[2]});
			if (lv == la && std::find(t.begin(), t.end(), lb) != t.end())
			{
				std::vector<uint32> cd;
				for (uint32 x : t)
					if (x != la && x != lb)
						cd.push_back(x);
				vab.insert(cd.begin(), cd.end());
				eab.insert(pair_of(cd[0], cd[1]));
			}
		}
	};
	link(a, la, va, ea, ta);
	if (!star_ok || !link_is_sphere_or_disk(link_triangles))
		return false;
	link(b, lb, vb, eb, tb);
	if (!star_ok || !link_is_sphere_or_disk(link_triangles))
		return false;
	for (uint32 c : va)
		if (c != lb && vb.count(c) && !vab.count(c))
			return false;
	for (const auto& x : ea)
		if (eb.count(x) && !eab.count(x))
			return false;
	for (const auto& x : ta)
		if (tb.count(x))
			return false;
	// the outside as a vertex: boundary faces around a and b
	auto boundary_faces = [&](Vertex v, std::set<std::pair<uint32, uint32>>& bs) {
		foreach_dart_of_orbit(m, v, [&](Dart x) {
			if (is_boundary(m, x))
				bs.insert(pair_of(label(phi1(m, x)), label(phi_1(m, x))));
		});
	};
	boundary_faces(a, ba);
	boundary_faces(b, bb);
	if (ba.empty() || bb.empty())
		return true;
	bool ab_on_boundary = false;
	std::set<uint32> bva, bvb;
	for (auto [x, y] : ba)
	{
		bva.insert({x, y});
		ab_on_boundary = ab_on_boundary || x == lb || y == lb;
	}
	for (auto [x, y] : bb)
		bvb.insert({x, y});
	if (!ab_on_boundary)
		return false; // would pinch two parts of the boundary together
	for (uint32 c : bva)
		if (c != la && c != lb && bvb.count(c) && !ba.count(pair_of(lb, c)))
			return false;
	for (const auto& x : ba)
		if (x.first != lb && x.second != lb && bb.count(x))
			return false;
	return true;
}

Vertex collapse_edge(CMap3& m, CMap3::Edge e, bool set_indices)
{
	assert(can_collapse_edge(m, e));
	const Dart d = e.dart;
	detail::Cavity cavity(m, volumes_around(m, Vertex(d)));
	const uint32 la = cavity.label(d), lb = cavity.label(phi1(m, d));
	std::vector<Tet> tets;
	for (Dart w : volumes_around(m, Vertex(d)))
	{
		Tet t = cavity.tetra_labels(w);
		if (std::find(t.begin(), t.end(), lb) != t.end())
			continue; // the tets around the edge vanish
		std::replace(t.begin(), t.end(), la, lb);
		tets.push_back(t);
	}
	cavity.merge_vertices(lb, la);
	cavity.fill(tets, set_indices);
	return Vertex(cavity.vertex_dart(lb));
}

bool can_flip_face(const CMap3& m, CMap3::Face f)
{
	const Dart d = f.dart, d3 = phi3(m, d);
	if (is_boundary(m, d) || is_boundary(m, d3) || !is_tetra(m, d) || !is_tetra(m, d3))
		return false;
	const Vertex apex_a(phi_1(m, phi2(m, d))), apex_b(phi_1(m, phi2(m, d3)));
	// five distinct vertices (volumes sewn onto themselves can repeat one)
	VertexLabels label(m);
	if (!all_distinct({label(d), label(phi1(m, d)), label(phi_1(m, d)), label(apex_a.dart), label(apex_b.dart)}))
		return false;
	bool joined = false;
	foreach_adjacent_vertex_through_edge(m, apex_a, [&](Vertex v) { return !(joined = same_orbit(m, v, apex_b)); });
	return !joined;
}

CMap3::Edge flip_face(CMap3& m, CMap3::Face f, bool set_indices)
{
	assert(can_flip_face(m, f));
	const Dart d = f.dart, d3 = phi3(m, d);
	detail::Cavity cavity(m, {d, d3});
	const uint32 a = cavity.label(d), b = cavity.label(phi1(m, d)), c = cavity.label(phi_1(m, d));
	const uint32 s = cavity.label(phi_1(m, phi2(m, d))), t = cavity.label(phi_1(m, phi2(m, d3)));
	cavity.fill({{a, b, s, t}, {b, c, s, t}, {c, a, s, t}}, set_indices);
	return CMap3::Edge(cavity.dart_between(s, t));
}

namespace
{
// the vertices around edge e in cyclic order (third vertex of each face), if
// every volume around it is a non-boundary tetrahedron
bool ring_of(const CMap3& m, CMap3::Edge e, std::vector<Dart>& faces)
{
	Dart it = e.dart;
	do
	{
		if (is_boundary(m, it) || !is_tetra(m, it))
			return false;
		faces.push_back(it);
		it = phi3(m, phi2(m, it));
	} while (it != e.dart);
	return true;
}
} // namespace

bool can_flip_edge(const CMap3& m, CMap3::Edge e)
{
	std::vector<Dart> faces;
	if (!ring_of(m, e, faces) || (faces.size() != 3 && faces.size() != 4))
		return false;
	VertexLabels label(m);
	std::vector<uint32> ring;
	for (Dart x : faces)
		ring.push_back(label(phi_1(m, x)));
	// the ends and the ring: distinct vertices (volumes sewn onto themselves can repeat one)
	std::vector<uint32> around = ring;
	around.insert(around.end(), {label(e.dart), label(phi1(m, e.dart))});
	if (!all_distinct(std::move(around)))
		return false;
	if (faces.size() == 3)
	{
		// no face (c1, c2, c3) already: look at the faces around the edge c1 c2
		bool exists = false;
		Dart c1c2;
		foreach_incident_edge(m, Vertex(phi_1(m, faces[0])), [&](CMap3::Edge x) {
			if (label(phi1(m, x.dart)) != ring[1])
				return true;
			c1c2 = x.dart;
			return false;
		});
		if (!c1c2.is_valid())
			return false;
		// a face around the edge c1 c2 whose third vertex is c3
		foreach_dart_of_orbit(m, CMap3::Edge(c1c2), [&](Dart x) { return !(exists = label(phi_1(m, x)) == ring[2]); });
		return !exists;
	}
	// 4-4: the diagonal c1 c3 must not be an edge already
	bool joined = false;
	foreach_adjacent_vertex_through_edge(m, Vertex(phi_1(m, faces[0])),
										 [&](Vertex v) { return !(joined = label(v.dart) == ring[2]); });
	return !joined;
}

Dart flip_edge(CMap3& m, CMap3::Edge e, bool set_indices)
{
	assert(can_flip_edge(m, e));
	std::vector<Dart> faces;
	ring_of(m, e, faces);
	std::vector<Dart> volumes(faces.begin(), faces.end());
	detail::Cavity cavity(m, volumes);
	const uint32 a = cavity.label(e.dart), b = cavity.label(phi1(m, e.dart));
	std::vector<uint32> c;
	for (Dart x : faces)
		c.push_back(cavity.label(phi_1(m, x)));
	if (faces.size() == 3)
	{
		cavity.fill({{c[0], c[1], c[2], a}, {c[0], c[1], c[2], b}}, set_indices);
		return cavity.dart_between(c[0], c[1]);
	}
	cavity.fill({{a, c[0], c[1], c[2]}, {a, c[0], c[2], c[3]}, {b, c[0], c[1], c[2]}, {b, c[0], c[2], c[3]}},
				set_indices);
	return cavity.dart_between(c[0], c[2]);
}

} // namespace cgogn
