// SPDX-License-Identifier: MIT
// The software renderer: picture size, the silhouette of a sphere against the
// analytic disk given by the camera convention, viridis colours of known
// scalar fields, the view conventions, determinism of the PNG bytes, and the
// errors on bad input.
#include "../io/io_test_utils.h"
#include "render_test_utils.h"

#include <filesystem>
#include <set>

namespace cgogn_test_render
{

using namespace cgogn;
using namespace cgogn::io_test;
using namespace cgogn::render_test;

namespace
{

std::shared_ptr<AttributeArray<Vec3>> positions_of(CMap2& m)
{
	return get_attribute<Vec3, CMap2::Vertex>(m, "position");
}

/// A flat square [0,1]^2 in the plane of axes (a, b) of a third axis fixed
/// at 0, with the vertex attribute "s" equal to coordinate `along`.
void square(CMap2& m, int a, int b, int along)
{
	SurfaceSoup s = grid_soup(1, 1);
	for (auto& p : s.positions)
	{
		const std::array<double, 3> q = p;
		p = {0.0, 0.0, 0.0};
		p[a] = q[0];
		p[b] = q[1];
	}
	build_with_positions(m, s);
	auto pos = positions_of(m);
	auto attr = add_attribute<double, CMap2::Vertex>(m, "s");
	foreach_cell(m, [&](CMap2::Vertex v) { (*attr)[v] = (*pos)[v][along]; });
}

render::RenderOptions unlit(render::View view, uint32_t w, uint32_t h)
{
	render::RenderOptions o;
	o.view = view;
	o.width = w;
	o.height = h;
	o.lighting = false;
	o.legend = false;
	o.supersampling = 1;
	return o;
}

// matplotlib's viridis at 0, 1/4, 1/2, 3/4 and 1, as published
constexpr render::Rgb viridis0{0x44, 0x01, 0x54}, viridis25{0x3b, 0x52, 0x8b}, viridis50{0x21, 0x91, 0x8c},
	viridis75{0x5e, 0xc9, 0x62}, viridis100{0xfd, 0xe7, 0x25};

} // namespace

TEST(Render, PictureHasTheRequestedSizeAndIsNotUniform)
{
	CMap2 m;
	build_with_positions(m, sphere_soup(32, 16, true));
	render::RenderOptions o;
	o.width = 321;
	o.height = 123;
	const render::Image img = render::render_surface(m, *positions_of(m), o);
	EXPECT_EQ(img.width, 321u);
	EXPECT_EQ(img.height, 123u);
	ASSERT_EQ(img.rgb.size(), 321u * 123u * 3u);
	std::set<std::tuple<int, int, int>> colours;
	for (uint32_t y = 0; y < img.height; ++y)
		for (uint32_t x = 0; x < img.width; ++x)
		{
			const render::Rgb c = img.at(x, y);
			colours.insert({c.r, c.g, c.b});
		}
	EXPECT_GT(colours.size(), 20u) << "shading varies over the sphere";
	EXPECT_EQ(img.at(0, 0), o.background);
	EXPECT_NE(img.at(160, 61), o.background) << "the sphere is in the middle";
}

TEST(Render, SphereSilhouetteIsTheAnalyticDisk)
{
	// poles on z, the equator (nv even) is the silhouette seen along z
	CMap2 m;
	const SurfaceSoup soup = sphere_soup(256, 64, true);
	build_with_positions(m, soup);
	render::RenderOptions o;
	o.view = render::View::Z;
	o.width = 400;
	o.height = 300;
	const render::Image img = render::render_surface(m, *positions_of(m), o);

	// the camera convention: orthographic, the bounding box's centre in the
	// middle, its projection filling 90% of the width or of the height
	double lo[3] = {1e9, 1e9, 1e9}, hi[3] = {-1e9, -1e9, -1e9};
	for (const auto& p : soup.positions)
		for (int i = 0; i < 3; ++i)
		{
			lo[i] = std::min(lo[i], p[i]);
			hi[i] = std::max(hi[i], p[i]);
		}
	const double k = 0.9 * std::min(400.0 / (hi[0] - lo[0]), 300.0 / (hi[1] - lo[1]));
	const double cx = 200.0 - 0.5 * (lo[0] + hi[0]) * k, cy = 150.0 + 0.5 * (lo[1] + hi[1]) * k, r = k;
	uint32_t differ = 0, inside = 0;
	double worst = 0.0;
	for (uint32_t y = 0; y < img.height; ++y)
		for (uint32_t x = 0; x < img.width; ++x)
		{
			const double d = std::hypot(x + 0.5 - cx, y + 0.5 - cy);
			const bool expected = d < r;
			const bool drawn = img.at(x, y) != o.background;
			inside += expected;
			if (expected != drawn)
			{
				++differ;
				worst = std::max(worst, std::abs(d - r));
			}
		}
	EXPECT_GT(inside, 50000u); // radius 135 pixels
	EXPECT_LE(differ, 0.015 * img.width * img.height) << differ << " pixels differ";
	EXPECT_LE(differ, 0.02 * inside);
	EXPECT_LE(worst, 2.0) << "every difference lies within 2 pixels of the circle";
}

TEST(Render, VertexScalarGivesViridisColours)
{
	// s = x on the unit square seen along z; height 40: 36 pixels per unit,
	// the square spans pixels [2.5, 38.5] in x, so that pixel columns 11,
	// 20, 29 have their centres at x = 1/4, 1/2, 3/4
	CMap2 m;
	square(m, 0, 1, 0);
	render::RenderOptions o = unlit(render::View::Z, 41, 40);
	o.color = render::ColorSource::Attribute;
	o.attribute = "s";
	const render::Image img = render::render_surface(m, *positions_of(m), o);
	for (uint32_t y : {5u, 20u, 35u})
	{
		EXPECT_LE(distance(img.at(11, y), viridis25), 2) << y;
		EXPECT_LE(distance(img.at(20, y), viridis50), 2) << y;
		EXPECT_LE(distance(img.at(29, y), viridis75), 2) << y;
	}
	// the ends: dark purple on the left, yellow on the right
	EXPECT_LE(distance(img.at(3, 20), viridis0), 12);
	EXPECT_LE(distance(img.at(37, 20), viridis100), 25);
	EXPECT_EQ(img.at(1, 20), o.background);
	EXPECT_EQ(img.at(39, 20), o.background);

	// lit: a face turned to the camera gets the full colour
	o.lighting = true;
	o.shading = render::Shading::Flat;
	const render::Image lit = render::render_surface(m, *positions_of(m), o);
	EXPECT_LE(distance(lit.at(20, 20), viridis50), 2);
}

TEST(Render, FaceScalarGivesViridisEnds)
{
	// two unit squares side by side, face attribute = x of the centre: the
	// left one is the minimum (viridis 0), the right one the maximum
	CMap2 m;
	build_with_positions(m, grid_soup(2, 1));
	auto pos = positions_of(m);
	auto fa = add_attribute<float, CMap2::Face>(m, "cx");
	foreach_cell(m, [&](CMap2::Face f) {
		double x = 0.0;
		int n = 0;
		foreach_dart_of_orbit(m, f, [&](Dart d) {
			x += (*pos)[CMap2::Vertex(d)][0];
			++n;
		});
		(*fa)[f] = float(x / n);
	});
	render::RenderOptions o = unlit(render::View::Z, 200, 100);
	o.color = render::ColorSource::Attribute;
	o.attribute = "cx";
	const render::Image img = render::render_surface(m, *pos, o);
	EXPECT_EQ(img.at(60, 50), viridis0);
	EXPECT_EQ(img.at(140, 50), viridis100);
}

TEST(Render, ScalarRangeIsRobustToOutliers)
{
	std::vector<double> v;
	for (int i = 0; i <= 100; ++i)
		v.push_back(i);
	v.push_back(1e9);
	v.push_back(-1e9);
	v.push_back(std::numeric_limits<double>::quiet_NaN());
	// 103 finite values: the 2nd percentile lies at 2.04 between the sorted
	// values (-1e9, 0, 1, 2, ...), i.e. 1.04; the 98th at 99.96, i.e. 98.96
	const render::ScalarRange r = render::scalar_range(v);
	EXPECT_NEAR(r.lo, 1.04, 1e-9);
	EXPECT_NEAR(r.hi, 98.96, 1e-9);
	EXPECT_TRUE(r.below);
	EXPECT_TRUE(r.above);
	EXPECT_EQ(r.normalized(1e9), 1.0);
	EXPECT_EQ(r.normalized(-5.0), 0.0);
	EXPECT_NEAR(r.normalized(50.0), 0.5, 1e-12);
	EXPECT_TRUE(std::isnan(r.normalized(std::numeric_limits<double>::infinity())));

	const render::ScalarRange given = render::scalar_range(v, 0.0, 200.0);
	EXPECT_EQ(given.lo, 0.0);
	EXPECT_EQ(given.hi, 200.0);
	EXPECT_TRUE(given.below);
	EXPECT_TRUE(given.above);
	const render::ScalarRange all = render::scalar_range(v, -2e9, 2e9);
	EXPECT_FALSE(all.below);
	EXPECT_FALSE(all.above);
	EXPECT_THROW(render::scalar_range(v, 1.0, 1.0), render::RenderError);
	EXPECT_THROW(render::scalar_range(v, 1.0, std::nullopt), render::RenderError);
	EXPECT_THROW(render::scalar_range(v, std::numeric_limits<double>::quiet_NaN(), 1.0), render::RenderError);
	const render::ScalarRange none = render::scalar_range({});
	EXPECT_EQ(none.lo, 0.0);
	EXPECT_EQ(none.hi, 0.0);
}

TEST(Render, OutliersDoNotFlattenTheColours)
{
	// s = x on a 10 x 10 grid of [0,1]^2 seen along z, but one corner vertex
	// holds 1e9: a min/max range would paint everything viridis(0); the
	// robust range still spreads the colours over x
	CMap2 m;
	SurfaceSoup soup = grid_soup(10, 10);
	for (auto& p : soup.positions)
		p = {p[0] / 10.0, p[1] / 10.0, 0.0};
	build_with_positions(m, soup);
	auto pos = positions_of(m);
	auto attr = add_attribute<double, CMap2::Vertex>(m, "s");
	foreach_cell(m, [&](CMap2::Vertex v) {
		const Vec3& p = (*pos)[v];
		(*attr)[v] = p[0] > 0.99 && p[1] > 0.99 ? 1e9 : p[0];
	});
	render::RenderOptions o = unlit(render::View::Z, 41, 40);
	o.color = render::ColorSource::Attribute;
	o.attribute = "s";
	const render::Image img = render::render_surface(m, *pos, o);
	EXPECT_LE(distance(img.at(11, 20), viridis25), 3);
	EXPECT_LE(distance(img.at(20, 20), viridis50), 3);
	EXPECT_LE(distance(img.at(29, 20), viridis75), 3);

	// an explicit range: [0, 2] puts x = 1/2 at a quarter of the map
	o.range_min = 0.0;
	o.range_max = 2.0;
	const render::Image given = render::render_surface(m, *pos, o);
	EXPECT_LE(distance(given.at(20, 20), viridis25), 3);
	o.range_max = 0.0;
	EXPECT_THROW(render::render_surface(m, *pos, o), render::RenderError);
}

TEST(Render, LegendMarksClampedEnds)
{
	// the legend's bar spans rows 15% to 85% of the height; a clamped end
	// gets a triangle of its end colour just beyond it
	CMap2 m;
	square(m, 0, 1, 0);
	auto pos = positions_of(m);
	render::RenderOptions o = unlit(render::View::Z, 400, 200);
	o.legend = true;
	o.color = render::ColorSource::Attribute;
	o.attribute = "s";
	const uint32_t xbar = 400 - render::legend_width(400, 200) + 4 + 2, ytop = 30, ybot = 170;
	const render::Image full = render::render_surface(m, *pos, o);
	EXPECT_EQ(full.at(xbar, ytop), viridis100);
	EXPECT_EQ(full.at(xbar, ytop - 2), o.background) << "nothing clamped: no triangle";
	EXPECT_EQ(full.at(xbar, ybot + 2), o.background);
	o.range_min = 0.25;
	o.range_max = 0.75;
	const render::Image clamped = render::render_surface(m, *pos, o);
	EXPECT_EQ(clamped.at(xbar, ytop - 2), viridis100);
	EXPECT_EQ(clamped.at(xbar, ybot + 2), viridis0);
	o.range_min = -1.0;
	const render::Image top = render::render_surface(m, *pos, o);
	EXPECT_EQ(top.at(xbar, ytop - 2), viridis100);
	EXPECT_EQ(top.at(xbar, ybot + 2), o.background);
}

TEST(Render, HiddenDefectsAreFaint)
{
	// a closed sphere hides an open square behind it, a second open square
	// beside it is in view: the visible boundary is red, the hidden one is
	// blended at 25% over the sphere
	CMap2 m;
	build_with_positions(m, sphere_soup(48, 24, true));
	auto square_at = [&](double x0, double z) {
		SurfaceSoup s = grid_soup(1, 1);
		for (auto& p : s.positions)
			p = {x0 + p[0], p[1] - 0.5, z};
		build_with_positions(m, s);
	};
	square_at(-0.5, -3.0); // behind the sphere
	square_at(2.0, 0.0);   // beside it
	render::RenderOptions o = unlit(render::View::Z, 400, 200);
	o.show_defects = true;
	const render::Image img = render::render_surface(m, *positions_of(m), o);
	const render::Rgb red{230, 25, 25}, s = o.surface_color;
	const render::Rgb faint{uint8_t((3 * s.r + red.r + 2) / 4), uint8_t((3 * s.g + red.g + 2) / 4),
							uint8_t((3 * s.b + red.b + 2) / 4)};
	// the bounding box is [-1, 3] x [-1, 1]: 90 pixels per unit, x = 0 at
	// column 110, y = 0 at row 100
	uint32_t red_left = 0, red_right = 0, faint_left = 0;
	for (uint32_t y = 0; y < img.height; ++y)
		for (uint32_t x = 0; x < img.width; ++x)
		{
			const render::Rgb c = img.at(x, y);
			const bool left = x < 200; // the sphere's side
			red_left += left && c == red;
			red_right += !left && c == red;
			faint_left += left && c == faint;
		}
	EXPECT_GT(red_right, 300u) << "the visible square's outline, 4 x 90 pixels long";
	EXPECT_GT(faint_left, 300u) << "the hidden square's outline shows faintly";
	EXPECT_EQ(red_left, 0u) << "hidden boundary edges are not drawn in full colour";
	EXPECT_EQ(img.at(110, 100), s) << "inside the hidden outline, the sphere is untouched";
}

TEST(Render, NonManifoldSurfaceAsItIs)
{
	// a book of three unit squares on the spine x = 0, z in [0, 1], seen
	// from +z: the pages at y = 0 (x in [0, 1]), x = 0 (y in [0, 1]) and
	// y = 0 (x in [-1, 0]); the spine is red with show_defects
	IncidenceGraph ig;
	auto pos = add_attribute<Vec3, IncidenceGraph::Vertex>(ig, "position");
	auto vertex = [&](double x, double y, double z) {
		const IncidenceGraph::Vertex v = add_vertex(ig);
		(*pos)[v] = Vec3(x, y, z);
		return v;
	};
	const IncidenceGraph::Vertex a = vertex(0, 0, 0), b = vertex(0, 0, 1);
	for (const Vec3& d : {Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0)})
	{
		const std::vector<IncidenceGraph::Vertex> page = {a, b, vertex(d[0], d[1], 1), vertex(d[0], d[1], 0)};
		add_face_through_vertices(ig, page);
	}
	add_edge(ig, vertex(0, 0, 2), vertex(0, 1, 2)); // a wire above
	render::RenderOptions o = unlit(render::View::X, 200, 200);
	const render::Image plain = render::render_surface(ig, *pos, o);
	uint32_t surface = 0, wire = 0;
	for (uint32_t y = 0; y < plain.height; ++y)
		for (uint32_t x = 0; x < plain.width; ++x)
		{
			surface += plain.at(x, y) == o.surface_color;
			wire += plain.at(x, y) == o.edge_color;
		}
	EXPECT_GT(surface, 1000u) << "the page facing the camera is drawn";
	EXPECT_GT(wire, 20u) << "the wire is drawn without --edges";
	o.show_defects = true;
	const render::Image defects = render::render_surface(ig, *pos, o);
	uint32_t red = 0;
	for (uint32_t y = 0; y < defects.height; ++y)
		for (uint32_t x = 0; x < defects.width; ++x)
			red += defects.at(x, y) == render::Rgb{230, 25, 25};
	EXPECT_GT(red, 100u) << "the spine, the borders and the wire are red";
	o.color = render::ColorSource::MeanCurvature;
	EXPECT_THROW(render::render_surface(ig, *pos, o), render::RenderError);
	o.color = render::ColorSource::Quality;
	EXPECT_NO_THROW(render::render_surface(ig, *pos, o));
}

