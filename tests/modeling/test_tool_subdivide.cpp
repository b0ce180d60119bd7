// SPDX-License-Identifier: MIT
// The modeling subcommands of the `cgogn` program, run as a user would.
#include <cgogn/cgogn.h>

#include "../io/io_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
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

} // namespace cgogn_test_tool_subdivide
