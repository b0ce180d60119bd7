// SPDX-License-Identifier: MIT
// Wavefront OBJ: v (optionally with r g b), vt, vn, f with v, v/t, v//n, v/t/n
// corners and negative (relative) indices. o, g, s, usemtl, mtllib, l, p and
// the free-form geometry statements are ignored; any other keyword is an error.
// Texture coordinates and normals become vertex attributes (`tex_coord` Vec2,
// `normal` Vec3) when every corner of a vertex uses the same one; otherwise
// they are not kept.
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <algorithm>
#include <array>

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

// Per-vertex attribute from per-corner indices, when consistent.
void corner_column(MeshData& d, const std::vector<uint32>& corner, const std::vector<double>& values, uint32 dim,
				   const char* name)
{
	if (values.empty() || corner.empty())
		return;
	std::vector<uint32> of_vertex(d.nb_vertices(), NONE);
	for (std::size_t c = 0; c < corner.size(); ++c)
	{
		const uint32 v = d.cell_vertices[c];
		if (corner[c] == NONE)
			return;
		if (of_vertex[v] == NONE)
			of_vertex[v] = corner[c];
		else if (of_vertex[v] != corner[c] && !std::equal(values.begin() + std::ptrdiff_t(of_vertex[v]) * dim,
														  values.begin() + std::ptrdiff_t(of_vertex[v] + 1) * dim,
														  values.begin() + std::ptrdiff_t(corner[c]) * dim))
			return;
	}
	Column col{name, dim, std::vector<double>(std::size_t(d.nb_vertices()) * dim, 0.0)};
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
		if (of_vertex[v] != NONE)
			std::copy_n(values.begin() + std::ptrdiff_t(of_vertex[v]) * dim, dim,
						col.values.begin() + std::ptrdiff_t(v) * dim);
	d.vertex_columns.push_back(std::move(col));
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

std::string write_obj(const MeshData& d)
{
	std::string s;
	s.reserve(std::size_t(d.nb_vertices()) * 40 + d.cell_vertices.size() * 8);
	const Column* normal = d.find_vertex_column("normal");
	const Column* tex = d.find_vertex_column("tex_coord");
	const Column* color = d.find_vertex_column("color");
	if (normal && normal->dim != 3)
		normal = nullptr;
	if (tex && tex->dim != 2)
		tex = nullptr;
	if (color && color->dim != 3)
		color = nullptr;
	auto put_line = [&](const char* key, const double* v, uint32 n) {
		s += key;
		for (uint32 k = 0; k < n; ++k)
		{
			s += ' ';
			append_double(s, v[k]);
		}
	};
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
	{
		put_line("v", &d.positions[3 * std::size_t(v)], 3);
		if (color)
			for (uint32 k = 0; k < 3; ++k)
			{
				s += ' ';
				append_double(s, color->values[3 * std::size_t(v) + k]);
			}
		s += '\n';
	}
	if (tex)
		for (uint32 v = 0; v < d.nb_vertices(); ++v)
		{
			put_line("vt", &tex->values[2 * std::size_t(v)], 2);
			s += '\n';
		}
	if (normal)
		for (uint32 v = 0; v < d.nb_vertices(); ++v)
		{
			put_line("vn", &normal->values[3 * std::size_t(v)], 3);
			s += '\n';
		}
	std::size_t k = 0;
	for (uint32 f = 0; f < d.nb_cells(); ++f)
	{
		s += 'f';
		for (uint32 i = 0; i < d.cell_sizes[f]; ++i)
		{
			const uint64 id = d.cell_vertices[k++] + 1;
			s += ' ';
			append_uint(s, id);
			if (tex || normal)
			{
				s += '/';
				if (tex)
					append_uint(s, id);
				if (normal)
				{
					s += '/';
					append_uint(s, id);
				}
			}
		}
		s += '\n';
	}
	return s;
}

} // namespace cgogn::io::detail
