// SPDX-License-Identifier: MIT
// The 3-map operators keep what their documentation states: which lines
// survive, which cells are new, that incidence caches are dropped; and their
// predicates refuse the pinched configurations the operators cannot handle.
#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace cgogn_test_operator_contracts_3d
{

using namespace cgogn;
using Vertex = CMap3::Vertex;
using Edge = CMap3::Edge;
using Face = CMap3::Face;
using Volume = CMap3::Volume;

using test::all;
using test::counts;
using test::Counts;
using test::find;
using test::index_everything;

namespace
{
using test::indexed;

CMap3 tets(uint32 nb_vertices, const std::vector<std::array<uint32, 4>>& cells)
{
	VolumeSoup s;
	s.nb_vertices = nb_vertices;
	for (const auto& c : cells)
	{
		s.cell_sizes.push_back(4);
		s.cell_vertices.insert(s.cell_vertices.end(), c.begin(), c.end());
	}
	return indexed(s);
}

bool inner(const CMap3& m, Face f)
{
	return !is_boundary(m, f.dart) && !is_boundary(m, phi3(m, f.dart));
}

template <typename CELL>
bool live(const CMap3& m, uint32 line)
{
	return container_of<CELL::ORBIT>(m).is_live(line);
}

// The vertex of m whose index is `line`.
Dart dart_of_vertex(const CMap3& m, uint32 line)
{
	return find<Vertex>(m, [&](Vertex v) { return index_of(m, v) == line; }).dart;
}

// The first edge of a vertex from a to b that the predicate accepts (invalid if none).
Edge collapsible_from(const CMap3& m, uint32 a)
{
	Edge r;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d) || index_of(m, Vertex(d)) != a || !can_collapse_edge(m, Edge(d)))
			return true;
		r = Edge(d);
		return false;
	});
	return r;
}
} // namespace

// Every operator changes relations, boundary marks or the set of darts, and
// each of those drops the map's incidence caches.
TEST(OperatorContracts3, EveryOperatorDropsIncidenceCaches)
{
	using VW = IncidenceCache<CMap3, Vertex, Volume>;
	const std::vector<std::pair<std::string, std::function<void(CMap3&)>>> edits = {
		{"add_tetra", [](CMap3& m) { add_tetra(m); }},
		{"sew_volumes",
		 [](CMap3& m) {
			 const Volume w = add_tetra(m);
			 const Face f = find<Face>(m, [&](Face x) {
				 return !is_boundary(m, x.dart) && is_boundary(m, phi3(m, x.dart)) && !same_orbit(m, Volume(x.dart), w);
			 });
			 sew_volumes(m, f, Face(w.dart));
		 }},
		{"unsew_volumes", [](CMap3& m) { unsew_volumes(m, find<Face>(m, [&](Face f) { return inner(m, f); })); }},
		{"remove_volume", [](CMap3& m) { remove_volume(m, all<Volume>(m)[0]); }},
		{"cut_edge", [](CMap3& m) { cut_edge(m, all<Edge>(m)[0]); }},
		{"cut_face",
		 [](CMap3& m) {
			 const Dart d = all<Face>(m)[0].dart;
			 cut_edge(m, Edge(d));
			 VW::build(m);
			 ASSERT_TRUE(can_cut_face(m, d, phi<1, 1>(m, d)));
			 cut_face(m, d, phi<1, 1>(m, d));
		 }},
		{"cut_volume",
		 [](CMap3& m) {
			 const Dart d = all<Volume>(m)[0].dart;
			 cut_volume(m, {d, phi1(m, d), phi_1(m, d)});
		 }},
		{"merge_incident_volumes",
		 [](CMap3& m) { merge_incident_volumes(m, find<Face>(m, [&](Face f) { return inner(m, f); })); }},
		{"merge_incident_faces",
		 [](CMap3& m) {
			 const Dart d = all<Face>(m)[0].dart;
			 cut_edge(m, Edge(d)); // a quad: d and phi<1, 1>(d) are opposite corners
			 ASSERT_TRUE(can_cut_face(m, d, phi<1, 1>(m, d)));
			 const Edge e = cut_face(m, d, phi<1, 1>(m, d));
			 VW::build(m);
			 merge_incident_faces(m, e);
		 }},
		{"split_tetra", [](CMap3& m) { split_tetra(m, all<Volume>(m)[0]); }},
		{"collapse_edge",
		 [](CMap3& m) {
			 split_tetra(m, all<Volume>(m)[0]);
			 const Edge e = find<Edge>(m, [&](Edge x) { return can_collapse_edge(m, x); });
			 VW::build(m);
			 collapse_edge(m, e);
		 }},
		{"flip_face", [](CMap3& m) { flip_face(m, find<Face>(m, [&](Face f) { return can_flip_face(m, f); })); }},
		{"flip_edge",
		 [](CMap3& m) {
			 const Edge e = flip_face(m, find<Face>(m, [&](Face f) { return can_flip_face(m, f); }));
			 VW::build(m);
			 ASSERT_TRUE(can_flip_edge(m, e));
			 flip_edge(m, e);
		 }},
	};
	for (const auto& [name, edit] : edits)
	{
		CMap3 m = indexed(tet_grid_soup(1, 1, 1));
		VW::build(m);
		edit(m);
		EXPECT_FALSE(VW::is_built(m)) << name;
		EXPECT_INTEGRITY(m);
	}
}

