// SPDX-License-Identifier: MIT
// Every volume format: write a map, read it back, compare counts, positions,
// attribute values and cell orientations.
#include <cgogn/cgogn.h>

#include "io_test_utils.h"
#include "volume_test_meshes.h"

#include <gtest/gtest.h>

namespace cgogn_test_volume_roundtrip
{

using namespace cgogn;
using namespace cgogn::io_test;
using Vertex = CMap3::Vertex;
using Volume = CMap3::Volume;

void make_mesh(CMap3& m, bool tets_only)
{
	if (tets_only)
		build_with_positions(m, tet_grid_soup(2, 2, 2));
	else
		build_with_positions(m, test::mixed_volume_soup());
	auto t = add_attribute<double, Vertex>(m, "temperature");
	auto f = add_attribute<Vec3, Vertex>(m, "flow");
	auto r = add_attribute<double, Volume>(m, "region");
	uint32 i = 0;
	foreach_cell(m, [&](Vertex v) {
		value<double>(m, t, v) = 0.1 * i;
		value<Vec3>(m, f, v) = Vec3(i, -0.5 * i, 1.0 / (1 + i));
		++i;
	});
	i = 0;
	foreach_cell(m, [&](Volume w) { value<double>(m, r, w) = double(i++ % 4); });
}

template <typename T>
std::vector<T> values_of(const AttributeArray<T>& a)
{
	return std::vector<T>(a.begin(), a.end());
}

int64 euler(const CMap3& m)
{
	return int64(nb_cells<Vertex>(m)) - nb_cells<CMap3::Edge>(m) + nb_cells<CMap3::Face>(m) - nb_cells<Volume>(m);
}

class VolumeRoundTrip : public testing::TestWithParam<VolumeCase>
{
};

TEST_P(VolumeRoundTrip, SameCountsPositionsAndAttributes)
{
	const VolumeCase& c = GetParam();
	TempDir dir;
	CMap3 a;
	make_mesh(a, c.tets_only);
	ASSERT_TRUE(check_integrity(a).ok());
	io::SaveOptions options;
	options.binary = c.binary;
	io::save_volume(a, dir.file(c.file), options);

	CMap3 b;
	const io::LoadReport r = io::load_volume(b, dir.file(c.file));
	EXPECT_EQ(r.nb_cells_reoriented, 0u) << "written cells must be positively oriented";
	EXPECT_EQ(r.nb_cells_skipped, 0u);
	EXPECT_TRUE(r.manifold());
	EXPECT_EQ(nb_cells<Vertex>(b), nb_cells<Vertex>(a));
	EXPECT_EQ(nb_cells<CMap3::Edge>(b), nb_cells<CMap3::Edge>(a));
	EXPECT_EQ(nb_cells<CMap3::Face>(b), nb_cells<CMap3::Face>(a));
	EXPECT_EQ(nb_cells<Volume>(b), nb_cells<Volume>(a));
	EXPECT_EQ(euler(b), euler(a));
	EXPECT_EQ(nb_boundary_components(b), nb_boundary_components(a));
	EXPECT_TRUE(check_integrity(b).ok()) << check_integrity(b).to_string();

	// vertices come back in the order of the vertex container: same positions
	EXPECT_EQ(values_of(*get_attribute<Vec3, Vertex>(b, "position")),
			  values_of(*get_attribute<Vec3, Vertex>(a, "position")));
	if (c.attributes)
	{
		auto t = get_attribute<double, Vertex>(b, "temperature");
		auto f = get_attribute<Vec3, Vertex>(b, "flow");
		auto reg = get_attribute<double, Volume>(b, "region");
		ASSERT_TRUE(t && f && reg);
		EXPECT_EQ(values_of(*t), values_of(*get_attribute<double, Vertex>(a, "temperature")));
		EXPECT_EQ(values_of(*f), values_of(*get_attribute<Vec3, Vertex>(a, "flow")));
		// volumes are written grouped by kind in some formats: compare as multisets
		std::vector<double> ra = values_of(*get_attribute<double, Volume>(a, "region")), rb = values_of(*reg);
		std::sort(ra.begin(), ra.end());
		std::sort(rb.begin(), rb.end());
		EXPECT_EQ(ra, rb);
	}
}

INSTANTIATE_TEST_SUITE_P(Formats, VolumeRoundTrip, testing::ValuesIn(volume_cases()), volume_case_name);

TEST(VolumeLoad, NegativeTetsAreTurnedOver)
{
	TempDir dir;
	// the second tet lists its vertices in negative order
	write_text(dir.file("neg.mesh"), "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 "
									 "0\n0 0 1 0\n0 0 -1 0\nTetrahedra\n2\n1 2 3 4 0\n1 2 3 5 0\nEnd\n");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("neg.mesh"));
	EXPECT_EQ(r.nb_cells_reoriented, 1u);
	EXPECT_EQ(nb_cells<Volume>(m), 2u);
	EXPECT_EQ(nb_cells<CMap3::Face>(m), 7u); // the shared face is sewn
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(VolumeSave, RefusesCellsTheFormatCannotHold)
{
	TempDir dir;
	CMap3 m;
	build_with_positions(m, hex_grid_soup(1, 1, 1));
	EXPECT_THROW(io::save_volume(m, dir.file("h.ele")), io::Error);
	CMap3 empty;
	build_volume(empty, hex_grid_soup(1, 1, 1));
	EXPECT_THROW(io::save_volume(empty, dir.file("h.mesh")), io::Error); // no position
}

} // namespace cgogn_test_volume_roundtrip
