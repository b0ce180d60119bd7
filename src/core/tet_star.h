// SPDX-License-Identifier: MIT
// The star of a vertex in a tetrahedral 3-map or 3-G-map, and the
// topological conditions for contracting an edge there, written once for
// both: the predicates only need vertex identities and three walks in a
// triangle (edge_end, third_corner, across_edge).
#pragma once

#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap3.h>

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <unordered_map>
#include <vector>

namespace cgogn::detail
{

/// The dart at the other end of the edge of x, in its face. O(1).
inline Dart edge_end(const CMap3& m, Dart x)
{
	return phi1(m, x);
}
inline Dart edge_end(const GMap3& m, Dart x)
{
	return beta0(m, x);
}
/// In a triangle, a dart at the corner that x's edge does not touch. O(1).
inline Dart third_corner(const CMap3& m, Dart x)
{
	return phi_1(m, x);
}
inline Dart third_corner(const GMap3& m, Dart x)
{
	return beta<1, 0>(m, x);
}
/// The dart of the other face of x's volume along x's edge. O(1).
inline Dart across_edge(const CMap3& m, Dart x)
{
	return phi2(m, x);
}
inline Dart across_edge(const GMap3& m, Dart x)
{
	return beta2(m, x);
}

/// Vertex identities for predicates, by flooding vertex orbits on demand.
template <typename MAP>
class VertexLabels
{
public:
	explicit VertexLabels(const MAP& m) : m_(m)
	{
	}
	uint32 operator()(Dart d)
	{
		auto it = labels_.find(d.index);
		if (it != labels_.end())
			return it->second;
		const uint32 l = next_++;
		foreach_dart_of_orbit(m_, typename mesh_traits<MAP>::Vertex(d), [&](Dart x) { labels_[x.index] = l; });
		return l;
	}

private:
	const MAP& m_;
	std::unordered_map<uint32, uint32> labels_;
	uint32 next_ = 0;
};

/// A tetrahedron: four triangles, three at each corner. Four triangles alone
/// can also make a sphere with a double edge (corners of 4, 4, 2 and 2
/// triangles, left by sewing a volume onto itself), which no tetrahedral
/// operator can rebuild. O(1).
inline bool is_tetra(const CMap3& m, Dart w)
{
	uint32 darts = 0;
	bool tet = true;
	foreach_dart_of_orbit(m, CMap3::Volume(w), [&](Dart d) {
		++darts;
		const Dart next = phi<2, 1>(m, d); // the next triangle around d's corner
		tet = tet && phi<1, 1, 1>(m, d) == d && next != d && phi<2, 1, 2, 1>(m, next) == d;
		return tet && darts <= 12;
	});
	return tet && darts == 12;
}
/// The same on a 3-G-map (24 darts; a corner is a cycle of 6 darts by beta1
/// and beta2). O(1).
inline bool is_tetra(const GMap3& m, Dart w)
{
	uint32 darts = 0;
	bool tet = true;
	foreach_dart_of_orbit(m, GMap3::Volume(w), [&](Dart d) {
		++darts;
		const Dart next = beta<1, 2>(m, d);
		tet = tet && beta<0, 1, 0, 1, 0, 1>(m, d) == d && next != d && beta<1, 2, 1, 2>(m, next) == d;
		return tet && darts <= 24;
	});
	return tet && darts == 24;
}

/// A dart of each volume around v (boundary volumes skipped). O(size of the
/// star of v).
template <typename MAP>
std::vector<Dart> volumes_around(const MAP& m, typename mesh_traits<MAP>::Vertex v)
{
	std::vector<Dart> w;
	foreach_incident_volume(m, v, [&](typename mesh_traits<MAP>::Volume x) { w.push_back(x.dart); });
	return w;
}

using Tet = std::array<uint32, 4>;

inline bool all_distinct(std::vector<uint32> labels)
{
	std::sort(labels.begin(), labels.end());
	return std::adjacent_find(labels.begin(), labels.end()) == labels.end();
}

/// The four corner labels of the tet of dart w (any order). O(1).
template <typename MAP>
Tet corners(const MAP& m, Dart w, VertexLabels<MAP>& label)
{
	return {label(w), label(edge_end(m, w)), label(third_corner(m, w)), label(third_corner(m, across_edge(m, w)))};
}

// True when the link of a vertex (one triangle per incident tet, given by the
// labels of its three other corners) is a sphere (an interior vertex) or a
// disk (a boundary vertex): its star is a ball or a half-ball. A pinched
// vertex (left by unsew_volumes or remove_volume) has a link of several
// pieces, or a disk pinched at a vertex; a collapse there cannot rebuild the
// faces around it (phi3 would keep fixed points).
inline bool link_is_sphere_or_disk(const std::vector<std::array<uint32, 3>>& triangles)
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

/// The conditions of can_collapse_edge on a tetrahedral region (see
/// operators/cmap3.h), for a CMap3 or a GMap3. O(size of the stars of the
/// two ends).
template <typename MAP>
bool can_collapse_tet_edge(const MAP& m, typename mesh_traits<MAP>::Edge e)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Volume = typename mesh_traits<MAP>::Volume;
	using Face = typename mesh_traits<MAP>::Face;
	const Dart d = e.dart;
	const Vertex a(d), b(edge_end(m, d));
	VertexLabels<MAP> label(m);
	const uint32 la = label(d), lb = label(edge_end(m, d));
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
		DartMarkerStore<MAP> face_seen(m);
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
				face_seen.mark_orbit(Face(x));
				repeated = !faces_at.insert(pair_of(label(edge_end(m, x)), label(third_corner(m, x)))).second;
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
				bs.insert(pair_of(label(edge_end(m, x)), label(third_corner(m, x))));
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

} // namespace cgogn::detail
