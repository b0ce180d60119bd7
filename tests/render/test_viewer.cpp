// SPDX-License-Identifier: MIT
// The HTML viewer: the page embeds the mesh (decoded here and compared with
// the map), the colour quantities, references nothing outside itself, and
// bad input is an error that writes no file; `cgogn view` run as a program.
#include "../io/io_test_utils.h"
#include "render_test_utils.h"

#include <cgogn_test_data.h>
#include <cstring>
#include <filesystem>

namespace cgogn_test_viewer
{

using namespace cgogn;
using namespace cgogn::io_test;

namespace
{

std::vector<uint8_t> base64_decode(const std::string& s)
{
	auto value = [](char c) -> int {
		if (c >= 'A' && c <= 'Z')
			return c - 'A';
		if (c >= 'a' && c <= 'z')
			return c - 'a' + 26;
		if (c >= '0' && c <= '9')
			return c - '0' + 52;
		if (c == '+')
			return 62;
		if (c == '/')
			return 63;
		return -1;
	};
	std::vector<uint8_t> out;
	uint32_t acc = 0;
	int bits = 0;
	for (char c : s)
	{
		const int v = value(c);
		if (v < 0)
			continue; // '=' padding
		acc = (acc << 6) | uint32_t(v);
		bits += 6;
		if (bits >= 8)
		{
			bits -= 8;
			out.push_back(uint8_t(acc >> bits));
		}
	}
	return out;
}

/// The text of the element with this id (empty when absent).
std::string element(const std::string& html, const std::string& id)
{
	const std::string open = "id=\"" + id + "\">";
	const std::size_t a = html.find(open);
	if (a == std::string::npos)
		return {};
	const std::size_t b = html.find("</script>", a);
	return html.substr(a + open.size(), b - a - open.size());
}

template <typename T>
std::vector<T> array(const std::string& html, const std::string& name)
{
	const std::vector<uint8_t> bytes = base64_decode(element(html, "cgogn-" + name));
	std::vector<T> v(bytes.size() / sizeof(T));
	if (!v.empty())
		std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
	EXPECT_EQ(bytes.size() % sizeof(T), 0u) << name;
	return v;
}

void expect_self_contained(const std::string& html)
{
	EXPECT_EQ(html.find("https://"), std::string::npos);
	// the only http:// text is the XHTML namespace name three.js passes to
	// createElementNS: a name, never fetched
	for (std::size_t i = html.find("http://"); i != std::string::npos; i = html.find("http://", i + 1))
		EXPECT_EQ(html.compare(i, 29, "http://www.w3.org/1999/xhtml\""), 0) << html.substr(i, 60);
	for (const char* ref : {" src=", " href=", "<link", "url(", "<iframe", "import("})
		EXPECT_EQ(html.find(ref), std::string::npos) << ref;
	EXPECT_NE(html.find("<script>"), std::string::npos) << "the script is inline";
}

} // namespace

TEST(Viewer, SurfacePageEmbedsTheMesh)
{
	CMap2 m;
	build_with_positions(m, torus_soup(12, 8)); // quads: 2 triangles each
	auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	auto attr = add_attribute<double, CMap2::Vertex>(m, "height");
	foreach_cell(m, [&](CMap2::Vertex v) { (*attr)[v] = (*pos)[v][2]; });
	render::ViewerOptions o;
	o.title = "a <torus>";
	o.color = render::ColorSource::Attribute;
	o.attribute = "height";
	const std::string html = render::viewer_html(m, *pos, o);
	EXPECT_EQ(html.rfind("<!DOCTYPE html>", 0), 0u);
	EXPECT_NE(html.find("<title>a &lt;torus&gt;</title>"), std::string::npos);

	const uint32_t nv = nb_cells<CMap2::Vertex>(m), nf = nb_cells<CMap2::Face>(m);
	const auto p = array<float>(html, "positions");
	const auto t = array<uint32_t>(html, "triangles");
	const auto flags = array<uint8_t>(html, "flags");
	ASSERT_EQ(p.size(), 3u * nv);
	ASSERT_EQ(t.size(), 3u * 2u * nf);
	EXPECT_EQ(flags.size(), 2u * nf);
	for (uint32_t i : t)
		EXPECT_LT(i, nv);
	// the first face of the map is the first two triangles, a fan from its
	// first vertex: their corners carry the face's positions
	std::vector<Vec3> corners;
	foreach_cell(m, [&](CMap2::Face f) {
		foreach_dart_of_orbit(m, f, [&](Dart d) { corners.push_back((*pos)[CMap2::Vertex(d)]); });
		return false;
	});
	ASSERT_EQ(corners.size(), 4u);
	const uint32_t fan[6] = {0, 1, 2, 0, 2, 3};
	for (int k = 0; k < 6; ++k)
		for (int c = 0; c < 3; ++c)
			EXPECT_EQ(p[3 * t[k] + c], float(corners[fan[k]][c])) << k << " " << c;
	// every quad edge is drawn once: 2 nf edges on a closed quad mesh, and
	// the diagonals are not edges
	uint32_t drawn = 0;
	for (uint8_t f : flags)
		drawn += (f & 1) + ((f >> 1) & 1) + ((f >> 2) & 1);
	EXPECT_EQ(drawn, 2u * nf);

	const std::string meta = element(html, "cgogn-meta");
	for (const char* label : {"\"uniform\"", "\"mean curvature\"", "\"Gaussian curvature\"", "\"face area\"",
							  "\"triangle quality\"", "\"height\""})
		EXPECT_NE(meta.find(label), std::string::npos) << label;
	// quantity 5 is the attribute: per vertex, selected, spread over [0, 1]
	EXPECT_NE(meta.find("\"initial\":{\"color\":5"), std::string::npos) << meta.substr(meta.find("\"initial\""));
	const auto q = array<uint8_t>(html, "q5");
	ASSERT_EQ(q.size(), nv);
	EXPECT_EQ(*std::min_element(q.begin(), q.end()), 0);
	EXPECT_EQ(*std::max_element(q.begin(), q.end()), 254);
	EXPECT_EQ(array<uint8_t>(html, "q3").size(), 2u * nf) << "face area: per triangle";
	expect_self_contained(html);

	o.all_quantities = false;
	const std::string small = render::viewer_html(m, *pos, o);
	EXPECT_LT(small.size(), html.size());
	EXPECT_NE(element(small, "cgogn-q1").size(), 0u);
	EXPECT_EQ(element(small, "cgogn-q2").size(), 0u);
}

TEST(Viewer, VolumePageGroupsTheFacesByCell)
{
	CMap3 m;
	build_with_positions(m, hex_grid_soup(2, 1, 1));
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	const std::string html = render::viewer_html(m, *pos);
	// 2 hexahedra, 6 quads each, 2 triangles a quad
	const auto offsets = array<uint32_t>(html, "cell_offsets");
	ASSERT_EQ(offsets.size(), 3u);
	EXPECT_EQ(offsets[0], 0u);
	EXPECT_EQ(offsets[1], 12u);
	EXPECT_EQ(offsets[2], 24u);
	EXPECT_EQ(array<uint32_t>(html, "triangles").size(), 3u * 24u);
	EXPECT_EQ(array<float>(html, "positions").size(), 3u * 12u);
	// the shared quad is inner (seen from both cells), the 10 others are on
	// the boundary
	uint32_t boundary = 0;
	for (uint8_t f : array<uint8_t>(html, "flags"))
		boundary += (f & 64) != 0;
	EXPECT_EQ(boundary, 20u);
	EXPECT_EQ(element(html, "cgogn-meta").find("curvature"), std::string::npos);
	expect_self_contained(html);
}

TEST(Viewer, BadInputIsAnErrorAndWritesNothing)
{
	TempDir dir;
	const std::string out = dir.file("v.html");
	{
		CMap2 m;
		auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
		EXPECT_THROW(render::write_viewer_html(m, *pos, out), render::RenderError);
	}
	{
		CMap2 m;
		build_with_positions(m, grid_soup(2, 2));
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		foreach_cell(m, [&](CMap2::Vertex v) {
			(*pos)[v][0] = std::numeric_limits<double>::quiet_NaN();
			return false;
		});
		EXPECT_THROW(render::write_viewer_html(m, *pos, out), render::RenderError);
	}
	{
		CMap2 m;
		build_with_positions(m, grid_soup(2, 2));
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		render::ViewerOptions o;
		o.color = render::ColorSource::Attribute;
		o.attribute = "nope";
		EXPECT_THROW(render::write_viewer_html(m, *pos, out, o), render::RenderError);
		EXPECT_THROW(render::write_viewer_html(m, *pos, dir.file("no/such/dir.html")), render::RenderError);
	}
	{
		CMap3 m;
		auto pos = add_attribute<Vec3, CMap3::Vertex>(m, "position");
		EXPECT_THROW(render::write_viewer_html(m, *pos, out), render::RenderError);
	}
	EXPECT_FALSE(std::filesystem::exists(out));
	EXPECT_TRUE(std::filesystem::is_empty(dir.file(""))) << "no temporary file left";
}

#ifdef CGOGN_TOOL_PATH
TEST(ToolView, WritesAPageAndRejectsBadInput)
{
	TempDir dir;
	const std::string out = dir.file("s.html");
	ToolRun r = run_tool("view " + quoted(cgogn_test_data::path("surface/elephant-with-holes.off")) + " " +
							 quoted(out) + " --color curvature --edges --show-defects",
						 dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.out, "");
	const std::string html = read_text(out);
	EXPECT_NE(html.find("<title>elephant-with-holes.off</title>"), std::string::npos);
	EXPECT_NE(html.find("\"initial\":{\"color\":1,\"edges\":true,\"defects\":true}"), std::string::npos);
	// boundary edges are flagged (bits 8, 16, 32)
	uint32_t boundary = 0;
	for (uint8_t f : array<uint8_t>(html, "flags"))
		boundary += (f & 56) != 0;
	EXPECT_GT(boundary, 100u);

	r = run_tool(
		"view " + quoted(cgogn_test_data::path("volume/liver_hex_624.mesh")) + " " + quoted(dir.file("v.html")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(array<uint32_t>(read_text(dir.file("v.html")), "cell_offsets").size(), 625u);

	const std::string bad = dir.file("bad.html");
	write_text(dir.file("empty.off"), "OFF\n0 0 0\n");
	r = run_tool("view " + quoted(dir.file("empty.off")) + " " + quoted(bad), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("empty.off"), std::string::npos) << r.err;
	write_text(dir.file("nan.off"), "OFF\n3 1 0\n0 0 0\n1 0 0\nnan 1 0\n3 0 1 2\n");
	r = run_tool("view " + quoted(dir.file("nan.off")) + " " + quoted(bad), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("nan.off"), std::string::npos) << r.err;
	r = run_tool("view " + quoted(cgogn_test_data::path("surface/suzanne.obj")) + " " + quoted(bad) + " --color nope",
				 dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("suzanne.obj"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(bad));
}
#endif

} // namespace cgogn_test_viewer
