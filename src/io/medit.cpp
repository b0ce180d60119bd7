// SPDX-License-Identifier: MIT
// MEDIT ascii .mesh: keyword sections (Vertices, Tetrahedra, Pyramids, Prisms,
// Hexahedra; Triangles and Quadrilaterals as listed faces; Edges as listed
// edges; the annotation sections are read and ignored), 1-based indices, a
// reference number after each record, kept as the column `medit:ref` of the
// vertices, cells, listed faces and listed edges when one of them is not 0.
#include "formats.h"
#include "text_reader.h"
#include "text_writer.h"
#include "value_type_names.h"

#include <climits>

#include <algorithm>
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
	static constexpr std::array<S, 9> sections = {{{"Corners", 1},
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
	Column vertex_ref{"medit:ref", 1, {}, ValueType::Int32}, cell_ref = vertex_ref, face_ref = vertex_ref,
															 edge_ref = vertex_ref;
	auto read_ref = [&](Column& c, const char* what) {
		const int64 ref = r.read_int(what);
		if (ref < INT32_MIN || ref > INT32_MAX)
			r.fail("reference " + std::to_string(ref) + " out of the 32-bit range");
		c.values.push_back(double(ref));
	};
	// n records of `size` 1-based vertex indices and a reference (cells or
	// listed faces)
	auto read_records = [&](uint32 n, uint32 size, std::vector<uint32>& sizes, std::vector<uint32>& ids, Column& ref,
							const char* what, const char* ref_what) {
		r.check_count(n, 2 * (size + 1), what);
		sizes.reserve(sizes.size() + n);
		ids.reserve(ids.size() + std::size_t(n) * size);
		for (uint32 i = 0; i < n; ++i)
		{
			sizes.push_back(size);
			for (uint32 j = 0; j < size; ++j)
			{
				const uint32 v = r.read_uint("a vertex index");
				if (v == 0)
					r.fail("vertex index 0 (MEDIT indices start at 1)");
				if (have_vertices && v > d.nb_vertices())
					r.fail("vertex index " + std::to_string(v) + " out of range (the file has " +
						   std::to_string(d.nb_vertices()) + " vertices)");
				ids.push_back(v - 1);
			}
			read_ref(ref, ref_what);
		}
	};
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
				read_ref(vertex_ref, "a vertex reference");
			}
			continue;
		}
		if (k == "Triangles" || k == "Quadrilaterals")
		{
			read_records(n, k == "Triangles" ? 3 : 4, d.face_sizes, d.face_vertices, face_ref, "faces",
						 "a face reference");
			continue;
		}
		if (k == "Edges")
		{
			std::vector<uint32> sizes, ids;
			read_records(n, 2, sizes, ids, edge_ref, "edges", "an edge reference");
			for (std::size_t i = 0; i < ids.size(); i += 2)
				d.segments.emplace_back(ids[i], ids[i + 1]);
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
			read_records(n, size, d.cell_sizes, d.cell_vertices, cell_ref, "cells", "a cell reference");
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
	for (const auto* ids : {&d.cell_vertices, &d.face_vertices})
		for (uint32 v : *ids)
			if (v >= d.nb_vertices())
				throw Error(path, "vertex index " + std::to_string(v + 1) + " out of range (the file has " +
									  std::to_string(d.nb_vertices()) + " vertices)");
	for (const auto& [a, b] : d.segments)
		if (std::max(a, b) >= d.nb_vertices())
			throw Error(path, "vertex index " + std::to_string(std::max(a, b) + 1) + " out of range (the file has " +
								  std::to_string(d.nb_vertices()) + " vertices)");
	// the references, when one is not 0
	auto keep = [](Column& c, std::vector<Column>& out) {
		if (std::any_of(c.values.begin(), c.values.end(), [](double v) { return v != 0.0; }))
			out.push_back(std::move(c));
	};
	keep(vertex_ref, d.vertex_columns);
	keep(cell_ref, d.cell_columns);
	keep(face_ref, d.face_columns);
	keep(edge_ref, d.segment_columns);
	return d;
}

// References come from `medit:ref`, else `gmsh:physical`, else 0.
std::string write_medit(const MeshData& d, const std::string& path)
{
	auto references = [&](const std::vector<Column>& columns, std::size_t rows) {
		return int32_tags(columns, {"medit:ref", "gmsh:physical"}, rows, 0, path);
	};
	std::string s = "MeshVersionFormatted 2\nDimension 3\n\nVertices\n";
	s.reserve(std::size_t(d.nb_vertices()) * 60 + d.cell_vertices.size() * 8);
	append_uint(s, d.nb_vertices());
	s += '\n';
	const std::vector<int32> vertex_ref = references(d.vertex_columns, d.nb_vertices());
	for (uint32 v = 0; v < d.nb_vertices(); ++v)
	{
		for (uint32 k = 0; k < 3; ++k)
		{
			append_double(s, d.positions[3 * std::size_t(v) + k]);
			s += ' ';
		}
		append_int(s, vertex_ref[v]);
		s += '\n';
	}
	// records grouped by kind, in the order of MEDIT's sections: the listed
	// edges, the listed faces of 3 and 4 vertices, then the cells
	auto section = [&](const char* name, uint32 size, const std::vector<uint32>& sizes, const std::vector<uint32>& ids,
					   const std::vector<int32>& ref) {
		const auto count = std::count(sizes.begin(), sizes.end(), size);
		if (count == 0)
			return;
		s += '\n';
		s += name;
		s += '\n';
		append_uint(s, uint64(count));
		s += '\n';
		std::size_t k = 0;
		for (std::size_t c = 0; c < sizes.size(); ++c)
		{
			if (sizes[c] == size)
			{
				for (uint32 i = 0; i < size; ++i)
				{
					append_uint(s, uint64(ids[k + i]) + 1);
					s += ' ';
				}
				append_int(s, ref[c]);
				s += '\n';
			}
			k += sizes[c];
		}
	};
	if (!d.segments.empty())
	{
		const std::vector<int32> edge_ref = references(d.segment_columns, d.segments.size());
		s += "\nEdges\n";
		append_uint(s, d.segments.size());
		s += '\n';
		for (std::size_t e = 0; e < d.segments.size(); ++e)
		{
			append_uint(s, uint64(d.segments[e].first) + 1);
			s += ' ';
			append_uint(s, uint64(d.segments[e].second) + 1);
			s += ' ';
			append_int(s, edge_ref[e]);
			s += '\n';
		}
	}
	const std::vector<int32> face_ref = references(d.face_columns, d.nb_faces());
	section("Triangles", 3, d.face_sizes, d.face_vertices, face_ref);
	section("Quadrilaterals", 4, d.face_sizes, d.face_vertices, face_ref);
	const std::vector<int32> cell_ref = references(d.cell_columns, d.nb_cells());
	section("Tetrahedra", 4, d.cell_sizes, d.cell_vertices, cell_ref);
	section("Pyramids", 5, d.cell_sizes, d.cell_vertices, cell_ref);
	section("Prisms", 6, d.cell_sizes, d.cell_vertices, cell_ref);
	section("Hexahedra", 8, d.cell_sizes, d.cell_vertices, cell_ref);
	s += "\nEnd\n";
	return s;
}

} // namespace cgogn::io::detail
