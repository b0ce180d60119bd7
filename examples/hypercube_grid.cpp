// A 4-dimensional map: a grid of hypercubes built, traversed (a vertex star,
// the 4-cells around a 4-cell through their 3-cells), edited (a vertex in
// every edge, then the new edges contracted back), checked, and its 3-D
// boundary written as a VTU file that ParaView opens.
//
//   hypercube_grid [output.vtu]
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

int main(int argc, char** argv)
{
	using Map = CMapN<4>; // GMapN<4> works the same
	using Vertex = CellD<0>;
	using Edge = CellD<1>;
	using Hypercube = CellD<4>; // a 4-cell (CellD<3> is a 3-cell, a cube here)

	Map m;
	generate_cube_grid(m, 3); // 3 x 3 x 3 x 3 hypercubes in [0, 1]^4, positions in "position"
	std::cout << "f-vector:";
	for (uint32 n : f_vector(m))
		std::cout << ' ' << n;
	std::cout << ", Euler characteristic " << euler_characteristic(m) << '\n';

	// the star of a vertex: its edges and the hypercubes around it
	auto position = get_attribute<PointD<4>, Vertex>(m, "position");
	Vertex center;
	foreach_cell(m, [&](Vertex v) {
		const PointD<4>& p = (*position)[v];
		if (p[0] > 0.3 && p[0] < 0.4 && p[1] > 0.3 && p[1] < 0.4 && p[2] > 0.3 && p[2] < 0.4 && p[3] > 0.3 &&
			p[3] < 0.4)
			center = v; // the inner vertex (1/3, 1/3, 1/3, 1/3)
	});
	uint32 edges = 0, hypercubes = 0;
	foreach_incident_cell<1>(m, center, [&](Edge) { ++edges; });
	foreach_incident_cell<4>(m, center, [&](Hypercube) { ++hypercubes; });
	std::cout << "an inner vertex has " << edges << " edges and " << hypercubes << " hypercubes around it\n";
	// once per incidence (a corner of each hypercube): the same count on a
	// grid, where a hypercube meets a vertex once, and no set of the cells met
	uint32 corners = 0;
	foreach_incident_cell<4>(
		m, center, [&](Hypercube) { ++corners; }, each_incidence);
	std::cout << "and " << corners << " hypercube corners\n";

	// the neighbours of each hypercube through its cubes (3-cells)
	uint32 most = 0;
	foreach_cell(m, [&](Hypercube h) {
		uint32 n = 0;
		foreach_adjacent_cell<3>(m, h, [&](Hypercube) { ++n; });
		most = std::max(most, n);
	});
	std::cout << "a hypercube has at most " << most << " neighbours through its cubes\n";

	// a vertex in the middle of every edge, then the edges from the new
	// vertices contracted: the grid is back
	const std::vector<uint32> before = f_vector(m);
	std::vector<Edge> all_edges;
	foreach_cell(m, [&](Edge e) { all_edges.push_back(e); });
	std::vector<Vertex> middles;
	for (Edge e : all_edges)
		middles.push_back(insert_vertex_in_edge(m, e));
	std::cout << "after the insertions: " << nb_cells<0>(m) << " vertices, " << nb_cells<1>(m) << " edges\n";
	for (Vertex v : middles)
	{
		const Edge half(v.dart); // an edge of the new vertex
		if (!can_contract_cell<1>(m, half))
			return 1;
		contract_cell<1>(m, half);
	}
	const bool restored = f_vector(m) == before;
	const bool valid = check_integrity(m).ok();
	std::cout << "after the contractions: " << (restored ? "the same f-vector" : "another f-vector") << ", "
			  << (valid ? "valid" : "INVALID") << '\n';

	// the 3-D boundary (a 3-sphere made of cubes), written for ParaView
	const CMapN<3> boundary = extract_boundary(m);
	std::cout << "boundary: " << nb_cells<3>(boundary) << " cubes, Euler characteristic "
			  << euler_characteristic(boundary) << '\n';
	const std::string out = argc > 1 ? argv[1] : "hypercube_grid_boundary.vtu";
	io::save_vtu(boundary, out, {3});
	std::cout << "wrote " << out << '\n';
	return restored && valid && hypercubes == 16 && most == 8 ? 0 : 1;
}