// cut_edge: the half holding e.dart keeps the edge's line, the new vertex and
// the other half are new; faces and volumes keep theirs.
TEST(OperatorContracts3, CutEdgeLines)
{
	CMap3 m = indexed(tet_grid_soup(1, 1, 1));
	const Edge e = find<Edge>(m, [&](Edge x) { return !is_incident_to_boundary(m, x); });
	ASSERT_TRUE(e.dart.is_valid());
	const uint32 edge = index_of(m, e), face = index_of(m, Face(e.dart)), volume = index_of(m, Volume(e.dart));
	const uint32 end = index_of(m, Vertex(phi2(m, e.dart)));
	const Vertex v = cut_edge(m, e);
	EXPECT_EQ(index_of(m, Edge(e.dart)), edge);
	EXPECT_NE(index_of(m, Edge(v.dart)), edge);
	EXPECT_EQ(index_of(m, Face(e.dart)), face);
	EXPECT_EQ(index_of(m, Volume(e.dart)), volume);
	EXPECT_EQ(index_of(m, Vertex(phi1(m, v.dart))), end);
	EXPECT_INTEGRITY(m);
}

// cut_face: the part holding d keeps the face's line; the other part and the
// new edge are new.
TEST(OperatorContracts3, CutFaceLines)
{
	CMap3 m = indexed(hex_grid_soup(1, 1, 1));
	const Dart d = all<Face>(m)[0].dart, e = phi<1, 1>(m, d);
	const uint32 face = index_of(m, Face(d));
	const Counts before = counts(m);
	const Edge n = cut_face(m, d, e);
	EXPECT_EQ(index_of(m, Face(d)), face);
	EXPECT_NE(index_of(m, Face(e)), face);
	EXPECT_EQ(counts(m), (Counts{before.v, before.e + 1, before.f + 1, before.w}));
	EXPECT_TRUE(same_orbit(m, Vertex(n.dart), Vertex(d)));
	EXPECT_INTEGRITY(m);
}

