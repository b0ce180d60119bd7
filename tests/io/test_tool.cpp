// SPDX-License-Identifier: MIT
// The `cgogn` program, run as a user would: exit codes, JSON keys, errors on
// stderr, no progress output when not on a terminal.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "io_test_utils.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <sys/wait.h>
#include <vector>

namespace cgogn_test_tool
{

using namespace cgogn;
using namespace cgogn::io_test;

namespace
{

std::string example_mesh()
{
	// appended, not `std::string(DIR) + "..."`: g++ 12 at -O1 sees a false
	// out-of-bounds copy in that temporary (-Warray-bounds)
	std::string path = CGOGN_EXAMPLE_DATA_DIR;
	path += "/spot_control_mesh.obj";
	return path;
}

} // namespace

TEST(Tool, InfoJsonHasTheDocumentedKeys)
{
	TempDir dir;
	const ToolRun r = run_tool("info --json '" + example_mesh() + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "") << "no progress output when stderr is not a terminal";
	const nlohmann::json j = nlohmann::json::parse(r.out);
	for (const char* k : {"dimension", "vertices", "edges", "faces", "boundary_components", "connected_components",
						  "euler_characteristic", "genus", "manifold", "bbox", "isolated_vertices",
						  "nonmanifold_vertices", "nonmanifold_edges", "edge_length", "face_degrees"})
		EXPECT_TRUE(j.contains(k)) << k;
	EXPECT_EQ(j["dimension"], 2);
	EXPECT_EQ(j["vertices"], 188);
	EXPECT_EQ(j["edges"], 366);
	EXPECT_EQ(j["faces"], 180);
	EXPECT_EQ(j["euler_characteristic"], 2);
	EXPECT_EQ(j["genus"], 0);
	EXPECT_EQ(j["manifold"], true);
	EXPECT_EQ(j["face_degrees"]["3"], 4);
	EXPECT_EQ(j["face_degrees"]["4"], 160);
	EXPECT_EQ(j["face_degrees"]["5"], 16);
	EXPECT_EQ(j["bbox"]["min"].size(), 3u);
}

TEST(Tool, VolumeInfoAndConvert)
{
	TempDir dir;
	CMap3 m;
	build_with_positions(m, tet_grid_soup(2, 2, 2));
	io::save_volume(m, dir.file("g.mesh"));
	ToolRun r = run_tool("convert '" + dir.file("g.mesh") + "' '" + dir.file("g.vtu") + "' --binary", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("info --json '" + dir.file("g.vtu") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["dimension"], 3);
	EXPECT_EQ(j["volumes"], 48);
	EXPECT_EQ(j["vertices"], 27);
	EXPECT_EQ(j["euler_characteristic"], 1);
	EXPECT_EQ(j["cell_kinds"]["tetrahedra"], 48);
	EXPECT_EQ(j["manifold"], true);
	EXPECT_EQ(j["orientable"], true);
	r = run_tool("info '" + dir.file("g.vtu") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(r.out.find("\norientable: true\n"), std::string::npos) << r.out;
	// a volume cannot go to a surface format
	r = run_tool("convert '" + dir.file("g.mesh") + "' '" + dir.file("g.off") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("surface format"), std::string::npos) << r.err;
}

namespace
{
// `cgogn info --json path`, which must succeed, parsed.
nlohmann::json info_json(const std::string& path, TempDir& dir)
{
	const ToolRun r = run_tool("info --json '" + path + "'", dir);
	EXPECT_EQ(r.status, 0) << r.err;
	return nlohmann::json::parse(r.out);
}

// `cgogn convert in out flags`, then `cgogn check --json out`, parsed.
nlohmann::json converted_and_checked(const std::string& in, const std::string& out, TempDir& dir,
									 const std::string& flags = "")
{
	ToolRun r = run_tool("convert '" + in + "' '" + out + "' " + flags, dir);
	EXPECT_EQ(r.status, 0) << r.err;
	r = run_tool("check --json '" + out + "'", dir);
	EXPECT_EQ(r.status, 0) << r.err;
	return nlohmann::json::parse(r.out);
}

// vertices, edges, faces (and volumes), boundary components and Euler
// characteristic of an info object
void expect_counts(const nlohmann::json& j, std::vector<int> cells, int boundary, int chi)
{
	const char* keys[] = {"vertices", "edges", "faces", "volumes"};
	for (std::size_t k = 0; k < cells.size(); ++k)
		EXPECT_EQ(j[keys[k]], cells[k]) << keys[k];
	EXPECT_EQ(j["boundary_components"], boundary);
	EXPECT_EQ(j["euler_characteristic"], chi);
}
} // namespace

TEST(Tool, SurfacesInVolumeFormatsKeepTheirTags)
{
	TempDir dir;
	const std::string plate = cgogn_test_data::path("gmsh/plate_v41.msh");
	ToolRun r = run_tool("info --json '" + plate + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["dimension"], 2);
	EXPECT_EQ(j["faces"], 44);
	// to VTU and back to .msh, then Loop subdivision: each face's tag is
	// its parent's, each tagged edge's two halves keep its tag
	r = run_tool("convert '" + plate + "' '" + dir.file("p.vtu") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("subdivide --scheme loop '" + dir.file("p.vtu") + "' '" + dir.file("p.msh") + "' --binary", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap2 m;
	io::load_surface(m, dir.file("p.msh"));
	std::map<int32, uint32> faces, edges;
	auto face_tag = get_attribute<int32, CMap2::Face>(m, "gmsh:physical");
	auto edge_tag = get_attribute<int32, CMap2::Edge>(m, "gmsh:physical");
	ASSERT_NE(face_tag, nullptr);
	ASSERT_NE(edge_tag, nullptr);
	foreach_cell(m, [&](CMap2::Face f) { ++faces[(*face_tag)[f]]; });
	foreach_cell(m, [&](CMap2::Edge e) {
		if ((*edge_tag)[e] != 0)
			++edges[(*edge_tag)[e]];
	});
	EXPECT_EQ(faces, (std::map<int32, uint32>{{1, 88}, {2, 88}}));
	EXPECT_EQ(edges, (std::map<int32, uint32>{{5, 8}, {6, 8}, {7, 8}}));
	// a volume-only format takes no surface
	r = run_tool("convert '" + plate + "' '" + dir.file("p.ovm") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("volume-only format"), std::string::npos) << r.err;
}

TEST(Tool, NonOrientableSurfacesAreLoadedWhole)
{
	TempDir dir;
	const std::string mobius = std::string(CGOGN_DATA_DIR) + "/surface/mobius_strip.off";
	nlohmann::json j = info_json(mobius, dir);
	EXPECT_EQ(j["map"], "GMap2");
	EXPECT_EQ(j["orientable"], false);
	EXPECT_EQ(j["manifold"], true);
	expect_counts(j, {48, 72, 24}, 1, 0);
	EXPECT_EQ(j["darts"], 288);
	// convert keeps it whole, check finds it valid
	j = converted_and_checked(mobius, dir.file("m.ply"), dir, "--binary");
	EXPECT_EQ(j["ok"], true);
	EXPECT_EQ(j["orientable"], false);
	EXPECT_EQ(j["manifold"], true);
	// an orientable surface stays a CMap2
	j = info_json(example_mesh(), dir);
	EXPECT_EQ(j["map"], "CMap2");
	EXPECT_EQ(j["orientable"], true);
}

TEST(Tool, NonOrientableVolumeMeshesAreLoadedWhole)
{
	// a solid Klein bottle written by the library; the 3-map leaves its
	// twisted face open, so the tool loads it into a GMap3
	TempDir dir;
	GMap3 g;
	build_with_positions(g, solid_klein_bottle_soup(6));
	const std::string file = dir.file("klein.mesh");
	io::save_volume(g, file);
	nlohmann::json j = info_json(file, dir);
	EXPECT_EQ(j["map"], "GMap3");
	EXPECT_EQ(j["orientable"], false);
	expect_counts(j, {24, 48, 30, 6}, 1, 0);
	j = converted_and_checked(file, dir.file("klein.vtu"), dir);
	EXPECT_EQ(j["ok"], true);
	EXPECT_EQ(j["orientable"], false);
	// an orientable volume mesh stays a CMap3
	CMap3 c;
	build_with_positions(c, hex_grid_soup(2, 1, 1));
	io::save_volume(c, dir.file("grid.mesh"));
	j = info_json(dir.file("grid.mesh"), dir);
	EXPECT_EQ(j["map"], "CMap3");
	EXPECT_EQ(j["orientable"], true);
}

TEST(Tool, CheckReportsIntegrityAndRepairs)
{
	TempDir dir;
	write_text(dir.file("bowtie.off"), "OFF\n5 2 0\n0 0 0\n1 0 0\n0.5 0.5 0\n0 1 0\n1 1 0\n3 0 1 2\n3 2 4 3\n");
	ToolRun r = run_tool("check --json '" + dir.file("bowtie.off") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["ok"], true);
	EXPECT_EQ(j["manifold"], false);
	EXPECT_EQ(j["nonmanifold_vertices"], 1);
	r = run_tool("info --json '" + dir.file("bowtie.off") + "'", dir);
	const nlohmann::json i = nlohmann::json::parse(r.out);
	// the file's true counts, and the repaired map's beside them
	EXPECT_EQ(i["map"], "IncidenceGraph");
	EXPECT_EQ(i["vertices"], 5);
	EXPECT_EQ(i["nonmanifold_vertices"], 1);
	EXPECT_EQ(i["repaired_map"]["vertices"], 6) << "the shared vertex is split, one per fan";
	EXPECT_EQ(i["manifold"], false);
	r = run_tool("check '" + dir.file("bowtie.off") + "'", dir);
	EXPECT_EQ(r.status, 0);
	EXPECT_NE(r.out.find("integrity ok"), std::string::npos);
}

TEST(Tool, ErrorsGoToStderrWithNonZeroExit)
{
	TempDir dir;
	write_text(dir.file("bad.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
	ToolRun r = run_tool("info '" + dir.file("bad.off") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_EQ(r.out, "");
	EXPECT_NE(r.err.find("bad.off:6: vertex index 9 out of range"), std::string::npos) << r.err;
	r = run_tool("info '" + dir.file("missing.off") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("cannot open"), std::string::npos) << r.err;
	r = run_tool("info '" + dir.file("x.unknown") + "'", dir);
	EXPECT_EQ(r.status, 2);
	r = run_tool("", dir);
	EXPECT_NE(r.status, 0);
	r = run_tool("frobnicate x", dir);
	EXPECT_NE(r.status, 0);
	r = run_tool("--help", dir);
	EXPECT_EQ(r.status, 0);
	EXPECT_NE(r.out.find("convert"), std::string::npos);
}

TEST(Tool, InfoOnEveryMalformedFileExitsTwoWithAMessage)
{
	// the committed malformed corpus (and the fuzzers' regressions in it):
	// status 2 and a message naming the file, never a signal (which the shell
	// reports as 128 + its number)
	TempDir dir;
	uint32 files = 0;
	for (const auto& entry : std::filesystem::directory_iterator(CGOGN_IO_BAD_DIR))
	{
		const std::string path = entry.path().string();
		const ToolRun r = run_tool("info " + quoted(path), dir);
		EXPECT_EQ(r.status, 2) << path << "\n" << r.err;
		EXPECT_EQ(r.out, "") << path;
		const std::string stem = entry.path().stem().string();
		EXPECT_NE(r.err.find(stem), std::string::npos) << path << "\n" << r.err;
		++files;
	}
	EXPECT_GE(files, 50u);
}

TEST(Tool, MapsOfAnyDimensionAreInspectedCheckedAndConverted)
{
	TempDir dir;
	CMapN<4> grid;
	generate_cube_grid(grid, 2);
	io::save_nmap(grid, dir.file("grid.nmap"));
	ToolRun r = run_tool("info --json '" + dir.file("grid.nmap") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["map"], "CMapN<4>");
	EXPECT_EQ(j["dimension"], 4);
	EXPECT_EQ(j["f_vector"], (std::vector<uint32>{81, 216, 216, 96, 16}));
	EXPECT_EQ(j["euler_characteristic"], 1);
	EXPECT_EQ(j["boundary"], true);
	EXPECT_EQ(j["boundary_f_vector"], (std::vector<uint32>{80, 208, 192, 64})); // a 3-sphere of 64 cubes
	r = run_tool("check '" + dir.file("grid.nmap") + "'", dir);
	EXPECT_EQ(r.status, 0) << r.err;
	// the boundary's cubes as polyhedra, the map itself copied
	r = run_tool("convert '" + dir.file("grid.nmap") + "' '" + dir.file("b.vtu") + "' --boundary", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(read_text(dir.file("b.vtu")).find("NumberOfCells=\"64\""), std::string::npos);
	r = run_tool("convert '" + dir.file("grid.nmap") + "' '" + dir.file("copy.nmap") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMapN<4> copy;
	io::load_nmap(copy, dir.file("copy.nmap"));
	EXPECT_EQ(f_vector(copy), f_vector(grid));
	// a G-map that cannot be oriented: the Klein bottle, from a surface file
	r = run_tool("convert '" + std::string(CGOGN_DATA_DIR) + "/surface/klein_bottle.off' '" + dir.file("k.nmap") + "'",
				 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("info --json '" + dir.file("k.nmap") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["map"], "GMapN<2>");
	EXPECT_EQ(j["orientable"], false);
	EXPECT_EQ(j["euler_characteristic"], 0);
	GMapN<2> klein;
	io::load_nmap(klein, dir.file("k.nmap"));
	EXPECT_TRUE((get_attribute<PointD<3>, CellD<0>>(klein, "position"))) << "the positions are carried";
	// a surface to a .nmap and on to a .vtu of its faces
	r = run_tool("convert '" + example_mesh() + "' '" + dir.file("spot.nmap") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("convert '" + dir.file("spot.nmap") + "' '" + dir.file("spot.vtu") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(read_text(dir.file("spot.vtu")).find("NumberOfCells=\"180\""), std::string::npos);
	// errors: a bad header, a format the maps of any dimension are not written in
	write_text(dir.file("bad.nmap"), "cgogn_nmap 1\nmodel xmap\ndimension 2\n");
	r = run_tool("info '" + dir.file("bad.nmap") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("bad.nmap:2: unknown model 'xmap'"), std::string::npos) << r.err;
	write_text(dir.file("deep.nmap"), "cgogn_nmap 1\nmodel cmap\ndimension 9\n");
	r = run_tool("check '" + dir.file("deep.nmap") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("deep.nmap:3: the dimension 9 is out of 1 ... 7"), std::string::npos) << r.err;
	r = run_tool("convert '" + dir.file("grid.nmap") + "' '" + dir.file("g.off") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find(".nmap or a .vtu"), std::string::npos) << r.err;
}

TEST(Tool, GraphInfoCheckAndConvert)
{
	TempDir dir;
	// a star of 3 around vertex 0, a triangle 4-5-6 and an isolated vertex 7
	write_text(dir.file("g.cgr"), "# D:3 NV:8 NE:6\n"
								  "v 0 0 0 1\nv 1 0 0 0.5\nv 0 1 0 0.5\nv 0 0 1 0.5\n"
								  "v 5 0 0 1\nv 6 0 0 1\nv 5 1 0 1\nv 9 9 9 2\n"
								  "e 0 1\ne 0 2\ne 0 3\ne 4 5\ne 5 6\ne 6 4\n");
	ToolRun r = run_tool("info --json '" + dir.file("g.cgr") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["map"], "Graph");
	EXPECT_EQ(j["vertices"], 8);
	EXPECT_EQ(j["edges"], 6);
	EXPECT_EQ(j["connected_components"], 3);
	EXPECT_EQ(j["cycle_rank"], 1);
	EXPECT_EQ(j["euler_characteristic"], 2);
	EXPECT_EQ(j["isolated_vertices"], 1);
	EXPECT_EQ(j["branches"]["open"], 3);
	EXPECT_EQ(j["branches"]["closed"], 1);
	EXPECT_EQ(j["vertex_degrees"]["3"], 1);
	EXPECT_EQ(j["radius"], true);
	EXPECT_EQ(j["bbox"]["max"][0], 9.0);
	r = run_tool("check '" + dir.file("g.cgr") + "'", dir);
	EXPECT_EQ(r.status, 0) << r.err;
	r = run_tool("convert '" + dir.file("g.cgr") + "' '" + dir.file("h.cgr") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(read_text(dir.file("h.cgr")), read_text(dir.file("g.cgr")));
	r = run_tool("convert '" + dir.file("g.cgr") + "' '" + dir.file("h.off") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("graph file"), std::string::npos) << r.err;
	// to ParaView's polylines and back, the same file
	r = run_tool("convert '" + dir.file("g.cgr") + "' '" + dir.file("g.vtu") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("convert '" + dir.file("g.vtu") + "' '" + dir.file("k.cgr") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(read_text(dir.file("k.cgr")), read_text(dir.file("g.cgr")));
	write_text(dir.file("bad.cg"), "# D:3 NV:1 NE:1\nv 0 0 0\ne 0 1\n");
	r = run_tool("info '" + dir.file("bad.cg") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("bad.cg:3: vertex index 1 out of range"), std::string::npos) << r.err;
}

TEST(Tool, NonManifoldInfoAndConvertKeepTheFileWhole)
{
	TempDir dir;
	const std::string file = cgogn_test_data::path("surface/icositetrachoron_2skeleton.off");
	ToolRun r = run_tool("info --json '" + file + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["map"], "IncidenceGraph");
	EXPECT_EQ(j["vertices"], 24);
	EXPECT_EQ(j["edges"], 96);
	EXPECT_EQ(j["faces"], 96);
	EXPECT_EQ(j["euler_characteristic"], 24);
	EXPECT_EQ(j["connected_components"], 1);
	EXPECT_EQ(j["nonmanifold_edges"], 96);
	EXPECT_EQ(j["max_faces_per_edge"], 3);
	// the repaired map's figures beside the true ones
	// no orientation glues its triangles two by two: the repaired map is a
	// GMap2, its vertices split into 112 and its edges into 192
	EXPECT_EQ(j["repaired_map"]["map"], "GMap2");
	EXPECT_EQ(j["repaired_map"]["vertices"], 112);
	EXPECT_EQ(j["repaired_map"]["edges"], 192);
	EXPECT_EQ(j["repaired_map"]["connected_components"], 18);

	// convert keeps it whole, in another surface format and as .ig
	r = run_tool("convert '" + file + "' '" + dir.file("c.ply") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("convert '" + dir.file("c.ply") + "' '" + dir.file("c.ig") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("info --json '" + dir.file("c.ig") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["vertices"], 24);
	EXPECT_EQ(j["edges"], 96);
	EXPECT_EQ(j["faces"], 96);
	r = run_tool("check '" + dir.file("c.ig") + "'", dir);
	EXPECT_EQ(r.status, 0) << r.err;
	r = run_tool("convert '" + dir.file("c.ig") + "' '" + dir.file("d.off") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	IncidenceGraph a, b;
	io::load_surface(a, file);
	io::load_surface(b, dir.file("d.off"));
	EXPECT_EQ(nb_cells<IncidenceGraph::Edge>(b), 96u);
	std::vector<uint32> fa, fb;
	foreach_cell(a, [&](IncidenceGraph::Face f) {
		foreach_incident_vertex(a, f, [&](IncidenceGraph::Vertex v) { fa.push_back(v.dart.index); });
	});
	foreach_cell(b, [&](IncidenceGraph::Face f) {
		foreach_incident_vertex(b, f, [&](IncidenceGraph::Vertex v) { fb.push_back(v.dart.index); });
	});
	EXPECT_EQ(fa, fb);

	// a manifold file keeps today's report
	r = run_tool("info --json '" + cgogn_test_data::path("surface/hemisphere.off") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(nlohmann::json::parse(r.out)["map"], "CMap2");
}

TEST(Tool, WholeMapFilesAreInspectedCheckedAndConverted)
{
	TempDir dir;
	const auto info = [&](const std::string& file) { return info_json(dir.file(file), dir); };
	// a surface: the .cgmap gives the counts of the mesh it was made from,
	// and converts back to the same file
	ToolRun r = run_tool("convert '" + example_mesh() + "' '" + dir.file("spot.cgmap") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	nlohmann::json j = info("spot.cgmap");
	EXPECT_EQ(j["format"], "cgmap");
	EXPECT_EQ(j["map"], "CMap2");
	EXPECT_EQ(j["vertices"], 188);
	EXPECT_EQ(j["faces"], 180);
	EXPECT_EQ(j["face_degrees"]["5"], 16);
	converted_and_checked(dir.file("spot.cgmap"), dir.file("spot.obj"), dir);
	converted_and_checked(dir.file("spot.obj"), dir.file("spot2.cgmap"), dir);
	EXPECT_EQ(read_text(dir.file("spot2.cgmap")), read_text(dir.file("spot.cgmap")));
	// a non-orientable surface is kept whole, in a GMap2
	r = run_tool("convert '" + std::string(CGOGN_DATA_DIR) + "/surface/klein_bottle.off' '" + dir.file("k.cgmap") + "'",
				 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	j = info("k.cgmap");
	EXPECT_EQ(j["map"], "GMap2");
	EXPECT_EQ(j["orientable"], false);
	// a volume mesh, a map of any dimension and a graph
	CMap3 m;
	build_with_positions(m, tet_grid_soup(2, 2, 2));
	io::save_volume(m, dir.file("g.mesh"));
	converted_and_checked(dir.file("g.mesh"), dir.file("g.cgmap"), dir);
	j = info("g.cgmap");
	EXPECT_EQ(j["map"], "CMap3");
	EXPECT_EQ(j["volumes"], 48);
	converted_and_checked(dir.file("g.cgmap"), dir.file("g.vtu"), dir);
	EXPECT_EQ(info("g.vtu")["volumes"], 48);
	CMapN<4> grid;
	generate_cube_grid(grid, 2);
	io::save_nmap(grid, dir.file("grid.nmap"));
	converted_and_checked(dir.file("grid.nmap"), dir.file("grid.cgmap"), dir);
	EXPECT_EQ(info("grid.cgmap")["f_vector"], (std::vector<uint32>{81, 216, 216, 96, 16}));
	write_text(dir.file("p.cg"), "# D:3 NV:3 NE:2\nv 0 0 0\nv 1 0 0\nv 2 0 0\ne 0 1\ne 1 2\n");
	converted_and_checked(dir.file("p.cg"), dir.file("p.cgmap"), dir);
	EXPECT_EQ(info("p.cgmap")["map"], "Graph");
	// errors: a damaged file, an incidence graph, a type of map no command takes
	std::string bytes = read_text(dir.file("g.cgmap"));
	write_text(dir.file("cut.cgmap"), bytes.substr(0, bytes.size() / 2));
	r = run_tool("info '" + dir.file("cut.cgmap") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("cut.cgmap: byte "), std::string::npos) << r.err;
	write_text(dir.file("t.ig"), "IG 3 3 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\ne 0 1\ne 1 2\ne 2 0\nf 3 0 1 2\n");
	r = run_tool("convert '" + dir.file("t.ig") + "' '" + dir.file("t.cgmap") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("not a map"), std::string::npos) << r.err;
	CMap1 polygon;
	add_face(polygon, 3);
	io::save_map(polygon, dir.file("c1.cgmap"));
	r = run_tool("info '" + dir.file("c1.cgmap") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("a map of type CMap1"), std::string::npos) << r.err;
}

TEST(Tool, PolyhedraAreInspectedAndConverted)
{
	TempDir dir;
	// two pentagonal prisms, stacked
	const PolyhedronSoup p = prism_column_soup(5, 2);
	CMap3 m;
	build_with_positions(m, p);
	io::save_volume(m, dir.file("p.vtu"));
	const nlohmann::json j = converted_and_checked(dir.file("p.vtu"), dir.file("p.vtk"), dir);
	EXPECT_EQ(j["ok"], true);
	const nlohmann::json info = info_json(dir.file("p.vtk"), dir);
	EXPECT_EQ(info["volumes"], 2);
	EXPECT_EQ(info["cell_kinds"]["other"], 2);
	EXPECT_EQ(info["faces"], 13); // 7 + 7, the middle pentagon shared
	ToolRun r = run_tool("convert '" + dir.file("p.vtk") + "' '" + dir.file("p.mesh") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("not tetrahedra, pyramids, prisms or hexahedra"), std::string::npos) << r.err;
	// an .ovm file: what it holds beyond the map is listed
	write_text(dir.file("e.ovm"), "OVM ASCII\nVertices\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\nEdges\n6\n0 1\n1 2\n2 0\n"
								  "0 3\n1 3\n2 3\nFaces\n4\n3 0 2 4\n3 0 8 7\n3 2 10 9\n3 4 6 11\nPolyhedra\n1\n4 "
								  "0 3 5 7\neprop int \"w\"\n1 2 3 4 5 6\n");
	const nlohmann::json ovm = info_json(dir.file("e.ovm"), dir);
	EXPECT_EQ(ovm["format"], "OVM");
	EXPECT_EQ(ovm["volumes"], 1);
	ASSERT_EQ(ovm["not_loaded"].size(), 1u);
	EXPECT_NE(ovm["not_loaded"][0].get<std::string>().find("eprop 'w'"), std::string::npos);
	r = run_tool("info '" + dir.file("e.ovm") + "'", dir);
	EXPECT_NE(r.out.find("not_loaded: [\"eprop 'w'"), std::string::npos) << r.out;
}

} // namespace cgogn_test_tool
