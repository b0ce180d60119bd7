#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <random>

namespace cgogn_test_operators_2d
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;
using Volume = CMap2::Volume;

using test::Counts;
using test::counts;
using test::index_everything;

namespace
{
using test::all;
using test::find;
using test::indexed;
} // namespace

TEST(Operators2, CutEdgeInsertsADegree2Vertex)
{
	CMap2 m = indexed(grid_soup(2, 2));
	const Counts before = counts(m);
	for (bool boundary : {false, true})
	{
		const Counts c0 = counts(m);
		Edge e = find<Edge>(m, [&](Edge x) { return is_incident_to_boundary(m, x) == boundary; });
		Vertex v = cut_edge(m, e);
		EXPECT_EQ(degree(m, v), 2u);
		EXPECT_EQ(counts(m), (Counts{c0.v + 1, c0.e + 1, c0.f, c0.w}));
		EXPECT_INTEGRITY(m);
	}
	EXPECT_EQ(counts(m).euler(), before.euler());
}

TEST(Operators2, CutEdgeThenMergeIncidentEdgesRestores)
{
	CMap2 m = indexed(torus_soup(4, 3, true));
	const Counts before = counts(m);
	Vertex v = cut_edge(m, all<Edge>(m)[5]);
	ASSERT_TRUE(can_merge_incident_edges(m, v));
	merge_incident_edges(m, v);
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
	EXPECT_FALSE(can_merge_incident_edges(m, all<Vertex>(m)[0])); // valence 6
}

TEST(Operators2, CollapseEdgeOnATriangleTorus)
{
	CMap2 m = indexed(torus_soup(6, 5, true));
	const Counts before = counts(m);
	Edge e = all<Edge>(m)[7];
	ASSERT_TRUE(can_collapse_edge(m, e));
	const uint32 survivor_line = index_of(m, Vertex(phi2(m, e.dart)));
	Vertex v = collapse_edge(m, e);
	EXPECT_EQ(index_of(m, v), survivor_line);
	EXPECT_EQ(counts(m), (Counts{before.v - 1, before.e - 3, before.f - 2, 1}));
	EXPECT_INTEGRITY(m);
}

TEST(Operators2, LinkConditionRefusals)
{
	{
		CMap2 m;
		add_face(m, 3); // a lone triangle: nothing can collapse
		foreach_cell(m, [&](Edge e) { EXPECT_FALSE(can_collapse_edge(m, e)); });
	}
	{
		CMap2 m = indexed(grid_soup(2, 2, true));
		// an interior edge between two boundary vertices would pinch the disk
		uint32 refused = 0, allowed = 0;
		foreach_cell(m, [&](Edge e) {
			const bool both_on_boundary =
				is_incident_to_boundary(m, Vertex(e.dart)) && is_incident_to_boundary(m, Vertex(phi2(m, e.dart)));
			if (both_on_boundary && !is_incident_to_boundary(m, e))
			{
				EXPECT_FALSE(can_collapse_edge(m, e));
				++refused;
			}
			else if (can_collapse_edge(m, e))
				++allowed;
		});
		EXPECT_GT(refused, 0u);
		EXPECT_GT(allowed, 0u);
	}
	{
		// a tetrahedron collapses to a pillow of 2 triangles, which cannot collapse further
		CMap2 m;
		add_tetra(m);
		index_everything(m);
		Edge e = all<Edge>(m)[0];
		ASSERT_TRUE(can_collapse_edge(m, e));
		collapse_edge(m, e);
		EXPECT_EQ(counts(m), (Counts{3, 3, 2, 1}));
		EXPECT_INTEGRITY(m);
		foreach_cell(m, [&](Edge x) { EXPECT_FALSE(can_collapse_edge(m, x)); });
	}
}

TEST(Operators2, CollapseABoundaryEdge)
{
	CMap2 m = indexed(grid_soup(3, 3, true));
	const Counts before = counts(m);
	Edge e = find<Edge>(m, [&](Edge x) { return is_incident_to_boundary(m, x) && can_collapse_edge(m, x); });
	ASSERT_TRUE(e.is_valid());
	collapse_edge(m, e);
	EXPECT_EQ(counts(m), (Counts{before.v - 1, before.e - 2, before.f - 1, 1}));
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_INTEGRITY(m);
}

