// Operators of 1- and 2-G-maps beyond cutting and merging: collapse, flip,
// triangulate, add faces, close holes, sew and unsew. Exact counts, lines
// and incidences on small known surfaces, orientable or not.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <random>
#include <set>

namespace cgogn_test_gmap2_editing
{

using namespace cgogn;

namespace
{

struct Counts
{
	uint32 v, e, f, loops;
	int64 chi;
	bool operator==(const Counts&) const = default;
};

Counts counts(const GMap2& m)
{
	return {nb_cells<GMap2::Vertex>(m), nb_cells<GMap2::Edge>(m), nb_cells<GMap2::Face>(m), nb_boundary_components(m),
			euler_characteristic(m)};
}

void index_everything(GMap2& m)
{
	add_attribute<double, GMap2::Vertex>(m, "v");
	add_attribute<double, GMap2::Edge>(m, "e");
	add_attribute<double, GMap2::Face>(m, "f");
	add_attribute<double, GMap2::Volume>(m, "w");
}

::testing::AssertionResult valid(const GMap2& m)
{
	const IntegrityReport r = check_integrity(m);
	if (r.ok())
		return ::testing::AssertionSuccess();
	return ::testing::AssertionFailure() << r.to_string();
}

} // namespace

TEST(GMap1Operators, AddCutCollapse)
{
	GMap1 m;
	add_attribute<double, GMap1::Vertex>(m, "v");
	add_attribute<double, GMap1::Edge>(m, "e");
	const GMap1::Face f = add_face(m, 4);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(nb_cells<GMap1::Vertex>(m), 4u);
	EXPECT_EQ(nb_darts(m), 8u);
	const uint32 edge_line = index_of(m, GMap1::Edge(f.dart));
	const GMap1::Vertex v = cut_edge(m, GMap1::Edge(f.dart));
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(nb_cells<GMap1::Vertex>(m), 5u);
	EXPECT_EQ(nb_cells<GMap1::Edge>(m), 5u);
	EXPECT_EQ(index_of(m, GMap1::Edge(f.dart)), edge_line);
	EXPECT_FALSE(same_cell(m, GMap1::Edge(v.dart), GMap1::Edge(f.dart)));
	// collapse the new half: its vertex (the new one) disappears
	const uint32 end_line = index_of(m, GMap1::Vertex(beta0(m, v.dart)));
	const GMap1::Vertex kept = collapse_edge(m, GMap1::Edge(v.dart));
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(nb_cells<GMap1::Vertex>(m), 4u);
	EXPECT_EQ(nb_cells<GMap1::Edge>(m), 4u);
	EXPECT_EQ(index_of(m, kept), end_line);
}

TEST(GMap2Editing, AddFaceIsAPolygonWithABoundary)
{
	GMap2 m;
	index_everything(m);
	const GMap2::Face f = add_face(m, 5);
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), (Counts{5, 5, 1, 1, 1}));
	EXPECT_EQ(nb_darts(m), 20u);
	EXPECT_EQ(codegree(m, f), 5u);
	EXPECT_FALSE(is_boundary(m, f.dart));
	EXPECT_TRUE(is_boundary(m, beta2(m, f.dart)));
	EXPECT_TRUE(is_orientable(m));
}

TEST(GMap2Editing, CloseHolesLeftByLowLevelSewing)
{
	GMap2 m;
	// two triangles glued along one edge by beta2, the rest of beta2 free
	const Dart a = add_face(static_cast<GMap1&>(m), 3, false).dart;
	const Dart b = add_face(static_cast<GMap1&>(m), 3, false).dart;
	beta_sew<2>(m, a, b);
	beta_sew<2>(m, beta0(m, a), beta0(m, b));
	EXPECT_EQ(close(m), 1u);
	EXPECT_TRUE(valid(m));
	index_everything(m);
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), (Counts{4, 5, 2, 1, 1}));
	// close_hole with a real face: a closed surface (two triangles and a quad)
	GMap2 k;
	const Dart c = add_face(static_cast<GMap1&>(k), 3, false).dart;
	const Dart d = add_face(static_cast<GMap1&>(k), 3, false).dart;
	beta_sew<2>(k, c, d);
	beta_sew<2>(k, beta0(k, c), beta0(k, d));
	index_everything(k);
	const GMap2::Face q = close_hole(k, beta<0, 1>(k, c), false);
	EXPECT_TRUE(valid(k));
	EXPECT_EQ(codegree(k, q), 4u);
	EXPECT_EQ(counts(k), (Counts{4, 5, 3, 0, 2}));
}