TEST(Render, GraphAsTubesAndLines)
{
	// a path of three vertices along x, with radii
	Graph g;
	auto pos = add_attribute<Vec3, Graph::Vertex>(g, "position");
	auto radius = add_attribute<double, Graph::Vertex>(g, "radius");
	std::vector<Graph::Vertex> v;
	for (int i = 0; i < 3; ++i)
	{
		v.push_back(add_vertex(g));
		(*pos)[v.back()] = Vec3(i, 0, 0);
		(*radius)[v.back()] = 0.1;
	}
	connect_vertices(g, v[0], v[1]);
	connect_vertices(g, v[1], v[2]);
	render::RenderOptions o = unlit(render::View::Z, 300, 100);
	auto count = [](const render::Image& img, render::Rgb c) {
		uint32_t n = 0;
		for (uint32_t y = 0; y < img.height; ++y)
			for (uint32_t x = 0; x < img.width; ++x)
				n += img.at(x, y) == c;
		return n;
	};
	const render::Image tubes = render::render_graph(g, *pos, o);
	// 2.2 units wide in 270 pixels: 0.2 thick is about 24 pixels, over 2 units
	const uint32_t covered = count(tubes, o.surface_color);
	EXPECT_GT(covered, 4000u);
	EXPECT_LT(covered, 8000u);
	render::GraphDrawing lines;
	lines.tubes = false;
	const render::Image thin = render::render_graph(g, *pos, o, lines);
	EXPECT_EQ(count(thin, o.surface_color), 0u);
	EXPECT_GT(count(thin, o.edge_color), 200u);
	// coloured by a vertex attribute; faces' colour sources are refused
	o.color = render::ColorSource::Attribute;
	o.attribute = "radius";
	EXPECT_NO_THROW(render::render_graph(g, *pos, o));
	o.attribute = "nothing";
	EXPECT_THROW(render::render_graph(g, *pos, o), render::RenderError);
	o.color = render::ColorSource::Area;
	EXPECT_THROW(render::render_graph(g, *pos, o), render::RenderError);
	EXPECT_THROW(render::render_graph(Graph(), *pos, unlit(render::View::Z, 10, 10)), render::RenderError);
}