TEST(Operators2, FlipAndFlipBack)
{
	CMap2 m = indexed(torus_soup(6, 6, true));
	const Counts before = counts(m);
	Edge e = all<Edge>(m)[3];
	ASSERT_TRUE(can_flip_edge(m, e));
	// darts that keep their origin through the flip (e.dart itself moves)
	const Vertex a(phi<2, 1>(m, e.dart)), b(phi1(m, e.dart));
	const Vertex c(phi<1, 1>(m, e.dart)), y(phi<1, 1>(m, phi2(m, e.dart)));
	const uint32 da = degree(m, a), db = degree(m, b), dc = degree(m, c), dy = degree(m, y);
	flip_edge(m, e);
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
	EXPECT_EQ(degree(m, a), da - 1);
	EXPECT_EQ(degree(m, b), db - 1);
	EXPECT_EQ(degree(m, c), dc + 1);
	EXPECT_EQ(degree(m, y), dy + 1);
	// the edge now joins y and c
	EXPECT_EQ(index_of(m, Vertex(e.dart)), index_of(m, y));
	EXPECT_EQ(index_of(m, Vertex(phi2(m, e.dart))), index_of(m, c));
	flip_back_edge(m, e);
	EXPECT_INTEGRITY(m);
	EXPECT_EQ(degree(m, a), da);
	EXPECT_EQ(index_of(m, Vertex(e.dart)), index_of(m, a));
	EXPECT_EQ(index_of(m, Vertex(phi2(m, e.dart))), index_of(m, b));
	// boundary edges cannot flip
	CMap2 g = indexed(grid_soup(2, 2, true));
	foreach_cell(g, [&](Edge x) {
		if (is_incident_to_boundary(g, x))
		{
			EXPECT_FALSE(can_flip_edge(g, x));
		}
	});
}

TEST(Operators2, FlipOnQuads)
{
	CMap2 m = indexed(torus_soup(5, 5));
	Edge e = all<Edge>(m)[0];
	ASSERT_TRUE(can_flip_edge(m, e));
	flip_edge(m, e);
	EXPECT_INTEGRITY(m);
	flip_back_edge(m, e);
	EXPECT_INTEGRITY(m);
	foreach_cell(m, [&](Face f) { EXPECT_EQ(codegree(m, f), 4u); });
}

TEST(Operators2, CutFaceAndMergeBack)
{
	CMap2 m = indexed(grid_soup(2, 2));
	const Counts before = counts(m);
	Face f = all<Face>(m)[0];
	const Vertex v1(f.dart), v2(phi<1, 1>(m, f.dart));
	EXPECT_FALSE(can_cut_face(m, v1, Vertex(phi1(m, f.dart)))); // consecutive
	ASSERT_TRUE(can_cut_face(m, v1, v2));
	Edge e = cut_face(m, v1, v2);
	EXPECT_EQ(counts(m), (Counts{before.v, before.e + 1, before.f + 1, 1}));
	EXPECT_EQ(index_of(m, Vertex(e.dart)), index_of(m, v1));
	EXPECT_EQ(index_of(m, Vertex(phi2(m, e.dart))), index_of(m, v2));
	EXPECT_INTEGRITY(m);
	ASSERT_TRUE(can_merge_incident_faces(m, e));
	Face g = merge_incident_faces(m, e);
	EXPECT_EQ(codegree(m, g), 4u);
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
	EXPECT_FALSE(can_merge_incident_faces(m, find<Edge>(m, [&](Edge x) { return is_incident_to_boundary(m, x); })));
}

TEST(Operators2, TriangulateFaceAndMergeItsVertexBack)
{
	CMap2 m = indexed(torus_soup(4, 4));
	const Counts before = counts(m);
	Face f = all<Face>(m)[2];
	const uint32 line = index_of(m, f);
	Vertex c = triangulate_face(m, f);
	EXPECT_EQ(degree(m, c), 4u);
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 4, before.f + 3, 1}));
	EXPECT_EQ(index_of(m, Face(f.dart)), line); // the triangle on f.dart keeps the line
	EXPECT_INTEGRITY(m);
	ASSERT_TRUE(can_merge_incident_faces(m, c));
	Face g = merge_incident_faces(m, c);
	EXPECT_EQ(codegree(m, g), 4u);
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
}

