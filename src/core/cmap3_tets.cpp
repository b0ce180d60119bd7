// SPDX-License-Identifier: MIT
// Operators of tetrahedral 3-maps: edge collapse, flips (the 1-to-4 split is
// in cmap3_split_tetra.cpp).
#include <cgogn/core/operators/cmap3.h>
#include <cgogn/core/properties/properties.h>

#include "cmap3_cavity.h"
#include "tet_star.h"

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
using detail::all_distinct;
using detail::is_tetra;
using detail::Tet;
using detail::volumes_around;
using VertexLabels = detail::VertexLabels<CMap3>;
} // namespace

bool can_collapse_edge(const CMap3& m, CMap3::Edge e)
{
	return detail::can_collapse_tet_edge(m, e);
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
