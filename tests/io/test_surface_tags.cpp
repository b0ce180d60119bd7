// SPDX-License-Identifier: MIT
// Tags of surfaces: gmsh physical and elementary tags and MEDIT references
// of triangles load as int face attributes, those of line elements (MEDIT
// edges) as int attributes of the edges they list, with the names of the
// physical groups; every format that lists faces and edges (.msh, .mesh,
// .vtk, .vtu) writes them back. The files were written by gmsh itself
// (tests/data/gmsh/plate.geo).
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <map>

namespace cgogn_test_surface_tags
{

using namespace cgogn;
using namespace cgogn::io_test;

using Histogram = std::map<int32, uint32>; // tag -> number of cells

// How many cells CELL of m have each nonzero value of the int32 attribute
// `name` (empty when there is no such attribute).
template <typename CELL, typename MAP>
Histogram histogram(const MAP& m, const std::string& name)
{
	Histogram h;
	auto a = get_attribute<int32, CELL>(m, name);
	if (a != nullptr)
		foreach_cell(m, [&](CELL c) {
			if ((*a)[c] != 0)
				++h[(*a)[c]];
		});
	return h;
}

// How many cells CELL have each name of physical group.
template <typename CELL, typename MAP>
std::map<std::string, uint32> names(const MAP& m)
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

// What gmsh wrote: 44 triangles, 22 in each physical surface (elementary
// surfaces 1 and 2), and 4 lines in each physical curve: clamped (5, curve
// 6), load (6, curve 3), interface (7, curve 7).
template <typename MAP>
void expect_plate_tags(const MAP& m, const std::string& physical, bool geometrical)
{
	using Face = typename mesh_traits<MAP>::Face;
	using Edge = typename mesh_traits<MAP>::Edge;
	EXPECT_EQ(nb_cells<Face>(m), 44u);
	EXPECT_EQ((histogram<Face>(m, physical)), (Histogram{{1, 22}, {2, 22}}));
	EXPECT_EQ((histogram<Edge>(m, physical)), (Histogram{{5, 4}, {6, 4}, {7, 4}}));
	if (geometrical)
	{
		EXPECT_EQ((histogram<Face>(m, "gmsh:geometrical")), (Histogram{{1, 22}, {2, 22}}));
		EXPECT_EQ((histogram<Edge>(m, "gmsh:geometrical")), (Histogram{{3, 4}, {6, 4}, {7, 4}}));
	}
	// the tagged edges are where the file says: the clamped ones at x = 0,
	// the loaded ones at x = 1, the interface at x = 0.5
	auto tag = get_attribute<int32, Edge>(m, physical);
	auto pos = get_attribute<Vec3, typename mesh_traits<MAP>::Vertex>(m, "position");
	ASSERT_NE(tag, nullptr);
	ASSERT_NE(pos, nullptr);
	uint32 misplaced = 0;
	foreach_cell(m, [&](Edge e) {
		const int32 t = (*tag)[e];
		if (t == 0)
			return;
		const double x = t == 5 ? 0.0 : t == 6 ? 1.0 : 0.5;
		foreach_incident_vertex(m, e, [&](auto v) { misplaced += std::abs((*pos)[v][0] - x) > 1e-12; });
	});
	EXPECT_EQ(misplaced, 0u);
}

class GmshPlate : public testing::TestWithParam<const char*>
{
};

INSTANTIATE_TEST_SUITE_P(Files, GmshPlate, testing::Values("plate_v22.msh", "plate_v41.msh", "plate_v41_bin.msh"),
						 [](const auto& i) { return std::string(i.param).substr(0, std::string(i.param).find('.')); });

TEST_P(GmshPlate, LoadsTheFaceAndEdgeTagsGmshWrote)
{
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, cgogn_test_data::path(std::string("gmsh/") + GetParam()));
	EXPECT_TRUE(r.dropped.empty()) << r.summary("CMap2");
	EXPECT_TRUE(check_integrity(m).ok());
	expect_plate_tags(m, "gmsh:physical", true);
	EXPECT_EQ((names<CMap2::Face>(m)), (std::map<std::string, uint32>{{"left", 22}, {"right", 22}}));
	EXPECT_EQ((names<CMap2::Edge>(m)), (std::map<std::string, uint32>{{"clamped", 4}, {"interface", 4}, {"load", 4}}));
	GMap2 g;
	io::load_surface(g, cgogn_test_data::path(std::string("gmsh/") + GetParam()));
	expect_plate_tags(g, "gmsh:physical", true);
}

