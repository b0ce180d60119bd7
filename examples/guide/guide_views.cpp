// The CGoGN API guide's "CellFilter" and "CellCache" sections, written as a user
// writes them.
#include <cgogn/cgogn.h>

#include <iostream>
#include <sstream>

using namespace cgogn;

using Mesh = CMap2;
using Vertex = typename mesh_traits<Mesh>::Vertex;
using Edge = typename mesh_traits<Mesh>::Edge;
using Face = typename mesh_traits<Mesh>::Face;
template <typename T>
using Attribute = typename mesh_traits<Mesh>::template Attribute<T>;

// prints only the faces whose area is above a threshold
void print_faces(const CMap2& m, const Attribute<double>& area, double threshold, std::ostream& out)
{
	CellFilter<CMap2> cfm(m);
	cfm.set_filter<Face>([&](Face f) -> bool { return value<double>(cfm, area, f) > threshold; });
	foreach_cell(cfm, [&](Face f) -> bool {
		out << f << std::endl;
		return true;
	});
}

int main()
{
	CMap2 map;
	build_surface(map, grid_soup(4, 4));
	auto area = add_attribute<double, Face>(map, "area");
	uint32 k = 0;
	foreach_cell(map, [&](Face f) { value<double>(map, area, f) = double(k++); });
	std::ostringstream printed;
	print_faces(map, *area, 11.5, printed); // faces 12..15
	uint32 lines = 0;
	for (char c : printed.str())
		lines += c == '\n';

	// the degree 4 vertices (the grid's interior ones) in a cache
	CellCache cache(map);
	cache.build<Vertex>([&](Vertex v) { return degree(map, v) == 4; });
	uint32 inner = 0;
	foreach_cell(cache, [&](Vertex v) { /* do something with v */
										(void)v;
										++inner;
	});

	// cut the edges that existed when the cache was built
	CMap2& m = map;
	const uint32 nb_edges = nb_cells<Edge>(m);
	CellCache edges(m);
	edges.build<Edge>();
	foreach_cell(edges, [&](Edge e) { cut_edge(m, e); });

	std::cout << lines << " faces printed, " << inner << " inner vertices\n";
	return lines == 4 && inner == 9 && nb_cells<Edge>(m) == 2 * nb_edges ? 0 : 1;
}
