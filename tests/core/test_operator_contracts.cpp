// SPDX-License-Identifier: MIT
// Operators keep their documented contracts in the smallest cases that once
// broke them: predicates refuse what the operator cannot do, lines survive
// as documented, caches are dropped, containers hand out default values.
#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace cgogn_test_operator_contracts
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;
using Volume = CMap2::Volume;

using test::all;
using test::index_everything;

namespace
{
// A map built from faces given by vertex ids: vertex i is the vertex of line i.
CMap2 surface(uint32 nb_vertices, const std::vector<std::vector<uint32>>& faces)
{
	SurfaceSoup s;
	s.nb_vertices = nb_vertices;
	for (const auto& f : faces)
	{
		s.face_sizes.push_back(uint32(f.size()));
		s.face_vertices.insert(s.face_vertices.end(), f.begin(), f.end());
	}
	CMap2 m;
	build_surface(m, s);
	index_everything(m);
	return m;
}

// The non-boundary dart from vertex a to vertex b (invalid when there is none).
Dart dart_from(const CMap2& m, uint32 a, uint32 b)
{
	Dart r;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d) || index_of(m, Vertex(d)) != a || index_of(m, Vertex(phi1(m, d))) != b)
			return true;
		r = d;
		return false;
	});
	return r;
}

// The number of live darts counted one by one, and free lists without duplicates.
void expect_consistent_containers(const CMap2& m)
{
	uint32 n = 0;
	foreach_dart(m, [&](Dart) { ++n; });
	EXPECT_EQ(nb_darts(m), n);
	auto no_duplicates = [](std::vector<uint32> v) {
		std::sort(v.begin(), v.end());
		return std::adjacent_find(v.begin(), v.end()) == v.end();
	};
	EXPECT_TRUE(no_duplicates(cgogn::detail::state_of(m).darts->free_lines()));
	for (const auto& c : cgogn::detail::state_of(m).cells)
		EXPECT_TRUE(no_duplicates(c->free_lines()));
}
} // namespace

// On polygons, flip_back_edge joins other vertices than flip_edge: it has its
// own predicate, which refuses a flip back that would double an edge.
TEST(OperatorContracts, FlipBackHasItsOwnPredicate)
{
	CMap2 m = surface(5, {{0, 1, 2}, {1, 0, 3, 4}, {2, 1, 4}});
	const Edge e(dart_from(m, 0, 1));
	ASSERT_TRUE(e.dart.is_valid());
	EXPECT_TRUE(can_flip_edge(m, e));       // joins 2 and 3
	EXPECT_FALSE(can_flip_back_edge(m, e)); // would join 2 and 4, already joined
	// the forward flip is fine, and so is flipping it back
	flip_edge(m, e);
	EXPECT_INTEGRITY(m);
	ASSERT_TRUE(can_flip_back_edge(m, e));
	flip_back_edge(m, e);
	EXPECT_INTEGRITY(m);
	EXPECT_EQ(dart_from(m, 0, 1), e.dart);
}

// Operators that change only boundary marks or only delete darts drop the
// incidence caches as the others do.
TEST(OperatorContracts, BoundaryChangesDropIncidenceCaches)
{
	using VF = IncidenceCache<CMap2, Vertex, Face>;
	CMap2 m;
	build_surface(m, grid_soup(3, 3, true));
	index_everything(m);
	add_tetra(m);
	VF::build(m);
	// an interior face: only boundary marks change
	Face inner = test::find<Face>(m, [&](Face f) {
		bool interior = true;
		foreach_dart_of_orbit(m, f, [&](Dart d) { interior = interior && !is_incident_to_boundary(m, Vertex(d)); });
		return interior && codegree(m, f) == 3;
	});
	ASSERT_TRUE(inner.dart.is_valid());
	remove_face(m, inner);
	EXPECT_FALSE(VF::is_built(m));
	EXPECT_INTEGRITY(m);

	VF::build(m);
	ASSERT_TRUE(is_boundary(m, inner.dart));
	fill_hole_with_face(m, inner.dart);
	EXPECT_FALSE(VF::is_built(m));
	EXPECT_INTEGRITY(m);

	VF::build(m);
	const Volume tetra = test::find<Volume>(m, [&](Volume w) { return !is_incident_to_boundary(m, Vertex(w.dart)); });
	ASSERT_TRUE(tetra.dart.is_valid());
	remove_volume(m, tetra);
	EXPECT_FALSE(VF::is_built(m));
	EXPECT_INTEGRITY(m);
}