TEST_P(GmshPlate, TagsSurviveEveryFormatThatListsEdges)
{
	TempDir dir;
	CMap2 m;
	io::load_surface(m, cgogn_test_data::path(std::string("gmsh/") + GetParam()));
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
		const std::string path = dir.file(std::string("plate.") + o.ext);
		io::save_surface(m, path, options);
		CMap2 back;
		const io::LoadReport r = io::load_surface(back, path);
		EXPECT_TRUE(r.dropped.empty()) << r.summary("CMap2");
		expect_plate_tags(back, std::string(o.ext) == "mesh" ? "medit:ref" : "gmsh:physical", o.geometrical);
		if (std::string(o.ext) == "msh")
		{
			EXPECT_EQ((names<CMap2::Face>(back)), (names<CMap2::Face>(m)));
			EXPECT_EQ((names<CMap2::Edge>(back)), (names<CMap2::Edge>(m)));
		}
	}
}

TEST(MeditPlate, LoadsTheReferencesOfFacesAndEdges)
{
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, cgogn_test_data::path("gmsh/plate.mesh"));
	EXPECT_TRUE(r.dropped.empty()) << r.summary("CMap2");
	EXPECT_EQ((histogram<CMap2::Face>(m, "medit:ref")), (Histogram{{1, 22}, {2, 22}}));
	EXPECT_EQ((histogram<CMap2::Edge>(m, "medit:ref")), (Histogram{{3, 4}, {6, 4}, {7, 4}}));
	TempDir dir;
	io::save_surface(m, dir.file("back.mesh"));
	CMap2 back;
	io::load_surface(back, dir.file("back.mesh"));
	EXPECT_EQ((histogram<CMap2::Face>(back, "medit:ref")), (Histogram{{1, 22}, {2, 22}}));
	EXPECT_EQ((histogram<CMap2::Edge>(back, "medit:ref")), (Histogram{{3, 4}, {6, 4}, {7, 4}}));
}

TEST(SurfaceTags, EdgesThatNoFaceHasAreReported)
{
	TempDir dir;
	// one triangle; edge 1-2 is one of its edges (ref 4), edge 1-4 is not
	write_text(dir.file("t.mesh"), "MeshVersionFormatted 2\nDimension 3\nVertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
								   "5 5 5 0\nTriangles\n1\n1 2 3 9\nEdges\n2\n2 1 4\n1 4 8\nEnd\n");
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, dir.file("t.mesh"));
	EXPECT_EQ((histogram<CMap2::Face>(m, "medit:ref")), (Histogram{{9, 1}}));
	EXPECT_EQ((histogram<CMap2::Edge>(m, "medit:ref")), (Histogram{{4, 1}}));
	ASSERT_FALSE(r.dropped.empty());
	EXPECT_NE(r.summary("CMap2").find("1 listed edge(s) with their data: no edge of the faces"), std::string::npos)
		<< r.summary("CMap2");
	// edges with no reference: nothing to hold, but said
	write_text(dir.file("u.mesh"), "MeshVersionFormatted 2\nDimension 3\nVertices\n3\n0 0 0 0\n1 0 0 0\n0 1 0 0\n"
								   "Triangles\n1\n1 2 3 0\nEdges\n1\n1 2 0\nEnd\n");
	CMap2 u;
	const io::LoadReport ru = io::load_surface(u, dir.file("u.mesh"));
	EXPECT_EQ((get_attribute<int32, CMap2::Edge>(u, "medit:ref")), nullptr);
	EXPECT_NE(ru.summary("CMap2").find("1 listed edge(s) without data"), std::string::npos) << ru.summary("CMap2");
}

TEST(SurfaceTags, AVolumeFileIsRefusedAndTheMapIsUnchanged)
{
	CMap2 m;
	io::load_surface(m, cgogn_test_data::path("gmsh/plate_v41.msh"));
	const uint32 before = nb_darts(m);
	try
	{
		io::load_surface(m, cgogn_test_data::path("gmsh/box_tet_v41.msh"));
		ADD_FAILURE() << "a volume mesh loaded into a CMap2";
	}
	catch (const io::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("184 volume cell(s)"), std::string::npos) << e.what();
	}
	EXPECT_EQ(nb_darts(m), before);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(SurfaceTags, PolygonsOfMoreThanFourVerticesAreRefusedByMshAndMesh)
{
	TempDir dir;
	CMap2 m;
	build_with_positions(m,
						 SurfaceSoup{5, {5}, {0, 1, 2, 3, 4}, {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}}});
	for (const char* file : {"p.msh", "p.mesh"})
	{
		EXPECT_THROW(io::save_surface(m, dir.file(file)), io::Error) << file;
		EXPECT_FALSE(std::filesystem::exists(dir.file(file))) << file;
	}
	// VTK has polygons
	io::save_surface(m, dir.file("p.vtu"));
	CMap2 back;
	io::load_surface(back, dir.file("p.vtu"));
	EXPECT_EQ(nb_cells<CMap2::Face>(back), 1u);
	foreach_cell(back, [&](CMap2::Face f) { EXPECT_EQ(codegree(back, f), 5u); });
}

} // namespace cgogn_test_surface_tags
