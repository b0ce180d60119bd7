// SPDX-License-Identifier: MIT
// Cells of a map of any dimension as a VTK XML unstructured grid (ASCII).
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_dimension.h>
#include <cgogn/io/nmap.h>

#include "file_io.h"
#include "text_writer.h"

namespace cgogn::io
{

namespace
{

constexpr uint8 VTK_VERTEX = 1, VTK_LINE = 3, VTK_POLYGON = 7, VTK_POLYHEDRON = 42;

// The vertices of the side of a face that holds d, in order.
template <typename MAP>
std::vector<CellD<0>> corners_of(const MAP& m, Dart d)
{
	std::vector<CellD<0>> v;
	Dart it = d;
	do
	{
		v.emplace_back(it);
		if constexpr (is_gmap_v<MAP>)
			it = beta<0, 1>(m, it);
		else
			it = phi<1>(m, it);
	} while (it != d);
	return v;
}

template <typename T>
void append_list(std::string& s, const char* type, const char* name, const std::vector<T>& values)
{
	s += std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" format=\"ascii\">\n";
	for (std::size_t i = 0; i < values.size(); ++i)
	{
		if (values[i] < 0)
			s.push_back('-');
		detail::append_uint(s, uint64(values[i] < 0 ? -int64(values[i]) : int64(values[i])));
		s.push_back(i + 1 == values.size() || i % 16 == 15 ? '\n' : ' ');
	}
	s += "</DataArray>\n";
}

// The coordinates of the point of each line of `vertices` (the vertex
// container of a map of any dimension), from its PointD attribute
// `position`, and their number per point; 0 when it has none.
std::pair<std::vector<double>, uint32> vertex_coordinates(const AttributeContainer& vertices)
{
	std::vector<double> coordinates;
	uint32 nb_coordinates = 0;
	[&]<std::size_t... K>(std::index_sequence<K...>)
	{
		(
			[&] {
				const auto p = vertices.get_attribute<PointD<K + 1>>("position");
				if (!p || nb_coordinates != 0)
					return;
				nb_coordinates = K + 1;
				coordinates.resize(std::size_t(vertices.end_index()) * nb_coordinates);
				for (uint32 l = 0; l < vertices.end_index(); ++l)
					if (vertices.is_live(l))
						std::copy_n((*p)[l].begin(), K + 1, coordinates.begin() + std::size_t(l) * nb_coordinates);
			}(),
			...);
	}
	(std::make_index_sequence<MAX_DIMENSION + 1>{});
	return {std::move(coordinates), nb_coordinates};
}

// The cells of a .vtu file, as save_vtu gathers them.
struct VtuCells
{
	std::vector<int64> connectivity, offsets, faces, face_offsets;
	std::vector<uint8> types, cell_dimension;
	bool polyhedra = false;

