// The first program to read: build a few meshes in code, count their cells,
// check them, and walk a neighbourhood.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

template <typename MAP>
void describe(const char* name, const MAP& m, const BuildReport& r)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Edge = typename mesh_traits<MAP>::Edge;
	using Face = typename mesh_traits<MAP>::Face;
	const int64 v = nb_cells<Vertex>(m), e = nb_cells<Edge>(m), f = nb_cells<Face>(m);
	std::cout << name << ": " << v << " vertices, " << e << " edges, " << f << " faces";
	if constexpr (MAP::dimension == 3)
	{
		const int64 w = nb_cells<typename mesh_traits<MAP>::Volume>(m);
		std::cout << ", " << w << " volumes, Euler characteristic " << v - e + f - w;
	}
	else
		std::cout << ", Euler characteristic " << v - e + f;
	std::cout << ", " << nb_boundary_components(m) << " boundary component(s), " << nb_darts(m) << " darts"
			  << (r.nb_isolated_vertices ? ", isolated vertices dropped" : "") << "\n";
	const IntegrityReport ok = check_integrity(m);
	std::cout << "  integrity: " << (ok.ok() ? "ok" : ok.to_string()) << "\n";
}

int main()
{
	CMap2 torus;
	describe("torus 32x16 quads", torus, build_surface(torus, torus_soup(32, 16)));

	CMap2 sphere;
	describe("sphere 24x12", sphere, build_surface(sphere, sphere_soup(24, 12, true)));

	CMap2 grid;
	describe("grid 10x10 triangles", grid, build_surface(grid, grid_soup(10, 10, true)));

	CMap3 tets;
	describe("tet grid 4x4x4", tets, build_volume(tets, tet_grid_soup(4, 4, 4)));

	CMap3 hexes;
	describe("hex grid 3x3x3", hexes, build_volume(hexes, hex_grid_soup(3, 3, 3)));

	// valence histogram of the sphere
	std::vector<uint32> histogram;
	foreach_cell(sphere, [&](CMap2::Vertex v) {
		const uint32 d = degree(sphere, v);
		if (histogram.size() <= d)
			histogram.resize(d + 1, 0);
		++histogram[d];
	});
	std::cout << "sphere valences:";
	for (uint32 d = 0; d < histogram.size(); ++d)
		if (histogram[d])
			std::cout << " " << d << "x" << histogram[d];
	std::cout << "\n";
	return 0;
}
