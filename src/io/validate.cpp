// SPDX-License-Identifier: MIT
#include <cgogn/io/error.h>

#include "formats.h"
#include "value_type_names.h"

#include <algorithm>
#include <cmath>

namespace cgogn::io::detail
{

std::string data_name_conflict(const std::vector<std::string>& earlier, const std::string& name, bool of_vertices)
{
	if (name.empty())
		return {};
	const char* elements = of_vertices ? "vertex" : "cell";
	if (of_vertices && (name == "position" || name == "original_vertex"))
		return std::string(elements) + " data '" + name + "' collides with the vertex attribute '" + name +
			   "' that loading creates";
	for (const auto& e : earlier)
		if (e == name)
			return "two " + std::string(elements) + " data arrays are named '" + name + "'";
	return {};
}

void validate(const MeshData& d, const std::string& path)
{
	std::size_t total = 0;
	for (uint32 n : d.cell_sizes)
		total += n;
	if (total != d.cell_vertices.size())
		throw Error(path, "inconsistent cell sizes");
	if (!d.cell_nb_faces.empty())
	{
		if (d.cell_nb_faces.size() != d.cell_sizes.size())
			throw Error(path, "inconsistent polyhedra");
		std::size_t nb_faces = 0, nb_ids = 0;
		for (uint32 n : d.cell_nb_faces)
			nb_faces += n;
		if (nb_faces != d.polyhedron_face_sizes.size())
			throw Error(path, "inconsistent polyhedron faces");
		for (uint32 n : d.polyhedron_face_sizes)
			nb_ids += n;
		if (nb_ids != d.polyhedron_face_vertices.size())
			throw Error(path, "inconsistent polyhedron faces");
		for (uint32 v : d.polyhedron_face_vertices)
			if (v >= d.nb_vertices())
				throw Error(path, "vertex index " + std::to_string(v) + " out of range (the file has " +
									  std::to_string(d.nb_vertices()) + " vertices)");
	}
	const uint32 nv = d.nb_vertices();
	for (uint32 v : d.cell_vertices)
		if (v >= nv)
			throw Error(path, "vertex index " + std::to_string(v) + " out of range (the file has " +
								  std::to_string(nv) + " vertices)");
	std::size_t nb_ids = 0;
	for (uint32 n : d.face_sizes)
		nb_ids += n;
	if (nb_ids != d.face_vertices.size())
		throw Error(path, "inconsistent listed faces");
	for (uint32 v : d.face_vertices)
		if (v >= nv)
			throw Error(path, "a face refers to vertex " + std::to_string(v) + ", out of range (the file has " +
								  std::to_string(nv) + " vertices)");
	// each kind of data: one row per element, integer data holding values of
	// its type (an attribute of that type receives them), distinct names
	auto check_columns = [&](const std::vector<Column>& columns, std::size_t rows, const char* of,
							 const char* per_element, bool of_vertices) {
		std::vector<std::string> names;
		for (const auto& c : columns)
		{
			if (c.values.size() != rows * c.dim)
				throw Error(path,
							std::string(of) + " data '" + c.name + "' does not have one value per " + per_element);
			if (is_integer_type(c.type))
				for (double v : c.values)
					if (!holds_value(c.type, v))
						throw Error(path, std::string(of) + " data '" + c.name + "' of type " +
											  value_type_name(c.type) + " holds the value " + std::to_string(v) +
											  ", which that type does not have" +
											  (std::abs(v) > MAX_EXACT_INTEGER
												   ? " (64-bit values are read below 2^53 in magnitude)"
												   : ""));
			if (std::string why = data_name_conflict(names, c.name, of_vertices); !why.empty())
				throw Error(path, why);
			names.push_back(c.name);
		}
	};
	check_columns(d.vertex_columns, nv, "vertex", "vertex", true);
	check_columns(d.cell_columns, d.nb_cells(), "cell", "cell", false);
	check_columns(d.corner_columns, d.cell_vertices.size(), "corner", "face corner", false);
	check_columns(d.face_columns, d.nb_faces(), "face", "listed face", false);
	for (const auto& [a, b] : d.segments)
		if (a >= nv || b >= nv)
			throw Error(path, "an edge refers to vertex " + std::to_string(std::max(a, b)) +
								  ", out of range (the file has " + std::to_string(nv) + " vertices)");
	check_columns(d.segment_columns, d.segments.size(), "edge", "listed edge", false);
}

void MeshData::faces_as_cells(const std::string& path)
{
	if (nb_cells() > 0)
		throw Error(path, "the file has " + std::to_string(nb_cells()) +
							  " volume cell(s): load it into a volume map (load_volume)");
	cell_sizes = std::move(face_sizes);
	cell_vertices = std::move(face_vertices);
	cell_columns = std::move(face_columns);
	face_sizes.clear();
	face_vertices.clear();
	face_columns.clear();
}

void MeshData::cells_as_faces()
{
	face_sizes = std::move(cell_sizes);
	face_vertices = std::move(cell_vertices);
	face_columns = std::move(cell_columns);
	cell_sizes.clear();
	cell_vertices.clear();
	cell_columns.clear();
	corner_columns.clear();
}

void check_written_names(const MeshData& d, const std::string& path)
{
	for (const auto& c : d.vertex_columns)
		if (c.dim >= 1 && c.dim <= 3 && !data_name_conflict({}, c.name, true).empty())
			throw Error(path, "cannot write the vertex attribute '" + c.name +
								  "': loading reserves that name (rename it, or save without attributes)");
}

} // namespace cgogn::io::detail
