// collapse_edge keeps, of the two edges of a vanishing triangle, the one with
// the lower darts: collapsing the centre a triangulate_face added gives back
// exactly the darts, relations and cell lines the split found. This keeps
// repeated split/collapse editing from scattering a mesh over its containers.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <random>

namespace cgogn_test_collapse_restores
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;
using Volume = CMap2::Volume;

using test::Counts;
using test::counts;

namespace
{
uint32 faces_of_degree(const CMap2& m, uint32 k)
{
	uint32 n = 0;
	foreach_cell(m, [&](Face f) { n += codegree(m, f) == k ? 1 : 0; });
	return n;
}

// Everything a dart line holds that a split/collapse pair could change.
struct DartState
{
	uint32 dart, phi1, phi2, vertex, edge, face;
	bool boundary;
	bool operator==(const DartState&) const = default;
};

std::vector<DartState> snapshot(const CMap2& m)
{
	std::vector<DartState> s;
	foreach_dart(m, [&](Dart d) {
		s.push_back({d.index, phi1(m, d).index, phi2(m, d).index, index_of(m, Vertex(d)), index_of(m, Edge(d)),
					 index_of(m, Face(d)), is_boundary(m, d)});
	});
	return s;
}

// The live lines of the cells of one orbit.
template <typename CELL>
std::vector<uint32> live_lines(const CMap2& m)
{
	std::vector<uint32> lines;
	foreach_cell(m, [&](CELL c) { lines.push_back(index_of(m, c)); });
	std::sort(lines.begin(), lines.end());
	return lines;
}

using test::indexed;

// Splits the faces at their centre in the given order, then collapses the
// centres in `collapse_order` (a permutation of the faces' positions), with
// check_integrity after every operator.
void split_then_collapse(CMap2& m, const std::vector<Face>& faces, const std::vector<std::size_t>& collapse_order)
{
	std::vector<Vertex> centres;
	for (Face f : faces)
	{
		centres.push_back(triangulate_face(m, f));
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << r.to_string();
	}
	for (std::size_t k : collapse_order)
	{
		const Edge e(centres[k].dart);
		ASSERT_TRUE(can_collapse_edge(m, e));
		const uint32 survivor = index_of(m, Vertex(phi2(m, e.dart)));
		const Vertex v = collapse_edge(m, e);
		EXPECT_EQ(index_of(m, v), survivor);
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << r.to_string();
	}
}

std::vector<std::size_t> identity(std::size_t n)
{
	std::vector<std::size_t> order(n);
	for (std::size_t i = 0; i < n; ++i)
		order[i] = i;
	return order;
}
} // namespace

TEST(CollapseRestores, OneSplitThenCollapseGivesEveryDartAndLineBack)
{
	CMap2 m = indexed(torus_soup(6, 5, true));
	const std::vector<DartState> before = snapshot(m);
	const auto faces = test::all<Face>(m);
	for (Face f : {faces[0], faces[7], faces[31]})
	{
		split_then_collapse(m, {f}, {0});
		EXPECT_EQ(snapshot(m), before); // same darts, phi1, phi2, vertex / edge / face lines, boundary marks
	}
}

TEST(CollapseRestores, FacesOnTheBoundary)
{
	CMap2 m = indexed(grid_soup(5, 4, true));
	const std::vector<DartState> before = snapshot(m);
	std::vector<Face> border;
	foreach_cell(m, [&](Face f) {
		if (is_incident_to_boundary(m, f))
			border.push_back(f);
	});
	ASSERT_GT(border.size(), 10u);
	split_then_collapse(m, border, identity(border.size()));
	EXPECT_EQ(snapshot(m), before);
}

TEST(CollapseRestores, CollapsingWithTheOtherEdgeOfTheCentre)
{
	// whichever edge of the centre is collapsed, the same darts come back
	CMap2 m = indexed(torus_soup(6, 5, true));
	const std::vector<DartState> before = snapshot(m);
	const Face f = test::all<Face>(m)[4];
	const Vertex c = triangulate_face(m, f);
	// the second edge around the centre
	collapse_edge(m, Edge(phi<2, 1>(m, c.dart)));
	EXPECT_INTEGRITY(m);
	EXPECT_EQ(snapshot(m), before);
}

TEST(CollapseRestores, RandomBatchesOnAClosedTorus)
{
	// like the dynamic-editing benchmark: batches that split a random set of
	// faces in random order and collapse the centres in another random order;
	// the freed lines are reused by the next batch
	CMap2 m = indexed(torus_soup(14, 10, true));
	const std::vector<DartState> before = snapshot(m);
	const auto v_lines = live_lines<Vertex>(m), e_lines = live_lines<Edge>(m), f_lines = live_lines<Face>(m);
	std::mt19937 rng(7);
	for (int batch = 0; batch < 4; ++batch)
	{
		std::vector<Face> faces = test::all<Face>(m);
		std::shuffle(faces.begin(), faces.end(), rng);
		faces.resize(faces.size() * (batch + 1) / 5); // 20% to 80%: many neighbours are split together
		std::vector<std::size_t> order = identity(faces.size());
		std::shuffle(order.begin(), order.end(), rng);
		split_then_collapse(m, faces, order);
		ASSERT_EQ(snapshot(m), before) << "batch " << batch;
		EXPECT_EQ(live_lines<Vertex>(m), v_lines);
		EXPECT_EQ(live_lines<Edge>(m), e_lines);
		EXPECT_EQ(live_lines<Face>(m), f_lines);
	}
}