	// Ends a cell of the given VTK type and dimension k.
	void end_cell(uint8 type, uint32 k)
	{
		offsets.push_back(int64(connectivity.size()));
		types.push_back(type);
		cell_dimension.push_back(uint8(k));
		// the end of the cell's face stream, -1 for a cell that is not a polyhedron
		face_offsets.push_back(type == VTK_POLYHEDRON ? int64(faces.size()) : -1);
	}
};

// The file: the points (written, a line of 3 coordinates each) and the cells.
void write_vtu(const std::string& path, const std::string& points, int64 nb_points, const VtuCells& c)
{
	std::string s =
		"<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
		"byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"" +
		std::to_string(nb_points) + "\" NumberOfCells=\"" + std::to_string(c.types.size()) + "\">\n";
	s += "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n" + points +
		 "</DataArray>\n</Points>\n<Cells>\n";
	append_list(s, "Int64", "connectivity", c.connectivity);
	append_list(s, "Int64", "offsets", c.offsets);
	append_list(s, "UInt8", "types", c.types);
	if (c.polyhedra)
	{
		append_list(s, "Int64", "faces", c.faces);
		append_list(s, "Int64", "faceoffsets", c.face_offsets);
	}
	s += "</Cells>\n<CellData Scalars=\"dimension\">\n";
	append_list(s, "UInt8", "dimension", c.cell_dimension);
	s += "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
	detail::write_file(path, s);
}

} // namespace

// Only the walk over the cells depends on the map type: the rest is in the
// functions above, compiled once for the 14 map types.
template <typename MAP>
requires is_nmap_v<MAP>
void save_vtu(const MAP& m, const std::string& path, const std::vector<uint32>& dimensions,
			  const std::function<std::array<double, 3>(std::span<const double>)>& project)
{
	constexpr uint32 D = MAP::dimension;
	// the coordinates of the point of each vertex line
	const AttributeContainer& vertices = container_of<Orbit::CELL0>(m);
	const auto [coordinates, nb_coordinates] = vertex_coordinates(vertices);
	if (nb_coordinates == 0)
		throw Error(path, "save_vtu: the map has no vertex attribute position (a PointD)");
	for (uint32 k : dimensions)
		if (k > 3 || k > D)
			throw Error(path, "save_vtu: cells of dimension " + std::to_string(k) +
								  " cannot be written (dimensions 0 to 3, at most the map's)");
	// the points: one per vertex line
	std::vector<int64> point_of_line(vertices.end_index(), -1);
	std::string points;
	int64 nb_points = 0;
	for (uint32 l = 0; l < vertices.end_index(); ++l)
		if (vertices.is_live(l))
		{
			point_of_line[l] = nb_points++;
			const std::span<const double> p(coordinates.data() + std::size_t(l) * nb_coordinates, nb_coordinates);
			std::array<double, 3> q{};
			if (project)
				q = project(p);
			else
				for (uint32 a = 0; a < std::min<uint32>(nb_coordinates, 3); ++a)
					q[a] = p[a];
			for (uint32 a = 0; a < 3; ++a)
			{
				detail::append_double(points, q[a]);
				points.push_back(a == 2 ? '\n' : ' ');
			}
		}
	auto point = [&](CellD<0> v) { return point_of_line[index_of(m, v)]; };
	VtuCells cells;
	auto write_cells = [&]<uint32 K>() {
		if constexpr (K <= D)
			foreach_cell(m, [&](CellD<K> c) {
				if constexpr (K == 0)
				{
					cells.connectivity.push_back(point(c));
					cells.end_cell(VTK_VERTEX, 0);
				}
				else if constexpr (K == 1)
				{
					cells.connectivity.push_back(point(CellD<0>(c.dart)));
					if constexpr (is_gmap_v<MAP>)
						cells.connectivity.push_back(point(CellD<0>(beta<0>(m, c.dart))));
					else
						cells.connectivity.push_back(point(CellD<0>(phi<1>(m, c.dart))));
					cells.end_cell(VTK_LINE, 1);
				}
				else if constexpr (K == 2)
				{
					for (CellD<0> v : corners_of(m, c.dart))
						cells.connectivity.push_back(point(v));
					cells.end_cell(VTK_POLYGON, 2);
				}
				else
				{
					cells.polyhedra = true;
					std::vector<int64> ids;
					std::vector<int64> cell_faces;
					uint32 nb_faces = 0;
					foreach_incident_cell<2>(m, c, [&](CellD<2> f) {
						const std::vector<CellD<0>> corners = corners_of(m, f.dart);
						cell_faces.push_back(int64(corners.size()));
						for (CellD<0> v : corners)
						{
							const int64 p = point(v);
							cell_faces.push_back(p);
							if (std::find(ids.begin(), ids.end(), p) == ids.end())
								ids.push_back(p);
						}
						++nb_faces;
					});
					cells.connectivity.insert(cells.connectivity.end(), ids.begin(), ids.end());
					cells.faces.push_back(nb_faces);
					cells.faces.insert(cells.faces.end(), cell_faces.begin(), cell_faces.end());
					cells.end_cell(VTK_POLYHEDRON, 3);
				}
			});
	};
	for (uint32 k : dimensions)
	{
		if (k == 0)
			write_cells.template operator()<0>();
		else if (k == 1)
			write_cells.template operator()<1>();
		else if (k == 2)
			write_cells.template operator()<2>();
		else
			write_cells.template operator()<3>();
	}
	write_vtu(path, points, nb_points, cells);
}

#define CGOGN_NMAP_VTU(MAP)                                                                                            \
	template void save_vtu(const MAP&, const std::string&, const std::vector<uint32>&,                                 \
						   const std::function<std::array<double, 3>(std::span<const double>)>&);
CGOGN_NMAP_VTU(CMapN<1>)
CGOGN_NMAP_VTU(CMapN<2>)
CGOGN_NMAP_VTU(CMapN<3>)
CGOGN_NMAP_VTU(CMapN<4>)
CGOGN_NMAP_VTU(CMapN<5>)
CGOGN_NMAP_VTU(CMapN<6>)
CGOGN_NMAP_VTU(CMapN<7>)
CGOGN_NMAP_VTU(GMapN<1>)
CGOGN_NMAP_VTU(GMapN<2>)
CGOGN_NMAP_VTU(GMapN<3>)
CGOGN_NMAP_VTU(GMapN<4>)
CGOGN_NMAP_VTU(GMapN<5>)
CGOGN_NMAP_VTU(GMapN<6>)
CGOGN_NMAP_VTU(GMapN<7>)
#undef CGOGN_NMAP_VTU

} // namespace cgogn::io
