// dist::partition: every cell gets one part, the report's sizes, cut and
// connectivity agree with a recount from the attribute, the parts are
// balanced and connected on grids and surfaces, and bad arguments leave the
// map unchanged.
#include <cgogn/core.h>
#include <cgogn/distributed/partition.h>

#include <gtest/gtest.h>

#include <numeric>
#include <vector>

namespace cgogn_test_partition
{

using namespace cgogn;

// Parts of each cell, and the cut and connectivity recounted from them.
template <typename MAP, typename CELL, typename FACET>
void expect_report_matches_attribute(const MAP& m, const dist::PartitionReport& r, const std::string& name)
{
	auto part = get_attribute<uint32, CELL>(m, name);
	ASSERT_NE(part, nullptr);
	std::vector<uint64> sizes(r.nb_parts, 0);
	foreach_cell(m, [&](CELL c) {
		ASSERT_LT((*part)[c], r.nb_parts);
		++sizes[(*part)[c]];
	});
	EXPECT_EQ(sizes, r.part_sizes);
	for (uint64 s : sizes)
		EXPECT_GT(s, 0u);
	const uint64 total = std::accumulate(sizes.begin(), sizes.end(), uint64(0));
	EXPECT_EQ(total, nb_cells<CELL>(m));
	EXPECT_DOUBLE_EQ(r.imbalance, double(*std::max_element(sizes.begin(), sizes.end())) * r.nb_parts / double(total));
	uint64 interior = 0, cut = 0;
	foreach_cell(m, [&](FACET f) {
		const Dart d = f.dart;
		Dart e;
		if constexpr (MAP::dimension == 3)
			e = phi3(m, d);
		else
			e = phi2(m, d);
		if (is_boundary(m, d) || is_boundary(m, e))
			return;
		++interior;
		cut += (*part)[CELL(d)] != (*part)[CELL(e)];
	});
	EXPECT_EQ(interior, r.nb_interior_facets);
	EXPECT_EQ(cut, r.nb_cut_facets);
}

TEST(Partition, TetGridIntoOneToFourParts)
{
	for (uint32 parts = 1; parts <= 4; ++parts)
	{
		SCOPED_TRACE(parts);
		CMap3 m;
		build_volume(m, tet_grid_soup(12, 12, 12)); // 10,368 tetrahedra
		const dist::PartitionReport r = dist::partition(m, parts);
		EXPECT_EQ(r.nb_parts, parts);
		EXPECT_EQ(r.nb_map_components, 1u);
		// (24 n^3 tetrahedron faces - 12 n^2 on the boundary) / 2
		EXPECT_EQ(r.nb_interior_facets, (24u * 1728u - 12u * 144u) / 2u);
		EXPECT_LE(r.imbalance, 1.05);
		EXPECT_TRUE(r.parts_connected());
		if (parts == 1)
			EXPECT_EQ(r.nb_cut_facets, 0u);
		else
			EXPECT_LT(r.cut_ratio(), 0.1);
		expect_report_matches_attribute<CMap3, CMap3::Volume, CMap3::Face>(m, r, "part");
		EXPECT_TRUE(check_integrity(m).ok());
	}
}

TEST(Partition, SameSeedSamePartition)
{
	CMap3 a, b;
	build_volume(a, tet_grid_soup(8, 8, 8));
	build_volume(b, tet_grid_soup(8, 8, 8));
	dist::PartitionOptions o;
	o.seed = 7;
	o.attribute = "rank";
	dist::partition(a, 3, o);
	dist::partition(b, 3, o);
	auto pa = get_attribute<uint32, CMap3::Volume>(a, "rank");
	auto pb = get_attribute<uint32, CMap3::Volume>(b, "rank");
	std::vector<uint32> va, vb;
	foreach_cell(a, [&](CMap3::Volume w) { va.push_back((*pa)[w]); });
	foreach_cell(b, [&](CMap3::Volume w) { vb.push_back((*pb)[w]); });
	EXPECT_EQ(va, vb);
}

TEST(Partition, SurfaceFaces)
{
	CMap2 m;
	build_surface(m, torus_soup(40, 20, true)); // 1,600 triangles, closed
	const dist::PartitionReport r = dist::partition(m, 3);
	EXPECT_EQ(r.nb_interior_facets, 2400u); // every edge of the closed torus
	EXPECT_LE(r.imbalance, 1.05);
	EXPECT_TRUE(r.parts_connected());
	EXPECT_GT(r.nb_cut_facets, 0u);
	expect_report_matches_attribute<CMap2, CMap2::Face, CMap2::Edge>(m, r, "part");
}

TEST(Partition, DisconnectedMapsArePartitionedAndSaidSo)
{
	// two grids side by side, not glued: METIS cannot be asked for connected parts
	VolumeSoup s = tet_grid_soup(4, 4, 4);
	const VolumeSoup t = tet_grid_soup(4, 4, 4);
	const uint32 offset = s.nb_vertices;
	s.positions.insert(s.positions.end(), t.positions.begin(), t.positions.end());
	s.nb_vertices += t.nb_vertices;
	for (uint32 v : t.cell_vertices)
		s.cell_vertices.push_back(v + offset);
	s.cell_sizes.insert(s.cell_sizes.end(), t.cell_sizes.begin(), t.cell_sizes.end());
	CMap3 m;
	build_volume(m, s);
	const dist::PartitionReport r = dist::partition(m, 2);
	EXPECT_EQ(r.nb_map_components, 2u);
	expect_report_matches_attribute<CMap3, CMap3::Volume, CMap3::Face>(m, r, "part");
	// with 3 parts, a part may take pieces of both grids; each is counted
	const dist::PartitionReport r3 = dist::partition(m, 3);
	uint32 pieces = 0;
	for (uint32 c : r3.part_components)
		pieces += c;
	EXPECT_GE(pieces, 3u);
	expect_report_matches_attribute<CMap3, CMap3::Volume, CMap3::Face>(m, r3, "part");
}

TEST(Partition, BadArgumentsLeaveTheMapUnchanged)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(2, 2, 2)); // 48 tetrahedra
	EXPECT_THROW(dist::partition(m, 0), dist::PartitionError);
	EXPECT_THROW(dist::partition(m, 49), dist::PartitionError);
	dist::PartitionOptions tight;
	tight.imbalance_tolerance = 1.0;
	EXPECT_THROW(dist::partition(m, 2, tight), dist::PartitionError);
	EXPECT_EQ((get_attribute<uint32, CMap3::Volume>(m, "part")), nullptr);
	EXPECT_FALSE(is_indexed<CMap3::Volume>(m));

	add_attribute<double, CMap3::Volume>(m, "part");
	EXPECT_THROW(dist::partition(m, 2), dist::PartitionError);
	dist::PartitionOptions reserved;
	reserved.attribute = "__part";
	EXPECT_THROW(dist::partition(m, 2, reserved), dist::PartitionError);

	CMap3 empty;
	EXPECT_THROW(dist::partition(empty, 1), dist::PartitionError);
}

TEST(Partition, AnExistingPartAttributeIsOverwritten)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(4, 4, 4));
	auto part = add_attribute<uint32, CMap3::Volume>(m, "part");
	foreach_cell(m, [&](CMap3::Volume w) { (*part)[w] = 99; });
	const dist::PartitionReport r = dist::partition(m, 2);
	expect_report_matches_attribute<CMap3, CMap3::Volume, CMap3::Face>(m, r, "part");
}

// A million-cell scale: 1,053,696 tetrahedra into 4 parts, with the balance
// (at most 1.05), cut (at most 2% of the interior faces) and connectivity a
// distributed run needs.
TEST(Partition, MillionTetrahedraIntoFourBalancedConnectedParts)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(56, 56, 56));
	ASSERT_EQ(nb_cells<CMap3::Volume>(m), 1053696u);
	const dist::PartitionReport r = dist::partition(m, 4);
	EXPECT_LE(r.imbalance, 1.05);
	EXPECT_LE(r.cut_ratio(), 0.02);
	EXPECT_TRUE(r.parts_connected());
	expect_report_matches_attribute<CMap3, CMap3::Volume, CMap3::Face>(m, r, "part");
}

} // namespace cgogn_test_partition