TEST(CollapseRestores, TheLowerEdgeOfAVanishingTriangleSurvivesWhole)
{
	// a plain collapse: each vanishing triangle loses both darts of the edge
	// whose lower dart is higher, and nothing else but e's two darts
	CMap2 m = indexed(torus_soup(8, 6, true));
	// make dart order differ from the build order: split and collapse a few faces first
	const auto faces = test::all<Face>(m);
	split_then_collapse(m, {faces[3], faces[10], faces[20]}, {2, 0, 1});
	const Edge e = test::all<Edge>(m)[17];
	ASSERT_TRUE(can_collapse_edge(m, e));
	std::vector<uint32> expected_gone = {e.dart.index, phi2(m, e.dart).index};
	for (Dart side : {e.dart, phi2(m, e.dart)})
	{
		const Dart n = phi1(m, side), p = phi_1(m, side);
		const Dart nn = phi2(m, n), pp = phi2(m, p);
		const bool n_survives = std::min(n.index, nn.index) < std::min(p.index, pp.index);
		expected_gone.push_back(n_survives ? p.index : n.index);
		expected_gone.push_back(n_survives ? pp.index : nn.index);
	}
	std::vector<uint32> live_before;
	foreach_dart(m, [&](Dart d) { live_before.push_back(d.index); });
	collapse_edge(m, e);
	EXPECT_INTEGRITY(m);
	std::vector<uint32> expected = live_before, live_after;
	std::erase_if(expected, [&](uint32 d) {
		return std::find(expected_gone.begin(), expected_gone.end(), d) != expected_gone.end();
	});
	foreach_dart(m, [&](Dart d) { live_after.push_back(d.index); });
	EXPECT_EQ(live_after, expected);
}

TEST(CollapseRestores, TenPercentBatchesOnARealMesh)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/suzanne.obj");
	CMap2 m;
	io::load_surface(m, path);
	// suzanne has quads: triangulate them (by cut_face) so that collapses undo splits
	for (Face f : test::all<Face>(m))
		while (codegree(m, f) > 3)
			cut_face(m, Vertex(f.dart), Vertex(phi<1, 1>(m, f.dart)));
	compact(m);
	add_attribute<uint32, Edge>(m, "etag");
	add_attribute<uint32, Face>(m, "ftag");
	const std::vector<DartState> before = snapshot(m);
	for (uint32 batch = 0; batch < 10; ++batch)
	{
		std::vector<Face> faces;
		uint32 rank = 0;
		foreach_cell(m, [&](Face f) {
			if (rank++ % 10 == batch)
				faces.push_back(f);
		});
		std::vector<Vertex> centres;
		for (Face f : faces)
			centres.push_back(triangulate_face(m, f));
		for (Vertex c : centres)
			collapse_edge(m, Edge(c.dart));
		ASSERT_EQ(snapshot(m), before) << "batch " << batch;
	}
	EXPECT_INTEGRITY(m);
}

TEST(CollapseRestores, ATriangleSharingTwoEdgesWithTheOtherFace)
{
	// b of degree 2 between a triangle (a, b, c) and a heptagon: collapsing an
	// edge of b merges two edges of the triangle, one of which borders the
	// heptagon too (the surviving edge may replace the heptagon's dart)
	for (uint32 which = 0; which < 4; ++which)
	{
		CMap2 m = indexed(torus_soup(6, 5, true));
		const Vertex b = test::all<Vertex>(m)[9];
		ASSERT_EQ(degree(m, b), 6u);
		// remove 4 of b's 6 edges: a triangle and a heptagon are left around b
		for (int k = 0; k < 4; ++k)
		{
			const Edge e(phi<2, 1>(m, b.dart));
			ASSERT_TRUE(can_merge_incident_faces(m, e));
			merge_incident_faces(m, e);
		}
		ASSERT_EQ(degree(m, b), 2u);
		ASSERT_EQ(faces_of_degree(m, 7), 1u);
		const Counts before = counts(m);
		std::vector<Dart> around_b;
		foreach_dart_of_orbit(m, b, [&](Dart d) {
			around_b.push_back(d);
			around_b.push_back(phi2(m, d));
		});
		const Edge e(around_b[which]); // b -> x or x -> b
		ASSERT_TRUE(can_collapse_edge(m, e)) << which;
		const uint32 survivor = index_of(m, Vertex(phi2(m, e.dart)));
		const Vertex v = collapse_edge(m, e);
		EXPECT_EQ(index_of(m, v), survivor);
		EXPECT_EQ(counts(m), (Counts{before.v - 1, before.e - 2, before.f - 1, 1})) << which;
		EXPECT_EQ(faces_of_degree(m, 7), 0u) << which;
		EXPECT_EQ(faces_of_degree(m, 6), 1u) << which; // the heptagon lost b's edge
		EXPECT_INTEGRITY(m);
	}
}

} // namespace cgogn_test_collapse_restores
