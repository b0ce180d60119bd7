// SPDX-License-Identifier: MIT
// What readers produce and writers consume: a cell soup with positions and
// named per-vertex and per-cell columns, independent of any map.
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <string>
#include <utility>
#include <vector>

namespace cgogn::io::detail
{

/// A named per-element array of `dim` doubles per element (dim 1: scalar,
/// 2: Vec2, 3: Vec3).
struct Column
{
	std::string name;
	uint32 dim = 1;
	std::vector<double> values;
};

/// Why a reader must reject a data array named `name` for the vertices
/// (`of_vertices`) or the cells, given the names of the arrays it has already
/// read for the same elements; empty when the array is accepted. Two arrays of
/// one name would become one attribute (of two types when their sizes differ),
/// and `position` and `original_vertex` are the loader's own vertex attributes.
/// Unnamed arrays never conflict. O(number of earlier names).
std::string data_name_conflict(const std::vector<std::string>& earlier, const std::string& name, bool of_vertices);

/// Polygons (surfaces) or tetrahedra/pyramids/prisms/hexahedra (volumes, in the
/// builder's vertex order) over vertices 0..nb_vertices()-1.
struct MeshData
{
	std::vector<double> positions; // x y z per vertex
	std::vector<uint32> cell_sizes;
	std::vector<uint32> cell_vertices;
	std::vector<Column> vertex_columns;
	std::vector<Column> cell_columns;
	/// Line cells, as vertex pairs: read by the VTK readers (a line, type 3;
	/// a polyline, type 4, as its consecutive segments), which do not count
	/// them as cells; written by the VTK writers after the cells, as lines.
	/// Graphs are stored here. A writer drops the cell columns when there are
	/// segments (the columns have one row per cell, none for the segments).
	std::vector<std::pair<uint32, uint32>> segments;

	uint32 nb_vertices() const
	{
		return uint32(positions.size() / 3);
	}
	uint32 nb_cells() const
	{
		return uint32(cell_sizes.size());
	}
	Column* find_vertex_column(const std::string& name)
	{
		for (auto& c : vertex_columns)
			if (c.name == name)
				return &c;
		return nullptr;
	}
	const Column* find_vertex_column(const std::string& name) const
	{
		for (auto& c : vertex_columns)
			if (c.name == name)
				return &c;
		return nullptr;
	}
	const Column* find_cell_column(const std::string& name) const
	{
		for (auto& c : cell_columns)
			if (c.name == name)
				return &c;
		return nullptr;
	}
};

} // namespace cgogn::io::detail
