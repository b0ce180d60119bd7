#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <utility>

namespace cgogn_test_properties
{

using namespace cgogn;

TEST(Properties, DegreesAndBoundaryOnAGrid)
{
	CMap2 m;
	build_surface(m, grid_soup(2, 2)); // ids 3j + i
	uint32 boundary_vertices = 0, boundary_edges = 0, boundary_faces = 0, deg_sum = 0;
	foreach_cell(m, [&](CMap2::Vertex v) {
		boundary_vertices += is_incident_to_boundary(m, v);
		deg_sum += degree(m, v);
		if (index_of(m, v) == 4)
		{
			EXPECT_EQ(degree(m, v), 4u);
			EXPECT_FALSE(is_incident_to_boundary(m, v));
		}
	});
	foreach_cell(m, [&](CMap2::Edge e) {
		boundary_edges += is_incident_to_boundary(m, e);
		EXPECT_EQ(degree(m, e), is_incident_to_boundary(m, e) ? 1u : 2u);
		EXPECT_EQ(codegree(m, e), 2u);
	});
	foreach_cell(m, [&](CMap2::Face f) {
		boundary_faces += is_incident_to_boundary(m, f);
		EXPECT_EQ(codegree(m, f), 4u);
	});
	EXPECT_EQ(boundary_vertices, 8u);
	EXPECT_EQ(boundary_edges, 8u);
	EXPECT_EQ(boundary_faces, 4u);
	EXPECT_EQ(deg_sum, 2u * 12u);
}

TEST(Properties, SameCell)
{
	CMap2 m;
	build_surface(m, torus_soup(4, 3));
	foreach_dart(m, [&](Dart d) {
		const Dart around = phi1(m, phi2(m, d));
		EXPECT_TRUE(same_cell(m, CMap2::Vertex(d), CMap2::Vertex(around))); // indexed orbit
		EXPECT_TRUE(same_cell(m, CMap2::Face(d), CMap2::Face(phi1(m, d)))); // not indexed
		EXPECT_FALSE(same_cell(m, CMap2::Face(d), CMap2::Face(phi2(m, d))));
		EXPECT_TRUE(same_cell(m, CMap2::Edge(d), CMap2::Edge(phi2(m, d))));
		EXPECT_FALSE(same_cell(m, CMap2::Vertex(d), CMap2::Vertex(phi1(m, d))));
	});
}

TEST(Properties, ConnectedAndBoundaryComponents)
{
	CMap2 m;
	build_surface(m, sphere_soup(6, 4));
	build_surface(m, cylinder_soup(6, 2));
	build_surface(m, grid_soup(2, 2));
	EXPECT_EQ(nb_connected_components(m), 3u);
	EXPECT_EQ(nb_boundary_components(m), 3u); // cylinder 2, grid 1
	CMap3 v;
	build_volume(v, hex_grid_soup(1, 1, 1));
	build_volume(v, tet_grid_soup(1, 1, 1));
	EXPECT_EQ(nb_connected_components(v), 2u);
	EXPECT_EQ(nb_boundary_components(v), 2u);
}

TEST(Properties, NbCellsIsO1WhenIndexed)
{
	CMap2 m;
	build_surface(m, torus_soup(10, 10, true));
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 200u); // counted by traversal
	add_attribute<int, CMap2::Face>(m, "x");
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 200u); // read from the container
	EXPECT_EQ(container_of<Orbit::PHI1>(m).nb_lines(), 200u);
}

namespace
{
/// degree and codegree of every cell of type CELL, summed: generic code that
/// must compile for every cell type of the map.
template <typename CELL, typename MAP>
std::pair<uint64, uint64> degree_sums(const MAP& m)
{
	uint64 d = 0, c = 0;
	foreach_cell(m, [&](CELL x) {
		d += degree(m, x);
		c += codegree(m, x);
	});
	return {d, c};
}
} // namespace

TEST(Properties, DegreeAndCodegreeOfEveryCellTypeOfASurface)
{
	CMap2 m;
	build_surface(m, grid_soup(3, 2)); // 12 vertices, 17 edges, 6 quads, one component
	using P = std::pair<uint64, uint64>;
	// vertices: sum of degrees = 2 E, codegree 0
	EXPECT_EQ(degree_sums<CMap2::Vertex>(m), P(2 * 17, 0));
	// edges: incident non-boundary faces
	const auto [edge_faces, edge_vertices] = degree_sums<CMap2::Edge>(m);
	EXPECT_EQ(edge_faces, 4u * 6u); // each quad counted by its 4 edges
	EXPECT_EQ(edge_vertices, 2u * 17u);
	// faces: in one volume each, 4 edges each
	EXPECT_EQ(degree_sums<CMap2::Face>(m), P(6, 4 * 6));
	// the volume (connected component): no higher cell, 6 faces
	EXPECT_EQ(degree_sums<CMap2::Volume>(m), P(0, 6));
}

TEST(Properties, DegreeAndCodegreeOfEveryCellTypeOfAVolume)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(2, 1, 1)); // two cubes sharing a face
	using P = std::pair<uint64, uint64>;
	const uint64 nv = nb_cells<CMap3::Vertex>(m), ne = nb_cells<CMap3::Edge>(m), nf = nb_cells<CMap3::Face>(m);
	EXPECT_EQ(nv, 12u);
	EXPECT_EQ(ne, 20u);
	EXPECT_EQ(nf, 11u);
	EXPECT_EQ(degree_sums<CMap3::Vertex>(m), P(2 * ne, 0));
	// each face is bounded by its edges: sum over edges of incident faces = sum over faces of codegree
	const auto [edge_faces, edge_vertices] = degree_sums<CMap3::Edge>(m);
	EXPECT_EQ(edge_faces, 4u * nf);
	EXPECT_EQ(edge_vertices, 2u * ne);
	// faces: 1 inner face in 2 volumes, 10 in one; 4 edges each
	EXPECT_EQ(degree_sums<CMap3::Face>(m), P(12, 4 * nf));
	EXPECT_EQ(degree_sums<CMap3::Volume>(m), P(0, 12));
}

} // namespace cgogn_test_properties