TEST(GMap2Editing, FillHoleWithFace)
{
	GMap2 m;
	build_surface(m, grid_soup(2, 2));
	index_everything(m);
	Dart hole;
	foreach_dart(m, [&](Dart d) { return !(is_boundary(m, d) && (hole = d).is_valid()); });
	ASSERT_TRUE(can_fill_hole_with_face(m, hole));
	const GMap2::Face f = fill_hole_with_face(m, hole);
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(codegree(m, f), 8u);
	EXPECT_EQ(counts(m), (Counts{9, 12, 5, 0, 2}));
}

TEST(GMap2Editing, TriangulateFace)
{
	GMap2 m;
	build_surface(m, hemi_cube_soup()); // 3 quads, a projective plane
	index_everything(m);
	const Counts before = counts(m);
	const GMap2::Face f(Dart(0));
	const uint32 face_line = index_of(m, f);
	const GMap2::Vertex centre = triangulate_face(m, f);
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 4, before.f + 3, 0, 1}));
	EXPECT_EQ(degree(m, centre), 4u);
	EXPECT_EQ(codegree(m, f), 3u);
	EXPECT_EQ(index_of(m, f), face_line);
	foreach_incident_face(m, centre, [&](GMap2::Face t) { EXPECT_EQ(codegree(m, t), 3u); });
	EXPECT_FALSE(is_orientable(m));
}

TEST(GMap2Editing, FlipEdgeMovesItsEndsAndBack)
{
	GMap2 m;
	build_surface(m, torus_soup(5, 4, true));
	index_everything(m);
	const Counts before = counts(m);
	const Dart d(0);
	// the four vertices, by darts that stay at them (e's darts move)
	const GMap2::Vertex a(beta1(m, d)), b(beta<0, 1>(m, d)), c(beta<0, 1, 0>(m, d)), dd(beta<2, 1, 0>(m, d));
	const uint32 la = index_of(m, a), lb = index_of(m, b), lc = index_of(m, c), ld = index_of(m, dd);
	const uint32 da = degree(m, a), db = degree(m, b), dc = degree(m, c), ddd = degree(m, dd);
	const uint32 f1 = index_of(m, GMap2::Face(d)), f2 = index_of(m, GMap2::Face(beta2(m, d)));
	ASSERT_TRUE(can_flip_edge(m, GMap2::Edge(d)));
	flip_edge(m, GMap2::Edge(d));
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), before);
	// the edge now joins the new ends, e.dart at the one from the other face
	EXPECT_EQ(index_of(m, GMap2::Vertex(d)), ld);
	EXPECT_EQ(index_of(m, GMap2::Vertex(beta0(m, d))), lc);
	EXPECT_EQ(degree(m, a), da - 1);
	EXPECT_EQ(degree(m, b), db - 1);
	EXPECT_EQ(degree(m, c), dc + 1);
	EXPECT_EQ(degree(m, dd), ddd + 1);
	EXPECT_EQ(index_of(m, a), la);
	EXPECT_EQ(index_of(m, b), lb);
	EXPECT_EQ(index_of(m, GMap2::Face(d)), f1);
	EXPECT_EQ(index_of(m, GMap2::Face(beta2(m, d))), f2);
	EXPECT_EQ(codegree(m, GMap2::Face(d)), 3u);
	// a flipped edge cannot be flipped onto an existing edge: (a, b) are now
	// two vertices apart; flipping back restores the degrees
	ASSERT_TRUE(can_flip_back_edge(m, GMap2::Edge(d)));
	flip_back_edge(m, GMap2::Edge(d));
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(degree(m, a), da);
	EXPECT_EQ(degree(m, b), db);
	EXPECT_EQ(degree(m, c), dc);
	EXPECT_EQ(degree(m, dd), ddd);
	EXPECT_TRUE((same_cell(m, GMap2::Vertex(d), a) && same_cell(m, GMap2::Vertex(beta0(m, d)), b)) ||
				(same_cell(m, GMap2::Vertex(d), b) && same_cell(m, GMap2::Vertex(beta0(m, d)), a)));
	// a boundary edge cannot be flipped
	GMap2 g;
	build_surface(g, grid_soup(2, 2, true));
	foreach_cell(g, [&](GMap2::Edge e) {
		if (is_incident_to_boundary(g, e))
		{
			EXPECT_FALSE(can_flip_edge(g, e));
		}
	});
}