TEST(Operators2, SplitVertex)
{
	CMap2 m = indexed(torus_soup(6, 6, true));
	const Counts before = counts(m);
	Vertex v = all<Vertex>(m)[4];
	ASSERT_EQ(degree(m, v), 6u);
	const Dart d1 = v.dart;
	const Dart d2 = phi<2, 1, 2, 1, 2, 1>(m, d1); // three steps around
	Edge e = split_vertex(m, d1, d2);
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 1, before.f, 1}));
	EXPECT_EQ(degree(m, Vertex(e.dart)) + degree(m, Vertex(phi2(m, e.dart))), 8u);
	EXPECT_INTEGRITY(m);
}

TEST(Operators2, RemoveFace)
{
	{
		CMap2 m = indexed(grid_soup(3, 3));
		Face centre = find<Face>(m, [&](Face f) { return !is_incident_to_boundary(m, f); });
		const Counts before = counts(m);
		remove_face(m, centre);
		EXPECT_EQ(counts(m), (Counts{before.v, before.e, before.f - 1, 1}));
		EXPECT_EQ(nb_boundary_components(m), 2u);
		EXPECT_INTEGRITY(m);
	}
	{
		CMap2 m = indexed(grid_soup(3, 3));
		// a corner quad: its two boundary edges and its corner vertex go
		Face corner = find<Face>(m, [&](Face f) {
			uint32 b = 0;
			foreach_dart_of_orbit(m, f, [&](Dart d) { b += is_boundary(m, phi2(m, d)); });
			return b == 2;
		});
		const Counts before = counts(m);
		remove_face(m, corner);
		EXPECT_EQ(counts(m), (Counts{before.v - 1, before.e - 2, before.f - 1, 1}));
		EXPECT_EQ(nb_boundary_components(m), 1u);
		EXPECT_INTEGRITY(m);
	}
	{
		CMap2 m;
		Face f = add_face(m, 5);
		index_everything(m);
		remove_face(m, f);
		EXPECT_EQ(nb_darts(m), 0u);
		EXPECT_EQ(counts(m), (Counts{0, 0, 0, 0}));
		EXPECT_INTEGRITY(m);
	}
}

TEST(Operators2, CloseAndFillHoles)
{
	CMap2 m = indexed(torus_soup(5, 4));
	Edge e = all<Edge>(m)[3];
	const Dart d2 = phi2(m, e.dart);
	phi2_unsew(m, e.dart); // low level: two fixed points
	EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::PhiFixedPoint));
	EXPECT_EQ(close(m), 1u);
	EXPECT_EQ(nb_boundary_components(m), 1u);
	// low-level sewing leaves indexing to the caller: the cut edge is now two
	// edges sharing one line, until the second gets its own
	EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::IndexShared));
	detail::write_index(m, Edge(d2), container_of<Orbit::PHI2>(m).new_line(d2.index));
	EXPECT_INTEGRITY(m);
	Dart b = find<CMap2::HalfEdge>(m, [](CMap2::HalfEdge) { return true; }).dart;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			b = d;
	});
	const Counts before = counts(m);
	// a hole of 2 edges would become a face of 2 edges: sewing closes it
	EXPECT_FALSE(can_fill_hole_with_face(m, b));
	ASSERT_TRUE(can_sew_faces(m, Edge(phi2(m, b)), Edge(phi2(m, phi1(m, b)))));
	sew_faces(m, Edge(phi2(m, b)), Edge(phi2(m, phi1(m, b))));
	EXPECT_EQ(counts(m), (Counts{before.v, before.e - 1, before.f, 1}));
	EXPECT_EQ(nb_boundary_components(m), 0u);
	EXPECT_INTEGRITY(m);
	// a hole of 3 edges is filled
	remove_face(m, all<Face>(m)[0]);
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			b = d;
	});
	ASSERT_TRUE(can_fill_hole_with_face(m, b));
	const Counts open = counts(m);
	const Face f = fill_hole_with_face(m, b);
	EXPECT_EQ(codegree(m, f), 4u);
	EXPECT_EQ(counts(m), (Counts{open.v, open.e, open.f + 1, 1}));
	EXPECT_INTEGRITY(m);
}

