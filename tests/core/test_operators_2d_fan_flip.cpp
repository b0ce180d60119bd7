// SPDX-License-Identifier: MIT
// triangulate_face and can_flip_edge / flip_edge on known meshes: exact lines
// of the fan, and the O(degree) flip predicate against its definition, on
// indexed and unindexed maps.
#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <set>

namespace cgogn_test_operators_2d_fan_flip
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;
using test::all;

namespace
{

// can_flip_edge as the documentation states it, walking every orbit it
// needs (the reference the O(degree) predicate must agree with)
bool can_flip_by_definition(const CMap2& m, Edge e)
{
	const Dart d = e.dart, d2 = phi2(m, d);
	if (is_boundary(m, d) || is_boundary(m, d2) || same_orbit(m, Face(d), Face(d2)))
		return false;
	if (codegree(m, Face(d)) < 3 || codegree(m, Face(d2)) < 3)
		return false;
	if (degree(m, Vertex(d)) < 3 || degree(m, Vertex(d2)) < 3)
		return false;
	const Vertex c(phi<1, 1>(m, d)), y(phi<1, 1>(m, d2));
	if (same_orbit(m, c, y))
		return false;
	bool adjacent = false;
	foreach_dart_of_orbit(m, c, [&](Dart x) { adjacent = adjacent || same_orbit(m, Vertex(phi2(m, x)), y); });
	return !adjacent;
}

void index_vertices_and_faces(CMap2& m)
{
	add_attribute<uint32, Vertex>(m, "vtag");
	add_attribute<uint32, Face>(m, "ftag");
}

struct FlipTally
{
	uint32 allowed = 0, refused = 0;
};

// Every edge of a snapshot: can_flip_edge must equal the definition; the
// allowed ones are flipped, so that later edges meet vertices made adjacent
// by earlier flips.
FlipTally flip_all_allowed(CMap2& m, bool set_indices)
{
	FlipTally t;
	for (Edge e : all<Edge>(m))
	{
		const bool expected = can_flip_by_definition(m, e);
		EXPECT_EQ(can_flip_edge(m, e), expected);
		if (!expected)
		{
			++t.refused;
			continue;
		}
		++t.allowed;
		flip_edge(m, e, set_indices);
	}
	return t;
}

} // namespace

TEST(Operators2FanFlip, TriangulateFaceGivesExactLines)
{
	CMap2 m;
	index_vertices_and_faces(m);
	const Face hexagon = Face(add_prism(m, 6).dart); // its first face: a hexagon
	ASSERT_EQ(codegree(m, hexagon), 6u);
	const uint32 nv = nb_cells<Vertex>(m), nf = nb_cells<Face>(m);
	const uint32 face_line = index_of(m, hexagon);
	// the sides d_i: v_i -> v_i+1 and their vertices' lines, before
	std::vector<Dart> sides;
	std::vector<uint32> origin;
	foreach_dart_of_orbit(m, hexagon, [&](Dart d) {
		sides.push_back(d);
		origin.push_back(index_of(m, Vertex(d)));
	});
	const Vertex c = triangulate_face(m, hexagon);
	EXPECT_EQ(nb_cells<Vertex>(m), nv + 1);
	EXPECT_EQ(nb_cells<Face>(m), nf + 5);
	EXPECT_EQ(degree(m, c), 6u);
	const uint32 centre = index_of(m, c);
	EXPECT_GE(centre, nv); // a new line (the prism's 12 vertices have lines 0..11)
	std::set<uint32> face_lines;
	for (std::size_t i = 0; i < sides.size(); ++i)
	{
		const Dart d = sides[i];
		// the triangle (v_i, v_i+1, c) on d_i
		ASSERT_EQ((phi<1, 1, 1>(m, d)), d);
		EXPECT_EQ(index_of(m, Vertex(d)), origin[i]);
		EXPECT_EQ(index_of(m, Vertex(phi1(m, d))), origin[(i + 1) % sides.size()]);
		EXPECT_EQ(index_of(m, Vertex(phi<1, 1>(m, d))), centre);
		// one line per triangle, on its three darts
		const uint32 f = index_of(m, Face(d));
		EXPECT_EQ(index_of(m, Face(phi1(m, d))), f);
		EXPECT_EQ(index_of(m, Face(phi<1, 1>(m, d))), f);
		face_lines.insert(f);
		// spokes: the dart arriving at c and the one leaving it are phi2 of
		// the neighbouring triangles' spokes
		EXPECT_EQ(phi2(m, phi1(m, d)), (phi<1, 1>(m, sides[(i + 1) % sides.size()])));
	}
	EXPECT_EQ(face_lines.size(), 6u);
	EXPECT_EQ(index_of(m, Face(sides[0])), face_line); // the triangle on f.dart keeps the line
	EXPECT_INTEGRITY(m);
}