// cut_volume: the path side keeps the volume's line, the phi2 side and the new
// face are new; a non-separating path leaves one volume with its line.
TEST(OperatorContracts3, CutVolumeLines)
{
	CMap3 m = indexed(hex_grid_soup(1, 1, 1));
	const Volume w = all<Volume>(m)[0];
	const uint32 volume = index_of(m, w);
	// around a corner of the hexahedron: 6 darts through 6 distinct vertices
	std::vector<Dart> path;
	Dart it = w.dart;
	do
	{
		path.push_back(phi1(m, it));
		path.push_back(phi<1, 1>(m, it));
		it = phi2(m, phi_1(m, it));
	} while (it != w.dart);
	ASSERT_TRUE(can_cut_volume(m, path));
	EXPECT_FALSE(can_cut_volume(m, {path[0], path[1]}));
	EXPECT_FALSE(can_cut_volume(m, {path[0], path[2], path[1]}));
	const Face f = cut_volume(m, path);
	EXPECT_EQ(index_of(m, Volume(path[0])), volume);
	EXPECT_NE(index_of(m, Volume(phi3(m, f.dart))), volume);
	EXPECT_EQ(codegree(m, f), 6u);
	EXPECT_EQ(counts(m), (Counts{8, 12, 7, 2}));
	EXPECT_INTEGRITY(m);
}

// merges keep the line of the cell of the given dart and release the other.
TEST(OperatorContracts3, MergesKeepTheLineOfTheGivenDart)
{
	CMap3 m = indexed(hex_grid_soup(2, 1, 1));
	const Face inner_face = find<Face>(m, [&](Face f) { return inner(m, f); });
	const uint32 kept = index_of(m, Volume(inner_face.dart)), gone = index_of(m, Volume(phi3(m, inner_face.dart)));
	EXPECT_EQ(index_of(m, merge_incident_volumes(m, inner_face)), kept);
	EXPECT_FALSE(live<Volume>(m, gone));
	EXPECT_INTEGRITY(m);

	const Dart d = all<Face>(m)[0].dart;
	const Edge e = cut_face(m, d, phi<1, 1>(m, d));
	const uint32 face = index_of(m, Face(e.dart)), other = index_of(m, Face(phi2(m, e.dart))), edge = index_of(m, e);
	EXPECT_EQ(index_of(m, merge_incident_faces(m, e)), face);
	EXPECT_FALSE(live<Face>(m, other));
	EXPECT_FALSE(live<Edge>(m, edge));
	EXPECT_INTEGRITY(m);
}

// sew_volumes: cells brought together keep the lines of f1's side; the
// boundary faces in between vanish with their lines.
TEST(OperatorContracts3, SewKeepsTheLinesOfF1)
{
	CMap3 m;
	index_everything(m);
	const Volume a = add_tetra(m), b = add_tetra(m);
	const Face f1(a.dart), f2(b.dart);
	std::vector<uint32> vertices, edges;
	foreach_dart_of_orbit(m, CMap3::Face2(f1.dart), [&](Dart x) {
		vertices.push_back(index_of(m, Vertex(x)));
		edges.push_back(index_of(m, Edge(x)));
	});
	const uint32 face = index_of(m, f1), other = index_of(m, f2);
	const uint32 component = index_of(m, CMap3::CC(a.dart)), gone = index_of(m, CMap3::CC(b.dart));
	sew_volumes(m, f1, f2);
	EXPECT_EQ(index_of(m, CMap3::CC(b.dart)), component);
	EXPECT_FALSE(live<CMap3::CC>(m, gone));
	std::size_t i = 0;
	foreach_dart_of_orbit(m, CMap3::Face2(f1.dart), [&](Dart x) {
		EXPECT_EQ(index_of(m, Vertex(x)), vertices[i]);
		EXPECT_EQ(index_of(m, Edge(x)), edges[i]);
		++i;
	});
	EXPECT_EQ(index_of(m, f1), face);
	EXPECT_FALSE(live<Face>(m, other));
	EXPECT_EQ(counts(m), (Counts{5, 9, 7, 2}));
	EXPECT_INTEGRITY(m);
}