TEST(Operators2, SewAndUnsewFaces)
{
	CMap2 m;
	Face t1 = add_face(m, 3);
	Face t2 = add_face(m, 3);
	index_everything(m);
	EXPECT_EQ(counts(m), (Counts{6, 6, 2, 2}));
	ASSERT_TRUE(can_sew_faces(m, Edge(t1.dart), Edge(t2.dart)));
	sew_faces(m, Edge(t1.dart), Edge(t2.dart));
	EXPECT_EQ(counts(m), (Counts{4, 5, 2, 1}));
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_INTEGRITY(m);
	unsew_faces(m, Edge(t1.dart));
	EXPECT_EQ(counts(m), (Counts{6, 6, 2, 2}));
	EXPECT_EQ(nb_boundary_components(m), 2u);
	EXPECT_INTEGRITY(m);
	// an interior edge of a closed surface opens a slit
	CMap2 t = indexed(torus_soup(5, 5));
	const Counts before = counts(t);
	unsew_faces(t, all<Edge>(t)[0]);
	EXPECT_EQ(counts(t), (Counts{before.v, before.e + 1, before.f, 1}));
	EXPECT_EQ(nb_boundary_components(t), 1u);
	EXPECT_INTEGRITY(t);
}

TEST(Operators2, ClosedPolyhedra)
{
	CMap2 m;
	Volume p = add_pyramid(m, 5);
	Volume q = add_prism(m, 6);
	add_tetra(m);
	add_hexa(m);
	index_everything(m);
	EXPECT_EQ(counts(m), (Counts{6 + 12 + 4 + 8, 10 + 18 + 6 + 12, 6 + 8 + 4 + 6, 4}));
	EXPECT_EQ(nb_boundary_components(m), 0u);
	EXPECT_INTEGRITY(m);
	remove_volume(m, p);
	remove_volume(m, q);
	EXPECT_EQ(counts(m), (Counts{12, 18, 10, 2}));
	EXPECT_INTEGRITY(m);
	// without indices: pure topology
	CMap2 t;
	add_prism(t, 7, false);
	EXPECT_EQ(counts(t), (Counts{14, 21, 9, 1}));
	EXPECT_TRUE(check_integrity(t).ok());
}

TEST(Operators2, ReverseOrientation)
{
	CMap2 m = indexed(grid_soup(3, 2));
	std::vector<std::vector<uint32>> before;
	foreach_cell(m, [&](Face f) {
		std::vector<uint32> ids;
		foreach_incident_vertex(m, f, [&](Vertex v) { ids.push_back(index_of(m, v)); });
		before.push_back(ids);
	});
	reverse_orientation(m);
	EXPECT_INTEGRITY(m);
	uint32 k = 0;
	foreach_cell(m, [&](Face f) {
		std::vector<uint32> ids;
		foreach_incident_vertex(m, f, [&](Vertex v) { ids.push_back(index_of(m, v)); });
		std::vector<uint32> reversed(before[k].rbegin(), before[k].rend());
		std::rotate(reversed.begin(), std::find(reversed.begin(), reversed.end(), ids[0]), reversed.end());
		EXPECT_EQ(ids, reversed);
		++k;
	});
}

TEST(Operators2, MergeCopiesCellsAndAttributes)
{
	CMap2 a = indexed(torus_soup(4, 4));
	CMap2 b;
	SurfaceSoup s = sphere_soup(5, 4);
	build_surface(b, s);
	auto h = add_attribute<double, Vertex>(b, "height");
	auto fid = add_attribute<int, Face>(b, "fid");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*h)[i] = s.positions[i][2];
	int k = 0;
	foreach_cell(b, [&](Face f) { value<int>(b, fid, f) = k++; });
	const Counts ca = counts(a), cb = counts(b);
	merge(a, b);
	EXPECT_EQ(counts(a), (Counts{ca.v + cb.v, ca.e + cb.e, ca.f + cb.f, 2}));
	EXPECT_INTEGRITY(a);
	auto ha = get_attribute<double, Vertex>(a, "height");
	auto fa = get_attribute<int, Face>(a, "fid");
	ASSERT_TRUE(ha && fa);
	double sum_a = 0, sum_b = 0;
	int fsum_a = 0;
	for (double x : *ha)
		sum_a += x;
	for (double x : *h)
		sum_b += x;
	for (int x : *fa)
		fsum_a += x;
	EXPECT_DOUBLE_EQ(sum_a, sum_b);
	EXPECT_EQ(fsum_a, k * (k - 1) / 2);
}