TEST(Operators2FanFlip, TriangulateALargeFace)
{
	// more sides than the pooled dart buffer's initial room (128)
	CMap2 m;
	index_vertices_and_faces(m);
	const Face f = add_face(m, 300);
	const Vertex c = triangulate_face(m, f);
	EXPECT_EQ(degree(m, c), 300u);
	EXPECT_EQ(nb_cells<Vertex>(m), 301u);
	EXPECT_EQ(nb_cells<Face>(m), 300u);
	EXPECT_EQ(nb_cells<Edge>(m), 600u);
	foreach_cell(m, [&](Face t) { EXPECT_EQ(codegree(m, t), 3u); });
	EXPECT_INTEGRITY(m);
}

TEST(Operators2FanFlip, NoEdgeOfATetrahedronCanFlip)
{
	// the two vertices opposite to any edge are already joined: the only
	// reason to refuse (interior edge, distinct triangles, degrees 3)
	for (bool indexed : {true, false})
	{
		CMap2 m;
		if (indexed)
			index_vertices_and_faces(m);
		add_tetra(m, indexed);
		for (Edge e : all<Edge>(m))
			EXPECT_FALSE(can_flip_edge(m, e));
	}
}

TEST(Operators2FanFlip, EdgeCanFlipAgreesWithItsDefinition)
{
	// a prism whose faces are split into fans, then rounds of flips of every
	// allowed edge: the same sequence on an indexed map (vertex lines
	// compared) and on an unindexed one (dart mark) must give the same
	// decisions, equal to the definition's
	CMap2 indexed_map, plain_map;
	index_vertices_and_faces(indexed_map);
	add_prism(indexed_map, 6);
	add_prism(plain_map, 6, false);
	for (Face f : all<Face>(indexed_map))
		triangulate_face(indexed_map, f);
	for (Face f : all<Face>(plain_map))
		triangulate_face(plain_map, f, false);
	FlipTally total;
	for (int round = 0; round < 3; ++round)
	{
		const FlipTally a = flip_all_allowed(indexed_map, true);
		const FlipTally b = flip_all_allowed(plain_map, false);
		EXPECT_EQ(a.allowed, b.allowed);
		EXPECT_EQ(a.refused, b.refused);
		total.allowed += a.allowed;
		total.refused += a.refused;
		EXPECT_INTEGRITY(indexed_map);
		EXPECT_INTEGRITY(plain_map);
	}
	// both kinds of decisions happened
	EXPECT_GT(total.allowed, 0u);
	EXPECT_GT(total.refused, 0u);
	// 8 faces split into fans: 12 + 8 vertices, flips keep the counts
	EXPECT_EQ(nb_cells<Vertex>(indexed_map), 20u);
	EXPECT_EQ(nb_cells<Face>(indexed_map), 36u);
}

TEST(Operators2FanFlip, EdgeCanFlipOnAnIndexedMapEditedWithoutIndices)
{
	// vertices indexed, but the fans and flips are made with set_indices =
	// false: the centres and many darts of the old vertices have no line, so
	// the predicate cannot trust the lines and must still equal the definition
	CMap2 m;
	index_vertices_and_faces(m);
	add_prism(m, 6);
	for (Face f : all<Face>(m))
		triangulate_face(m, f, false);
	FlipTally total;
	for (int round = 0; round < 3; ++round)
	{
		const FlipTally t = flip_all_allowed(m, false);
		total.allowed += t.allowed;
		total.refused += t.refused;
	}
	EXPECT_GT(total.allowed, 0u);
	EXPECT_GT(total.refused, 0u);
}

} // namespace cgogn_test_operators_2d_fan_flip
