// SPDX-License-Identifier: MIT
// `cgogn render` run as a program: a surface and a volume mesh from the test
// data give valid PNG pictures; bad input exits 2 and writes nothing.
#include "../io/io_test_utils.h"
#include "render_test_utils.h"

#include <cgogn_test_data.h>

namespace cgogn_test_tool_render
{

using namespace cgogn;
using namespace cgogn::io_test;
using namespace cgogn::render_test;

namespace
{

/// Distinct colours in a picture (capped at 1000).
std::size_t nb_colours(const render::Image& img)
{
	std::set<uint32_t> s;
	for (std::size_t i = 0; i + 2 < img.rgb.size() && s.size() < 1000; i += 3)
		s.insert(uint32_t(img.rgb[i]) << 16 | uint32_t(img.rgb[i + 1]) << 8 | img.rgb[i + 2]);
	return s.size();
}

} // namespace

TEST(ToolRender, SurfaceToPng)
{
	TempDir dir;
	const std::string in = quoted(cgogn_test_data::path("surface/spot_control_mesh.obj"));
	ToolRun r = run_tool("render " + in + " " + quoted(dir.file("s.png")) + " --size 300x200 --edges", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "");
	EXPECT_EQ(r.out, "");
	const render::Image img = read_png(dir.file("s.png"));
	ASSERT_EQ(img.width, 300u);
	ASSERT_EQ(img.height, 200u);
	EXPECT_EQ(img.at(0, 0), (render::Rgb{255, 255, 255}));
	EXPECT_GT(nb_colours(img), 20u);

	r = run_tool("render " + in + " " + quoted(dir.file("c.png")) +
					 " --size 300x200 --view z --azimuth 30 --elevation 20 --shading flat --ssaa 1 --color "
					 "curvature --background 0,0,0 --show-defects",
				 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const render::Image c = read_png(dir.file("c.png"));
	ASSERT_EQ(c.width, 300u);
	EXPECT_EQ(c.at(0, 0), (render::Rgb{0, 0, 0}));
	EXPECT_NE(c.rgb, img.rgb);

	// an explicit colour range changes the colours
	r = run_tool("render " + in + " " + quoted(dir.file("r.png")) +
					 " --size 300x200 --view z --azimuth 30 --elevation 20 --shading flat --ssaa 1 --color "
					 "curvature --background 0,0,0 --show-defects --range -100 100",
				 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(read_png(dir.file("r.png")).rgb, c.rgb);
}

TEST(ToolRender, VolumeBoundaryToPng)
{
	TempDir dir;
	const std::string in = quoted(cgogn_test_data::path("volume/liver_hex_624.mesh"));
	const ToolRun r = run_tool("render " + in + " " + quoted(dir.file("v.png")) + " --size 120x90 --color area", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const render::Image img = read_png(dir.file("v.png"));
	ASSERT_EQ(img.width, 120u);
	ASSERT_EQ(img.height, 90u);
	EXPECT_GT(nb_colours(img), 20u);
}

TEST(ToolRender, BadInputExits2AndWritesNothing)
{
	TempDir dir;
	const std::string out = dir.file("o.png");
	write_text(dir.file("empty.off"), "OFF\n0 0 0\n");
	ToolRun r = run_tool("render " + quoted(dir.file("empty.off")) + " " + quoted(out), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("empty.off"), std::string::npos) << r.err;
	EXPECT_NE(r.err.find("no face"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(out));

	write_text(dir.file("nan.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n");
	r = run_tool("render " + quoted(dir.file("nan.off")) + " " + quoted(out), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("nan.off"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(out));

	const std::string spot = quoted(cgogn_test_data::path("surface/spot_control_mesh.obj"));
	r = run_tool("render " + spot + " " + quoted(out) + " --color nope", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("'nope'"), std::string::npos) << r.err;
	EXPECT_NE(r.err.find("available"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(out));

	r = run_tool("render " + spot + " " + quoted(out) + " --color curvature --range 2 1", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("range"), std::string::npos) << r.err;
	r = run_tool("render " + spot + " " + quoted(out) + " --range 1", dir);
	EXPECT_EQ(r.status, 2);
	r = run_tool("render " + spot + " " + quoted(out) + " --size 0x10", dir);
	EXPECT_EQ(r.status, 2);
	r = run_tool("render " + spot + " " + quoted(out) + " --ssaa 9", dir);
	EXPECT_EQ(r.status, 2);
	r = run_tool("render " + spot + " " + quoted(out) + " --background pink", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_FALSE(std::filesystem::exists(out));

	r = run_tool("render " + spot + " " + quoted(dir.file("no/such/dir.png")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("dir.png"), std::string::npos) << r.err;
}

TEST(ToolRender, NonManifoldSurfaceAndGraph)
{
	TempDir dir;
	const std::string skeleton = quoted(cgogn_test_data::path("surface/icositetrachoron_2skeleton.off"));
	ToolRun r =
		run_tool("render " + skeleton + " " + quoted(dir.file("nm.png")) + " --size 200x200 --show-defects", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const render::Image nm = read_png(dir.file("nm.png"));
	ASSERT_EQ(nm.width, 200u);
	uint32_t red = 0;
	for (uint32_t y = 0; y < nm.height; ++y)
		for (uint32_t x = 0; x < nm.width; ++x)
			red += nm.at(x, y) == render::Rgb{230, 25, 25};
	EXPECT_GT(red, 100u) << "every edge has three faces: the edges are red";

	write_text(dir.file("tree.cg"), "# D:3 NV:4 NE:3\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ne 0 1\ne 0 2\ne 0 3\n");
	r = run_tool("render " + quoted(dir.file("tree.cg")) + " " + quoted(dir.file("tree.png")) + " --size 200x150", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_GT(nb_colours(read_png(dir.file("tree.png"))), 5u) << "shaded tubes";
	r = run_tool("render " + quoted(dir.file("tree.cg")) + " " + quoted(dir.file("lines.png")) +
					 " --size 200x150 --lines --ssaa 1",
				 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_LE(nb_colours(read_png(dir.file("lines.png"))), 2u) << "lines only: the background and the edge colour";
	r = run_tool("render " + quoted(dir.file("tree.cg")) + " " + quoted(dir.file("x.png")) + " --color area", dir);
	EXPECT_NE(r.status, 0);
	EXPECT_NE(r.err.find("tree.cg"), std::string::npos) << r.err;
}

} // namespace cgogn_test_tool_render
