// SPDX-License-Identifier: MIT
// OFF: [ST][C][N]OFF header (comments with '#'), counts, vertices with optional
// normal, color and texture coordinates, faces with an optional color.
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <array>

namespace cgogn::io::detail
{

MeshData read_off(std::string_view text, const std::string& path)
{
	TextReader r(text, path);
	MeshData d;
	std::string_view head = r.token();
	if (head.size() < 3 || head.substr(head.size() - 3) != "OFF")
		r.fail("not an OFF file: expected a header ending in 'OFF', found '" + TextReader::printable(head) + "'");
	std::string_view prefix = head.substr(0, head.size() - 3);
	bool has_tex = false, has_color = false, has_normal = false;
	if (prefix.substr(0, 2) == "ST")
	{
		has_tex = true;
		prefix.remove_prefix(2);
	}
	if (!prefix.empty() && prefix.front() == 'C')
	{
		has_color = true;
		prefix.remove_prefix(1);
	}
	if (!prefix.empty() && prefix.front() == 'N')
	{
		has_normal = true;
		prefix.remove_prefix(1);
	}
	if (!prefix.empty())
		r.fail("unsupported OFF variant '" + TextReader::printable(head) + "' (4D and nOFF are not read)");
	if (!r.at_eol())
	{
		// "OFF BINARY" or counts on the header line
		const char* save = r.position();
		std::string_view t = r.token_in_line();
		if (t == "BINARY")
			r.fail("binary OFF is not supported");
		r.set_position(save);
	}

	const uint32 nv = r.read_uint("number of vertices");
	const uint32 nf = r.read_uint("number of faces");
	r.read_uint("number of edges");
	r.check_count(nv, 6, "vertices"); // "x y z\n" at least
	r.check_count(nf, 2, "faces");    // "0\n" at least
	d.positions.reserve(3 * std::size_t(nv));

	d.vertex_columns.reserve(3); // the pointers below stay valid
	Column* normal = nullptr;
	Column* color = nullptr;
	Column* tex = nullptr;
	if (has_normal)
		normal = &d.vertex_columns.emplace_back(Column{"normal", 3, {}});
	if (has_color)
		color = &d.vertex_columns.emplace_back(Column{"color", 3, {}});
	if (has_tex)
		tex = &d.vertex_columns.emplace_back(Column{"tex_coord", 2, {}});

	for (uint32 v = 0; v < nv; ++v)
	{
		for (int k = 0; k < 3; ++k)
			d.positions.push_back(r.read_double("a vertex coordinate"));
		if (normal)
			for (int k = 0; k < 3; ++k)
				normal->values.push_back(r.read_double("a normal coordinate"));
		if (color)
		{
			// r g b [a]: the alpha, when present, is dropped
			for (int k = 0; k < 3; ++k)
				color->values.push_back(r.read_double("a color component"));
			if (!r.at_eol() && !tex)
				r.read_double("a color component");
			else if (tex)
			{
				// 4 numbers left on the line: r g b a were followed by s t
				const char* save = r.position();
				int n = 0;
				while (!r.at_eol() && n < 4)
				{
					r.token_in_line();
					++n;
				}
				r.set_position(save);
				if (n == 3)
					r.read_double("a color component");
			}
		}
		if (tex)
			for (int k = 0; k < 2; ++k)
				tex->values.push_back(r.read_double("a texture coordinate"));
		// anything else on the vertex line is ignored
		if (!r.at_eol())
			r.next_line();
	}

	d.cell_sizes.reserve(nf);
	d.cell_vertices.reserve(std::min<std::size_t>(3 * std::size_t(nf), r.remaining() / 2));
	Column* fcolor = nullptr;
	for (uint32 f = 0; f < nf; ++f)
	{
		const uint32 n = r.read_uint("a face size");
		if (n > r.remaining() / 2)
			r.fail("face of " + std::to_string(n) + " vertices does not fit in the rest of the file");
		d.cell_sizes.push_back(n);
		for (uint32 i = 0; i < n; ++i)
		{
			const uint32 id = r.read_uint("a vertex index");
			if (id >= nv)
				r.fail("vertex index " + std::to_string(id) + " out of range (the file has " + std::to_string(nv) +
					   " vertices)");
			d.cell_vertices.push_back(id);
		}
		// optional face color: 3 or 4 numbers on the same line
		if (!r.at_eol())
		{
			std::array<double, 3> c{};
			for (int k = 0; k < 3; ++k)
				c[k] = r.to_double(r.token_in_line(), "a face color component");
			if (!fcolor)
			{
				fcolor = &d.cell_columns.emplace_back(Column{"color", 3, {}});
				fcolor->values.assign(3 * std::size_t(f), 0.0);
			}
			fcolor->values.insert(fcolor->values.end(), c.begin(), c.end());
			if (!r.at_eol())
				r.next_line();
		}
		else if (fcolor)
			fcolor->values.insert(fcolor->values.end(), {0.0, 0.0, 0.0});
	}
	if (!r.at_end())
	{
		// trailing content after the declared faces: tolerated only if blank
		r.fail("unexpected content after the " + std::to_string(nf) + " declared faces: '" +
			   TextReader::printable(r.token()) + "'");
	}
	return d;
}

std::string write_off(const MeshData& d)
{
	std::string s;
	s.reserve(std::size_t(d.nb_vertices()) * 40 + d.cell_vertices.size() * 8);
	const Column* normal = d.find_vertex_column("normal");
	const Column* color = d.find_vertex_column("color");
	const Column* tex = d.find_vertex_column("tex_coord");
	if (normal && normal->dim != 3)
		normal = nullptr;
	if (color && color->dim != 3)
		color = nullptr;
	if (tex && tex->dim != 2)
		tex = nullptr;
	const Column* fcolor = d.find_cell_column("color");
	if (fcolor && fcolor->dim != 3)
		fcolor = nullptr;
	s += tex ? "ST" : "";
	s += color ? "C" : "";
	s += normal ? "N" : "";
	s += "OFF\n";
	append_uint(s, d.nb_vertices());
	s += ' ';
	append_uint(s, d.nb_cells());
	s += " 0\n";
	auto put = [&](const Column* c, uint32 i) {
		if (!c)
			return;
		for (uint32 k = 0; k < c->dim; ++k)
		{
			s += ' ';
			append_double(s, c->values[std::size_t(i) * c->dim + k]);
		}
	};
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
	{
		append_double(s, d.positions[3 * std::size_t(v)]);
		s += ' ';
		append_double(s, d.positions[3 * std::size_t(v) + 1]);
		s += ' ';
		append_double(s, d.positions[3 * std::size_t(v) + 2]);
		put(normal, v);
		put(color, v);
		put(tex, v);
		s += '\n';
	}
	std::size_t k = 0;
	for (uint32 f = 0; f < d.nb_cells(); ++f)
	{
		const uint32 n = d.cell_sizes[f];
		append_uint(s, n);
		for (uint32 i = 0; i < n; ++i)
		{
			s += ' ';
			append_uint(s, d.cell_vertices[k++]);
		}
		put(fcolor, f);
		s += '\n';
	}
	return s;
}

} // namespace cgogn::io::detail
