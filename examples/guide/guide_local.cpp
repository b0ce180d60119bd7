// The CGoGN API guide's "Local traversals" and "Properties" sections, written as a
// user writes them.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

using Mesh = CMap2;
using Vertex = typename mesh_traits<Mesh>::Vertex;
using Edge = typename mesh_traits<Mesh>::Edge;
using Face = typename mesh_traits<Mesh>::Face;
using Volume = typename mesh_traits<Mesh>::Volume;
template <typename T>
using Attribute = typename mesh_traits<Mesh>::template Attribute<T>;

// the average of a vertex attribute over the vertices of a face
template <typename T>
T average(const Mesh& map, Face f, const Attribute<T>& attribute)
{
	T result(0);
	uint32 nbv = 0;
	foreach_incident_vertex(map, f, [&](Vertex v) {
		result += attribute[v];
		++nbv;
	});
	return result / nbv;
}

// the same over the vertices of any cell of any map
template <typename T, typename CellType, typename MESH>
T average(const MESH& m, CellType c, const Attribute<T>& attribute)
{
	T result(0);
	uint32 nbv = 0;
	foreach_incident_vertex(m, c, [&](typename MESH::Vertex v) {
		result += value(m, attribute, v);
		++nbv;
	});
	return result / nbv;
}

// "degree of any cell": generic code over every cell type of a map
template <typename MESH, typename CELL>
uint64 sum_of_degrees(const MESH& m)
{
	uint64 s = 0;
	foreach_cell(m, [&](CELL c) { s += degree(m, c) + codegree(m, c); });
	return s;
}

int main()
{
	Mesh m;
	build_surface(m, grid_soup(2, 1)); // two unit squares side by side
	auto weight = add_attribute<double, Vertex>(m, "weight");
	foreach_cell(m, [&](Vertex v) { value<double>(m, weight, v) = double(degree(m, v)); });

	uint32 nb_neighbours = 0;
	Vertex some_vertex;
	foreach_cell(m, [&](Vertex v) {
		some_vertex = v;
		return false;
	});
	foreach_incident_edge(m, some_vertex, [&](Edge) { ++nb_neighbours; });
	foreach_adjacent_vertex_through_edge(m, some_vertex, [&](Vertex) { ++nb_neighbours; });
	foreach_incident_face(m, some_vertex, [&](Face) { ++nb_neighbours; });

	double sum_of_face_averages = 0.0;
	foreach_cell(m, [&](Face f) { sum_of_face_averages += average<double>(m, f, *weight); });
	// every square has two corners of degree 2 and two of degree 3
	if (sum_of_face_averages != 5.0)
		return 1;

	// a 3-map: the average over the vertices of a volume
	CMap3 m3;
	using Volume3 = mesh_traits<CMap3>::Volume;
	using Vertex3 = mesh_traits<CMap3>::Vertex;
	const Volume3 tet = add_pyramid(m3, 3); // a tetrahedron
	close(m3);
	auto w3 = add_attribute<double, Vertex3>(m3, "weight");
	foreach_incident_vertex(m3, tet, [&](Vertex3 v) { (*w3)[v] = 2.0; });
	if (average<double>(m3, tet, *w3) != 2.0)
		return 1;

	// properties
	const uint32 nbv = nb_cells<Vertex>(m);
	const uint64 degrees = sum_of_degrees<Mesh, Vertex>(m) + sum_of_degrees<Mesh, Edge>(m) +
						   sum_of_degrees<Mesh, Face>(m) + sum_of_degrees<Mesh, Volume>(m);
	bool on_boundary = is_incident_to_boundary(m, some_vertex);
	std::cout << nbv << " vertices, sum of degrees and codegrees " << degrees << "\n";
	return nbv == 6 && on_boundary && nb_neighbours > 0 && codegree(m3, mesh_traits<CMap3>::Edge(tet.dart)) == 2 ? 0
																												 : 1;
}
