// SPDX-License-Identifier: MIT
// Region and boundary tags: gmsh physical and elementary tags and MEDIT
// references load as int attributes of the volumes and of the faces the file
// lists (boundary faces), and every volume format that has them writes them
// back. The gmsh files were written by gmsh itself (tests/data/gmsh).
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <map>

namespace cgogn_test_mesh_tags
{

using namespace cgogn;
using namespace cgogn::io_test;

using Histogram = std::map<int32, uint32>; // tag -> number of cells

// How many cells CELL of m have each value of the int32 attribute `name`
// (empty when there is no such attribute); with `only_nonzero`, the cells
// of value 0 are not counted.
template <typename CELL>
Histogram histogram(const CMap3& m, const std::string& name, bool only_nonzero = false)
{
	Histogram h;
	auto a = get_attribute<int32, CELL>(m, name);
	if (a == nullptr)
		return h;
	foreach_cell(m, [&](CELL c) {
		if (!only_nonzero || (*a)[c] != 0)
			++h[(*a)[c]];
	});
	return h;
}

// What gmsh wrote in the box files: 1 volume of physical tag 10, six
// surfaces (elementary 1 to 6) in physical groups 1 (bottom), 2 (top) and
// 3 (the four walls), `per_side` faces on each.
struct Box
{
	const char* file;
	uint32 nb_volumes;
	uint32 per_side;
};

class GmshBox : public testing::TestWithParam<Box>
{
};

std::string box_name(const testing::TestParamInfo<Box>& i)
{
	std::string n = i.param.file;
	return n.substr(0, n.find('.'));
}

INSTANTIATE_TEST_SUITE_P(Files, GmshBox,
						 testing::Values(Box{"box_tet_v22.msh", 184, 26}, Box{"box_tet_v22_bin.msh", 184, 26},
										 Box{"box_tet_v41.msh", 184, 26}, Box{"box_tet_v41_bin.msh", 184, 26},
										 Box{"box_hex_v22.msh", 27, 9}, Box{"box_hex_v22_bin.msh", 27, 9},
										 Box{"box_hex_v41.msh", 27, 9}, Box{"box_hex_v41_bin.msh", 27, 9}),
						 box_name);

// The tags of a box as loaded: volumes all physical 10 (elementary 1 when
// `geometrical`), the boundary faces by side.
void expect_box_tags(const CMap3& m, const Box& b, const std::string& physical, bool geometrical)
{
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), b.nb_volumes);
	EXPECT_EQ((histogram<CMap3::Volume>(m, physical)), (Histogram{{10, b.nb_volumes}}));
	EXPECT_EQ((histogram<CMap3::Face>(m, physical, true)),
			  (Histogram{{1, b.per_side}, {2, b.per_side}, {3, 4 * b.per_side}}));
	if (geometrical)
	{
		EXPECT_EQ((histogram<CMap3::Volume>(m, "gmsh:geometrical")), (Histogram{{1, b.nb_volumes}}));
		Histogram sides;
		for (int32 s = 1; s <= 6; ++s)
			sides[s] = b.per_side;
		EXPECT_EQ((histogram<CMap3::Face>(m, "gmsh:geometrical", true)), sides);
	}
	// the tagged faces are exactly the boundary faces
	auto tag = get_attribute<int32, CMap3::Face>(m, physical);
	ASSERT_NE(tag, nullptr);
	uint32 mismatches = 0;
	foreach_cell(m, [&](CMap3::Face f) {
		const bool on_boundary = is_boundary(m, f.dart) || is_boundary(m, phi3(m, f.dart));
		mismatches += on_boundary != ((*tag)[f] != 0);
	});
	EXPECT_EQ(mismatches, 0u);
}

TEST_P(GmshBox, LoadsTheVolumeAndBoundaryTagsGmshWrote)
{
	const Box& b = GetParam();
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, cgogn_test_data::path(std::string("gmsh/") + b.file));
	EXPECT_TRUE(r.dropped.empty()) << r.summary("CMap3");
	EXPECT_TRUE(check_integrity(m).ok());
	expect_box_tags(m, b, "gmsh:physical", true);
}

TEST_P(GmshBox, TagsSurviveEveryVolumeFormatThatHasThem)
{
	const Box& b = GetParam();
	TempDir dir;
	CMap3 m;
	io::load_volume(m, cgogn_test_data::path(std::string("gmsh/") + b.file));
	struct Out
	{
		const char* ext;
		bool binary;
		bool geometrical; // MEDIT has one reference per record: the physical tag
	};
	for (const Out& o :
		 {Out{"msh", false, true}, Out{"msh", true, true}, Out{"vtu", false, true}, Out{"vtu", true, true},
		  Out{"vtk", false, true}, Out{"vtk", true, true}, Out{"mesh", false, false}})
	{
		SCOPED_TRACE(std::string(o.ext) + (o.binary ? " binary" : ""));
		io::SaveOptions options;
		options.binary = o.binary;
		const std::string path = dir.file(std::string("box.") + o.ext);
		io::save_volume(m, path, options);
		CMap3 back;
		const io::LoadReport r = io::load_volume(back, path);
		EXPECT_TRUE(r.dropped.empty()) << r.summary("CMap3");
		expect_box_tags(back, b, std::string(o.ext) == "mesh" ? "medit:ref" : "gmsh:physical", o.geometrical);
	}
}

