#include <cgogn/core.h>

#include <gtest/gtest.h>

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
		EXPECT_TRUE(same_cell(m, CMap2::Vertex(d), CMap2::Vertex(around)));   // indexed orbit
		EXPECT_TRUE(same_cell(m, CMap2::Face(d), CMap2::Face(phi1(m, d))));  // not indexed
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