TEST(GMap2Editing, CollapseEdgeOnAKleinBottle)
{
	GMap2 m;
	build_surface(m, klein_bottle_soup(6, 5, true));
	index_everything(m);
	const Counts before = counts(m);
	const Dart d(0);
	ASSERT_TRUE(can_collapse_edge(m, GMap2::Edge(d)));
	const uint32 lb = index_of(m, GMap2::Vertex(beta0(m, d)));
	const uint32 deg = degree(m, GMap2::Vertex(d)) + degree(m, GMap2::Vertex(beta0(m, d)));
	const GMap2::Vertex v = collapse_edge(m, GMap2::Edge(d));
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), (Counts{before.v - 1, before.e - 3, before.f - 2, 0, 0}));
	EXPECT_EQ(index_of(m, v), lb);
	EXPECT_EQ(degree(m, v), deg - 4);
	EXPECT_FALSE(is_orientable(m));
}

// can_collapse_edge and can_flip_edge give the CMap2's answers on the same
// surface, edge by edge (edges matched by their end vertices' lines, which
// both builders give from the soup's vertex ids).
TEST(GMap2Editing, CollapseAndFlipPredicatesAgreeWithCMap2)
{
	SurfaceSoup tet;
	tet.nb_vertices = 4;
	tet.positions.resize(4);
	tet.face_sizes = {3, 3, 3, 3};
	tet.face_vertices = {0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0};
	uint32 total_flippable = 0;
	for (const SurfaceSoup& s : {tet, grid_soup(3, 1, true), grid_soup(4, 3, true), torus_soup(5, 4, true),
								 sphere_soup(6, 4, true), cylinder_soup(5, 2, true)})
	{
		CMap2 c;
		GMap2 g;
		build_surface(c, s);
		build_surface(g, s);
		add_attribute<double, CMap2::Vertex>(c, "v");
		add_attribute<double, GMap2::Vertex>(g, "v");
		std::map<std::pair<uint32, uint32>, std::pair<bool, bool>> expected;
		foreach_cell(c, [&](CMap2::Edge e) {
			const uint32 a = index_of(c, CMap2::Vertex(e.dart)), b = index_of(c, CMap2::Vertex(phi2(c, e.dart)));
			expected[{std::min(a, b), std::max(a, b)}] = {can_collapse_edge(c, e), can_flip_edge(c, e)};
		});
		uint32 collapsible = 0, flippable = 0;
		foreach_cell(g, [&](GMap2::Edge e) {
			const uint32 a = index_of(g, GMap2::Vertex(e.dart)), b = index_of(g, GMap2::Vertex(beta0(g, e.dart)));
			const auto it = expected.find({std::min(a, b), std::max(a, b)});
			ASSERT_NE(it, expected.end());
			EXPECT_EQ(can_collapse_edge(g, e), it->second.first) << "edge " << a << " " << b;
			EXPECT_EQ(can_flip_edge(g, e), it->second.second) << "edge " << a << " " << b;
			collapsible += it->second.first;
			flippable += it->second.second;
		});
		EXPECT_EQ(nb_cells<GMap2::Edge>(g), expected.size());
		EXPECT_GT(collapsible, 0u);
		total_flippable += flippable;
	}
	EXPECT_GT(total_flippable, 0u) << "the flip predicates were compared on flippable edges";
}

TEST(GMap2Editing, UnsewThenSewStraightOrTwisted)
{
	GMap2 m;
	build_surface(m, cylinder_soup(6, 1)); // a ring of 6 quads
	index_everything(m);
	const Counts cylinder = counts(m);
	EXPECT_EQ(cylinder, (Counts{12, 18, 6, 2, 0}));
	// an edge across the ring
	Dart d;
	foreach_dart(m, [&](Dart x) { return !((!is_incident_to_boundary(m, GMap2::Edge(x))) && (d = x).is_valid()); });
	ASSERT_TRUE(can_unsew_faces(m, GMap2::Edge(d)));
	const Dart d2 = beta2(m, d);
	const uint32 edge_line = index_of(m, GMap2::Edge(d));
	unsew_faces(m, GMap2::Edge(d));
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), (Counts{14, 19, 6, 1, 1})) << "a strip";
	EXPECT_EQ(index_of(m, GMap2::Edge(d)), edge_line);
	EXPECT_NE(index_of(m, GMap2::Edge(d2)), edge_line);
	// sewn back as it was: the cylinder
	ASSERT_TRUE(can_sew_faces(m, GMap2::Edge(d), GMap2::Edge(d2)));
	sew_faces(m, GMap2::Edge(d), GMap2::Edge(d2));
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), cylinder);
	EXPECT_EQ(index_of(m, GMap2::Edge(d)), edge_line);
	EXPECT_TRUE(is_orientable(m));
	// sewn with a twist: a Möbius strip, one boundary loop
	unsew_faces(m, GMap2::Edge(d));
	ASSERT_TRUE(can_sew_faces(m, GMap2::Edge(d), GMap2::Edge(beta0(m, d2))));
	sew_faces(m, GMap2::Edge(d), GMap2::Edge(beta0(m, d2)));
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), (Counts{12, 18, 6, 1, 0}));
	EXPECT_FALSE(is_orientable(m));
	EXPECT_EQ(nb_connected_components(m), 1u);
}