TEST(Render, ViewConventions)
{
	struct Case
	{
		render::View view;
		int a, b;      // the square's plane
		int along;     // the scalar's axis
		bool right;    // true: the scalar grows to the right, false: upwards
		bool positive; // ... or to the left / downwards when false
	};
	const Case cases[] = {
		{render::View::Z, 0, 1, 0, true, true},  // +x to the right
		{render::View::Z, 0, 1, 1, false, true}, // +y up
		{render::View::X, 1, 2, 1, true, true},  // +y to the right
		{render::View::X, 1, 2, 2, false, true}, // +z up
		{render::View::Y, 0, 2, 0, true, false}, // -x to the right
		{render::View::Y, 0, 2, 2, false, true}, // +z up
	};
	for (const Case& c : cases)
	{
		CMap2 m;
		square(m, c.a, c.b, c.along);
		render::RenderOptions o = unlit(c.view, 100, 100);
		o.color = render::ColorSource::Attribute;
		o.attribute = "s";
		const render::Image img = render::render_surface(m, *positions_of(m), o);
		// 5.5 pixels inside the square at each end (t = 0.06 and 0.94): the
		// low end is closer to viridis(0), the high end to viridis(1)
		const render::Rgb left = img.at(10, 50), right = img.at(89, 50), top = img.at(50, 10), bottom = img.at(50, 89);
		const render::Rgb low = c.right ? (c.positive ? left : right) : (c.positive ? bottom : top);
		const render::Rgb high = c.right ? (c.positive ? right : left) : (c.positive ? top : bottom);
		EXPECT_LT(distance(low, viridis0), distance(low, viridis100)) << int(c.view) << " " << c.along;
		EXPECT_LT(distance(high, viridis100), distance(high, viridis0)) << int(c.view) << " " << c.along;
		EXPECT_LE(distance(low, viridis0), 30) << int(c.view) << " " << c.along;
		EXPECT_LE(distance(high, viridis100), 45) << int(c.view) << " " << c.along;
	}
}

