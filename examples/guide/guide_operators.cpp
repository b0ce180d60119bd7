// The CGoGN API guide's "Operators", "Creation" and "Marking" sections, written as
// a user writes them.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

using Mesh = CMap2;
using Vertex = typename mesh_traits<Mesh>::Vertex;
using Edge = typename mesh_traits<Mesh>::Edge;
using Face = typename mesh_traits<Mesh>::Face;
using Volume = typename mesh_traits<Mesh>::Volume;

int main()
{
	Mesh m;
	build_surface(m, grid_soup(3, 3, true)); // triangles
	Edge some_edge;
	foreach_cell(m, [&](Edge e) {
		if (is_incident_to_boundary(m, e))
			return true;
		some_edge = e;
		return false;
	});
	flip_edge(m, some_edge);
	Vertex v = cut_edge(m, some_edge);
	Edge e2(phi1(m, v.dart));
	Vertex w = collapse_edge(m, Edge(v.dart));
	if (!w.is_valid() || !check_integrity(m).ok())
		return 1;
	foreach_cell(m, [&](Edge e) {
		if (!can_merge_incident_faces(m, e))
			return true;
		merge_incident_faces(m, e);
		return false;
	});
	(void)e2;

	// creation
	Face f = add_face(m, 5);
	CMap3 m3;
	mesh_traits<CMap3>::Volume prism = add_prism(m3, 3);
	mesh_traits<CMap3>::Volume pyramid = add_pyramid(m3, 4);
	close(m3);

	// marking
	CellMarker<Mesh, Vertex> cm{m};
	uint32 marked = 0;
	foreach_incident_vertex(m, f, [&](Vertex x) {
		if (!cm.is_marked(x))
			cm.mark(x);
		++marked;
	});
	foreach_incident_vertex(m, f, [&](Vertex x) { cm.unmark(x); });
	cm.unmark_all();
	CellMarkerStore<Mesh, Vertex> cms{m};
	foreach_incident_vertex(m, f, [&](Vertex x) { cms.mark(x); });
	const std::size_t stored = cms.marked_cells().size();

	std::cout << marked << " vertices marked, " << stored << " stored\n";
	return marked == 5 && stored == 5 && check_integrity(m).ok() && check_integrity(m3).ok() && prism.is_valid() &&
				   pyramid.is_valid()
			   ? 0
			   : 1;
}
