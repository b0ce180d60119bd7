#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <sstream>
#include <unordered_set>

namespace cgogn_test_maps
{

using namespace cgogn;

TEST(Dart, ValidityPrintingHashing)
{
	Dart d;
	EXPECT_FALSE(d.is_valid());
	Dart e(5);
	EXPECT_TRUE(e.is_valid());
	std::ostringstream s;
	s << e << " " << d << " " << CMap2::Vertex(e);
	EXPECT_EQ(s.str(), "Dart(5) Dart(invalid) Cell<PHI21>(5)");
	std::unordered_set<Dart> set{Dart(1), Dart(2), Dart(1)};
	EXPECT_EQ(set.size(), 2u);
	EXPECT_FALSE(CMap2::Face().is_valid());
}

TEST(CMap1, FaceIsAPhi1Cycle)
{
	CMap1 m;
	CMap1::Face f = add_face(m, 5);
	EXPECT_EQ(nb_darts(m), 5u);
	EXPECT_EQ(codegree(m, f), 5u);
	Dart d = f.dart;
	for (int i = 0; i < 5; ++i)
		d = phi1(m, d);
	EXPECT_EQ(d, f.dart);
	EXPECT_EQ(phi1(m, phi_1(m, f.dart)), f.dart);
	EXPECT_EQ(phi_1(m, phi1(m, f.dart)), f.dart);
	EXPECT_EQ((phi<1, -1>(m, f.dart)), f.dart);
	EXPECT_EQ(nb_cells<CMap1::Face>(m), 1u);
	EXPECT_EQ(nb_cells<CMap1::Vertex>(m), 5u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CMap1, Phi1SewSplitsAndJoinsCycles)
{
	CMap1 m;
	CMap1::Face f = add_face(m, 6);
	const Dart d = f.dart;
	const Dart e = phi<1, 1, 1>(m, d);
	phi1_sew(m, d, e); // splits into a 3-cycle and a 3-cycle
	EXPECT_EQ(nb_cells<CMap1::Face>(m), 2u);
	EXPECT_EQ(codegree(m, CMap1::Face(d)), 3u);
	phi1_sew(m, d, e); // joins them back
	EXPECT_EQ(nb_cells<CMap1::Face>(m), 1u);
	phi1_unsew(m, d); // the dart after d becomes a fixed point
	EXPECT_EQ(nb_cells<CMap1::Face>(m), 2u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CMap2, AddFaceCreatesItsBoundaryFace)
{
	CMap2 m;
	CMap2::Face f = add_face(m, 4);
	EXPECT_EQ(nb_darts(m), 8u);
	EXPECT_FALSE(is_boundary(m, f.dart));
	EXPECT_TRUE(is_boundary(m, phi2(m, f.dart)));
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 1u); // the boundary face is not counted
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), 4u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 4u);
	EXPECT_EQ(nb_cells<CMap2::Volume>(m), 1u);
	EXPECT_EQ(nb_boundary_components(m), 1u);
	// phi2 o phi2 = id, phi1 o phi2 turns around a vertex of 2 darts
	foreach_dart(m, [&](Dart d) {
		EXPECT_EQ(phi2(m, phi2(m, d)), d);
		EXPECT_EQ((phi<2, 1, 2, 1>(m, d)), d);
	});
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CMap2, LazyIndexingMatchesUnindexedCounts)
{
	CMap2 m;
	build_surface(m, torus_soup(6, 5));
	const uint32 faces_unindexed = nb_cells<CMap2::Face>(m);
	const uint32 edges_unindexed = nb_cells<CMap2::Edge>(m);
	EXPECT_FALSE(is_indexed<CMap2::Face>(m));
	auto area = add_attribute<double, CMap2::Face>(m, "area");
	auto flag = add_attribute<int, CMap2::Edge>(m, "flag");
	EXPECT_TRUE(is_indexed<CMap2::Face>(m));
	EXPECT_EQ(nb_cells<CMap2::Face>(m), faces_unindexed);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), edges_unindexed);
	EXPECT_EQ(faces_unindexed, 30u);
	EXPECT_EQ(edges_unindexed, 60u);
	// all darts of a face share its index, and indices are distinct
	std::unordered_set<uint32> seen;
	foreach_cell(m, [&](CMap2::Face f) {
		const uint32 i = index_of(m, f);
		EXPECT_TRUE(seen.insert(i).second);
		foreach_dart_of_orbit(m, f, [&](Dart d) { EXPECT_EQ(index_of(m, CMap2::Face(d)), i); });
	});
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CMap2, SetIndexMovesACellToAnotherLineAndReleasesTheOldOne)
{
	CMap2 m;
	build_surface(m, grid_soup(2, 1)); // two quads
	auto w = add_attribute<int, CMap2::Face>(m, "w");
	std::vector<CMap2::Face> faces;
	foreach_cell(m, [&](CMap2::Face f) { faces.push_back(f); });
	ASSERT_EQ(faces.size(), 2u);
	AttributeContainer& fc = container_of<Orbit::PHI1>(m);
	const uint32 old = index_of(m, faces[0]);
	const uint32 fresh = fc.new_line(faces[0].dart.index);
	set_index(m, faces[0], fresh);
	EXPECT_EQ(index_of(m, faces[0]), fresh);
	EXPECT_FALSE(fc.is_live(old));
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 2u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CMap2, MovedMapKeepsEverything)
{
	CMap2 a;
	build_surface(a, sphere_soup(8, 6));
	auto h = add_attribute<int, CMap2::Vertex>(a, "h");
	foreach_cell(a, [&](CMap2::Vertex v) { value<int>(a, h, v) = int(index_of(a, v)); });
	CMap2 b = std::move(a);
	EXPECT_EQ(nb_cells<CMap2::Vertex>(b), 2u + 8u * 5u);
	EXPECT_EQ((get_attribute<int, CMap2::Vertex>(b, "h")), h);
	foreach_cell(b, [&](CMap2::Vertex v) { EXPECT_EQ(value<int>(b, h, v), int(index_of(b, v))); });
	EXPECT_TRUE(check_integrity(b).ok());
}

TEST(CMap3, CellTypesOfATetrahedron)
{
	CMap3 m;
	const uint32 tet[4] = {0, 1, 2, 3};
	const uint32 size[1] = {4};
	build_volume(m, 4, size, tet);
	EXPECT_EQ(nb_darts(m), 24u); // 12 + 12 of the boundary volume
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), 4u);
	EXPECT_EQ(nb_cells<CMap3::Edge>(m), 6u);
	EXPECT_EQ(nb_cells<CMap3::Face>(m), 4u);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 1u);
	EXPECT_EQ(nb_cells<CMap3::CC>(m), 1u);
	// the 2-D sub-cells of the volume (those of the boundary volume excluded)
	EXPECT_EQ(nb_cells<CMap3::Face2>(m), 4u);
	EXPECT_EQ(nb_cells<CMap3::Edge2>(m), 6u);
	EXPECT_EQ(nb_cells<CMap3::Vertex2>(m), 4u);
	EXPECT_EQ(nb_cells<CMap3::HalfEdge>(m), 12u);
	foreach_dart(m, [&](Dart d) {
		EXPECT_EQ(phi3(m, phi3(m, d)), d);
		EXPECT_NE(is_boundary(m, d), is_boundary(m, phi3(m, d)));
	});
	EXPECT_TRUE(check_integrity(m).ok());
}

} // namespace cgogn_test_maps
