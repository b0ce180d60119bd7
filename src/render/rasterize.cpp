// SPDX-License-Identifier: MIT
// The software rasterizer: orthographic camera, a visibility pass (depth and
// triangle per sample), then one shading pass over the samples, so that each
// sample is shaded once whatever the depth complexity. Vertices are snapped
// to 1/16 of a sample and the edge functions are computed in integers: two
// triangles sharing an edge cover each sample along it exactly once (no
// cracks, no double hits), and the result does not depend on rounding order.
#include "scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace cgogn::render
{

uint32_t legend_width(uint32_t width, uint32_t height)
{
	return std::min(48 * std::max(1u, height / 200), width / 2);
}

Rgb parse_color(const std::string& text)
{
	auto bad = [&]() { return RenderError("'" + text + "' is not a colour (#rrggbb, rrggbb or r,g,b)"); };
	std::string t = text;
	if (!t.empty() && t[0] == '#')
		t = t.substr(1);
	if (t.find(',') != std::string::npos)
	{
		int c[3];
		char tail = 0;
		if (std::sscanf(t.c_str(), "%d,%d,%d%c", &c[0], &c[1], &c[2], &tail) != 3)
			throw bad();
		for (int v : c)
			if (v < 0 || v > 255)
				throw bad();
		return {uint8_t(c[0]), uint8_t(c[1]), uint8_t(c[2])};
	}
	if (t.size() != 6 || t.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
		throw bad();
	const unsigned long v = std::stoul(t, nullptr, 16);
	return {uint8_t(v >> 16), uint8_t(v >> 8), uint8_t(v)};
}

double ScalarRange::normalized(double v) const
{
	if (!std::isfinite(v))
		return std::numeric_limits<double>::quiet_NaN();
	return hi > lo ? std::clamp((v - lo) / (hi - lo), 0.0, 1.0) : 0.5;
}

ScalarRange scalar_range(const std::vector<double>& values, std::optional<double> min, std::optional<double> max)
{
	if (min.has_value() != max.has_value())
		throw RenderError("the colour range needs both its ends (minimum and maximum)");
	if (min && !(std::isfinite(*min) && std::isfinite(*max) && *min < *max))
		throw RenderError("the colour range must have finite ends with minimum < maximum");
	std::vector<double> v;
	v.reserve(values.size());
	for (double x : values)
		if (std::isfinite(x))
			v.push_back(x);
	ScalarRange r;
	if (v.empty())
	{
		if (min)
			r.lo = *min, r.hi = *max;
		return r;
	}
	if (min)
	{
		r.lo = *min;
		r.hi = *max;
	}
	else
	{
		// linear interpolation between the sorted values at q (n - 1)
		auto percentile = [&](double q) {
			const double at = q * double(v.size() - 1);
			const std::size_t i = std::size_t(at);
			std::nth_element(v.begin(), v.begin() + i, v.end());
			const double a = v[i];
			if (i + 1 >= v.size())
				return a;
			const double b = *std::min_element(v.begin() + i + 1, v.end());
			return a + (b - a) * (at - double(i));
		};
		r.lo = percentile(0.02);
		r.hi = percentile(0.98);
	}
	for (double x : v)
	{
		r.below = r.below || x < r.lo;
		r.above = r.above || x > r.hi;
	}
	return r;
}

namespace detail
{

namespace
{

constexpr uint32_t NONE = ~uint32_t(0);
constexpr int64_t SUB = 16; // fixed-point steps per sample

struct Frame
{
	Vec3 right, up, back;
};

Frame camera_frame(const RenderOptions& o)
{
	Vec3 r0(1, 0, 0), u0(0, 1, 0), b0(0, 0, 1);
	double az = o.azimuth, el = o.elevation;
	switch (o.view)
	{
	case View::Z:
		break;
	case View::X:
		r0 = Vec3(0, 1, 0), u0 = Vec3(0, 0, 1), b0 = Vec3(1, 0, 0);
		break;
	case View::Y:
		r0 = Vec3(-1, 0, 0), u0 = Vec3(0, 0, 1), b0 = Vec3(0, 1, 0);
		break;
	case View::Iso:
		az += 45.0;
		el += std::atan(1.0 / std::sqrt(2.0)) * 180.0 / std::numbers::pi;
		break;
	}
	const double a = az * std::numbers::pi / 180.0, e = el * std::numbers::pi / 180.0;
	const Vec3 back1 = std::cos(a) * b0 + std::sin(a) * r0;
	Frame f;
	f.right = std::cos(a) * r0 - std::sin(a) * b0;
	f.back = std::cos(e) * back1 + std::sin(e) * u0;
	f.up = std::cos(e) * u0 - std::sin(e) * back1;
	return f;
}

int64_t floor_div(int64_t a, int64_t b)
{
	return a >= 0 ? a / b : -((-a + b - 1) / b);
}

int64_t ceil_div(int64_t a, int64_t b)
{
	return -floor_div(-a, b);
}

/// The samples of the picture and the projection into it.
struct Target
{
	int w = 0, h = 0; // in samples
	std::vector<float> depth;
	std::vector<uint32_t> tri;
	std::vector<uint8_t> rgb;

	std::vector<int64_t> fx, fy; // fixed-point sample coordinates of the vertices
	std::vector<double> sx, sy;  // the same, unrounded
	std::vector<float> z;        // towards the camera

	/// Test: drawn where it is not behind the surface (with the bias);
	/// Defect: like Test, and blended at 25% where it is behind, once per
	/// sample (stamp: 0 untouched, 1 faint, 2 full).
	enum class Mode
	{
		Test,
		Defect
	};
	std::vector<uint8_t> stamp;

	void plot(int x, int y, float zz, float bias, Mode mode, Rgb c)
	{
		if (x < 0 || y < 0 || x >= w || y >= h)
			return;
		const std::size_t i = std::size_t(y) * w + x;
		const bool hidden = zz + bias < depth[i];
		if (mode == Mode::Test && hidden)
			return;
		if (mode == Mode::Defect)
		{
			if (stamp[i] == 2 || (hidden && stamp[i] == 1))
				return;
			stamp[i] = hidden ? 1 : 2;
			if (hidden)
			{
				rgb[3 * i] = uint8_t((3 * rgb[3 * i] + c.r + 2) / 4);
				rgb[3 * i + 1] = uint8_t((3 * rgb[3 * i + 1] + c.g + 2) / 4);
				rgb[3 * i + 2] = uint8_t((3 * rgb[3 * i + 2] + c.b + 2) / 4);
				return;
			}
		}
		rgb[3 * i] = c.r;
		rgb[3 * i + 1] = c.g;
		rgb[3 * i + 2] = c.b;
	}

	/// A line `thick` samples wide from vertex a to vertex b.
	void line(uint32_t a, uint32_t b, int thick, float bias, Mode mode, Rgb c)
	{
		const double dx = sx[b] - sx[a], dy = sy[b] - sy[a];
		const int n = std::max(1, int(std::ceil(std::max(std::abs(dx), std::abs(dy)))));
		const bool xmajor = std::abs(dx) >= std::abs(dy);
		for (int i = 0; i <= n; ++i)
		{
			const double t = double(i) / n;
			const double px = sx[a] + dx * t, py = sy[a] + dy * t;
			const float zz = float(z[a] + (z[b] - z[a]) * t);
			if (xmajor)
			{
				const int x = int(std::floor(px)), y0 = int(std::ceil(py - thick / 2.0 - 0.5));
				for (int j = 0; j < thick; ++j)
					plot(x, y0 + j, zz, bias, mode, c);
			}
			else
			{
				const int y = int(std::floor(py)), x0 = int(std::ceil(px - thick / 2.0 - 0.5));
				for (int j = 0; j < thick; ++j)
					plot(x0 + j, y, zz, bias, mode, c);
			}
		}
	}

	/// A disk around vertex v at the vertex's depth.
	void dot(uint32_t v, double radius, float bias, Rgb c)
	{
		const int r = int(std::ceil(radius));
		const int cx = int(std::floor(sx[v])), cy = int(std::floor(sy[v]));
		for (int y = cy - r; y <= cy + r; ++y)
			for (int x = cx - r; x <= cx + r; ++x)
			{
				const double ddx = x + 0.5 - sx[v], ddy = y + 0.5 - sy[v];
				if (ddx * ddx + ddy * ddy <= radius * radius)
					plot(x, y, z[v], bias, Mode::Defect, c);
			}
	}
};

/// Vertices a, b, c of triangle t in positive order, with twice its area in
/// fixed point (0: degenerate on screen).
struct ScreenTriangle
{
	uint32_t a, b, c;
	int64_t area;
};

ScreenTriangle screen_triangle(const Target& g, const uint32_t* v)
{
	ScreenTriangle t{v[0], v[1], v[2], 0};
	t.area = (g.fx[t.b] - g.fx[t.a]) * (g.fy[t.c] - g.fy[t.a]) - (g.fy[t.b] - g.fy[t.a]) * (g.fx[t.c] - g.fx[t.a]);
	if (t.area < 0)
	{
		std::swap(t.b, t.c);
		t.area = -t.area;
	}
	return t;
}

/// Edge function of (a, b) at fixed-point point (px, py): positive on the
/// inner side of a positive triangle.
int64_t edge(const Target& g, uint32_t a, uint32_t b, int64_t px, int64_t py)
{
	return (g.fx[b] - g.fx[a]) * (py - g.fy[a]) - (g.fy[b] - g.fy[a]) * (px - g.fx[a]);
}

/// A sample exactly on an edge belongs to one of the two triangles sharing
/// it: the one that runs the edge downwards (or leftwards when horizontal).
int64_t edge_bias(const Target& g, uint32_t a, uint32_t b)
{
	const int64_t dy = g.fy[b] - g.fy[a], dx = g.fx[b] - g.fx[a];
	return dy > 0 || (dy == 0 && dx < 0) ? 0 : -1;
}

void visibility(const Scene& s, Target& g)
{
	const std::size_t nt = s.triangle_face.size();
	for (std::size_t t = 0; t < nt; ++t)
	{
		const ScreenTriangle st = screen_triangle(g, &s.triangles[3 * t]);
		if (st.area == 0)
			continue;
		const uint32_t a = st.a, b = st.b, c = st.c;
		const int64_t minx = std::min({g.fx[a], g.fx[b], g.fx[c]}), maxx = std::max({g.fx[a], g.fx[b], g.fx[c]});
		const int64_t miny = std::min({g.fy[a], g.fy[b], g.fy[c]}), maxy = std::max({g.fy[a], g.fy[b], g.fy[c]});
		const int64_t x0 = std::max<int64_t>(0, ceil_div(minx - SUB / 2, SUB));
		const int64_t x1 = std::min<int64_t>(g.w - 1, floor_div(maxx - SUB / 2, SUB));
		const int64_t y0 = std::max<int64_t>(0, ceil_div(miny - SUB / 2, SUB));
		const int64_t y1 = std::min<int64_t>(g.h - 1, floor_div(maxy - SUB / 2, SUB));
		if (x0 > x1 || y0 > y1)
			continue;
		// w0 weighs a (edge bc), w1 b (edge ca), w2 c (edge ab)
		const int64_t b0 = edge_bias(g, b, c), b1 = edge_bias(g, c, a), b2 = edge_bias(g, a, b);
		const int64_t sx0 = -(g.fy[c] - g.fy[b]) * SUB, sx1 = -(g.fy[a] - g.fy[c]) * SUB,
					  sx2 = -(g.fy[b] - g.fy[a]) * SUB;
		const double inv = 1.0 / double(st.area);
		const double za = g.z[a] * inv, zb = g.z[b] * inv, zc = g.z[c] * inv;
		const uint32_t id = uint32_t(t);
		for (int64_t y = y0; y <= y1; ++y)
		{
			const int64_t px = x0 * SUB + SUB / 2, py = y * SUB + SUB / 2;
			int64_t w0 = edge(g, b, c, px, py) + b0, w1 = edge(g, c, a, px, py) + b1, w2 = edge(g, a, b, px, py) + b2;
			float* depth = g.depth.data() + y * g.w;
			uint32_t* tri = g.tri.data() + y * g.w;
			for (int64_t x = x0; x <= x1; ++x, w0 += sx0, w1 += sx1, w2 += sx2)
			{
				if ((w0 | w1 | w2) < 0)
					continue;
				const float zz = float(double(w0 - b0) * za + double(w1 - b1) * zb + double(w2 - b2) * zc);
				if (zz > depth[x])
				{
					depth[x] = zz;
					tri[x] = id;
				}
			}
		}
	}
}

struct Shader
{
	const Scene& s;
	const RenderOptions& o;
	Eigen::Vector3f light;
	ScalarRange range;
	std::vector<float> vertex_t; // normalized scalar per vertex (NaN: none)
	std::vector<Rgb> face_rgb;   // colour per face

	static constexpr Rgb no_value{128, 128, 128};

	double normalized(double v) const
	{
		return range.normalized(v);
	}

	Shader(const Scene& sc, const RenderOptions& op, const Vec3& back) : s(sc), o(op), light(back.cast<float>())
	{
		if (s.scalar_on != Scene::ScalarOn::None)
			range = scalar_range(s.scalar, o.range_min, o.range_max);
		if (s.scalar_on == Scene::ScalarOn::Vertices)
		{
			vertex_t.resize(s.scalar.size());
			for (std::size_t i = 0; i < s.scalar.size(); ++i)
				vertex_t[i] = float(normalized(s.scalar[i]));
		}
		else if (s.scalar_on == Scene::ScalarOn::Faces)
		{
			face_rgb.resize(s.scalar.size());
			for (std::size_t i = 0; i < s.scalar.size(); ++i)
			{
				const double t = normalized(s.scalar[i]);
				face_rgb[i] = std::isnan(t) ? no_value : viridis(t);
			}
		}
	}

	Rgb shade(const Target& g, uint32_t t, int64_t px, int64_t py) const
	{
		const ScreenTriangle st = screen_triangle(g, &s.triangles[3 * t]);
		const double inv = 1.0 / double(st.area);
		const float l0 = float(double(edge(g, st.b, st.c, px, py)) * inv);
		const float l1 = float(double(edge(g, st.c, st.a, px, py)) * inv);
		const float l2 = 1.0f - l0 - l1;
		const uint32_t face = s.triangle_face[t];
		Rgb base = o.surface_color;
		if (s.scalar_on == Scene::ScalarOn::Faces)
			base = face_rgb[face];
		else if (s.scalar_on == Scene::ScalarOn::Vertices)
		{
			const float v = l0 * vertex_t[st.a] + l1 * vertex_t[st.b] + l2 * vertex_t[st.c];
			base = std::isnan(v) ? no_value : viridis(std::clamp(double(v), 0.0, 1.0));
		}
		if (!o.lighting)
			return base;
		Eigen::Vector3f n = s.face_normal[face];
		if (o.shading == Shading::Smooth)
		{
			const Eigen::Vector3f m =
				l0 * s.vertex_normal[st.a] + l1 * s.vertex_normal[st.b] + l2 * s.vertex_normal[st.c];
			const float len = m.norm();
			if (len > 1e-6f)
				n = m / len;
		}
		// faces without a normal (zero area) are lit as if facing the camera
		const float f = n.squaredNorm() > 0.0f ? 0.2f + 0.8f * std::min(1.0f, std::abs(n.dot(light))) : 1.0f;
		auto scale = [f](uint8_t c) { return uint8_t(std::lround(float(c) * f)); };
		return {scale(base.r), scale(base.g), scale(base.b)};
	}
};

// ---- legend: a viridis bar with the minimum and maximum written next to it

// 3 x 5 glyphs, one row of 3 bits per entry, most significant bit on the left
struct Glyph
{
	char c;
	uint8_t rows[5];
};
constexpr Glyph font[] = {{'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}},
						  {'3', {7, 1, 7, 1, 7}}, {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}},
						  {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}}, {'8', {7, 5, 7, 5, 7}},
						  {'9', {7, 5, 7, 1, 7}}, {'-', {0, 0, 7, 0, 0}}, {'+', {0, 2, 7, 2, 0}},
						  {'.', {0, 0, 0, 0, 2}}, {'e', {0, 3, 7, 4, 3}}};

void put(Image& img, int x, int y, Rgb c)
{
	if (x < 0 || y < 0 || x >= int(img.width) || y >= int(img.height))
		return;
	const std::size_t i = (std::size_t(y) * img.width + x) * 3;
	img.rgb[i] = c.r;
	img.rgb[i + 1] = c.g;
	img.rgb[i + 2] = c.b;
}

void text(Image& img, int x, int y, int scale, const std::string& s, Rgb c)
{
	for (char ch : s)
	{
		for (const Glyph& gl : font)
			if (gl.c == ch)
				for (int r = 0; r < 5; ++r)
					for (int col = 0; col < 3; ++col)
						if (gl.rows[r] & (4 >> col))
							for (int dy = 0; dy < scale; ++dy)
								for (int dx = 0; dx < scale; ++dx)
									put(img, x + col * scale + dx, y + r * scale + dy, c);
		x += 4 * scale;
	}
}

std::string number(double v)
{
	char buf[32];
	std::snprintf(buf, sizeof(buf), "%.3g", v);
	return buf;
}

/// The bar from range.lo (bottom) to range.hi (top), the two numbers next to
/// its ends, and a triangle beyond an end that clamps values (as
/// matplotlib's extended colour bars).
void legend(Image& img, const RenderOptions& o, const ScalarRange& range)
{
	const int s = int(std::max(1u, img.height / 200));
	const int x0 = int(img.width) - int(legend_width(img.width, img.height)) + 4 * s;
	const int bw = 4 * s;
	const int ytop = int(img.height) * 15 / 100, ybot = int(img.height) * 85 / 100;
	for (int y = ytop; y <= ybot; ++y)
	{
		const Rgb c = viridis(ybot > ytop ? double(ybot - y) / (ybot - ytop) : 0.5);
		for (int x = x0; x < x0 + bw; ++x)
			put(img, x, y, c);
	}
	// triangles of height bw: row j (from the bar) spans bw - 2 j * ... pixels
	auto triangle = [&](int ybase, int dir, Rgb c) {
		for (int j = 1; j <= bw; ++j)
		{
			const double half = 0.5 * bw * double(bw - j) / bw;
			for (int x = x0; x < x0 + bw; ++x)
				if (std::abs(x + 0.5 - (x0 + 0.5 * bw)) <= half + 0.5)
					put(img, x, ybase + dir * j, c);
		}
	};
	if (range.above)
		triangle(ytop, -1, viridis(1.0));
	if (range.below)
		triangle(ybot, 1, viridis(0.0));
	const Rgb bg = o.background;
	const Rgb ink = 299 * bg.r + 587 * bg.g + 114 * bg.b > 128000 ? Rgb{0, 0, 0} : Rgb{255, 255, 255};
	text(img, x0 + bw + 2 * s, ytop, s, number(range.hi), ink);
	text(img, x0 + bw + 2 * s, ybot - 5 * s + 1, s, number(range.lo), ink);
}

} // namespace

Image rasterize(const Scene& s, const RenderOptions& o)
{
	if (o.width == 0 || o.height == 0)
		throw RenderError("the picture size must be at least 1x1");
	if (o.supersampling < 1 || o.supersampling > 8)
		throw RenderError("supersampling must be between 1 and 8");
	const int n = int(o.supersampling);
	const uint64_t samples = uint64_t(o.width) * o.height * uint64_t(n * n);
	if (samples > (uint64_t(1) << 26) || o.width > 32768 || o.height > 32768)
		throw RenderError("the picture is too large (" + std::to_string(o.width) + "x" + std::to_string(o.height) +
						  " with supersampling " + std::to_string(n) + ": more than 2^26 samples)");
	const bool show_legend = o.legend && s.scalar_on != Scene::ScalarOn::None;

	// camera: the bounding box's centre, scaled so that its projection fills
	// 90% of the drawing area in one direction
	const Frame f = camera_frame(o);
	Vec3 lo = s.points[0], hi = s.points[0];
	for (const Vec3& p : s.points)
	{
		lo = lo.cwiseMin(p);
		hi = hi.cwiseMax(p);
	}
	const Vec3 centre = 0.5 * (lo + hi);
	double eu = 0.0, ev = 0.0;
	for (int k = 0; k < 8; ++k)
	{
		const Vec3 corner((k & 1) ? hi[0] : lo[0], (k & 2) ? hi[1] : lo[1], (k & 4) ? hi[2] : lo[2]);
		eu = std::max(eu, 2.0 * std::abs((corner - centre).dot(f.right)));
		ev = std::max(ev, 2.0 * std::abs((corner - centre).dot(f.up)));
	}
	const double dw = double(o.width - (show_legend ? legend_width(o.width, o.height) : 0u));
	const double dh = double(o.height);
	double k = 1.0;
	if (eu > 0.0 && ev > 0.0)
		k = 0.9 * std::min(dw / eu, dh / ev);
	else if (eu > 0.0)
		k = 0.9 * dw / eu;
	else if (ev > 0.0)
		k = 0.9 * dh / ev;

	Target g;
	g.w = int(o.width) * n;
	g.h = int(o.height) * n;
	const std::size_t ns = std::size_t(g.w) * g.h;
	g.depth.assign(ns, -std::numeric_limits<float>::infinity());
	g.tri.assign(ns, NONE);
	const std::size_t nv = s.points.size();
	g.fx.resize(nv);
	g.fy.resize(nv);
	g.sx.resize(nv);
	g.sy.resize(nv);
	g.z.resize(nv);
	for (std::size_t i = 0; i < nv; ++i)
	{
		const Vec3 d = s.points[i] - centre;
		g.sx[i] = n * (dw / 2.0 + d.dot(f.right) * k);
		g.sy[i] = n * (dh / 2.0 - d.dot(f.up) * k);
		g.fx[i] = std::llround(g.sx[i] * SUB);
		g.fy[i] = std::llround(g.sy[i] * SUB);
		g.z[i] = float(d.dot(f.back));
	}

	visibility(s, g);

	const Shader shader(s, o, f.back);
	g.rgb.resize(3 * ns);
	for (int y = 0; y < g.h; ++y)
		for (int x = 0; x < g.w; ++x)
		{
			const std::size_t i = std::size_t(y) * g.w + x;
			const Rgb c =
				g.tri[i] == NONE ? o.background : shader.shade(g, g.tri[i], x * SUB + SUB / 2, y * SUB + SUB / 2);
			g.rgb[3 * i] = c.r;
			g.rgb[3 * i + 1] = c.g;
			g.rgb[3 * i + 2] = c.b;
		}

	// overlays, in samples: edges one pixel wide, depth-tested with a bias of
	// 0.5% of the diagonal of the bounding box so that the edges of the
	// visible faces win against those faces; defects with the same test, in
	// full colour where visible and faint (25%) where hidden
	const float bias = float(0.005 * (hi - lo).norm());
	for (std::size_t e = 0; 2 * e < s.edges.size(); ++e)
		g.line(s.edges[2 * e], s.edges[2 * e + 1], n, bias, Target::Mode::Test, o.edge_color);
	if (!s.boundary_edges.empty() || !s.split_vertices.empty())
		g.stamp.assign(ns, 0);
	for (std::size_t e = 0; 2 * e < s.boundary_edges.size(); ++e)
		g.line(s.boundary_edges[2 * e], s.boundary_edges[2 * e + 1], 2 * n, bias, Target::Mode::Defect,
			   Rgb{230, 25, 25});
	// the dots go over the lines: a sample of a line may take a dot's colour
	std::fill(g.stamp.begin(), g.stamp.end(), uint8_t(0));
	for (uint32_t v : s.split_vertices)
		g.dot(v, 3.0 * n, bias, Rgb{255, 140, 0});

	// box filter
	Image img;
	img.width = o.width;
	img.height = o.height;
	img.rgb.resize(std::size_t(o.width) * o.height * 3);
	const uint32_t nn = uint32_t(n * n);
	for (uint32_t y = 0; y < o.height; ++y)
		for (uint32_t x = 0; x < o.width; ++x)
			for (int ch = 0; ch < 3; ++ch)
			{
				uint32_t sum = 0;
				for (int j = 0; j < n; ++j)
				{
					const uint8_t* row = g.rgb.data() + 3 * ((std::size_t(y) * n + j) * g.w + std::size_t(x) * n);
					for (int i = 0; i < n; ++i)
						sum += row[3 * i + ch];
				}
				img.rgb[(std::size_t(y) * o.width + x) * 3 + ch] = uint8_t((sum + nn / 2) / nn);
			}

	if (show_legend)
		legend(img, o, shader.range);
	return img;
}

} // namespace detail

} // namespace cgogn::render
