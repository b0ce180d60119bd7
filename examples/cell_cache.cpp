// The "CellCache" section of the CGoGN API guide: a cache of the degree 5
// vertices, and the snapshot property: cells created while traversing a
// cache are not visited.
#include <cgogn/cgogn.h>
#if __has_include(<cgogn/core/operators/cmap2.h>)
#include <cgogn/core/operators/cmap2.h>
#define CGOGN_HAS_CUT_EDGE 1
#endif

#include <iostream>

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

int main()
{
	CMap2 map;
	build_surface(map, sphere_soup(5, 6, true)); // poles and some ring vertices have degree 5

	// given a CMap2 map
	CellCache cache(map);
	cache.build<Vertex>([&](Vertex v) { return degree(map, v) == 5; });
	uint32 nb_degree_5 = 0;
	foreach_cell(cache, [&](Vertex) { /* do something with v */ ++nb_degree_5; });
	uint32 expected = 0;
	foreach_cell(map, [&](Vertex v) { expected += degree(map, v) == 5; });
	std::cout << nb_degree_5 << " vertices of degree 5\n";
	if (nb_degree_5 != expected || expected == 0)
		return 1;

	// snapshot: new faces created during the traversal of the cache are not visited
	const uint32 nb_faces = nb_cells<Face>(map);
	cache.build<Face>();
	uint32 visited = 0;
	foreach_cell(cache, [&](Face) {
		add_face(map, 3);
		++visited;
	});
	std::cout << visited << " faces visited, " << nb_cells<Face>(map) << " faces now\n";
	if (visited != nb_faces || nb_cells<Face>(map) != 2 * nb_faces)
		return 1;

#ifdef CGOGN_HAS_CUT_EDGE
	{
		// given a CMap2 m: every edge that existed when the cache was built is cut once
		CMap2 m;
		build_surface(m, sphere_soup(5, 6, true));
		const uint32 nb_edges = nb_cells<Edge>(m), nb_vertices = nb_cells<Vertex>(m);
		CellCache cache(m);
		cache.build<Edge>();
		foreach_cell(cache, [&](Edge e) { cut_edge(m, e); });
		std::cout << nb_edges << " edges cut: " << nb_cells<Edge>(m) << " edges, " << nb_cells<Vertex>(m)
				  << " vertices\n";
		if (nb_cells<Edge>(m) != 2 * nb_edges || nb_cells<Vertex>(m) != nb_vertices + nb_edges ||
			!check_integrity(m).ok())
			return 1;
	}
#else
	std::cout << "cut_edge not available in this build: the guide's cut-every-edge example is skipped\n";
#endif
	return 0;
}