// ---- randomized sequences

namespace
{
void random_editing(CMap2& m, uint32 steps, uint32 seed)
{
	index_everything(m);
	auto tag = get_attribute<uint32, Vertex>(m, "vtag");
	uint32 next_tag = 1;
	foreach_cell(m, [&](Vertex v) { value<uint32>(m, tag, v) = next_tag++; });
	const int64 chi = counts(m).euler();
	std::mt19937 rng(seed);
	auto pick = [&](auto& v) { return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)]; };
	uint32 applied = 0;
	for (uint32 step = 0; step < steps; ++step)
	{
		// remember every vertex line's value
		std::vector<std::pair<uint32, uint32>> values;
		foreach_cell(m, [&](Vertex v) { values.emplace_back(index_of(m, v), value<uint32>(m, tag, v)); });
		auto edges = all<Edge>(m);
		auto faces = all<Face>(m);
		auto vertices = all<Vertex>(m);
		const int op = std::uniform_int_distribution<int>(0, 8)(rng);
		bool done = false;
		switch (op)
		{
		case 0:
			cut_edge(m, pick(edges));
			done = true;
			break;
		case 1: {
			Edge e = pick(edges);
			if ((done = can_collapse_edge(m, e)))
				collapse_edge(m, e);
			break;
		}
		case 2: {
			Edge e = pick(edges);
			if ((done = can_flip_edge(m, e)))
				flip_edge(m, e);
			break;
		}
		case 3: {
			Face f = pick(faces);
			const Vertex v1(f.dart), v2(phi<1, 1>(m, f.dart));
			if ((done = can_cut_face(m, v1, v2)))
				cut_face(m, v1, v2);
			break;
		}
		case 4: {
			Edge e = pick(edges);
			if ((done = can_merge_incident_faces(m, e)) &&
				codegree(m, Face(e.dart)) + codegree(m, Face(phi2(m, e.dart))) < 12)
				merge_incident_faces(m, e);
			break;
		}
		case 5: {
			Face f = pick(faces);
			if ((done = codegree(m, f) < 8))
				triangulate_face(m, f);
			break;
		}
		case 6: {
			Vertex v = pick(vertices);
			if ((done = can_merge_incident_faces(m, v) && degree(m, v) < 6))
				merge_incident_faces(m, v);
			break;
		}
		case 7: {
			Vertex v = pick(vertices);
			if ((done = can_merge_incident_edges(m, v)))
				merge_incident_edges(m, v);
			break;
		}
		case 8: {
			Edge e = pick(edges);
			if ((done = can_flip_back_edge(m, e)))
				flip_back_edge(m, e);
			break;
		}
		}
		applied += done;
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << "step " << step << " op " << op << "\n" << r.to_string();
		ASSERT_EQ(counts(m).euler(), chi) << "step " << step << " op " << op;
		// untouched vertex lines keep their values; new lines start at the default
		const AttributeContainer& vc = container_of<Orbit::PHI21>(m);
		for (auto [line, val] : values)
		{
			if (vc.is_live(line))
			{
				ASSERT_TRUE((*tag)[line] == val || (*tag)[line] == 0) << "step " << step;
			}
		}
		foreach_cell(m, [&](Vertex v) {
			uint32& t = value<uint32>(m, tag, v);
			if (t == 0)
				t = next_tag++;
		});
	}
	EXPECT_GT(applied, steps / 3);
}
} // namespace

TEST(Operators2Random, ClosedTriangleTorus)
{
	CMap2 m;
	build_surface(m, torus_soup(8, 6, true));
	random_editing(m, 1500, 1);
}

