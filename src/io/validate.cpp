// SPDX-License-Identifier: MIT
#include <cgogn/io/error.h>

#include "formats.h"
#include "value_type_names.h"

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
	// integer data must hold values of its type: an attribute of that type
	// receives them
	auto check_values = [&](const Column& c, const char* of) {
		if (is_integer_type(c.type))
			for (double v : c.values)
				if (!holds_value(c.type, v))
					throw Error(path, std::string(of) + " data '" + c.name + "' of type " + value_type_name(c.type) +
										  " holds the value " + std::to_string(v) + ", which that type does not have" +
										  (std::abs(v) > MAX_EXACT_INTEGER
											   ? " (64-bit values are read below 2^53 in magnitude)"
											   : ""));
	};
	std::vector<std::string> names;
	for (const auto& c : d.vertex_columns)
	{
		if (c.values.size() != std::size_t(nv) * c.dim)
			throw Error(path, "vertex data '" + c.name + "' does not have one value per vertex");
		check_values(c, "vertex");
		if (std::string why = data_name_conflict(names, c.name, true); !why.empty())
			throw Error(path, why);
		names.push_back(c.name);
	}
	names.clear();
	for (const auto& c : d.cell_columns)
	{
		if (c.values.size() != std::size_t(d.nb_cells()) * c.dim)
			throw Error(path, "cell data '" + c.name + "' does not have one value per cell");
		check_values(c, "cell");
		if (std::string why = data_name_conflict(names, c.name, false); !why.empty())
			throw Error(path, why);
		names.push_back(c.name);
	}
	names.clear();
	for (const auto& c : d.corner_columns)
	{
		if (c.values.size() != d.cell_vertices.size() * c.dim)
			throw Error(path, "corner data '" + c.name + "' does not have one value per face corner");
		check_values(c, "corner");
		if (std::string why = data_name_conflict(names, c.name, false); !why.empty())
			throw Error(path, why);
		names.push_back(c.name);
	}
	std::size_t nb_ids = 0;
	for (uint32 n : d.face_sizes)
		nb_ids += n;
	if (nb_ids != d.face_vertices.size())
		throw Error(path, "inconsistent listed faces");
	for (uint32 v : d.face_vertices)
		if (v >= nv)
			throw Error(path, "a face refers to vertex " + std::to_string(v) + ", out of range (the file has " +
								  std::to_string(nv) + " vertices)");
	names.clear();
	for (const auto& c : d.face_columns)
	{
		if (c.values.size() != std::size_t(d.nb_faces()) * c.dim)
			throw Error(path, "face data '" + c.name + "' does not have one value per listed face");
		check_values(c, "face");
		if (std::string why = data_name_conflict(names, c.name, false); !why.empty())
			throw Error(path, why);
		names.push_back(c.name);
	}
}

void check_written_names(const MeshData& d, const std::string& path)
{
	for (const auto& c : d.vertex_columns)
		if (c.dim >= 1 && c.dim <= 3 && !data_name_conflict({}, c.name, true).empty())
			throw Error(path, "cannot write the vertex attribute '" + c.name +
								  "': loading reserves that name (rename it, or save without attributes)");
}

} // namespace cgogn::io::detail
