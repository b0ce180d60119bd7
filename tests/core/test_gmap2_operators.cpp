// Operators of 2-G-maps: exact results on small maps, and randomized sequences
// on orientable and non-orientable surfaces with every orbit indexed and
// check_integrity after every step.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <random>

namespace cgogn_test_gmap2_operators
{

using namespace cgogn;

namespace
{

struct Counts
{
	uint32 v, e, f;
	int64 chi;
	bool operator==(const Counts&) const = default;
};

Counts counts(const GMap2& m)
{
	return {nb_cells<GMap2::Vertex>(m), nb_cells<GMap2::Edge>(m), nb_cells<GMap2::Face>(m), euler_characteristic(m)};
}

void index_everything(GMap2& m)
{
	add_attribute<double, GMap2::Vertex>(m, "v");
	add_attribute<double, GMap2::Edge>(m, "e");
	add_attribute<double, GMap2::Face>(m, "f");
	add_attribute<double, GMap2::Volume>(m, "w");
}

std::vector<Dart> darts_of(const GMap2& m)
{
	std::vector<Dart> out;
	foreach_dart(m, [&](Dart d) { out.push_back(d); });
	return out;
}

} // namespace

TEST(GMap2Operators, CutEdgeAddsAVertexAndAnEdge)
{
	GMap2 m;
	build_surface(m, hemi_cube_soup());
	index_everything(m);
	const Counts before = counts(m);
	auto e_line = index_of(m, GMap2::Edge(Dart(0)));
	const GMap2::Vertex v = cut_edge(m, GMap2::Edge(Dart(0)));
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 1, before.f, before.chi}));
	EXPECT_EQ(degree(m, v), 2u);
	EXPECT_EQ(index_of(m, GMap2::Edge(Dart(0))), e_line) << "the half of e.dart keeps the edge's line";
	EXPECT_NE(index_of(m, GMap2::Edge(v.dart)), e_line);
	EXPECT_FALSE(same_cell(m, GMap2::Edge(v.dart), GMap2::Edge(Dart(0))));
	EXPECT_EQ(codegree(m, GMap2::Face(Dart(0))), 5u);
	EXPECT_FALSE(is_orientable(m));
}

TEST(GMap2Operators, CutFaceAndMergeBack)
{
	GMap2 m;
	build_surface(m, grid_soup(2, 1)); // two quads
	index_everything(m);
	const Counts before = counts(m);
	const Dart d(0);                           // the first corner of the first quad
	const Dart opposite = beta<0, 1, 0>(m, d); // two edges further: the third corner
	ASSERT_TRUE(can_cut_face(m, GMap2::Vertex(d), GMap2::Vertex(opposite)));
	EXPECT_FALSE(can_cut_face(m, GMap2::Vertex(d), GMap2::Vertex(beta0(m, d)))) << "joined by an edge";
	EXPECT_FALSE(can_cut_face(m, GMap2::Vertex(d), GMap2::Vertex(beta1(m, d)))) << "the same corner";
	const uint32 face_line = index_of(m, GMap2::Face(d));
	const GMap2::Edge e = cut_face(m, GMap2::Vertex(d), GMap2::Vertex(opposite));
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(counts(m), (Counts{before.v, before.e + 1, before.f + 1, before.chi}));
	EXPECT_EQ(codegree(m, GMap2::Face(d)), 3u);
	EXPECT_EQ(index_of(m, GMap2::Face(d)), face_line);
	EXPECT_TRUE(same_cell(m, GMap2::Vertex(e.dart), GMap2::Vertex(d)));
	ASSERT_TRUE(can_merge_incident_faces(m, e));
	const GMap2::Face f = merge_incident_faces(m, e);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(counts(m), before);
	EXPECT_EQ(codegree(m, f), 4u);
	EXPECT_EQ(index_of(m, f), face_line);
	// a boundary edge has one face: nothing to merge
	bool found = false;
	foreach_cell(m, [&](GMap2::Edge x) {
		if (is_incident_to_boundary(m, x))
		{
			EXPECT_FALSE(can_merge_incident_faces(m, x));
			found = true;
		}
	});
	EXPECT_TRUE(found);
}

// Random cut_edge / cut_face / merge_incident_faces: the map stays valid and
// its counts follow (the Euler characteristic never changes).
TEST(GMap2Operators, RandomSequencesKeepTheMapValid)
{
	const uint32 steps = 1500;
	std::mt19937 rng(20261126);
	for (const SurfaceSoup& s :
		 {klein_bottle_soup(6, 5, true), mobius_soup(7), hemi_icosahedron_soup(), torus_soup(5, 4), grid_soup(3, 3)})
	{
		GMap2 m;
		build_surface(m, s);
		index_everything(m);
		const bool orientable = is_orientable(m);
		const uint32 loops = nb_boundary_components(m);
		Counts c = counts(m);
		uint32 done[3] = {0, 0, 0};
		for (uint32 step = 0, attempts = 0; step < steps && attempts < 20 * steps; ++attempts)
		{
			const std::vector<Dart> darts = darts_of(m);
			const Dart d = darts[rng() % darts.size()];
			const uint32 r = rng() % 8; // cut_edge 2/8, cut_face 3/8, merge 3/8
			const uint32 op = r < 2 ? 0 : r < 5 ? 1 : 2;
			if (op == 0)
			{
				cut_edge(m, GMap2::Edge(d));
				c = {c.v + 1, c.e + 1, c.f, c.chi};
			}
			else if (op == 1)
			{
				// another corner of d's face
				std::vector<Dart> face;
				foreach_dart_of_orbit(m, GMap2::Face(d), [&](Dart x) { face.push_back(x); });
				const Dart e = face[rng() % face.size()];
				if (!can_cut_face(m, GMap2::Vertex(d), GMap2::Vertex(e)))
					continue;
				cut_face(m, GMap2::Vertex(d), GMap2::Vertex(e));
				c = {c.v, c.e + 1, c.f + 1, c.chi};
			}
			else
			{
				// keep the faces small: merge only when the result has at most 10 edges
				if (!can_merge_incident_faces(m, GMap2::Edge(d)) ||
					codegree(m, GMap2::Face(d)) + codegree(m, GMap2::Face(beta2(m, d))) > 12)
					continue;
				merge_incident_faces(m, GMap2::Edge(d));
				c = {c.v, c.e - 1, c.f - 1, c.chi};
			}
			++done[op];
			const IntegrityReport report = check_integrity(m);
			ASSERT_TRUE(report.ok()) << "step " << step << ", operator " << op << ": " << report.to_string();
			ASSERT_EQ(counts(m), c) << "step " << step << ", operator " << op;
			++step;
		}
		EXPECT_EQ(done[0] + done[1] + done[2], steps);
		EXPECT_EQ(is_orientable(m), orientable);
		EXPECT_EQ(nb_boundary_components(m), loops);
		for (uint32 op = 0; op < 3; ++op)
			EXPECT_GT(done[op], 100u) << "operator " << op;
	}
}

} // namespace cgogn_test_gmap2_operators