TEST(Operators2Random, QuadSphere)
{
	CMap2 m;
	build_surface(m, sphere_soup(8, 6));
	random_editing(m, 1500, 2);
}

TEST(Operators2Random, GridWithBoundary)
{
	CMap2 m;
	build_surface(m, grid_soup(6, 5, true));
	random_editing(m, 1500, 3);
}

TEST(Operators2, SplitEveryFaceThenCollapseRestores)
{
	CMap2 m = indexed(torus_soup(12, 9, true));
	const Counts before = counts(m);
	std::vector<Face> faces = all<Face>(m);
	std::vector<Vertex> centres;
	for (Face f : faces)
		centres.push_back(triangulate_face(m, f));
	EXPECT_EQ(counts(m), (Counts{before.v + before.f, before.e + 3 * before.f, 3 * before.f, 1}));
	EXPECT_INTEGRITY(m);
	for (Vertex c : centres)
	{
		// collapse an edge leaving the centre: the centre disappears
		Edge e(c.dart);
		ASSERT_TRUE(can_collapse_edge(m, e));
		collapse_edge(m, e);
	}
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
}

TEST(Operators2, PureTopologyWithoutIndices)
{
	// nothing indexed: every operator with set_indices = false changes the
	// topology only, and the map stays valid
	CMap2 m;
	add_hexa(m, false);
	add_prism(m, 5, false);
	const int64 chi = counts(m).euler();
	Vertex v = cut_edge(m, all<Edge>(m)[0], false);
	merge_incident_edges(m, v, false);
	Face f = all<Face>(m)[0];
	Edge cut = cut_face(m, Vertex(f.dart), Vertex(phi<1, 1>(m, f.dart)), false);
	merge_incident_faces(m, cut, false);
	Vertex c = triangulate_face(m, all<Face>(m)[1], false);
	Edge e = all<Edge>(m)[4];
	if (can_flip_edge(m, e))
	{
		flip_edge(m, e, false);
		flip_back_edge(m, e, false);
	}
	merge_incident_faces(m, c, false);
	Vertex w = all<Vertex>(m)[2];
	split_vertex(m, w.dart, phi<2, 1, 2, 1>(m, w.dart), false);
	Edge col = find<Edge>(m, [&](Edge x) { return can_collapse_edge(m, x); });
	ASSERT_TRUE(col.is_valid());
	collapse_edge(m, col, false);
	EXPECT_EQ(counts(m).euler(), chi);
	unsew_faces(m, all<Edge>(m)[0], false);
	remove_face(m, all<Face>(m)[0], false);
	reverse_orientation(m);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_FALSE(is_indexed<Vertex>(m));
	EXPECT_FALSE(is_indexed<Face>(m));
	// indices given afterwards are consistent
	index_cells<Vertex>(m);
	index_cells<Face>(m);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
}

// The predicates' former names (kept, deprecated, for one release) answer as
// the new ones, and the former fill_hole fills as fill_hole_with_face.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wdeprecated-declarations"
TEST(Operators2, FormerNamesAnswerAsTheNewOnes)
{
	CMap2 m = indexed(grid_soup(3, 3));
	uint32 differences = 0, edges = 0;
	foreach_cell(m, [&](Edge e) {
		++edges;
		differences += edge_can_collapse(m, e) != can_collapse_edge(m, e);
		differences += edge_can_flip(m, e) != can_flip_edge(m, e);
		differences += edge_can_flip_back(m, e) != can_flip_back_edge(m, e);
		return true;
	});
	EXPECT_EQ(edges, 24u);
	EXPECT_EQ(differences, 0u);
	remove_face(m, all<Face>(m)[4]); // a second hole
	Dart b;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d))
			b = d;
		return true;
	});
	ASSERT_TRUE(b.is_valid());
	EXPECT_EQ(can_fill_hole(m, b), can_fill_hole_with_face(m, b));
	const uint32 faces = nb_cells<Face>(m);
	fill_hole(m, b);
	EXPECT_EQ(nb_cells<Face>(m), faces + 1);
	EXPECT_INTEGRITY(m);
}
#pragma GCC diagnostic pop

} // namespace cgogn_test_operators_2d