TEST(GMap2Editing, SewingTwoPolygonsMergesTheirComponents)
{
	GMap2 m;
	index_everything(m);
	const GMap2::Face f = add_face(m, 4), g = add_face(m, 3);
	const uint32 wf = index_of(m, GMap2::Volume(f.dart));
	EXPECT_EQ(nb_connected_components(m), 2u);
	sew_faces(m, GMap2::Edge(f.dart), GMap2::Edge(g.dart));
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), (Counts{5, 6, 2, 1, 1}));
	EXPECT_EQ(nb_connected_components(m), 1u);
	EXPECT_EQ(index_of(m, GMap2::Volume(g.dart)), wf);
	EXPECT_FALSE(can_sew_faces(m, GMap2::Edge(f.dart), GMap2::Edge(beta<0, 1>(m, f.dart))));
}

// Random sequences of every 2-G-map operator, on orientable and
// non-orientable surfaces with every orbit indexed: check_integrity after
// every step, exact counts after each operator whose effect on them is
// known, and the Euler characteristic kept by all but the sews.
TEST(GMap2Editing, RandomSequencesOfEveryOperator)
{
	enum Op
	{
		CutEdge,
		CutFace,
		MergeFaces,
		Triangulate,
		Flip,
		FlipBack,
		Collapse,
		UnsewSewBack,
		UnsewSewElsewhere,
		NbOps
	};
	const uint32 steps = 1200;
	std::mt19937 rng(20261127);
	for (const SurfaceSoup& s : {klein_bottle_soup(6, 5, true), mobius_soup(8, true), hemi_icosahedron_soup(),
								 torus_soup(6, 4, true), grid_soup(4, 4, true)})
	{
		GMap2 m;
		build_surface(m, s);
		index_everything(m);
		Counts c = counts(m);
		std::array<uint32, NbOps> done{};
		for (uint32 step = 0, attempts = 0; step < steps && attempts < 50 * steps; ++attempts)
		{
			std::vector<Dart> darts;
			foreach_dart(m, [&](Dart d) { darts.push_back(d); });
			const Dart d = darts[rng() % darts.size()];
			const Op op = Op(rng() % NbOps);
			const GMap2::Edge e(d);
			const uint32 f1 = is_boundary(m, d) ? 0 : codegree(m, GMap2::Face(d));
			const uint32 f2 = is_boundary(m, beta2(m, d)) ? 0 : codegree(m, GMap2::Face(beta2(m, d)));
			switch (op)
			{
			case CutEdge:
				if (f1 + f2 > 16)
					continue;
				cut_edge(m, e);
				c = {c.v + 1, c.e + 1, c.f, c.loops, c.chi};
				break;
			case CutFace: {
				if (f1 == 0)
					continue;
				std::vector<Dart> face;
				foreach_dart_of_orbit(m, GMap2::Face(d), [&](Dart x) { face.push_back(x); });
				const Dart x = face[rng() % face.size()];
				if (!can_cut_face(m, GMap2::Vertex(d), GMap2::Vertex(x)))
					continue;
				cut_face(m, GMap2::Vertex(d), GMap2::Vertex(x));
				c = {c.v, c.e + 1, c.f + 1, c.loops, c.chi};
				break;
			}
			case MergeFaces:
				if (!can_merge_incident_faces(m, e) || f1 + f2 > 12)
					continue;
				merge_incident_faces(m, e);
				c = {c.v, c.e - 1, c.f - 1, c.loops, c.chi};
				break;
			case Triangulate:
				if (f1 == 0 || f1 > 6)
					continue;
				triangulate_face(m, GMap2::Face(d));
				c = {c.v + 1, c.e + f1, c.f + f1 - 1, c.loops, c.chi};
				break;
			case Flip:
				if (!can_flip_edge(m, e))
					continue;
				flip_edge(m, e);
				break;
			case FlipBack:
				if (!can_flip_back_edge(m, e))
					continue;
				flip_back_edge(m, e);
				break;
			case Collapse: {
				if (!can_collapse_edge(m, e))
					continue;
				// a triangle on each side goes, with one of its edges
				const uint32 triangles = uint32(f1 == 3) + uint32(f2 == 3);
				const bool boundary_triangle = (f1 == 0 && codegree(m, GMap2::Face(d)) == 3) ||
											   (f2 == 0 && codegree(m, GMap2::Face(beta2(m, d))) == 3);
				collapse_edge(m, e);
				c = {c.v - 1, c.e - 1 - triangles - uint32(boundary_triangle), c.f - triangles,
					 c.loops - uint32(boundary_triangle), c.chi};
				break;
			}
			case UnsewSewBack:
			case UnsewSewElsewhere: {
				if (!can_unsew_faces(m, e))
					continue;
				const Dart d2 = beta2(m, d);
				unsew_faces(m, e);
				const IntegrityReport r = check_integrity(m);
				ASSERT_TRUE(r.ok()) << "step " << step << ", unsew: " << r.to_string();
				Dart other = d2;
				if (op == UnsewSewElsewhere)
				{
					// any other non-boundary dart of a boundary edge, either way round
					std::vector<Dart> sides;
					foreach_dart(m, [&](Dart x) {
						if (!is_boundary(m, x) && is_boundary(m, beta2(m, x)) && can_sew_faces(m, e, GMap2::Edge(x)))
							sides.push_back(x);
					});
					ASSERT_FALSE(sides.empty());
					other = sides[rng() % sides.size()];
				}
				sew_faces(m, e, GMap2::Edge(other));
				if (op == UnsewSewElsewhere)
				{
					// an edge cut, an edge glued: vertices and loops follow the
					// two boundary edges chosen, edges and faces do not change
					ASSERT_EQ(counts(m).e, c.e) << "step " << step;
					ASSERT_EQ(counts(m).f, c.f) << "step " << step;
					c = counts(m);
				}
				break;
			}
			case NbOps:
				break;
			}
			++done[op];
			const IntegrityReport report = check_integrity(m);
			ASSERT_TRUE(report.ok()) << "step " << step << ", operator " << op << ": " << report.to_string();
			ASSERT_EQ(counts(m), c) << "step " << step << ", operator " << op;
			++step;
		}
		for (uint32 op = 0; op < NbOps; ++op)
			EXPECT_GT(done[op], 20u) << "operator " << op;
	}
}

