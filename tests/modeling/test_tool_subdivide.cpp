// SPDX-License-Identifier: MIT
// The modeling subcommands of the `cgogn` program, run as a user would.
#include <cgogn/cgogn.h>

#include "../io/io_test_utils.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <sys/wait.h>

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