// sew_faces keeps the lines of e1's end vertices, with their values.
TEST(OperatorContracts, SewFacesKeepsTheLinesOfE1sEnds)
{
	CMap2 m;
	const Face t1 = add_face(m, 3);
	const Face t2 = add_face(m, 3);
	index_everything(m);
	auto tag = add_attribute<uint32, Vertex>(m, "tag");
	foreach_cell(m, [&](Vertex v) { value<uint32>(m, tag, v) = 100 + index_of(m, v); });
	const Dart e1 = t1.dart, e2 = t2.dart; // A1 -> B1, A2 -> B2
	const uint32 a1 = index_of(m, Vertex(e1)), b1 = index_of(m, Vertex(phi1(m, e1)));
	const uint32 a2 = index_of(m, Vertex(e2)), b2 = index_of(m, Vertex(phi1(m, e2)));
	ASSERT_TRUE(can_sew_faces(m, Edge(e1), Edge(e2)));
	sew_faces(m, Edge(e1), Edge(e2));
	EXPECT_INTEGRITY(m);
	// {A1, B2} keeps A1's line, {B1, A2} keeps B1's; A2's and B2's are released
	EXPECT_EQ(index_of(m, Vertex(e1)), a1);
	EXPECT_EQ(index_of(m, Vertex(e2)), b1);
	EXPECT_EQ(value<uint32>(m, tag, Vertex(e1)), 100 + a1);
	EXPECT_EQ(value<uint32>(m, tag, Vertex(e2)), 100 + b1);
	EXPECT_FALSE(container_of<Orbit::PHI21>(m).is_live(a2));
	EXPECT_FALSE(container_of<Orbit::PHI21>(m).is_live(b2));
	EXPECT_EQ(nb_cells<Vertex>(m), 4u);
}

// A triangle attached by a pinched vertex, all its edges on the boundary:
// collapsing one of them would leave an edge with the boundary on both sides.
TEST(OperatorContracts, CollapseRefusedAlongAPinchedTriangle)
{
	CMap2 m = surface(5, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
	remove_face(m, Face(dart_from(m, 0, 2)));
	ASSERT_INTEGRITY(m);
	for (auto [a, b] : {std::pair{0u, 1u}, {1u, 2u}, {2u, 0u}, {0u, 3u}, {3u, 4u}, {4u, 0u}})
	{
		const Dart d = dart_from(m, a, b);
		ASSERT_TRUE(d.is_valid());
		EXPECT_FALSE(can_collapse_edge(m, Edge(d))) << a << " -> " << b;
		EXPECT_FALSE(can_collapse_edge(m, Edge(phi2(m, d)))) << b << " -> " << a;
	}
}

// After compact() and reorder(), new cells of attributes without a rule
// start with default values, new darts without indices.
TEST(OperatorContracts, NewLinesAfterCompactionHoldDefaults)
{
	for (bool use_reorder : {false, true})
	{
		CMap2 m;
		build_surface(m, torus_soup(6, 5, true));
		index_everything(m);
		// free some lines, then give every live line a value
		for (int i = 0; i < 4; ++i)
		{
			const Edge e = test::find<Edge>(m, [&](Edge x) { return can_collapse_edge(m, x); });
			collapse_edge(m, e);
		}
		auto vtag = get_attribute<uint32, Vertex>(m, "vtag");
		auto etag = get_attribute<uint32, Edge>(m, "etag");
		// no rule: new cells hold the default, not a stale value of a freed line
		set_attribute_rule(m, vtag, AttributeRule::None);
		set_attribute_rule(m, etag, AttributeRule::None);
		foreach_cell(m, [&](Vertex v) { value<uint32>(m, vtag, v) = 7; });
		foreach_cell(m, [&](Edge e) { value<uint32>(m, etag, e) = 7; });
		if (use_reorder)
			reorder(m, [&](Vertex v) { return uint64(index_of(m, v)) * 7919 % 101; });
		else
			compact(m);
		ASSERT_INTEGRITY(m);
		const Vertex v = cut_edge(m, all<Edge>(m)[0]);
		EXPECT_INTEGRITY(m);
		EXPECT_EQ(value<uint32>(m, vtag, v), 0u);
		EXPECT_EQ(value<uint32>(m, etag, Edge(v.dart)), 0u);
	}
}

// A boundary face of a single edge (left by zipping two edges of a triangular
// hole) is handled by sew_faces and remove_face.
TEST(OperatorContracts, BoundaryFaceOfOneEdge)
{
	// a tetrahedron without its face (1, 2, 3): the hole is 1 -> 3 -> 2
	const auto last_boundary_dart = [](const CMap2& m) {
		Dart b;
		foreach_dart(m, [&](Dart d) {
			if (is_boundary(m, d))
				b = d;
		});
		return b;
	};
	auto zipped = [] {
		CMap2 m = surface(4, {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}});
		// zip at 2: 1 -> 2 against 2 -> 3... real darts 2 -> 1 and 3 -> 2
		const Dart d1 = dart_from(m, 1, 2), d2 = dart_from(m, 2, 3);
		EXPECT_TRUE(can_sew_faces(m, Edge(d1), Edge(d2)));
		sew_faces(m, Edge(d1), Edge(d2));
		EXPECT_INTEGRITY(m);
		return m;
	};
	{
		CMap2 m = zipped();
		// one boundary face left, of one dart
		const Dart b = last_boundary_dart(m);
		ASSERT_TRUE(b.is_valid());
		ASSERT_EQ(phi1(m, b), b);
		// its edge is a loop: it cannot be contracted
		EXPECT_FALSE(can_collapse_edge(m, Edge(b)));
		EXPECT_FALSE(can_collapse_edge(m, Edge(phi2(m, b))));
		remove_face(m, Face(phi2(m, b)));
		EXPECT_INTEGRITY(m);
		expect_consistent_containers(m);
	}
	{
		CMap2 m = zipped();
		const Dart b = last_boundary_dart(m);
		ASSERT_TRUE(b.is_valid());
		const Face other = add_face(m, 3);
		ASSERT_TRUE(can_sew_faces(m, Edge(phi2(m, b)), Edge(other.dart)));
		sew_faces(m, Edge(phi2(m, b)), Edge(other.dart));
		EXPECT_INTEGRITY(m);
		expect_consistent_containers(m);
	}
}