// After editing, compact leaves no free dart or line and keeps the values
// with their cells; reorder puts the vertices in key order.
TEST(GMap2Editing, CompactAndReorderKeepCellsAndValues)
{
	GMap2 m;
	build_surface(m, klein_bottle_soup(8, 6, true));
	index_everything(m);
	auto id = add_attribute<uint32, GMap2::Vertex>(m, "id");
	uint32 next = 0;
	foreach_cell(m, [&](GMap2::Vertex v) { value<uint32>(m, *id, v) = next++ * 7919u % 1000u; });
	// free darts and lines in the containers: collapse edges
	std::mt19937 rng(7);
	for (uint32 i = 0; i < 40; ++i)
	{
		std::vector<Dart> darts;
		foreach_dart(m, [&](Dart d) { darts.push_back(d); });
		const GMap2::Edge e(darts[rng() % darts.size()]);
		if (can_collapse_edge(m, e))
			collapse_edge(m, e);
	}
	const Counts before = counts(m);
	std::multiset<uint32> ids;
	foreach_cell(m, [&](GMap2::Vertex v) { ids.insert(value<uint32>(m, *id, v)); });
	ASSERT_LT(nb_darts(m), container_of<Orbit::DART>(m).end_index()) << "the edits left free darts";
	compact(m);
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), before);
	EXPECT_EQ(container_of<Orbit::DART>(m).end_index(), nb_darts(m));
	EXPECT_EQ(container_of<Orbit::BETA1_BETA2>(m).end_index(), before.v);
	std::multiset<uint32> after;
	foreach_cell(m, [&](GMap2::Vertex v) { after.insert(value<uint32>(m, *id, v)); });
	EXPECT_EQ(after, ids);
	// reorder by id: vertex lines in id order
	reorder(m, [&](GMap2::Vertex v) { return uint64(value<uint32>(m, *id, v)); });
	EXPECT_TRUE(valid(m));
	EXPECT_EQ(counts(m), before);
	for (uint32 l = 1; l < before.v; ++l)
		EXPECT_LE((*id)[l - 1], (*id)[l]);
	EXPECT_FALSE(is_orientable(m));
}

} // namespace cgogn_test_gmap2_editing
