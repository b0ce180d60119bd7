// The "Local traversals" section of the CGoGN API guide: a generic average over the
// vertices incident to any cell, in a 2-map and in a 3-map.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

template <typename T, typename MESH, typename CELL>
T average(const MESH& m, CELL c, const typename mesh_traits<MESH>::template Attribute<T>& attribute)
{
	T result(0);
	uint32 nbv = 0;
	foreach_incident_vertex(m, c, [&](typename mesh_traits<MESH>::Vertex v) {
		result += value<T>(m, attribute, v);
		++nbv;
	});
	return result / nbv;
}

int main()
{
	CMap2 surface;
	build_surface(surface, grid_soup(3, 3));
	auto id2 = add_attribute<double, CMap2::Vertex>(surface, "id");
	foreach_cell(surface, [&](CMap2::Vertex v) { value<double>(surface, id2, v) = index_of(surface, v); });

	CMap3 volume;
	build_volume(volume, hex_grid_soup(2, 2, 2));
	auto id3 = add_attribute<double, CMap3::Vertex>(volume, "id");
	foreach_cell(volume, [&](CMap3::Vertex v) { value<double>(volume, id3, v) = index_of(volume, v); });

	// the centre quad of the 3x3 grid has vertices 5, 6, 9, 10
	double face_avg = 0;
	foreach_cell(surface, [&](CMap2::Face f) {
		const double a = average<double>(surface, f, *id2);
		if (a == 7.5)
			face_avg = a;
	});
	std::cout << "average id over the centre quad: " << face_avg << "\n";

	// every hex of the 2x2x2 grid, and every edge of the surface
	double sum = 0;
	foreach_cell(volume, [&](CMap3::Volume w) { sum += average<double>(volume, w, *id3); });
	std::cout << "mean of the hexes' average vertex ids: " << sum / 8 << "\n";
	foreach_cell(surface, [&](CMap2::Edge e) { sum += average<double>(surface, e, *id2); });

	// neighbourhoods of the centre vertex of the hex grid
	CMap3::Vertex centre;
	foreach_cell(volume, [&](CMap3::Vertex v) {
		if (index_of(volume, v) != 13)
			return true;
		centre = v;
		return false;
	});
	uint32 ne = 0, nf = 0, nw = 0, nvv = 0;
	foreach_incident_edge(volume, centre, [&](CMap3::Edge) { ++ne; });
	foreach_incident_face(volume, centre, [&](CMap3::Face) { ++nf; });
	foreach_incident_volume(volume, centre, [&](CMap3::Volume) { ++nw; });
	foreach_adjacent_vertex_through_volume(volume, centre, [&](CMap3::Vertex) { ++nvv; });
	std::cout << "centre vertex: " << ne << " edges, " << nf << " faces, " << nw << " volumes, " << nvv
			  << " vertices sharing a volume\n";
	return (face_avg == 7.5 && sum / 8 > 0 && ne == 6 && nf == 12 && nw == 8 && nvv == 26) ? 0 : 1;
}
