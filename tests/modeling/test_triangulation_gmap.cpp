// SPDX-License-Identifier: MIT
// Ear clipping on 2-G-maps: the same triangles as on a CMap2 of the same
// surface, and a non-orientable surface triangulated whole.
#include <cgogn/cgogn.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

namespace cgogn_test_triangulation_gmap
{

using namespace cgogn;

namespace
{

template <typename MAP>
std::shared_ptr<AttributeArray<Vec3>> build(MAP& m, const SurfaceSoup& s)
{
	const BuildReport r = build_surface(m, s);
	auto pos = add_attribute<Vec3, typename mesh_traits<MAP>::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return pos;
}

// The faces as sorted triples of vertex lines.
template <typename MAP>
std::set<std::array<uint32, 3>> triangles(const MAP& m)
{
	using T = mesh_traits<MAP>;
	std::set<std::array<uint32, 3>> out;
	foreach_cell(m, [&](typename T::Face f) {
		std::vector<uint32> v;
		foreach_incident_vertex(m, f, [&](typename T::Vertex x) { v.push_back(index_of(m, x)); });
		EXPECT_EQ(v.size(), 3u);
		std::sort(v.begin(), v.end());
		out.insert({v[0], v[1], v[2]});
	});
	return out;
}

} // namespace

TEST(TriangulationGMap, SameTrianglesAsTheCMap2)
{
	// a grid of distorted quads and hexagons of a torus: no two ears tie
	for (SurfaceSoup s : {grid_soup(4, 3), torus_soup(6, 4)})
	{
		for (uint32 i = 0; i < s.nb_vertices; ++i)
		{
			s.positions[i][0] += 0.013 * double((i * 7919u) % 11u);
			s.positions[i][1] += 0.007 * double((i * 104729u) % 7u);
		}
		CMap2 c;
		GMap2 g;
		auto pc = build(c, s);
		auto pg = build(g, s);
		EXPECT_EQ(modeling::triangulate_faces(c, *pc), modeling::triangulate_faces(g, *pg));
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_TRUE(modeling::is_triangle_mesh(g));
		EXPECT_EQ(triangles(c), triangles(g));
	}
}

TEST(TriangulationGMap, KleinBottleTriangulatedWhole)
{
	GMap2 g;
	auto pos = build(g, klein_bottle_soup(8, 6));
	const uint32 faces = nb_cells<GMap2::Face>(g);
	EXPECT_EQ(modeling::triangulate_faces(g, *pos), faces);
	EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
	EXPECT_EQ(nb_cells<GMap2::Face>(g), 2 * faces);
	EXPECT_EQ(euler_characteristic(g), 0);
	EXPECT_FALSE(is_orientable(g));
	EXPECT_TRUE(modeling::is_triangle_mesh(g));
	// a hexagon of a polygon: 4 triangles, no new vertex
	GMap2 h;
	const GMap2::Face f = add_face(h, 6);
	auto hp = add_attribute<Vec3, GMap2::Vertex>(h, "position");
	uint32 k = 0;
	foreach_incident_vertex(h, f, [&](GMap2::Vertex v) {
		const double a = 2.0 * 3.14159265358979 * double(k++) / 6.0;
		value<Vec3>(h, *hp, v) = Vec3(std::cos(a), std::sin(a), 0.0);
	});
	EXPECT_EQ(modeling::ear_clip_face(h, *hp, f), 4u);
	EXPECT_TRUE(check_integrity(h).ok()) << check_integrity(h).to_string();
	EXPECT_EQ(nb_cells<GMap2::Face>(h), 4u);
	EXPECT_EQ(nb_cells<GMap2::Vertex>(h), 6u);
}

} // namespace cgogn_test_triangulation_gmap
