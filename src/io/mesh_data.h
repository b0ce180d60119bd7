// SPDX-License-Identifier: MIT
// What readers produce and writers consume: a cell soup with positions and
// named per-vertex and per-cell columns, independent of any map.
#pragma once

#include <cgogn/core/utils/numeric.h>

#include <algorithm>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace cgogn::io::detail
{

/// The type of a column's values, in the file and in the map: floating
/// point (float32 data is widened, exactly, to double) or an integer of a
/// given width and sign.
enum class ValueType : uint8
{
	Float64,
	Int8,
	UInt8,
	Int16,
	UInt16,
	Int32,
	UInt32,
	Int64,
	UInt64
};

inline bool is_integer_type(ValueType t)
{
	return t != ValueType::Float64;
}

/// The C++ type of a value type: calls f.template operator()<T>().
template <typename F>
decltype(auto) visit_value_type(ValueType t, const F& f)
{
	switch (t)
	{
	case ValueType::Int8:
		return f.template operator()<int8>();
	case ValueType::UInt8:
		return f.template operator()<uint8>();
	case ValueType::Int16:
		return f.template operator()<std::int16_t>();
	case ValueType::UInt16:
		return f.template operator()<uint16>();
	case ValueType::Int32:
		return f.template operator()<int32>();
	case ValueType::UInt32:
		return f.template operator()<uint32>();
	case ValueType::Int64:
		return f.template operator()<int64>();
	case ValueType::UInt64:
		return f.template operator()<uint64>();
	case ValueType::Float64:
		break;
	}
	return f.template operator()<double>();
}

/// The value type of the C++ type T (an integer type, or double).
template <typename T>
constexpr ValueType value_type_of()
{
	if constexpr (std::is_same_v<T, int8>)
		return ValueType::Int8;
	else if constexpr (std::is_same_v<T, uint8>)
		return ValueType::UInt8;
	else if constexpr (std::is_same_v<T, std::int16_t>)
		return ValueType::Int16;
	else if constexpr (std::is_same_v<T, uint16>)
		return ValueType::UInt16;
	else if constexpr (std::is_same_v<T, int32>)
		return ValueType::Int32;
	else if constexpr (std::is_same_v<T, uint32>)
		return ValueType::UInt32;
	else if constexpr (std::is_same_v<T, int64>)
		return ValueType::Int64;
	else if constexpr (std::is_same_v<T, uint64>)
		return ValueType::UInt64;
	else
	{
		static_assert(std::is_same_v<T, double>, "columns hold doubles and integers");
		return ValueType::Float64;
	}
}

/// The largest magnitude of a 64-bit integer value a column holds (its
/// values are doubles): 2^53 - 1, below which every integer is exact. Loads
/// refuse larger ones (a larger value may have been rounded already).
constexpr double MAX_EXACT_INTEGER = 9007199254740991.0;

/// A named per-element array of `dim` values per element (dim 1: scalar,
/// 2: Vec2, 3: Vec3), stored as doubles whatever `type` (every value of
/// every type is exact: integers are integral, in their type's range, and 64-bit
/// ones within +-MAX_EXACT_INTEGER). A column of one integer component
/// becomes an integer attribute of its type; integer columns of several
/// components become vectors of double (the load reports it).
struct Column
{
	std::string name;
	uint32 dim = 1;
	std::vector<double> values;
	ValueType type = ValueType::Float64;
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
	/// Graphs are stored here. Also the edges a file lists with data (gmsh's
	/// line elements, MEDIT's Edges, VTK's line cells), with one row of
	/// `segment_columns` each: a surface map holds those columns as edge
	/// attributes, on its edges between these two vertices; a writer lists
	/// the edges with a nonzero value there.
	std::vector<std::pair<uint32, uint32>> segments;
	std::vector<Column> segment_columns;
	/// Polyhedra (VTK's general polyhedron, cell type 42), beside the cells
	/// of the standard kinds. Empty when there is none; otherwise one entry
	/// per cell: 0 for a standard cell, else the polyhedron's number of
	/// faces, whose sizes and vertex ids follow one another (polyhedron
	/// after polyhedron) in polyhedron_face_sizes and
	/// polyhedron_face_vertices, each face counterclockwise seen from
	/// outside. A polyhedron's cell_sizes entry is its number of distinct
	/// vertices, which cell_vertices lists in the order of their first use.
	std::vector<uint32> cell_nb_faces;
	std::vector<uint32> polyhedron_face_sizes;
	std::vector<uint32> polyhedron_face_vertices;
	/// Per-corner data of a surface: one row per entry of cell_vertices (the
	/// corner of that cell at that vertex), such as the texture coordinates
	/// and normals of an OBJ file that differ between the corners of a
	/// vertex (seams, creases). A map holds them as dart attributes (every
	/// dart of the face at that vertex).
	std::vector<Column> corner_columns;
	/// Faces a volume file lists beside its cells (gmsh's triangles and
	/// quadrangles, VTK's triangle, quad and polygon cells, MEDIT's Triangles
	/// and Quadrilaterals), usually boundary faces carrying tags, with one
	/// row of `face_columns` each. A volume map holds the columns as face
	/// attributes, on the faces of its volumes that have these vertices (in
	/// any order); a writer lists the faces with a nonzero value there.
	std::vector<uint32> face_sizes;
	std::vector<uint32> face_vertices;
	std::vector<Column> face_columns;
	/// The names of gmsh's physical groups ($PhysicalNames): a map gives
	/// each volume (dimension 3), face (dimension 2) and listed edge
	/// (dimension 1) whose `gmsh:physical` tag has a name that name, in the
	/// string attribute `gmsh:physical_name`; a writer takes them back from
	/// there.
	struct PhysicalName
	{
		int32 dim;
		int32 tag;
		std::string name;
	};
	std::vector<PhysicalName> physical_names;
	/// What a reader read but the map will not hold, each with why
	/// (LoadReport::dropped).
	std::vector<std::string> dropped;

	uint32 nb_vertices() const
	{
		return uint32(positions.size() / 3);
	}
	uint32 nb_cells() const
	{
		return uint32(cell_sizes.size());
	}
	uint32 nb_faces() const
	{
		return uint32(face_sizes.size());
	}
	/// A surface read from a volume format: its listed faces become the
	/// cells, with their columns. Throws io::Error (naming path) when the
	/// file has volume cells. O(size of the faces).
	void faces_as_cells(const std::string& path);
	/// The reverse, for a volume format's writer: the cells (polygons)
	/// become listed faces, with their columns. O(size of the cells).
	void cells_as_faces();
	/// Whether cell c is a polyhedron given by its faces.
	bool is_polyhedron(uint32 c) const
	{
		return c < cell_nb_faces.size() && cell_nb_faces[c] > 0;
	}
	/// Appends a polyhedron: its faces as (size, ids...) lists, `nb_faces`
	/// of them; its vertices are the distinct ids in the order of first use.
	void add_polyhedron(uint32 nb_faces, const std::vector<uint32>& sizes, const std::vector<uint32>& ids)
	{
		cell_nb_faces.resize(cell_sizes.size(), 0);
		cell_nb_faces.push_back(nb_faces);
		polyhedron_face_sizes.insert(polyhedron_face_sizes.end(), sizes.begin(), sizes.end());
		polyhedron_face_vertices.insert(polyhedron_face_vertices.end(), ids.begin(), ids.end());
		// the distinct ids in the order of their first use: O(n log n)
		std::vector<std::pair<uint32, uint32>> first_use(ids.size()); // (id, position)
		for (uint32 i = 0; i < uint32(ids.size()); ++i)
			first_use[i] = {ids[i], i};
		std::sort(first_use.begin(), first_use.end());
		first_use.erase(std::unique(first_use.begin(), first_use.end(),
									[](const auto& a, const auto& b) { return a.first == b.first; }),
						first_use.end());
		std::sort(first_use.begin(), first_use.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
		for (const auto& [id, position] : first_use)
			cell_vertices.push_back(id);
		cell_sizes.push_back(uint32(first_use.size()));
	}
	/// Makes cell_nb_faces one entry per cell when there are polyhedra.
	void finish_polyhedra()
	{
		if (!cell_nb_faces.empty())
			cell_nb_faces.resize(cell_sizes.size(), 0);
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