// How many cells CELL have each name of physical group.
template <typename CELL>
std::map<std::string, uint32> names(const CMap3& m)
{
	std::map<std::string, uint32> h;
	auto a = get_attribute<std::string, CELL>(m, "gmsh:physical_name");
	if (a != nullptr)
		foreach_cell(m, [&](CELL c) {
			if (!(*a)[c].empty())
				++h[(*a)[c]];
		});
	return h;
}

TEST_P(GmshBox, NamesOfPhysicalGroupsSurviveMsh)
{
	const Box& b = GetParam();
	TempDir dir;
	CMap3 m;
	io::load_volume(m, cgogn_test_data::path(std::string("gmsh/") + b.file));
	const std::map<std::string, uint32> volumes{{"solid", b.nb_volumes}};
	const std::map<std::string, uint32> faces{{"bottom", b.per_side}, {"top", b.per_side}, {"walls", 4 * b.per_side}};
	EXPECT_EQ(names<CMap3::Volume>(m), volumes);
	EXPECT_EQ(names<CMap3::Face>(m), faces);
	for (bool binary : {false, true})
	{
		io::SaveOptions o;
		o.binary = binary;
		io::save_volume(m, dir.file("box.msh"), o);
		EXPECT_NE(read_text(dir.file("box.msh")).find("$PhysicalNames\n4\n"), std::string::npos);
		CMap3 back;
		io::load_volume(back, dir.file("box.msh"));
		EXPECT_EQ(names<CMap3::Volume>(back), volumes);
		EXPECT_EQ(names<CMap3::Face>(back), faces);
	}
}

TEST(MeshTags, MeditReferencesOfVerticesCellsAndFaces)
{
	TempDir dir;
	// two tets sharing face 1 2 3: refs 7 and 8, the shared face listed with
	// ref 5 (an interface), one outer face with ref 4, vertex 4 with ref 2
	write_text(dir.file("t.mesh"), "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
								   "0 0 1 2\n1 1 1 0\nTriangles\n2\n2 3 4 5\n1 2 3 4\nTetrahedra\n2\n1 2 3 4 7\n"
								   "2 3 4 5 8\nEdges\n1\n1 2 9\nEnd\n");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("t.mesh"));
	EXPECT_EQ((histogram<CMap3::Volume>(m, "medit:ref")), (Histogram{{7, 1}, {8, 1}}));
	EXPECT_EQ((histogram<CMap3::Face>(m, "medit:ref", true)), (Histogram{{4, 1}, {5, 1}}));
	EXPECT_EQ((histogram<CMap3::Vertex>(m, "medit:ref", true)), (Histogram{{2, 1}}));
	ASSERT_EQ(r.dropped.size(), 1u);
	EXPECT_NE(r.dropped[0].find("1 listed edge(s) with their data: a volume map"), std::string::npos) << r.dropped[0];

	io::save_volume(m, dir.file("back.mesh"));
	CMap3 back;
	io::load_volume(back, dir.file("back.mesh"));
	EXPECT_EQ((histogram<CMap3::Volume>(back, "medit:ref")), (Histogram{{7, 1}, {8, 1}}));
	EXPECT_EQ((histogram<CMap3::Face>(back, "medit:ref", true)), (Histogram{{4, 1}, {5, 1}}));
	EXPECT_EQ((histogram<CMap3::Vertex>(back, "medit:ref", true)), (Histogram{{2, 1}}));
}

TEST(MeshTags, MeditFilesWithoutReferencesGetNoAttribute)
{
	CMap3 m;
	io::load_volume(m, cgogn_test_data::path("volume/liver_hex_624.mesh"));
	EXPECT_EQ((get_attribute<int32, CMap3::Volume>(m, "medit:ref")), nullptr);
	EXPECT_EQ((get_attribute<int32, CMap3::Vertex>(m, "medit:ref")), nullptr);
}

TEST(MeshTags, ListedFacesThatMatchNoFaceAreReported)
{
	TempDir dir;
	write_text(dir.file("t.mesh"), "MeshVersionFormatted 2\nDimension 3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
								   "0 0 1 0\n1 1 1 0\nTriangles\n2\n1 2 3 4\n1 2 5 6\nTetrahedra\n1\n1 2 3 4 1\nEnd\n");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("t.mesh"));
	EXPECT_EQ((histogram<CMap3::Face>(m, "medit:ref", true)), (Histogram{{4, 1}}));
	ASSERT_EQ(r.dropped.size(), 1u);
	EXPECT_NE(r.dropped[0].find("1 listed face(s)"), std::string::npos) << r.dropped[0];
}

TEST(MeshTags, GmshTagsBecomeMeditReferencesAndBack)
{
	TempDir dir;
	CMap3 m;
	io::load_volume(m, cgogn_test_data::path("gmsh/box_hex_v41.msh"));
	io::save_volume(m, dir.file("box.mesh"));
	CMap3 medit;
	io::load_volume(medit, dir.file("box.mesh"));
	io::save_volume(medit, dir.file("box.msh"));
	CMap3 back;
	io::load_volume(back, dir.file("box.msh"));
	expect_box_tags(back, Box{"", 27, 9}, "gmsh:physical", false);
}

} // namespace cgogn_test_mesh_tags