// unsew_volumes: f.dart's side keeps the face's line, the other side gets a
// new one; remove_volume: every other cell keeps its line.
TEST(OperatorContracts3, UnsewAndRemoveLines)
{
	CMap3 m = indexed(hex_grid_soup(2, 1, 1));
	const Face f = find<Face>(m, [&](Face x) { return inner(m, x); });
	const Dart other_side = phi3(m, f.dart);
	const uint32 face = index_of(m, f), edge = index_of(m, Edge(f.dart)), vertex = index_of(m, Vertex(f.dart));
	const uint32 volume = index_of(m, Volume(f.dart)), other_volume = index_of(m, Volume(other_side));
	unsew_volumes(m, f);
	EXPECT_EQ(index_of(m, Volume(f.dart)), volume);
	EXPECT_EQ(index_of(m, Volume(other_side)), other_volume);
	EXPECT_EQ(index_of(m, f), face);
	EXPECT_NE(index_of(m, Face(other_side)), face);
	EXPECT_EQ(index_of(m, Edge(f.dart)), edge);
	EXPECT_NE(index_of(m, Edge(other_side)), edge);
	EXPECT_EQ(index_of(m, Vertex(f.dart)), vertex);
	EXPECT_EQ(nb_connected_components(m), 2u);
	EXPECT_INTEGRITY(m);

	CMap3 g = indexed(hex_grid_soup(3, 1, 1));
	const std::vector<Vertex> vs = all<Vertex>(g);
	std::vector<uint32> lines;
	for (Vertex v : vs)
		lines.push_back(index_of(g, v));
	remove_volume(g, all<Volume>(g)[2]);
	for (std::size_t k = 0; k < vs.size(); ++k)
		if (is_dart_valid(g, vs[k].dart))
		{
			EXPECT_EQ(index_of(g, vs[k]), lines[k]);
		}
	EXPECT_INTEGRITY(g);
}

// Flips keep the lines of the vertices and of the cells on the boundary of
// the replaced tets; the tets are rebuilt with new lines, the old released.
TEST(OperatorContracts3, FlipsKeepTheSurroundingLines)
{
	CMap3 m = indexed(tet_grid_soup(1, 1, 1));
	const Face f = find<Face>(m, [&](Face x) { return can_flip_face(m, x); });
	ASSERT_TRUE(f.dart.is_valid());
	const Dart outside = phi3(m, phi2(m, f.dart)); // a face of the first tet, seen from outside it
	const uint32 face = index_of(m, Face(outside)), vertex = index_of(m, Vertex(f.dart));
	const uint32 tet = index_of(m, Volume(f.dart));
	const Counts before = counts(m);
	const Edge e = flip_face(m, f);
	EXPECT_EQ(index_of(m, Face(outside)), face);
	EXPECT_TRUE(dart_of_vertex(m, vertex).is_valid()); // the vertex survives with its line
	EXPECT_FALSE(live<Volume>(m, tet));                // the replaced tets release their lines
	foreach_incident_volume(m, e, [&](Volume w) { EXPECT_NE(index_of(m, w), INVALID_INDEX); });
	EXPECT_EQ(counts(m), (Counts{before.v, before.e + 1, before.f + 2, before.w + 1}));
	EXPECT_INTEGRITY(m);
}

// A fan of four tets around an edge, the second removed: the first and the
// last two meet only along that edge, whose vertices are pinched, and no edge
// at them may be contracted.
TEST(OperatorContracts3, CollapseRefusedAtAPinchedVertex)
{
	CMap3 m = tets(7, {{0, 1, 2, 3}, {0, 1, 3, 4}, {0, 1, 4, 5}, {0, 1, 5, 6}});
	remove_volume(m, find<Volume>(m, [&](Volume w) { // the tet (0, 1, 3, 4)
					  uint32 found = 0;
					  foreach_incident_vertex(m, w,
											  [&](Vertex v) { found += index_of(m, v) == 3 || index_of(m, v) == 4; });
					  return found == 2;
				  }));
	ASSERT_INTEGRITY(m);
	ASSERT_EQ(nb_cells<Volume>(m), 3u);
	EXPECT_FALSE(collapsible_from(m, 0).dart.is_valid());
	EXPECT_FALSE(collapsible_from(m, 1).dart.is_valid());
	// and unsewing at the pinched edge keeps the map closed
	const Face f = find<Face>(m, [&](Face x) { return inner(m, x); });
	ASSERT_TRUE(f.dart.is_valid());
	unsew_volumes(m, f);
	EXPECT_INTEGRITY(m);
	EXPECT_EQ(nb_cells<Volume>(m), 3u);
}

