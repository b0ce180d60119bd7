// SPDX-License-Identifier: MIT
// Volume files and 3-G-maps: every volume format written from a GMap3 and
// read back into one (counts, positions, attributes), the GMap3 load against
// the CMap3 load converted, cells written in the format's order whatever the
// orientation of the darts, and a mesh no 3-map can hold.
#include <cgogn/cgogn.h>

#include "io_test_utils.h"
#include "volume_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace cgogn_test_gmap3_io
{

using namespace cgogn;
using namespace cgogn::io_test;
using GVertex = GMap3::Vertex;
using GVolume = GMap3::Volume;

// The same cells, each listed in the other orientation: a GMap3 built from
// it has the same cells, but each volume's first darts turn inwards.
VolumeSoup turned_over(VolumeSoup s)
{
	std::size_t k = 0;
	for (uint32 n : s.cell_sizes)
	{
		uint32* v = s.cell_vertices.data() + k;
		k += n;
		const uint32 b = n == 4 || n == 6 ? 3 : 4;
		std::reverse(v + 1, v + b);
		if (n == 6 || n == 8)
			std::reverse(v + b + 1, v + 2 * b);
	}
	return s;
}

template <typename T>
std::vector<T> values_of(const AttributeArray<T>& a)
{
	return std::vector<T>(a.begin(), a.end());
}

void add_values(GMap3& m)
{
	auto t = add_attribute<double, GVertex>(m, "temperature");
	auto r = add_attribute<double, GVolume>(m, "region");
	uint32 i = 0;
	foreach_cell(m, [&](GVertex v) { value<double>(m, t, v) = 0.25 * i++; });
	i = 0;
	foreach_cell(m, [&](GVolume w) { value<double>(m, r, w) = double(i++ % 5); });
}

// The region of each volume, by the sorted vertex lines of the volume.
std::map<std::vector<uint32>, double> region_by_cell(const GMap3& m)
{
	auto reg = get_attribute<double, GVolume>(m, "region");
	std::map<std::vector<uint32>, double> out;
	foreach_cell(m, [&](GVolume w) {
		std::vector<uint32> vs;
		foreach_dart_of_orbit(m, w, [&](Dart d) { vs.push_back(index_of(m, GVertex(d))); });
		std::sort(vs.begin(), vs.end());
		vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
		out[vs] = value<double>(m, *reg, w);
	});
	return out;
}

class GMap3Formats : public testing::TestWithParam<VolumeCase>
{
};

TEST_P(GMap3Formats, RoundTripKeepsCountsPositionsAndAttributes)
{
	const VolumeCase& c = GetParam();
	TempDir dir;
	GMap3 a;
	build_with_positions(a, c.tets_only ? tet_grid_soup(2, 2, 2) : test::mixed_volume_soup());
	add_values(a);
	ASSERT_TRUE(check_integrity(a).ok());
	io::SaveOptions options;
	options.binary = c.binary;
	const std::string path = dir.file(c.file);
	io::save_volume(a, path, options);

	GMap3 b;
	const io::LoadReport r = io::load_volume(b, path);
	EXPECT_EQ(r.nb_cells_reoriented, 0u) << "written cells must be positively oriented";
	EXPECT_EQ(r.nb_cells_skipped, 0u);
	EXPECT_TRUE(r.manifold());
	EXPECT_TRUE(check_integrity(b).ok()) << check_integrity(b).to_string();
	EXPECT_EQ(test::volume_counts(b), test::volume_counts(a));
	EXPECT_EQ(values_of(*get_attribute<Vec3, GVertex>(b, "position")),
			  values_of(*get_attribute<Vec3, GVertex>(a, "position")));
	if (c.attributes)
	{
		auto t = get_attribute<double, GVertex>(b, "temperature");
		auto reg = get_attribute<double, GVolume>(b, "region");
		ASSERT_TRUE(t && reg);
		EXPECT_EQ(values_of(*t), values_of(*get_attribute<double, GVertex>(a, "temperature")));
		std::vector<double> ra = values_of(*get_attribute<double, GVolume>(a, "region")), rb = values_of(*reg);
		std::sort(ra.begin(), ra.end());
		std::sort(rb.begin(), rb.end());
		EXPECT_EQ(ra, rb);
		// each volume got the value of its own cell (vertices keep their lines)
		EXPECT_EQ(region_by_cell(b), region_by_cell(a));
	}

	// the same file into a CMap3, converted: the same cells
	CMap3 cm;
	const io::LoadReport rc = io::load_volume(cm, path);
	EXPECT_EQ(rc.nb_cells_reoriented, 0u);
	const GMap3 converted = to_gmap(cm);
	EXPECT_EQ(test::volume_counts(b), test::volume_counts(converted));
	EXPECT_EQ(nb_darts(b), 2 * nb_darts(cm));
	EXPECT_EQ(values_of(*get_attribute<Vec3, GVertex>(b, "position")),
			  values_of(*get_attribute<Vec3, GVertex>(converted, "position")));
}

TEST_P(GMap3Formats, CellsWithInwardDartsAreWrittenInTheFormatsOrder)
{
	const VolumeCase& c = GetParam();
	TempDir dir;
	const VolumeSoup s = c.tets_only ? tet_grid_soup(2, 1, 2) : test::mixed_volume_soup();
	GMap3 a;
	build_with_positions(a, turned_over(s));
	const std::string path = dir.file(c.file);
	io::save_volume(a, path);
	CMap3 reference;
	build_with_positions(reference, s);
	CMap3 b;
	const io::LoadReport r = io::load_volume(b, path);
	EXPECT_EQ(r.nb_cells_reoriented, 0u);
	EXPECT_EQ(test::volume_counts(b), test::volume_counts(reference)); // every shared face sewn
	EXPECT_TRUE(check_integrity(b).ok());
}

INSTANTIATE_TEST_SUITE_P(Formats, GMap3Formats, testing::ValuesIn(volume_cases()), volume_case_name);

TEST(GMap3Load, DataFilesGiveTheCMap3LoadConverted)
{
	for (const char* file : {"volume/armadillo_tet_4k.mesh", "volume/liver_hex_624.mesh"})
	{
		SCOPED_TRACE(file);
		const std::string path = std::string(CGOGN_DATA_DIR) + "/" + file;
		GMap3 g;
		const io::LoadReport rg = io::load_volume(g, path);
		CMap3 c;
		const io::LoadReport rc = io::load_volume(c, path);
		const GMap3 converted = to_gmap(c);
		EXPECT_EQ(test::volume_counts(g), test::volume_counts(converted));
		EXPECT_EQ(rg.nb_cells_built, rc.nb_cells_built);
		EXPECT_EQ(rg.nb_cells_reoriented, rc.nb_cells_reoriented);
		EXPECT_EQ(rg.nb_holes_closed, rc.nb_holes_closed);
		EXPECT_EQ(rg.manifold(), rc.manifold());
		EXPECT_EQ(values_of(*get_attribute<Vec3, GVertex>(g, "position")),
				  values_of(*get_attribute<Vec3, GVertex>(converted, "position")));
		EXPECT_TRUE(check_integrity(g).ok());
		// and back through a file
		TempDir dir;
		io::save_volume(g, dir.file("back.vtu"));
		GMap3 h;
		const io::LoadReport rh = io::load_volume(h, dir.file("back.vtu"));
		EXPECT_EQ(rh.nb_cells_reoriented, 0u);
		EXPECT_EQ(test::volume_counts(h), test::volume_counts(g));
	}
}

TEST(GMap3Load, NegativeTetsAreTurnedOverAndGlued)
{
	TempDir dir;
	write_text(dir.file("neg.mesh"), "MeshVersionFormatted 1\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 "
									 "0\n0 0 1 0\n0 0 -1 0\nTetrahedra\n2\n1 2 3 4 0\n1 2 3 5 0\nEnd\n");
	GMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("neg.mesh"));
	EXPECT_EQ(r.nb_cells_reoriented, 1u);
	EXPECT_EQ(nb_cells<GVolume>(m), 2u);
	EXPECT_EQ(nb_cells<GMap3::Face>(m), 7u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(GMap3Load, AppendsToAMapAndFailsWithoutTouchingIt)
{
	TempDir dir;
	GMap3 m;
	build_with_positions(m, hex_grid_soup(1, 1, 1));
	io::save_volume(m, dir.file("h.vtk"));
	const io::LoadReport r = io::load_volume(m, dir.file("h.vtk"));
	EXPECT_EQ(r.build.vertex_offset, 8u);
	EXPECT_EQ(nb_cells<GVolume>(m), 2u);
	EXPECT_EQ(nb_cells<GMap3::CC>(m), 2u);
	EXPECT_TRUE(check_integrity(m).ok());
	// a malformed file: typed error, nothing changed
	const MapSnapshot<GMap3> before(m);
	write_text(dir.file("bad.mesh"), "MeshVersionFormatted 1\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 "
									 "0\n0 0 1 0\nTetrahedra\n1\n1 2 3 9 0\nEnd\n");
	try
	{
		io::load_volume(m, dir.file("bad.mesh"));
		ADD_FAILURE() << "loaded without error";
	}
	catch (const io::Error& e)
	{
		EXPECT_EQ(e.path(), dir.file("bad.mesh"));
		EXPECT_EQ(e.where(), io::Error::Where::Line);
		EXPECT_EQ(e.position(), 11u);
	}
	EXPECT_TRUE(MapSnapshot<GMap3>(m) == before);
	// an attribute of the file's name but another type: refused before building
	add_attribute<uint32, GVertex>(m, "temperature");
	GMap3 src;
	build_with_positions(src, tet_grid_soup(1, 1, 1));
	add_attribute<double, GVertex>(src, "temperature");
	io::save_volume(src, dir.file("t.vtk"));
	const MapSnapshot<GMap3> before2(m);
	EXPECT_THROW(io::load_volume(m, dir.file("t.vtk")), io::Error);
	EXPECT_TRUE(MapSnapshot<GMap3>(m) == before2);
	EXPECT_TRUE(check_integrity(m).ok());
	// not a volume format
	EXPECT_THROW(io::load_volume(m, dir.file("x.off")), io::Error);
	// a GMap3 has no position to write
	GMap3 bare;
	build_volume(bare, hex_grid_soup(1, 1, 1));
	EXPECT_THROW(io::save_volume(bare, dir.file("bare.mesh")), io::Error);
	// TetGen holds tetrahedra only
	EXPECT_THROW(io::save_volume(m, dir.file("h.ele")), io::Error);
}

TEST(GMap3Load, ASolidKleinBottleRoundTrips)
{
	// a ring of hexahedra glued back through a reflection of its section
	const VolumeSoup s = solid_klein_bottle_soup(6);
	GMap3 a;
	const BuildReport br = build_with_positions(a, s);
	ASSERT_FALSE(br.orientable);
	ASSERT_FALSE(is_orientable(a));
	TempDir dir;
	for (const char* file : {"k.mesh", "k.vtk", "k.vtu", "k.msh"})
	{
		SCOPED_TRACE(file);
		io::save_volume(a, dir.file(file));
		GMap3 b;
		const io::LoadReport r = io::load_volume(b, dir.file(file));
		EXPECT_FALSE(r.build.orientable);
		EXPECT_EQ(r.summary("GMap3"), "the volume mesh is not orientable\n");
		EXPECT_FALSE(is_orientable(b));
		EXPECT_TRUE(check_integrity(b).ok());
		EXPECT_EQ(test::volume_counts(b), test::volume_counts(a));
	}
}

} // namespace cgogn_test_gmap3_io
