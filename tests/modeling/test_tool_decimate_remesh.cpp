// SPDX-License-Identifier: MIT
// `cgogn decimate` and `cgogn remesh`, run as a user would.
#include <cgogn/cgogn.h>

#include "../geometry/geometry_test_meshes.h"
#include "../io/io_test_utils.h"

#include <gtest/gtest.h>

#include <sys/wait.h>

namespace cgogn_test_tool_decimate_remesh
{

using namespace cgogn;
using namespace cgogn::io_test;

namespace
{

uint32 count_faces(const CMap2& m)
{
	uint32 n = 0;
	foreach_cell(m, [&](CMap2::Face) { ++n; });
	return n;
}

/// A closed triangulated sphere of 3968 faces, saved as OFF.
std::string sphere_file(const TempDir& dir)
{
	CMap2 m;
	test::build_with_positions(m, sphere_soup(64, 32, true));
	const std::string path = dir.file("sphere.off");
	io::save_surface(m, path);
	return path;
}

} // namespace

TEST(ModelingTool, DecimateToAFaceCountAndARatio)
{
	TempDir dir;
	const std::string in = sphere_file(dir);
	ToolRun r = run_tool("decimate '" + in + "' '" + dir.file("a.obj") + "' --faces 1000", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "") << "no progress output when stderr is not a terminal";
	CMap2 a;
	io::load_surface(a, dir.file("a.obj"));
	EXPECT_EQ(count_faces(a), 1000u);
	EXPECT_TRUE(check_integrity(a).ok());

	r = run_tool("decimate '" + in + "' '" + dir.file("b.ply") + "' --ratio 0.25 --midedge --keep-boundary", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap2 b;
	io::load_surface(b, dir.file("b.ply"));
	EXPECT_EQ(count_faces(b), 992u);
}

TEST(ModelingTool, DecimateErrors)
{
	TempDir dir;
	const std::string in = sphere_file(dir);
	ToolRun r = run_tool("decimate '" + in + "' '" + dir.file("o.off") + "' --ratio 1.5", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--ratio"), std::string::npos) << r.err;
	r = run_tool("decimate '" + in + "' '" + dir.file("o.off") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--faces"), std::string::npos) << r.err;
	r = run_tool("decimate '" + in + "' '" + dir.file("o.off") + "' --faces 10 --ratio 0.5", dir);
	EXPECT_EQ(r.status, 2);
	// quads are refused with a message, and nothing is written
	CMap2 q;
	test::build_with_positions(q, test::box_soup());
	io::save_surface(q, dir.file("box.off"));
	r = run_tool("decimate '" + dir.file("box.off") + "' '" + dir.file("o.off") + "' --faces 4", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("triangulated"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("o.off")));
	r = run_tool("remesh '" + dir.file("box.off") + "' '" + dir.file("o.off") + "'", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("triangulated"), std::string::npos) << r.err;
	r = run_tool("remesh '" + in + "' '" + dir.file("o.off") + "' --edge-length -1", dir);
	EXPECT_EQ(r.status, 2);
}

TEST(ModelingTool, RemeshToAnEdgeLength)
{
	TempDir dir;
	const std::string in = sphere_file(dir);
	const ToolRun r = run_tool("remesh '" + in + "' '" + dir.file("r.off") + "' --edge-length 0.15 -n 5", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap2 m;
	io::load_surface(m, dir.file("r.off"));
	auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_NEAR(geometry::mean_edge_length(m, *pos), 0.15, 0.015);
}

} // namespace cgogn_test_tool_decimate_remesh
