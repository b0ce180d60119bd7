// SPDX-License-Identifier: MIT
// The modeling subcommands of the `cgogn` program, run as a user would.
#include <cgogn/cgogn.h>

#include "../io/io_test_utils.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <limits>
#include <sys/wait.h>

namespace cgogn_test_tool_subdivide
{

using namespace cgogn;
using namespace cgogn::io_test;

namespace
{

const std::string spot = std::string(CGOGN_EXAMPLE_DATA_DIR) + "/spot_control_mesh.obj";

} // namespace

TEST(ToolSubdivide, CatmullClarkTwiceOnSpot)
{
	TempDir dir;
	const ToolRun r = run_tool("subdivide " + quoted(spot) + " " + quoted(dir.file("out.off")) +
								   " --scheme catmull-clark --iterations 2",
							   dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "") << "no progress output when stderr is not a terminal";
	CMap2 m;
	io::load_surface(m, dir.file("out.off"));
	// 180 faces of total degree 732 -> 732 quads -> 2928 quads
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 2928u);
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), 2930u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(ToolSubdivide, LoopOnPolygonsIsAClearError)
{
	TempDir dir;
	const ToolRun r = run_tool("subdivide " + quoted(spot) + " " + quoted(dir.file("out.off")) + " --scheme loop", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("spot_control_mesh.obj"), std::string::npos) << r.err;
	EXPECT_NE(r.err.find("triangle"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("out.off")));
	const ToolRun s =
		run_tool("subdivide " + quoted(spot) + " " + quoted(dir.file("out.off")) + " --scheme sqrt3", dir);
	EXPECT_EQ(s.status, 2);
	EXPECT_NE(s.err.find("triangle"), std::string::npos) << s.err;
}

