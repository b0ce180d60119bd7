// The "Marking" section of the CGoGN API guide: cell markers, and stores for few cells.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

int main()
{
	using Mesh = CMap2;
	using Vertex = mesh_traits<Mesh>::Vertex;
	using Face = mesh_traits<Mesh>::Face;

	Mesh m;
	build_surface(m, torus_soup(12, 8, true));

	// mark the vertices of every other face; count the marked vertices once each
	CellMarker<Mesh, Vertex> cm{m};
	uint32 k = 0, marked = 0;
	foreach_cell(m, [&](Face f) {
		if (k++ % 2)
			return;
		foreach_incident_vertex(m, f, [&](Vertex v) {
			if (!cm.is_marked(v))
			{
				cm.mark(v);
				++marked;
			}
		});
	});
	std::cout << marked << " of " << nb_cells<Vertex>(m) << " vertices touched by every other face\n";
	cm.unmark_all();

	// a store for a few cells: the one-ring of one vertex
	CellMarkerStore<Mesh, Vertex> ring{m};
	Vertex center;
	foreach_cell(m, [&](Vertex v) {
		center = v;
		return false;
	});
	foreach_adjacent_vertex_through_edge(m, center, [&](Vertex v) { ring.mark(v); });
	std::cout << "one-ring of vertex " << index_of(m, center) << ": " << ring.marked_cells().size() << " vertices\n";

	// low-level: mark whole orbits of darts
	DartMarker dm{m};
	dm.mark_orbit(Face(center.dart));
	uint32 darts = 0;
	foreach_dart(m, [&](Dart d) { darts += dm.is_marked(d); });
	std::cout << "a triangle has " << darts << " darts\n";
	return darts == 3 && ring.marked_cells().size() == 6 ? 0 : 1;
}