// The four tets around the vertex added by split_tetra, one inner face
// unsewn: by labels the star still looks like a ball, but two of its faces
// have the same corners, so no collapse at that vertex is accepted.
TEST(OperatorContracts3, CollapseRefusedAcrossAnUnsewnFace)
{
	CMap3 m;
	index_everything(m);
	const Vertex c = split_tetra(m, add_tetra(m));
	ASSERT_NE(collapsible_from(m, index_of(m, c)).dart, Dart()); // accepted while sewn
	unsew_volumes(m, Face(c.dart));
	ASSERT_INTEGRITY(m);
	EXPECT_FALSE(collapsible_from(m, index_of(m, Vertex(c.dart))).dart.is_valid());
}

// Four triangles with three at every corner make a tetrahedron; four with
// corners of 4, 4, 2 and 2 triangles make a sphere with a double edge (a tet
// whose faces at one edge were merged, then cut along the other diagonal).
// No tetrahedral predicate may take it for a tet: the flips and the collapse
// rebuild tets from corners and would leave phi3 fixed points.
TEST(OperatorContracts3, TetPredicatesRefuseASphereWithADoubleEdge)
{
	CMap3 m;
	index_everything(m);
	const Volume w = add_tetra(m);
	const Dart cd = w.dart;
	const uint32 c = index_of(m, Vertex(cd)), d = index_of(m, Vertex(phi1(m, cd)));
	ASSERT_TRUE(can_merge_incident_faces(m, Edge(cd)));
	const Face quad = merge_incident_faces(m, Edge(cd));
	ASSERT_EQ(codegree(m, quad), 4u);
	Dart a = quad.dart;
	while (index_of(m, Vertex(a)) == c || index_of(m, Vertex(a)) == d)
		a = phi1(m, a);
	const Dart b = phi<1, 1>(m, a);
	ASSERT_TRUE(can_cut_face(m, a, b));
	cut_face(m, a, b);
	ASSERT_INTEGRITY(m);
	// the sphere: 12 darts in 4 triangles, 4 corners, 6 edges (two join a and b)
	const Volume sphere(a);
	uint32 triangles = 0;
	foreach_incident_face(m, sphere, [&](Face f) { triangles += codegree(m, f) == 3; });
	ASSERT_EQ(triangles, 4u);
	ASSERT_EQ(counts(m).e, 6u);

	// glue a real tet onto a face of the sphere
	const Volume t = add_tetra(m);
	const Face f1 =
		find<Face>(m, [&](Face f) { return !is_boundary(m, f.dart) && same_orbit(m, Volume(f.dart), sphere); });
	ASSERT_TRUE(can_sew_volumes(m, f1, Face(t.dart)));
	sew_volumes(m, f1, Face(t.dart));
	ASSERT_INTEGRITY(m);

	foreach_dart_of_orbit(m, Face(f1.dart), [&](Dart x) {
		EXPECT_FALSE(can_flip_face(m, Face(x))) << "dart " << x.index;
		EXPECT_FALSE(can_flip_face(m, Face(phi3(m, x)))) << "dart " << x.index;
	});
	foreach_dart(m, [&](Dart x) {
		if (!is_boundary(m, x))
		{
			EXPECT_FALSE(can_flip_edge(m, Edge(x))) << "dart " << x.index;
			EXPECT_FALSE(can_collapse_edge(m, Edge(x))) << "dart " << x.index;
		}
	});
	EXPECT_THROW(split_tetra(m, sphere), TopologyError);
}

} // namespace cgogn_test_operator_contracts_3d