TEST(ToolSubdivide, LoopAndSqrt3OnTriangles)
{
	TempDir dir;
	CMap2 t;
	{
		const SurfaceSoup s = sphere_soup(8, 6, true);
		const BuildReport b = build_surface(t, s);
		auto pos = add_attribute<Vec3, CMap2::Vertex>(t, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[b.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		io::save_surface(t, dir.file("sphere.ply"));
	}
	const uint32 v = nb_cells<CMap2::Vertex>(t), e = nb_cells<CMap2::Edge>(t), f = nb_cells<CMap2::Face>(t);
	ToolRun r = run_tool(
		"subdivide " + quoted(dir.file("sphere.ply")) + " " + quoted(dir.file("loop.obj")) + " --scheme loop", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap2 l;
	io::load_surface(l, dir.file("loop.obj"));
	EXPECT_EQ(nb_cells<CMap2::Vertex>(l), v + e);
	EXPECT_EQ(nb_cells<CMap2::Face>(l), 4 * f);
	r = run_tool("subdivide " + quoted(dir.file("sphere.ply")) + " " + quoted(dir.file("s3.ply")) +
					 " --scheme sqrt3 -n 2 --binary",
				 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap2 s3;
	io::load_surface(s3, dir.file("s3.ply"));
	EXPECT_EQ(nb_cells<CMap2::Face>(s3), 9 * f);
	EXPECT_TRUE(check_integrity(s3).ok());
}

TEST(ToolSubdivide, TetMeshAndWrongKinds)
{
	TempDir dir;
	CMap3 g;
	{
		const VolumeSoup s = tet_grid_soup(1, 1, 2);
		const BuildReport b = build_volume(g, s);
		auto pos = add_attribute<Vec3, CMap3::Vertex>(g, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[b.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		io::save_volume(g, dir.file("grid.mesh"));
	}
	ToolRun r = run_tool(
		"subdivide " + quoted(dir.file("grid.mesh")) + " " + quoted(dir.file("fine.vtu")) + " --scheme tet", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap3 fine;
	io::load_volume(fine, dir.file("fine.vtu"));
	EXPECT_EQ(nb_cells<CMap3::Volume>(fine), 8 * nb_cells<CMap3::Volume>(g));
	EXPECT_TRUE(check_integrity(fine).ok());
	// hexahedral refinement of tetrahedra, a surface scheme on a volume file
	r = run_tool("subdivide " + quoted(dir.file("grid.mesh")) + " " + quoted(dir.file("x.mesh")) + " --scheme hex",
				 dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("hexahedron"), std::string::npos) << r.err;
	r = run_tool("subdivide " + quoted(dir.file("grid.mesh")) + " " + quoted(dir.file("x.off")) + " --scheme loop",
				 dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("volume"), std::string::npos) << r.err;
}

// A surface that cannot be oriented is subdivided or triangulated whole
// (through a GMap2), not cut apart as a CMap2 would cut it.
TEST(ToolSubdivide, NonOrientableSurfacesStayWhole)
{
	TempDir dir;
	const std::string klein = std::string(CGOGN_DATA_DIR) + "/surface/klein_bottle.off";
	const std::string mobius = std::string(CGOGN_DATA_DIR) + "/surface/mobius_strip.off";
	const ToolRun r = run_tool("subdivide " + quoted(klein) + " " + quoted(dir.file("k.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	GMap2 k;
	const io::LoadReport rk = io::load_surface(k, dir.file("k.off"));
	EXPECT_FALSE(rk.orientable);
	EXPECT_EQ(nb_cells<GMap2::Face>(k), 4u * 128u);
	EXPECT_EQ(nb_cells<GMap2::Vertex>(k), 128u + 256u + 128u);
	EXPECT_EQ(euler_characteristic(k), 0);
	EXPECT_EQ(nb_boundary_components(k), 0u);
	EXPECT_TRUE(check_integrity(k).ok());

	const ToolRun t = run_tool("triangulate " + quoted(mobius) + " " + quoted(dir.file("m.obj")), dir);
	ASSERT_EQ(t.status, 0) << t.err;
	const ToolRun l =
		run_tool("subdivide " + quoted(dir.file("m.obj")) + " " + quoted(dir.file("m2.off")) + " --scheme loop", dir);
	ASSERT_EQ(l.status, 0) << l.err;
	GMap2 m;
	EXPECT_FALSE(io::load_surface(m, dir.file("m2.off")).orientable);
	EXPECT_EQ(nb_cells<GMap2::Face>(m), 4u * 48u);
	EXPECT_EQ(euler_characteristic(m), 0);
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_FALSE(is_orientable(m));
	EXPECT_TRUE(check_integrity(m).ok());

	// smoothing moves the vertices of the whole Klein bottle, none cut off
	for (const char* method : {"laplacian", "taubin", "bilateral", "implicit"})
	{
		const ToolRun sm =
			run_tool("smooth " + quoted(klein) + " " + quoted(dir.file("s.off")) + " --method " + method, dir);
		ASSERT_EQ(sm.status, 0) << method << ": " << sm.err;
		GMap2 s, k0;
		EXPECT_FALSE(io::load_surface(s, dir.file("s.off")).orientable) << method;
		io::load_surface(k0, klein);
		EXPECT_EQ(nb_cells<GMap2::Vertex>(s), 128u) << method;
		EXPECT_EQ(nb_cells<GMap2::Face>(s), 128u) << method;
		EXPECT_EQ(euler_characteristic(s), 0) << method;
		auto p = get_attribute<Vec3, GMap2::Vertex>(s, "position");
		auto p0 = get_attribute<Vec3, GMap2::Vertex>(k0, "position");
		double moved = 0.0;
		for (uint32 i = 0; i < 128; ++i)
			moved = std::max(moved, ((*p)[i] - (*p0)[i]).norm());
		EXPECT_GT(moved, 1e-3) << method;
	}
}

namespace
{

// The positions of the vertices of a surface.
template <typename MAP>
std::vector<Vec3> vertex_positions(const MAP& m)
{
	auto pos = get_attribute<Vec3, typename MAP::Vertex>(m, "position");
	std::vector<Vec3> p;
	foreach_cell(m, [&](typename MAP::Vertex v) { p.push_back(value<Vec3>(m, *pos, v)); });
	return p;
}

// The largest distance from a point of a to the nearest point of b, and
// from b to a: 0 for the same points in any order.
double distance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
	const auto one_way = [](const std::vector<Vec3>& x, const std::vector<Vec3>& y) {
		double d = 0.0;
		for (const Vec3& p : x)
		{
			double nearest = std::numeric_limits<double>::infinity();
			for (const Vec3& q : y)
				nearest = std::min(nearest, (p - q).norm());
			d = std::max(d, nearest);
		}
		return d;
	};
	return std::max(one_way(a, b), one_way(b, a));
}

// Every level k of the MRMap2 file is the surface `in` subdivided k times
// by the scheme: the same f-vector and positions (to 1e-9).
void expect_levels_of_the_scheme(const std::string& in, const std::string& file, modeling::SurfaceScheme scheme,
								 uint32 nb_levels)
{
	MRMap2 h{CMap2()};
	io::load_map(h, file);
	ASSERT_EQ(max_level(h), nb_levels);
	EXPECT_EQ(current_level(h), nb_levels);
	EXPECT_FALSE((get_attribute<Vec3, MRMap2::Vertex>(h, "details"))) << "the synthesis' details are not written";
	for (uint32 k = 0; k <= nb_levels; ++k)
	{
		SCOPED_TRACE("level " + std::to_string(k));
		CMap2 flat;
		io::load_surface(flat, in);
		if (k > 0)
			modeling::subdivide(flat, *get_attribute<Vec3, CMap2::Vertex>(flat, "position"), scheme, k);
		const MRLevelView2 v = level_view(h, k);
		EXPECT_EQ(f_vector(v), f_vector(flat));
		const CMap2 level = extract_level(h, k);
		const std::vector<Vec3> a = vertex_positions(level), b = vertex_positions(flat);
		ASSERT_EQ(a.size(), b.size());
		EXPECT_LT(distance(a, b), 1e-9);
	}
}

} // namespace

TEST(ToolSubdivide, KeepLevelsWritesEveryLevelOfTheScheme)
{
	TempDir dir;
	// Catmull-Clark on spot's control mesh (triangles, quads, pentagons)
	ToolRun r = run_tool("subdivide " + quoted(spot) + " " + quoted(dir.file("cc.cgmap")) +
							 " --scheme catmull-clark --levels 2 --keep-levels",
						 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "");
	EXPECT_EQ(io::read_map_header(dir.file("cc.cgmap")).map_type, "MRMap2");
	expect_levels_of_the_scheme(spot, dir.file("cc.cgmap"), modeling::SurfaceScheme::CatmullClark, 2);
	// Loop on a sphere of triangles with boundary
	CMap2 t;
	io_test::build_with_positions(t, sphere_soup(8, 6, true));
	io::save_surface(t, dir.file("sphere.ply"));
	r = run_tool("subdivide " + quoted(dir.file("sphere.ply")) + " " + quoted(dir.file("loop.cgmap")) +
					 " --scheme loop -n 3 --keep-levels --origin parent",
				 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	expect_levels_of_the_scheme(dir.file("sphere.ply"), dir.file("loop.cgmap"), modeling::SurfaceScheme::Loop, 3);
	MRMap2 h{CMap2()};
	io::load_map(h, dir.file("loop.cgmap"));
	auto parent = get_attribute<uint32, MRMap2::Face>(h, "parent");
	ASSERT_TRUE(parent);
	std::vector<uint32> seen(nb_cells<CMap2::Face>(t), 0);
	foreach_cell(h, [&](MRMap2::Face f) { ++seen.at(value<uint32>(h, *parent, f)); });
	EXPECT_EQ(seen, std::vector<uint32>(seen.size(), 64u)) << "each input face has 4^3 faces at level 3";
}

TEST(ToolSubdivide, KeepLevelsRefusals)
{
	TempDir dir;
	const auto refused = [&](const std::string& args, const std::string& message) {
		const ToolRun r = run_tool("subdivide " + args, dir);
		EXPECT_EQ(r.status, 2) << args;
		EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
	};
	const std::string out = quoted(dir.file("out.cgmap"));
	refused(
		quoted(spot) + " " + out + " --scheme sqrt3 --keep-levels",
		"--keep-levels: the scheme sqrt3 makes no multiresolution levels (loop, catmull-clark, hex and tetra-octa do)");
	refused(quoted(spot) + " " + out + " --scheme tet --keep-levels",
			"--keep-levels: the scheme tet makes no multiresolution levels");
	refused(quoted(spot) + " " + quoted(dir.file("out.off")) + " --keep-levels", "the output must be a .cgmap file");
	refused(quoted(spot) + " " + out + " --scheme hex --keep-levels", "not a volume format");
	refused(quoted(std::string(CGOGN_DATA_DIR) + "/volume/armadillo_tet_4k.mesh") + " " + out +
				" --scheme hex --keep-levels",
			"not a hexahedron");
	refused(quoted(spot) + " " + out + " --scheme loop --keep-levels", "triangle");
	refused(quoted(std::string(CGOGN_DATA_DIR) + "/surface/klein_bottle.off") + " " + out + " --keep-levels",
			"not orientable");
	EXPECT_FALSE(std::filesystem::exists(dir.file("out.cgmap")));
	EXPECT_FALSE(std::filesystem::exists(dir.file("out.off")));
}

TEST(ToolSubdivide, InfoRenderAndViewReadTheLevels)
{
	TempDir dir;
	const std::string h = quoted(dir.file("h.cgmap"));
	ToolRun r = run_tool("subdivide " + quoted(spot) + " " + h + " -n 2 --keep-levels", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	// info: the levels, the current one, darts and f-vector per level, the attributes
	r = run_tool("info --json " + h, dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["map"], "MRMap2");
	EXPECT_EQ(j["format"], "cgmap");
	EXPECT_EQ(j["max_level"], 2);
	EXPECT_EQ(j["current_level"], 2);
	ASSERT_EQ(j["levels"].size(), 3u);
	EXPECT_EQ(j["levels"][0]["f_vector"], (std::vector<uint32>{188, 366, 180}));
	EXPECT_EQ(j["levels"][0]["darts"], 732);
	EXPECT_EQ(j["levels"][1]["f_vector"], (std::vector<uint32>{734, 1464, 732}));
	EXPECT_EQ(j["levels"][1]["darts"], 4 * 732);
	EXPECT_EQ(j["levels"][2]["f_vector"], (std::vector<uint32>{2930, 5856, 2928}));
	EXPECT_EQ(j["vertices"], 2930) << "the counts are those of the current level";
	EXPECT_EQ(j["genus"], 0);
	const auto position = std::find_if(j["attributes"].begin(), j["attributes"].end(),
									   [](const nlohmann::json& a) { return a["name"] == "position"; });
	ASSERT_NE(position, j["attributes"].end()) << j["attributes"].dump();
	EXPECT_EQ((*position)["cell"], "vertex");
	EXPECT_EQ((*position)["type"], "Vec3");
	r = run_tool("info " + h, dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(r.out.find("map: MRMap2\nmax_level: 2\ncurrent_level: 2\n"), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("level 1: darts 2928, f_vector [734,1464,732]\n"), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("attributes: "), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("position (vertex, Vec3)"), std::string::npos) << r.out;
	r = run_tool("check " + h, dir);
	EXPECT_EQ(r.status, 0) << r.out << r.err;

	// render: level 0 is the input mesh; the default is the current level
	const auto render = [&](const std::string& in, const std::string& png, const std::string& more) {
		const ToolRun x =
			run_tool("render " + in + " " + quoted(dir.file(png)) + " --size 160x120 --edges" + more, dir);
		EXPECT_EQ(x.status, 0) << x.err;
		return io_test::read_text(dir.file(png));
	};
	const std::string level0 = render(h, "l0.png", " --level 0");
	EXPECT_EQ(level0, render(quoted(spot), "spot.png", ""));
	const std::string level2 = render(h, "l2.png", " --level 2");
	EXPECT_NE(level2, level0);
	EXPECT_NE(render(h, "l1.png", " --level 1"), level2);
	EXPECT_EQ(render(h, "default.png", ""), level2);

	// view: the same choice of level
	const auto view = [&](const std::string& html, const std::string& more) {
		const ToolRun x = run_tool("view " + h + " " + quoted(dir.file(html)) + " --title t" + more, dir);
		EXPECT_EQ(x.status, 0) << x.err;
		return io_test::read_text(dir.file(html));
	};
	const std::string v0 = view("v0.html", " --level 0"), v2 = view("v2.html", " --level 2");
	EXPECT_NE(v0, v2);
	EXPECT_GT(v2.size(), v0.size());
	EXPECT_EQ(view("v.html", ""), v2);

	// convert writes the current level
	r = run_tool("convert " + h + " " + quoted(dir.file("current.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap2 current;
	io::load_surface(current, dir.file("current.off"));
	EXPECT_EQ(f_vector(current), (std::vector<uint32>{2930, 5856, 2928}));

	// errors: a level above the finest, a level of a file without levels
	r = run_tool("render " + h + " " + quoted(dir.file("x.png")) + " --level 3", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--level 3: the file's finest level is 2"), std::string::npos) << r.err;
	r = run_tool("view " + h + " " + quoted(dir.file("x.html")) + " --level 5", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--level 5: the file's finest level is 2"), std::string::npos) << r.err;
	r = run_tool("render " + quoted(spot) + " " + quoted(dir.file("x.png")) + " --level 1", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("not a .cgmap file"), std::string::npos) << r.err;
	r = run_tool("convert " + quoted(spot) + " " + quoted(dir.file("flat.cgmap")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	r = run_tool("render " + quoted(dir.file("flat.cgmap")) + " " + quoted(dir.file("x.png")) + " --level 1", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--level applies to multiresolution maps; the file holds a CMap2"), std::string::npos)
		<< r.err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("x.png")));
	EXPECT_FALSE(std::filesystem::exists(dir.file("x.html")));
	// a flat .cgmap file is drawn as it is
	EXPECT_EQ(render(quoted(dir.file("flat.cgmap")), "flat.png", ""), level0);
}

TEST(ToolSubdivide, HexKeepLevelsWritesAHexahedralHierarchy)
{
	TempDir dir;
	const std::string liver = std::string(CGOGN_DATA_DIR) + "/volume/liver_hex_624.mesh";
	const std::string h = quoted(dir.file("liver.cgmap"));
	ToolRun r = run_tool("subdivide " + quoted(liver) + " " + h + " --scheme hex -n 1 --keep-levels", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(io::read_map_header(dir.file("liver.cgmap")).map_type, "MRMap3");
	// level 1 has the cells and points of one flat hex_subdivision step
	MRMap3 m{CMap3()};
	io::load_map(m, dir.file("liver.cgmap"));
	ASSERT_EQ(max_level(m), 1u);
	EXPECT_EQ(current_level(m), 1u);
	CMap3 flat;
	io::load_volume(flat, liver);
	auto fpos = get_attribute<Vec3, CMap3::Vertex>(flat, "position");
	modeling::hex_subdivision(flat, *fpos);
	const CMap3 level = extract_level(m, 1);
	EXPECT_EQ(f_vector(level), f_vector(flat));
	EXPECT_LT(distance(vertex_positions(level), vertex_positions(flat)), 1e-9);
	// info and render read its levels
	r = run_tool("info --json " + h, dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const nlohmann::json j = nlohmann::json::parse(r.out);
	EXPECT_EQ(j["map"], "MRMap3");
	EXPECT_EQ(j["max_level"], 1);
	ASSERT_EQ(j["levels"].size(), 2u);
	EXPECT_EQ(j["levels"][0]["f_vector"][3], 624);
	EXPECT_EQ(j["levels"][1]["f_vector"][3], 8 * 624);
	const auto render = [&](const std::string& in, const std::string& png, const std::string& more) {
		const ToolRun x = run_tool("render " + in + " " + quoted(dir.file(png)) + " --size 160x120" + more, dir);
		EXPECT_EQ(x.status, 0) << x.err;
		return io_test::read_text(dir.file(png));
	};
	EXPECT_EQ(render(h, "l0.png", " --level 0"), render(quoted(liver), "liver.png", ""));
	EXPECT_NE(render(h, "l1.png", " --level 1"), render(h, "l0b.png", " --level 0"));
}

TEST(ToolSubdivide, TetraOctaLevelsOfATetrahedralMesh)
{
	TempDir dir;
	// the 48 tetrahedra of a 2 x 2 x 2 grid of cubes
	{
		const VolumeSoup s = tet_grid_soup(2, 2, 2);
		CMap3 grid;
		const BuildReport b = build_volume(grid, s);
		auto pos = add_attribute<Vec3, CMap3::Vertex>(grid, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[b.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		io::save_volume(grid, dir.file("grid.mesh"));
	}
	const std::string grid = quoted(dir.file("grid.mesh")), h = quoted(dir.file("grid.cgmap"));
	ToolRun r = run_tool("subdivide " + grid + " " + h + " --scheme tetra-octa -n 2 --keep-levels", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	MRMap3 m{CMap3()};
	io::load_map(m, dir.file("grid.cgmap"));
	ASSERT_EQ(max_level(m), 2u);
	EXPECT_TRUE(check_integrity(m).ok());
	r = run_tool("info --json " + h, dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const nlohmann::json j = nlohmann::json::parse(r.out);
	ASSERT_EQ(j["levels"].size(), 3u);
	// 48 tetrahedra; 4 x 48 and 48 octahedra; 24 x 48 and 10 x 48
	EXPECT_EQ(j["levels"][0]["f_vector"][3], 48);
	EXPECT_EQ(j["levels"][1]["f_vector"][3], 5 * 48);
	EXPECT_EQ(j["levels"][2]["f_vector"][3], 34 * 48);

	// without levels: the finest level, its octahedra as polyhedra
	r = run_tool("subdivide " + grid + " " + quoted(dir.file("out.vtu")) + " --scheme tetra-octa", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap3 flat;
	io::load_volume(flat, dir.file("out.vtu"));
	EXPECT_TRUE(check_integrity(flat).ok());
	const CMap3 level = extract_level(m, 1);
	EXPECT_EQ(f_vector(flat), f_vector(level));
	EXPECT_LT(distance(vertex_positions(flat), vertex_positions(level)), 1e-9);
	// octahedra do not fit a MEDIT file; hexahedra are not refined so
	r = run_tool("subdivide " + grid + " " + quoted(dir.file("out.mesh")) + " --scheme tetra-octa", dir);
	EXPECT_EQ(r.status, 2);
	const std::string liver = std::string(CGOGN_DATA_DIR) + "/volume/liver_hex_624.mesh";
	r = run_tool(
		"subdivide " + quoted(liver) + " " + quoted(dir.file("l.cgmap")) + " --scheme tetra-octa --keep-levels", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("neither a tetrahedron nor an octahedron"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("l.cgmap")));
}

} // namespace cgogn_test_tool_subdivide