// remove_face on a face holding both darts of a dangling edge frees them once.
TEST(OperatorContracts, RemoveFaceWithADanglingEdge)
{
	CMap2 m = surface(4, {{0, 1, 2}, {1, 0, 3}});
	const Vertex v = cut_edge(m, Edge(dart_from(m, 0, 1)));
	// merging the faces along one edge of v leaves the other dangling inside
	ASSERT_TRUE(can_merge_incident_faces(m, Edge(v.dart)));
	const Face f = merge_incident_faces(m, Edge(v.dart));
	ASSERT_INTEGRITY(m);
	const uint32 vertices = nb_cells<Vertex>(m), edges = nb_cells<Edge>(m);
	remove_face(m, f);
	EXPECT_INTEGRITY(m);
	expect_consistent_containers(m);
	EXPECT_EQ(nb_darts(m), 0u); // the whole component was that face
	EXPECT_EQ(nb_cells<Vertex>(m), 0u);
	EXPECT_EQ(nb_cells<Edge>(m), 0u);
	EXPECT_GT(vertices, 0u);
	EXPECT_GT(edges, 0u);
}

// Merging the two triangles around a vertex of degree 2 would make a face of
// 2 edges: refused.
TEST(OperatorContracts, MergeAroundADegree2VertexOfTwoTriangles)
{
	CMap2 m = surface(3, {{0, 1, 2}, {0, 2, 1}});
	ASSERT_INTEGRITY(m);
	foreach_cell(m, [&](Vertex v) { EXPECT_FALSE(can_merge_incident_faces(m, v)); });
	// around a degree-2 vertex between two quads the merge is fine
	CMap2 q = surface(4, {{0, 1, 2, 3}, {0, 3, 2, 1}});
	const Vertex v(dart_from(q, 0, 1));
	ASSERT_TRUE(can_merge_incident_faces(q, v));
	merge_incident_faces(q, v);
	EXPECT_INTEGRITY(q);
}

// merge() into a map that does not index an orbit the other map indexes:
// the cells already in m get lines too.
TEST(OperatorContracts, MergeIndexesTheOrbitsOfTheOtherMap)
{
	CMap2 m;
	add_face(m, 4);
	CMap2 other;
	add_face(other, 3);
	add_attribute<uint32, Face>(other, "f");
	merge(m, other);
	EXPECT_TRUE(is_indexed<Face>(m));
	EXPECT_EQ(nb_cells<Face>(m), 2u);
	EXPECT_INTEGRITY(m);
}

} // namespace cgogn_test_operator_contracts
