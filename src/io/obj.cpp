// SPDX-License-Identifier: MIT
// Wavefront OBJ: v (optionally with r g b), vt, vn, f with v, v/t, v//n, v/t/n
// corners and negative (relative) indices. o, g, s, usemtl, mtllib, l, p and
// the free-form geometry statements are ignored; any other keyword is an error.
// Texture coordinates and normals become vertex attributes (`tex_coord` Vec2,
// `normal` Vec3) when every corner of a vertex uses the same value;
// otherwise (seams, creases) corner attributes of those names, on the darts.
// Writing, corner attributes give vt/vn lines shared by the corners of equal
// value.
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <algorithm>
#include <array>
#include <map>

namespace cgogn::io::detail
{

namespace
{

bool ignored_keyword(std::string_view k)
{
	static constexpr std::array<std::string_view, 33> ignored = {
		"o",      "g",      "s",          "usemtl",    "mtllib", "l",     "p",        "vp",       "cstype",
		"deg",    "bmat",   "step",       "curv",      "curv2",  "surf",  "parm",     "trim",     "hole",
		"scrv",   "sp",     "end",        "con",       "mg",     "bevel", "c_interp", "d_interp", "lod",
		"maplib", "usemap", "shadow_obj", "trace_obj", "ctech",  "stech"};
	return std::find(ignored.begin(), ignored.end(), k) != ignored.end();
}

// Resolves an OBJ index (1-based, or negative: relative to the current count).
uint32 resolve(const TextReader& r, int64 i, std::size_t count, const char* what)
{
	int64 k = i > 0 ? i - 1 : int64(count) + i;
	if (i == 0 || k < 0 || k >= int64(count))
		r.fail(std::string(what) + " index " + std::to_string(i) + " out of range (" + std::to_string(count) +
			   " defined so far)");
	return uint32(k);
}

constexpr uint32 NONE = INVALID_INDEX;

// The data of per-corner indices into `values` (dim values each): a vertex
// column when every corner of a vertex has the same value, else a corner
// column (a corner without an index: zeros).
void corner_column(MeshData& d, const std::vector<uint32>& corner, const std::vector<double>& values, uint32 dim,
				   const char* name)
{
	if (values.empty() || corner.empty())
		return;
	auto value = [&](uint32 i) { return values.begin() + std::ptrdiff_t(i) * dim; };
	std::vector<uint32> of_vertex(d.nb_vertices(), NONE);
	bool per_vertex = true;
	for (std::size_t c = 0; c < corner.size() && per_vertex; ++c)
	{
		const uint32 v = d.cell_vertices[c];
		if (corner[c] == NONE)
			per_vertex = false;
		else if (of_vertex[v] == NONE)
			of_vertex[v] = corner[c];
		else if (of_vertex[v] != corner[c] &&
				 !std::equal(value(of_vertex[v]), value(of_vertex[v] + 1), value(corner[c])))
			per_vertex = false;
	}
	if (per_vertex)
	{
		Column col{name, dim, std::vector<double>(std::size_t(d.nb_vertices()) * dim, 0.0)};
		for (uint32 v = 0; v < d.nb_vertices(); ++v)
			if (of_vertex[v] != NONE)
				std::copy_n(value(of_vertex[v]), dim, col.values.begin() + std::ptrdiff_t(v) * dim);
		d.vertex_columns.push_back(std::move(col));
		return;
	}
	Column col{name, dim, {}};
	col.values.reserve(corner.size() * dim);
	for (uint32 c : corner)
		if (c == NONE)
			col.values.insert(col.values.end(), dim, 0.0);
		else
			col.values.insert(col.values.end(), value(c), value(c + 1));
	d.corner_columns.push_back(std::move(col));
}

} // namespace

MeshData read_obj(std::string_view text, const std::string& path)
{
	TextReader r(text, path);
	MeshData d;
	std::vector<double> tex, normals, colors;
	std::vector<uint32> corner_tex, corner_normal;
	bool any_tex = false, any_normal = false;
	d.positions.reserve(std::min<std::size_t>(text.size() / 8, 3u << 20));

	while (!r.at_end())
	{
		std::string_view k = r.token();
		if (k == "v")
		{
			for (int i = 0; i < 3; ++i)
				d.positions.push_back(r.to_double(r.token_in_line(), "a vertex coordinate"));
			// optional w, or r g b (common extension)
			std::array<double, 4> extra{};
			int n = 0;
			while (!r.at_eol() && n < 4)
				extra[std::size_t(n++)] = r.to_double(r.token_in_line(), "a vertex value");
			if (n >= 3)
			{
				if (colors.empty())
					colors.assign(d.positions.size() - 3, 0.0);
				colors.insert(colors.end(), extra.begin() + (n == 4), extra.begin() + (n == 4) + 3);
			}
			else if (!colors.empty())
				colors.insert(colors.end(), {0.0, 0.0, 0.0});
		}
		else if (k == "vt")
		{
			tex.push_back(r.to_double(r.token_in_line(), "a texture coordinate"));
			tex.push_back(r.at_eol() ? 0.0 : r.to_double(r.token_in_line(), "a texture coordinate"));
			if (!r.at_eol())
				r.to_double(r.token_in_line(), "a texture coordinate"); // w, not kept
		}
		else if (k == "vn")
			for (int i = 0; i < 3; ++i)
				normals.push_back(r.to_double(r.token_in_line(), "a normal coordinate"));
		else if (k == "f" || k == "fo")
		{
			uint32 n = 0;
			while (!r.at_eol())
			{
				std::string_view c = r.token_in_line();
				// v, v/t, v//n, v/t/n
				std::array<std::string_view, 3> parts{};
				std::size_t p = 0;
				for (std::size_t i = 0; i < 3; ++i)
				{
					std::size_t q = c.find('/', p);
					parts[i] = c.substr(p, q == std::string_view::npos ? std::string_view::npos : q - p);
					if (q == std::string_view::npos)
						break;
					p = q + 1;
					if (i == 2)
						r.fail("malformed face corner '" + TextReader::printable(c) + "'");
				}
				d.cell_vertices.push_back(resolve(r, r.to_int(parts[0], "a vertex index"), d.nb_vertices(), "vertex"));
				uint32 t = NONE, nn = NONE;
				if (!parts[1].empty())
				{
					t = resolve(r, r.to_int(parts[1], "a texture index"), tex.size() / 2, "texture coordinate");
					any_tex = true;
				}
				if (!parts[2].empty())
				{
					nn = resolve(r, r.to_int(parts[2], "a normal index"), normals.size() / 3, "normal");
					any_normal = true;
				}
				if (any_tex && corner_tex.size() + 1 < d.cell_vertices.size())
					corner_tex.resize(d.cell_vertices.size() - 1, NONE);
				if (any_normal && corner_normal.size() + 1 < d.cell_vertices.size())
					corner_normal.resize(d.cell_vertices.size() - 1, NONE);
				if (any_tex)
					corner_tex.push_back(t);
				if (any_normal)
					corner_normal.push_back(nn);
				++n;
			}
			d.cell_sizes.push_back(n);
		}
		else if (ignored_keyword(k))
			r.rest_of_line();
		else
			r.fail("unknown OBJ statement '" + TextReader::printable(k) + "'");
		if (!r.at_eol())
			r.fail("unexpected '" + TextReader::printable(r.token_in_line()) + "' at the end of the line");
	}
	if (any_tex)
		corner_tex.resize(d.cell_vertices.size(), NONE);
	if (any_normal)
		corner_normal.resize(d.cell_vertices.size(), NONE);
	if (!colors.empty())
	{
		colors.resize(d.positions.size(), 0.0);
		d.vertex_columns.push_back(Column{"color", 3, std::move(colors)});
	}
	corner_column(d, corner_tex, tex, 2, "tex_coord");
	corner_column(d, corner_normal, normals, 3, "normal");
	return d;
}

namespace
{

// The vt or vn lines of a writer and the index of each corner into them:
// from a corner column (values shared by the corners that agree), else from
// a vertex column (one line per vertex), else none.
struct CornerIndices
{
	const double* values = nullptr; // the lines' values, dim each
	std::vector<double> shared;     // the distinct values of a corner column
	std::vector<uint32> of_corner;  // 0-based line of each corner
	uint32 nb_lines = 0;
};

CornerIndices corner_indices(const MeshData& d, const char* name, uint32 dim)
{
	CornerIndices out;
	for (const Column& c : d.corner_columns)
		if (c.name == name && c.dim == dim)
		{
			std::map<std::vector<double>, uint32> line_of;
			std::vector<double> v(dim);
			out.of_corner.reserve(d.cell_vertices.size());
			for (std::size_t k = 0; k < d.cell_vertices.size(); ++k)
			{
				std::copy_n(c.values.begin() + std::ptrdiff_t(k * dim), dim, v.begin());
				const auto [it, added] = line_of.try_emplace(v, out.nb_lines);
				if (added)
				{
					out.shared.insert(out.shared.end(), v.begin(), v.end());
					++out.nb_lines;
				}
				out.of_corner.push_back(it->second);
			}
			out.values = out.shared.data();
			return out;
		}
	const Column* c = d.find_vertex_column(name);
	if (c != nullptr && c->dim == dim)
	{
		out.values = c->values.data();
		out.nb_lines = d.nb_vertices();
		out.of_corner.assign(d.cell_vertices.begin(), d.cell_vertices.end());
	}
	return out;
}

} // namespace

std::string write_obj(const MeshData& d)
{
	std::string s;
	s.reserve(std::size_t(d.nb_vertices()) * 40 + d.cell_vertices.size() * 8);
	const CornerIndices tex = corner_indices(d, "tex_coord", 2);
	const CornerIndices normal = corner_indices(d, "normal", 3);
	const Column* color = d.find_vertex_column("color");
	if (color && color->dim != 3)
		color = nullptr;
	auto put_line = [&](const char* key, const double* v, uint32 n) {
		s += key;
		for (uint32 k = 0; k < n; ++k)
		{
			s += ' ';
			append_double(s, v[k]);
		}
		s += '\n';
	};
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
	{
		s += 'v';
		for (uint32 k = 0; k < 3; ++k)
		{
			s += ' ';
			append_double(s, d.positions[3 * std::size_t(v) + k]);
		}
		if (color)
			for (uint32 k = 0; k < 3; ++k)
			{
				s += ' ';
				append_double(s, color->values[3 * std::size_t(v) + k]);
			}
		s += '\n';
	}
	for (uint32 i = 0; i < tex.nb_lines; ++i)
		put_line("vt", tex.values + 2 * std::size_t(i), 2);
	for (uint32 i = 0; i < normal.nb_lines; ++i)
		put_line("vn", normal.values + 3 * std::size_t(i), 3);
	const bool with_tex = tex.values != nullptr, with_normal = normal.values != nullptr;
	std::size_t k = 0;
	for (uint32 f = 0; f < d.nb_cells(); ++f)
	{
		s += 'f';
		for (uint32 i = 0; i < d.cell_sizes[f]; ++i, ++k)
		{
			s += ' ';
			append_uint(s, uint64(d.cell_vertices[k]) + 1);
			if (with_tex || with_normal)
			{
				s += '/';
				if (with_tex)
					append_uint(s, uint64(tex.of_corner[k]) + 1);
				if (with_normal)
				{
					s += '/';
					append_uint(s, uint64(normal.of_corner[k]) + 1);
				}
			}
		}
		s += '\n';
	}
	return s;
}

} // namespace cgogn::io::detail