TEST(Render, SameInputSamePngBytes)
{
	TempDir dir;
	CMap2 m;
	build_with_positions(m, torus_soup(24, 12, true));
	render::RenderOptions o;
	o.edges = true;
	o.color = render::ColorSource::MeanCurvature;
	o.azimuth = 20;
	o.elevation = -10;
	render::write_png(render::render_surface(m, *positions_of(m), o), dir.file("a.png"));
	render::write_png(render::render_surface(m, *positions_of(m), o), dir.file("b.png"));
	const std::string a = read_text(dir.file("a.png")), b = read_text(dir.file("b.png"));
	EXPECT_GT(a.size(), 1000u);
	EXPECT_EQ(a, b);
	// and the picture read back is the one rendered
	const render::Image back = read_png(dir.file("a.png"));
	EXPECT_EQ(back.rgb, render::render_surface(m, *positions_of(m), o).rgb);
	// no temporary file left next to it
	uint32_t files = 0;
	for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.file("")))
		++files;
	EXPECT_EQ(files, 2u);
}

TEST(Render, EveryColourSourceAndOverlayRuns)
{
	CMap2 m;
	build_with_positions(m, cylinder_soup(16, 4)); // open: two boundary loops
	const auto pos = positions_of(m);
	render::RenderOptions o;
	o.width = 160;
	o.height = 120;
	const render::Image plain = render::render_surface(m, *pos, o);
	for (render::ColorSource c : {render::ColorSource::MeanCurvature, render::ColorSource::GaussianCurvature,
								  render::ColorSource::Area, render::ColorSource::Quality})
	{
		o.color = c;
		EXPECT_NE(render::render_surface(m, *pos, o).rgb, plain.rgb) << int(c);
	}
	o.color = render::ColorSource::Uniform;
	o.show_defects = true;
	const render::Image defects = render::render_surface(m, *pos, o);
	uint32_t red = 0;
	for (uint32_t y = 0; y < defects.height; ++y)
		for (uint32_t x = 0; x < defects.width; ++x)
			red += defects.at(x, y) == render::Rgb{230, 25, 25};
	EXPECT_GT(red, 100u) << "the two boundary loops are drawn in red";
	o.show_defects = false;
	o.edges = true;
	EXPECT_NE(render::render_surface(m, *pos, o).rgb, plain.rgb);
}

