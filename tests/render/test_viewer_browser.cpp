// SPDX-License-Identifier: MIT
// The page of the HTML viewer in a real browser: headless Chromium (Debian
// package chromium, software WebGL through SwiftShader) opens a page from a
// file:// URL and takes a screenshot, in which the mesh must be drawn in
// the middle; without WebGL, the page must show its message instead. The
// tests skip when chromium is not installed (scripts/install-deps.sh
// installs it).
#include "../io/io_test_utils.h"
#include "render_test_utils.h"

#include <cstdlib>
#include <filesystem>

namespace cgogn_test_viewer_browser
{

using namespace cgogn;
using namespace cgogn::io_test;
using namespace cgogn::render_test;

namespace
{

/// The Chromium program in PATH, empty when there is none.
std::string chromium()
{
	for (const char* name : {"chromium", "chromium-browser"})
		if (std::system(("command -v " + std::string(name) + " >/dev/null 2>&1").c_str()) == 0)
			return name;
	return {};
}

/// Runs headless Chromium on the page with extra flags; its output goes to
/// `out` (with --dump-dom, the page's DOM once loaded); hash is appended to
/// the page's URL. True when it ran.
bool run_chromium(const std::string& program, const std::string& page, const std::string& flags, const TempDir& dir,
				  const std::string& out, const std::string& hash = "")
{
	const std::string cmd = "timeout 120 " + program +
							" --headless --no-sandbox --disable-gpu --disable-background-networking "
							"--disable-component-update --disable-sync --no-first-run --disable-dev-shm-usage "
							"--user-data-dir=" +
							quoted(dir.file("profile")) + " --window-size=800,600 --virtual-time-budget=10000 " +
							flags + " " + quoted("file://" + page + hash) + " >" + quoted(out) + " 2>" +
							quoted(dir.file("chromium.log"));
	return std::system(cmd.c_str()) == 0;
}

std::string sphere_page(const TempDir& dir)
{
	CMap2 m;
	build_with_positions(m, sphere_soup(48, 24, true));
	auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	const std::string page = dir.file("sphere.html");
	render::write_viewer_html(m, *pos, page);
	return page;
}

} // namespace

TEST(ViewerBrowser, TheMeshIsDrawnInTheMiddle)
{
	const std::string program = chromium();
	if (program.empty())
		GTEST_SKIP() << "chromium is not installed (Debian package chromium; scripts/install-deps.sh installs it)";
	TempDir dir;
	const std::string page = sphere_page(dir);
	const std::string shot = dir.file("shot.png");
	ASSERT_TRUE(run_chromium(program, page,
							 "--use-angle=swiftshader --enable-unsafe-swiftshader --screenshot=" + quoted(shot), dir,
							 dir.file("stdout")))
		<< read_text(dir.file("chromium.log"));
	const render::Image img = read_png(shot);
	ASSERT_EQ(img.width, 800u) << read_text(dir.file("chromium.log"));
	ASSERT_EQ(img.height, 600u);
	// the panel is in the top left corner: look right of it. The camera
	// looks at the centre of the sphere from a distance where its bounding
	// sphere (radius sqrt(3)) fits the height, so the unit sphere is a disk
	// of radius about 300 / sqrt(3) = 173 pixels around (400, 300)
	const render::Rgb white{255, 255, 255};
	uint32_t drawn = 0, x0 = 800, x1 = 0, y0 = 600, y1 = 0;
	for (uint32_t y = 0; y < img.height; ++y)
		for (uint32_t x = 300; x < img.width; ++x)
			if (distance(img.at(x, y), white) > 16)
			{
				++drawn;
				x0 = std::min(x0, x), x1 = std::max(x1, x);
				y0 = std::min(y0, y), y1 = std::max(y1, y);
			}
	EXPECT_GT(drawn, 40000u) << "the right part of a disk of radius 170";
	EXPECT_NE(img.at(400, 300), white);
	EXPECT_NEAR(0.5 * (y0 + y1), 300.0, 20.0);
	EXPECT_NEAR(x1, 400.0 + 173.0, 40.0);
	EXPECT_NEAR(y1 - y0, 2 * 173.0, 60.0);
	EXPECT_LT(img.at(400, 300).b, 250) << "shaded, not blank";

	// the page says it drew the mesh
	ASSERT_TRUE(run_chromium(program, page, "--use-angle=swiftshader --enable-unsafe-swiftshader --dump-dom", dir,
							 dir.file("dom.html")));
	EXPECT_NE(read_text(dir.file("dom.html")).find("data-state=\"ready\""), std::string::npos);
}

TEST(ViewerBrowser, WithoutWebGLThePageSaysSo)
{
	const std::string program = chromium();
	if (program.empty())
		GTEST_SKIP() << "chromium is not installed (Debian package chromium; scripts/install-deps.sh installs it)";
	TempDir dir;
	const std::string page = sphere_page(dir);
	ASSERT_TRUE(run_chromium(program, page, "--disable-webgl --disable-3d-apis --dump-dom", dir, dir.file("dom.html")))
		<< read_text(dir.file("chromium.log"));
	const std::string dom = read_text(dir.file("dom.html"));
	EXPECT_NE(dom.find("data-state=\"no-webgl\""), std::string::npos) << dom.substr(0, 2000);
	// the message element is shown: no longer `hidden`
	EXPECT_NE(dom.find("<div id=\"no-webgl\">"), std::string::npos);
	EXPECT_NE(dom.find("WebGL is not available"), std::string::npos);
}

TEST(ViewerBrowser, TheClippingPlaneShowsTheCellsItCuts)
{
	const std::string program = chromium();
	if (program.empty())
		GTEST_SKIP() << "chromium is not installed (Debian package chromium; scripts/install-deps.sh installs it)";
	TempDir dir;
	CMap3 m;
	build_with_positions(m, hex_grid_soup(4, 4, 4)); // unit cubes in [0, 4]^3
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	const std::string page = dir.file("cube.html");
	render::write_viewer_html(m, *pos, page);
	// the plane x = 2.4 (0.6 of the box), keeping x <= 2.4: the 16 cells of
	// [2, 3] are crossed and drawn whole (16 x 6 quads), the 32 cells of
	// [0, 2] show their boundary quads (16 at x = 0, 8 on each of the four
	// sides), the cells of [3, 4] are hidden: 2 x (96 + 48) of 768 triangles
	ASSERT_TRUE(run_chromium(program, page, "--use-angle=swiftshader --enable-unsafe-swiftshader --dump-dom", dir,
							 dir.file("dom.html"), "#clip=x:0.6"))
		<< read_text(dir.file("chromium.log"));
	const std::string dom = read_text(dir.file("dom.html"));
	EXPECT_NE(dom.find("data-state=\"ready\""), std::string::npos);
	EXPECT_NE(dom.find("288 of 768 triangles"), std::string::npos)
		<< dom.substr(std::min(dom.find("clip-count"), dom.size()), 100);
	// the other side (x >= 2.4): the crossed cells and the 32 boundary quads of
	// the cells of [3, 4]: 192 + 64 triangles
	ASSERT_TRUE(run_chromium(program, page, "--use-angle=swiftshader --enable-unsafe-swiftshader --dump-dom", dir,
							 dir.file("dom.html"), "#clip=x:0.6:flip"));
	EXPECT_NE(read_text(dir.file("dom.html")).find("256 of 768 triangles"), std::string::npos);
}

} // namespace cgogn_test_viewer_browser
