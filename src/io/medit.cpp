// SPDX-License-Identifier: MIT
// MEDIT ascii .mesh: keyword sections (Vertices, Tetrahedra, Pyramids, Prisms,
// Hexahedra; boundary and annotation sections are read and ignored), 1-based
// indices, a reference number after each record (not kept).
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"

#include <array>

namespace cgogn::io::detail
{

namespace
{

// Sections we skip: their name and the number of values per record
// (0: dimension-dependent).
int skipped_record_size(std::string_view k, uint32 dim)
{
	struct S
	{
		std::string_view name;
		int size;
	};
	static constexpr std::array<S, 12> sections = {{{"Edges", 3},
													{"Triangles", 4},
													{"Quadrilaterals", 5},
													{"Corners", 1},
													{"Ridges", 1},
													{"RequiredVertices", 1},
													{"RequiredEdges", 1},
													{"RequiredTriangles", 1},
													{"Normals", 0},
													{"Tangents", 0},
													{"NormalAtVertices", 2},
													{"TangentAtVertices", 2}}};
	for (const auto& s : sections)
		if (s.name == k)
			return s.size == 0 ? int(dim) : s.size;
	return -1;
}

} // namespace

MeshData read_medit(std::string_view text, const std::string& path)
{
	TextReader r(text, path);
	MeshData d;
	std::string_view k = r.token();
	if (k != "MeshVersionFormatted")
		r.fail("not a MEDIT file: expected 'MeshVersionFormatted', found '" + TextReader::printable(k) + "'");
	r.read_uint("a version number");
	uint32 dim = 3;
	bool have_vertices = false;
	// cells are checked against the vertex count at the end (sections may come in any order)
	std::vector<uint64> cell_lines;
	while (true)
	{
		k = r.token();
		if (k.empty() || k == "End")
			break;
		if (k == "Dimension")
		{
			dim = r.read_uint("the dimension");
			if (dim != 2 && dim != 3)
				r.fail("dimension " + std::to_string(dim) + " is not supported");
			continue;
		}
		const uint64 section_line = r.line();
		const uint32 n = r.read_uint("a record count");
		if (k == "Vertices")
		{
			if (have_vertices)
				r.fail("a second Vertices section");
			have_vertices = true;
			r.check_count(n, 2 * (dim + 1), "vertices");
			d.positions.reserve(3 * std::size_t(n));
			for (uint32 i = 0; i < n; ++i)
			{
				for (uint32 c = 0; c < dim; ++c)
					d.positions.push_back(r.read_double("a vertex coordinate"));
				if (dim == 2)
					d.positions.push_back(0.0);
				r.read_int("a vertex reference");
			}
			continue;
		}
		uint32 size = 0;
		if (k == "Tetrahedra")
			size = 4;
		else if (k == "Pyramids")
			size = 5;
		else if (k == "Prisms")
			size = 6;
		else if (k == "Hexahedra")
			size = 8;
		if (size > 0)
		{
			r.check_count(n, 2 * (size + 1), "cells");
			d.cell_sizes.reserve(d.cell_sizes.size() + n);
			d.cell_vertices.reserve(d.cell_vertices.size() + std::size_t(n) * size);
			for (uint32 i = 0; i < n; ++i)
			{
				d.cell_sizes.push_back(size);
				for (uint32 j = 0; j < size; ++j)
				{
					const uint32 v = r.read_uint("a vertex index");
					if (v == 0)
						r.fail("vertex index 0 (MEDIT indices start at 1)");
					if (have_vertices && v > d.nb_vertices())
						r.fail("vertex index " + std::to_string(v) + " out of range (the file has " +
							   std::to_string(d.nb_vertices()) + " vertices)");
					d.cell_vertices.push_back(v - 1);
				}
				r.read_int("a cell reference");
			}
			cell_lines.push_back(section_line);
			continue;
		}
		const int skip = skipped_record_size(k, dim);
		if (skip < 0)
			r.fail("unknown MEDIT section '" + TextReader::printable(k) + "'");
		r.check_count(n, 2 * uint64(skip), "records");
		for (uint64 i = 0; i < uint64(n) * uint64(skip); ++i)
			r.read_double("a value");
	}
	if (!have_vertices)
		r.fail("no Vertices section");
	for (uint32 v : d.cell_vertices)
		if (v >= d.nb_vertices())
			throw Error(path, "vertex index " + std::to_string(v + 1) + " out of range (the file has " +
								  std::to_string(d.nb_vertices()) + " vertices)");
	return d;
}

std::string write_medit(const MeshData& d)
{
	std::string s = "MeshVersionFormatted 2\nDimension 3\n\nVertices\n";
	s.reserve(std::size_t(d.nb_vertices()) * 60 + d.cell_vertices.size() * 8);
	append_uint(s, d.nb_vertices());
	s += '\n';
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
	{
		for (uint32 k = 0; k < 3; ++k)
		{
			append_double(s, d.positions[3 * std::size_t(v) + k]);
			s += ' ';
		}
		s += "0\n";
	}
	// cells grouped by kind, in the order of MEDIT's sections
	std::vector<std::size_t> first(d.nb_cells());
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		first[c] = k;
		k += d.cell_sizes[c];
	}
	const std::array<std::pair<uint32, const char*>, 4> kinds = {
		{{4, "Tetrahedra"}, {5, "Pyramids"}, {6, "Prisms"}, {8, "Hexahedra"}}};
	for (const auto& [size, name] : kinds)
	{
		uint32 count = 0;
		for (uint32 n : d.cell_sizes)
			count += n == size;
		if (count == 0)
			continue;
		s += '\n';
		s += name;
		s += '\n';
		append_uint(s, count);
		s += '\n';
		for (uint32 c = 0; c < d.nb_cells(); ++c)
		{
			if (d.cell_sizes[c] != size)
				continue;
			for (uint32 i = 0; i < size; ++i)
			{
				append_uint(s, uint64(d.cell_vertices[first[c] + i]) + 1);
				s += ' ';
			}
			s += "0\n";
		}
	}
	s += "\nEnd\n";
	return s;
}

} // namespace cgogn::io::detail