TEST(Render, TriangleQuality)
{
	EXPECT_NEAR(render::triangle_quality(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(3.0) / 2, 0)), 1.0, 1e-12);
	EXPECT_NEAR(render::triangle_quality(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)), 0.0, 1e-12);
	EXPECT_EQ(render::triangle_quality(Vec3(1, 1, 1), Vec3(1, 1, 1), Vec3(1, 1, 1)), 0.0);
}

TEST(Render, ParseColor)
{
	EXPECT_EQ(render::parse_color("#ff8000"), (render::Rgb{255, 128, 0}));
	EXPECT_EQ(render::parse_color("10,20,30"), (render::Rgb{10, 20, 30}));
	EXPECT_THROW(render::parse_color("red"), render::RenderError);
	EXPECT_THROW(render::parse_color("1,2,300"), render::RenderError);
}

TEST(Render, EmptyMeshIsAnError)
{
	CMap2 m;
	auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
	EXPECT_THROW(render::render_surface(m, *pos, {}), render::RenderError);
}

TEST(Render, NonFinitePositionIsAnError)
{
	for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
	{
		CMap2 m;
		build_with_positions(m, grid_soup(2, 2));
		auto pos = positions_of(m);
		bool first = true;
		foreach_cell(m, [&](CMap2::Vertex v) {
			if (first)
				(*pos)[v][1] = bad;
			first = false;
		});
		try
		{
			render::render_surface(m, *pos, {});
			ADD_FAILURE() << "no error";
		}
		catch (const render::RenderError& e)
		{
			EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
		}
	}
}

