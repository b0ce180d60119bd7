// SPDX-License-Identifier: MIT
// The HTML viewer: one self-contained page holding the mesh (base64 typed
// arrays described by a JSON object) and the bundled script (three.js and
// viewer/src/main.js, embedded in the library at build time).
//
// The page reads, by element id:
//   cgogn-meta            JSON: title, counts, dimension, bbox, viridis
//                         table, surface colour, the arrays' types and
//                         lengths, the colour quantities, the initial state
//   cgogn-positions       Float32, 3 per vertex
//   cgogn-triangles       Uint32, 3 vertex numbers per triangle
//   cgogn-flags           Uint8 per triangle: Scene::EDGE_* and
//                         Scene::BOUNDARY_* bits, ON_BOUNDARY (volumes)
//   cgogn-split_vertices  Uint32 vertex numbers
//   cgogn-cell_offsets    Uint32, volumes: cell c has the triangles
//                         [offsets[c], offsets[c+1])
//   cgogn-qN              Uint8 per vertex or per triangle: quantity N
//                         normalized over its range times 254, 255 when the
//                         value is not finite (the page maps it to one of the
//                         256 viridis colours: 8 bits lose nothing visible)
#include "extract.h"

#include <cerrno>
#include <cstring>

namespace cgogn::render
{

namespace detail
{
// generated at build time from the bundled script (src/render/CMakeLists.txt)
extern const unsigned char viewer_bundle[];
extern const std::size_t viewer_bundle_size;
} // namespace detail

namespace
{

using detail::Extractor;
using detail::Scene;

constexpr uint8_t ON_BOUNDARY = 64;

void base64(std::string& out, const void* data, std::size_t n)
{
	static const char table[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	const auto* p = static_cast<const unsigned char*>(data);
	out.reserve(out.size() + (n + 2) / 3 * 4);
	std::size_t i = 0;
	for (; i + 2 < n; i += 3)
	{
		const uint32_t v = uint32_t(p[i]) << 16 | uint32_t(p[i + 1]) << 8 | p[i + 2];
		out += table[v >> 18];
		out += table[(v >> 12) & 63];
		out += table[(v >> 6) & 63];
		out += table[v & 63];
	}
	if (i < n)
	{
		const uint32_t v = uint32_t(p[i]) << 16 | (i + 1 < n ? uint32_t(p[i + 1]) << 8 : 0u);
		out += table[v >> 18];
		out += table[(v >> 12) & 63];
		out += i + 1 < n ? table[(v >> 6) & 63] : '=';
		out += '=';
	}
}

/// A JSON string; <, > and & escaped too, so that it is safe inside a
/// <script> element.
std::string json_string(const std::string& s)
{
	std::string out = "\"";
	for (unsigned char c : s)
	{
		if (c == '"' || c == '\\')
			out += {'\\', char(c)};
		else if (c < 0x20 || c == '<' || c == '>' || c == '&')
		{
			char buf[8];
			std::snprintf(buf, sizeof(buf), "\\u%04x", c);
			out += buf;
		}
		else
			out += char(c);
	}
	return out + "\"";
}

std::string html_text(const std::string& s)
{
	std::string out;
	for (char c : s)
	{
		switch (c)
		{
		case '&':
			out += "&amp;";
			break;
		case '<':
			out += "&lt;";
			break;
		case '>':
			out += "&gt;";
			break;
		case '"':
			out += "&quot;";
			break;
		default:
			out += c;
		}
	}
	return out;
}

std::string json_number(double v)
{
	if (!std::isfinite(v))
		return "0";
	char buf[32];
	std::snprintf(buf, sizeof(buf), "%.9g", v);
	return buf;
}

/// The arrays of the page, little-endian (the typed arrays of every browser
/// platform are), in the order they are added.
struct Page
{
	struct Array
	{
		std::string name, type;
		std::size_t length;
		std::string data; // base64
	};
	std::vector<Array> arrays;

	template <typename T>
	void add(const std::string& name, const char* type, const std::vector<T>& v)
	{
		static_assert(std::is_arithmetic_v<T>);
		Array a{name, type, v.size(), {}};
		base64(a.data, v.data(), v.size() * sizeof(T));
		arrays.push_back(std::move(a));
	}
};

struct Quantity
{
	std::string label, array, on; // on: "vertices" or "triangles"
	ScalarRange range;
};

/// Quantity values as 0..254 over their robust range (255: no value); per
/// face values are spread to the face's triangles.
std::vector<uint8_t> quantize(const Scene& s, const ScalarRange& r)
{
	const bool faces = s.scalar_on == Scene::ScalarOn::Faces;
	const std::size_t n = faces ? s.triangle_face.size() : s.scalar.size();
	std::vector<uint8_t> q(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		const double t = r.normalized(faces ? s.scalar[s.triangle_face[i]] : s.scalar[i]);
		q[i] = std::isnan(t) ? uint8_t(255) : uint8_t(std::lround(t * 254.0));
	}
	return q;
}

template <typename MAP>
std::string page(const MAP& m, const AttributeArray<Vec3>& pos, const ViewerOptions& vo, Extractor<MAP>& x, Scene& s,
				 const std::vector<uint32_t>& cell_offsets)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;
	Page p;
	std::vector<float> positions;
	positions.reserve(3 * s.points.size());
	Vec3 lo = s.points[0], hi = s.points[0];
	for (const Vec3& v : s.points)
	{
		lo = lo.cwiseMin(v);
		hi = hi.cwiseMax(v);
		positions.insert(positions.end(), {float(v[0]), float(v[1]), float(v[2])});
	}
	p.add("positions", "Float32", positions);
	positions = {};
	p.add("triangles", "Uint32", s.triangles);
	p.add("flags", "Uint8", s.triangle_flags);
	p.add("split_vertices", "Uint32", s.split_vertices);
	if (MAP::dimension == 3)
		p.add("cell_offsets", "Uint32", cell_offsets);

	// the colour quantities: those of `render`, each computed by add_scalar
	struct Source
	{
		ColorSource color;
		std::string attribute, label;
	};
	std::vector<Source> sources;
	if constexpr (MAP::dimension == 2)
		sources.push_back({ColorSource::MeanCurvature, "", "mean curvature"});
	if constexpr (MAP::dimension == 2)
		sources.push_back({ColorSource::GaussianCurvature, "", "Gaussian curvature"});
	sources.push_back({ColorSource::Area, "", "face area"});
	sources.push_back({ColorSource::Quality, "", "triangle quality"});
	std::vector<std::string> names = detail::scalar_attribute_names(container_of<Vertex::ORBIT>(m));
	for (const std::string& n : detail::scalar_attribute_names(container_of<Face::ORBIT>(m)))
		names.push_back(n);
	if constexpr (MAP::dimension == 3)
		for (const std::string& n : detail::scalar_attribute_names(container_of<mesh_traits<MAP>::Volume::ORBIT>(m)))
			names.push_back(n);
	for (const std::string& n : names)
		if (std::find_if(sources.begin(), sources.end(), [&](const Source& q) { return q.attribute == n; }) ==
			sources.end())
			sources.push_back({ColorSource::Attribute, n, n});

	std::vector<Quantity> quantities{{"uniform", "", "", {}}};
	std::size_t initial = 0;
	if (vo.color == ColorSource::Attribute && std::find(names.begin(), names.end(), vo.attribute) == names.end())
	{
		std::string list;
		for (const std::string& n : names)
			list += (list.empty() ? "" : ", ") + n;
		throw RenderError("no double or float vertex or cell attribute named '" + vo.attribute +
						  "' (available: " + (list.empty() ? std::string("none") : list) + ")");
	}
	if (MAP::dimension == 3 && (vo.color == ColorSource::MeanCurvature || vo.color == ColorSource::GaussianCurvature))
		throw RenderError("curvature colours are defined on surfaces, not on volume meshes");
	RenderOptions ro;
	for (const Source& src : sources)
	{
		const bool selected =
			src.color == vo.color && (src.color != ColorSource::Attribute || src.attribute == vo.attribute);
		if (!vo.all_quantities && !selected)
			continue;
		ro.color = src.color;
		ro.attribute = src.attribute;
		s.scalar.clear();
		s.scalar_on = Scene::ScalarOn::None;
		detail::add_scalar(m, pos, ro, s, x.face_darts(), x.vertex_darts());
		Quantity q;
		q.label = src.label;
		q.array = "q" + std::to_string(quantities.size());
		q.on = s.scalar_on == Scene::ScalarOn::Vertices ? "vertices" : "triangles";
		q.range = scalar_range(s.scalar);
		p.add(q.array, "Uint8", quantize(s, q.range));
		if (selected)
			initial = quantities.size();
		quantities.push_back(std::move(q));
	}
	s.scalar = {};

	// ---- the page
	std::string meta = "{";
	const std::string title = vo.title.empty() ? std::string("cgogn view") : vo.title;
	meta += "\"title\":" + json_string(title);
	meta += ",\"dimension\":" + std::to_string(MAP::dimension);
	std::string counts = std::to_string(s.points.size()) + " vertices, " + std::to_string(x.face_darts().size()) +
						 (MAP::dimension == 2 ? " faces, " : " cell faces, ") + std::to_string(s.triangle_face.size()) +
						 " triangles";
	if (MAP::dimension == 3)
		counts += ", " + std::to_string(cell_offsets.size() - 1) + " volume cells";
	meta += ",\"counts\":" + json_string(counts);
	meta += ",\"bbox\":[";
	for (int i = 0; i < 6; ++i)
		meta += (i ? "," : "") + json_number(i < 3 ? lo[i] : hi[i - 3]);
	meta += "],\"surface_color\":[190,198,214],\"viridis\":[";
	for (int i = 0; i < 256; ++i)
	{
		const Rgb c = viridis(i / 255.0);
		meta += (i ? ",[" : "[") + std::to_string(c.r) + "," + std::to_string(c.g) + "," + std::to_string(c.b) + "]";
	}
	meta += "],\"arrays\":{";
	for (std::size_t i = 0; i < p.arrays.size(); ++i)
		meta += (i ? "," : "") + json_string(p.arrays[i].name) + ":{\"type\":\"" + p.arrays[i].type +
				"\",\"length\":" + std::to_string(p.arrays[i].length) + "}";
	meta += "},\"quantities\":[";
	for (std::size_t i = 0; i < quantities.size(); ++i)
	{
		const Quantity& q = quantities[i];
		meta += (i ? ",{" : "{") + std::string("\"label\":") + json_string(q.label);
		if (!q.array.empty())
			meta += ",\"array\":" + json_string(q.array) + ",\"on\":\"" + q.on +
					"\",\"lo\":" + json_number(q.range.lo) + ",\"hi\":" + json_number(q.range.hi) +
					",\"below\":" + (q.range.below ? "true" : "false") +
					",\"above\":" + (q.range.above ? "true" : "false");
		meta += "}";
	}
	meta += "],\"initial\":{\"color\":" + std::to_string(initial) + ",\"edges\":" + (vo.edges ? "true" : "false") +
			",\"defects\":" + (vo.show_defects ? "true" : "false") + "}}";

	std::size_t size = meta.size() + detail::viewer_bundle_size + 4096;
	for (const Page::Array& a : p.arrays)
		size += a.data.size() + 100;
	std::string html;
	html.reserve(size);
	html += R"(<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>)";
	html += html_text(title);
	html += R"(</title>
<style>
html, body { margin: 0; height: 100%; overflow: hidden; font: 13px system-ui, sans-serif; background: #fff; color: #222; }
#view { position: absolute; inset: 0; }
#ui { position: absolute; top: 8px; left: 8px; background: rgba(255, 255, 255, 0.9); padding: 8px 10px;
      border-radius: 6px; box-shadow: 0 1px 4px rgba(0, 0, 0, 0.25); max-width: 240px; }
#ui label { display: block; margin: 3px 0; }
#ui .group { border-top: 1px solid #ccc; margin-top: 6px; padding-top: 4px; }
#ui input[type=range] { width: 100%; }
#title { font-weight: bold; }
.small { font-size: 11px; color: #555; }
#legend { position: absolute; right: 16px; top: 15%; bottom: 15%; width: 110px; }
#legend-bar { position: absolute; left: 0; top: 0; bottom: 0; width: 18px; border: 1px solid #888; }
#legend-hi { position: absolute; left: 26px; top: -2px; }
#legend-lo { position: absolute; left: 26px; bottom: -2px; }
#legend-name { position: absolute; right: 0; top: -24px; white-space: nowrap; }
#no-webgl, #error { position: absolute; top: 35%; left: 10%; right: 10%; padding: 16px; border: 2px solid #c33;
                    background: #fff4f4; font-size: 16px; text-align: center; }
[hidden] { display: none !important; }
</style>
</head>
<body>
<div id="view"></div>
<div id="ui"><div id="title"></div><div id="counts" class="small"></div><div id="controls"></div>
<div class="small">drag: rotate; right drag or shift drag: pan; wheel: zoom</div></div>
<div id="legend" hidden><div id="legend-name"></div><div id="legend-bar"></div><div id="legend-hi"></div><div id="legend-lo"></div></div>
<div id="no-webgl" hidden><strong>WebGL is not available.</strong> This page draws the mesh with WebGL 2, which this
browser does not provide (it is disabled or not supported). Enable WebGL or open the file in another browser.
<span id="no-webgl-reason"></span></div>
<div id="error" hidden></div>
<noscript><div id="no-script">This page needs JavaScript to draw the mesh.</div></noscript>
<script type="application/json" id="cgogn-meta">)";
	html += meta;
	html += "</script>\n";
	for (const Page::Array& a : p.arrays)
	{
		html += "<script type=\"application/octet-stream\" id=\"cgogn-" + a.name + "\">";
		html += a.data;
		html += "</script>\n";
	}
	html += "<script>";
	// "</script" cannot appear inside the element: written "<\/script", the
	// same text inside the script's strings and regular expressions
	const std::string_view bundle(reinterpret_cast<const char*>(detail::viewer_bundle), detail::viewer_bundle_size);
	for (std::size_t i = 0; i < bundle.size();)
	{
		const std::size_t j = bundle.find("</script", i);
		html.append(bundle.substr(i, j == std::string_view::npos ? std::string_view::npos : j - i));
		if (j == std::string_view::npos)
			break;
		html += "<\\/script";
		i = j + 8;
	}
	html += "</script>\n</body>\n</html>\n";
	return html;
}

} // namespace

std::string viewer_html(const CMap2& m, const AttributeArray<Vec3>& pos, const ViewerOptions& options)
{
	RenderOptions ro;
	Extractor<CMap2> x(m, pos, ro);
	x.use_flags(false);
	Scene s = x.run([](Dart) { return true; });
	return page(m, pos, options, x, s, {});
}

std::string viewer_html(const CMap3& m, const AttributeArray<Vec3>& pos, const ViewerOptions& options)
{
	RenderOptions ro;
	Extractor<CMap3> x(m, pos, ro);
	x.use_flags(true);
	std::vector<uint32_t> offsets{0};
	std::vector<uint8_t> on_boundary; // per triangle
	bool any_boundary = false;
	std::vector<uint8_t> added; // per dart index: its phi1 orbit is added
	foreach_cell(m, [&](CMap3::Volume w) {
		// each phi1 orbit of w's darts is one face as seen from w
		foreach_dart_of_orbit(m, w, [&](Dart d) {
			if (d.index >= added.size())
				added.resize(std::size_t(d.index) + 1 + added.size() / 2, 0);
			if (added[d.index])
				return;
			Dart y = d;
			do
			{
				if (y.index >= added.size())
					added.resize(std::size_t(y.index) + 1 + added.size() / 2, 0);
				added[y.index] = 1;
				y = phi1(m, y);
			} while (y != d);
			const bool b = is_boundary(m, phi3(m, d));
			any_boundary = any_boundary || b;
			x.add_face(d);
			on_boundary.resize(x.scene().triangle_face.size(), b ? ON_BOUNDARY : 0);
		});
		offsets.push_back(uint32_t(x.scene().triangle_face.size()));
	});
	if (!any_boundary)
		throw RenderError("the volume mesh has no boundary face to render");
	Scene s = x.finish();
	for (std::size_t t = 0; t < s.triangle_flags.size(); ++t)
		s.triangle_flags[t] |= on_boundary[t];
	return page(m, pos, options, x, s, offsets);
}

void write_file(const std::string& bytes, const std::string& path)
{
	detail::write_file(path, [&](FILE* f) {
		return std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() ? std::string() : std::strerror(errno);
	});
}

void write_viewer_html(const CMap2& m, const AttributeArray<Vec3>& pos, const std::string& path,
					   const ViewerOptions& options)
{
	write_file(viewer_html(m, pos, options), path);
}

void write_viewer_html(const CMap3& m, const AttributeArray<Vec3>& pos, const std::string& path,
					   const ViewerOptions& options)
{
	write_file(viewer_html(m, pos, options), path);
}

} // namespace cgogn::render