TEST(Render, UnknownAttributeListsTheAvailableOnes)
{
	CMap2 m;
	square(m, 0, 1, 0);
	render::RenderOptions o;
	o.color = render::ColorSource::Attribute;
	o.attribute = "nope";
	try
	{
		render::render_surface(m, *positions_of(m), o);
		ADD_FAILURE() << "no error";
	}
	catch (const render::RenderError& e)
	{
		const std::string w = e.what();
		EXPECT_NE(w.find("nope"), std::string::npos) << w;
		EXPECT_NE(w.find("available: s"), std::string::npos) << w;
	}
}

TEST(Render, VolumeBoundary)
{
	CMap3 m;
	build_with_positions(m, hex_grid_soup(2, 2, 2));
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	render::RenderOptions o = unlit(render::View::Z, 100, 100);
	const render::Image img = render::render_volume_boundary(m, *pos, o);
	// the 2x2 top of the cube fills the middle of the picture
	EXPECT_EQ(img.at(50, 50), o.surface_color);
	EXPECT_EQ(img.at(2, 50), o.background);
	o.color = render::ColorSource::MeanCurvature;
	EXPECT_THROW(render::render_volume_boundary(m, *pos, o), render::RenderError);
}

TEST(Render, VolumeWithoutBoundaryIsAnError)
{
	{
		CMap3 m;
		auto pos = add_attribute<Vec3, CMap3::Vertex>(m, "position");
		EXPECT_THROW(render::render_volume_boundary(m, *pos, {}), render::RenderError);
	}
	// two tetrahedra glued along their four faces: a closed 3-manifold
	CMap3 m;
	CMap3::Volume v[2];
	VolumeSoup s;
	s.nb_vertices = 4;
	s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	s.cell_sizes = {4};
	s.cell_vertices = {0, 1, 2, 3};
	build_with_positions(m, s);
	build_with_positions(m, s);
	uint32_t k = 0;
	foreach_cell(m, [&](CMap3::Volume w) { v[k++] = w; });
	ASSERT_EQ(k, 2u);
	std::vector<CMap3::Face> f0, f1;
	foreach_incident_face(m, v[0], [&](CMap3::Face f) { f0.push_back(f); });
	foreach_incident_face(m, v[1], [&](CMap3::Face f) { f1.push_back(f); });
	ASSERT_EQ(f0.size(), 4u);
	ASSERT_EQ(f1.size(), 4u);
	uint32_t sewn = 0;
	for (CMap3::Face a : f0)
		for (CMap3::Face b : f1)
			if (is_boundary(m, phi3(m, a.dart)) && is_boundary(m, phi3(m, b.dart)) && can_sew_volumes(m, a, b))
			{
				sew_volumes(m, a, b);
				++sewn;
				break;
			}
	if (sewn < 4)
		GTEST_SKIP() << "only " << sewn << " faces could be glued";
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	try
	{
		render::render_volume_boundary(m, *pos, {});
		ADD_FAILURE() << "no error";
	}
	catch (const render::RenderError& e)
	{
		EXPECT_NE(std::string(e.what()).find("no boundary face"), std::string::npos) << e.what();
	}
}

TEST(Render, WritePngFailsCleanly)
{
	TempDir dir;
	const render::Image empty;
	EXPECT_THROW(render::write_png(empty, dir.file("e.png")), render::RenderError);
	EXPECT_FALSE(std::filesystem::exists(dir.file("e.png")));
	render::Image one;
	one.width = one.height = 1;
	one.rgb = {1, 2, 3};
	EXPECT_THROW(render::write_png(one, dir.file("missing/x.png")), render::RenderError);
	render::write_png(one, dir.file("one.png"));
	const render::Image back = read_png(dir.file("one.png"));
	EXPECT_EQ(back.width, 1u);
	EXPECT_EQ(back.rgb, one.rgb);
}

} // namespace cgogn_test_render
