#include <cgogn/core.h>

#include <gtest/gtest.h>

namespace cgogn_test_builder
{

using namespace cgogn;

namespace
{
int64 euler(const CMap2& m)
{
	return int64(nb_cells<CMap2::Vertex>(m)) - nb_cells<CMap2::Edge>(m) + nb_cells<CMap2::Face>(m);
}
int64 euler(const CMap3& m)
{
	return int64(nb_cells<CMap3::Vertex>(m)) - nb_cells<CMap3::Edge>(m) + nb_cells<CMap3::Face>(m) -
		   nb_cells<CMap3::Volume>(m);
}
BuildReport build(CMap2& m, uint32 nv, std::vector<std::vector<uint32>> faces)
{
	std::vector<uint32> sizes, ids;
	for (auto& f : faces)
	{
		sizes.push_back(uint32(f.size()));
		ids.insert(ids.end(), f.begin(), f.end());
	}
	return build_surface(m, nv, sizes, ids);
}
BuildReport build(CMap3& m, uint32 nv, std::vector<std::vector<uint32>> cells)
{
	std::vector<uint32> sizes, ids;
	for (auto& c : cells)
	{
		sizes.push_back(uint32(c.size()));
		ids.insert(ids.end(), c.begin(), c.end());
	}
	return build_volume(m, nv, sizes, ids);
}
} // namespace

struct GeneratedSurface
{
	const char* name;
	SurfaceSoup soup;
	int64 euler;
	uint32 boundaries;
};

TEST(SurfaceBuilder, GeneratedSurfacesHaveTheirTopology)
{
	const std::vector<GeneratedSurface> cases = {
		{"grid quads", grid_soup(5, 4), 1, 1},   {"grid triangles", grid_soup(5, 4, true), 1, 1},
		{"cylinder", cylinder_soup(8, 3), 0, 2}, {"cylinder triangles", cylinder_soup(8, 3, true), 0, 2},
		{"sphere", sphere_soup(8, 5), 2, 0},     {"sphere triangles", sphere_soup(8, 5, true), 2, 0},
		{"torus", torus_soup(7, 5), 0, 0},       {"torus triangles", torus_soup(7, 5, true), 0, 0},
	};
	for (const auto& c : cases)
	{
		CMap2 m;
		BuildReport r = build_surface(m, c.soup);
		SCOPED_TRACE(c.name);
		EXPECT_EQ(r.nb_cells_built, c.soup.face_sizes.size());
		EXPECT_EQ(nb_cells<CMap2::Vertex>(m), c.soup.nb_vertices);
		EXPECT_EQ(nb_cells<CMap2::Face>(m), c.soup.face_sizes.size());
		EXPECT_EQ(euler(m), c.euler);
		EXPECT_EQ(nb_boundary_components(m), c.boundaries);
		EXPECT_EQ(r.nb_boundary_cells, c.boundaries);
		EXPECT_EQ(r.nb_nonmanifold_edges + r.nb_nonmanifold_vertices + r.nb_isolated_vertices, 0u);
		EXPECT_EQ(nb_connected_components(m), 1u);
		EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	}
}

TEST(SurfaceBuilder, SkipsAndCountsBadFaces)
{
	CMap2 m;
	BuildReport r = build(m, 5, {{0, 1, 2}, {0, 1}, {2, 3, 3}, {1, 7, 2}, {0, 2, 3}});
	EXPECT_EQ(r.nb_cells_read, 5u);
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(r.nb_cells_degenerate, 2u);
	EXPECT_EQ(r.nb_cells_invalid, 1u);
	EXPECT_EQ(r.nb_isolated_vertices, 1u); // vertex 4
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), 4u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 2u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(SurfaceBuilder, TruncatedIdListIsCounted)
{
	CMap2 m;
	const uint32 sizes[2] = {3, 4};
	const uint32 ids[5] = {0, 1, 2, 0, 2};
	BuildReport r = build_surface(m, 3, sizes, ids);
	EXPECT_EQ(r.nb_cells_built, 1u);
	EXPECT_EQ(r.nb_cells_invalid, 1u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(SurfaceBuilder, NonManifoldEdgeDetachesTheExtraFace)
{
	CMap2 m;
	// three triangles on edge (0, 1)
	BuildReport r = build(m, 5, {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}});
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 3u);
	EXPECT_GE(r.nb_nonmanifold_edges, 1u);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
}

TEST(SurfaceBuilder, NonManifoldVertexIsSplitPerFan)
{
	CMap2 m;
	// a bow tie: two triangles sharing only vertex 0
	BuildReport r = build(m, 5, {{0, 1, 2}, {0, 3, 4}});
	EXPECT_EQ(r.nb_nonmanifold_vertices, 1u);
	ASSERT_EQ(r.split_vertices.size(), 1u);
	EXPECT_EQ(r.split_vertices[0].second, 0u);
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), 6u);
	EXPECT_EQ(nb_boundary_components(m), 2u);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
}

TEST(SurfaceBuilder, InconsistentOrientationLeavesABoundary)
{
	CMap2 m;
	BuildReport r = build(m, 4, {{0, 1, 2}, {0, 1, 3}}); // both use 0->1
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 2u);
	EXPECT_EQ(r.nb_nonmanifold_edges, 1u); // one edge, whose two half-edges are detached
	EXPECT_EQ(r.nb_orientation_conflicts, 1u);
	EXPECT_TRUE(r.orientable); // turning one face over would do
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(SurfaceBuilder, AppendsToANonEmptyMapAndIndexesItsOrbits)
{
	CMap2 m;
	build_surface(m, sphere_soup(6, 4));
	auto fa = add_attribute<int, CMap2::Face>(m, "f");
	auto ea = add_attribute<int, CMap2::Edge>(m, "e");
	const uint32 v0 = nb_cells<CMap2::Vertex>(m), f0 = nb_cells<CMap2::Face>(m);
	BuildReport r = build_surface(m, torus_soup(5, 4));
	EXPECT_EQ(r.vertex_offset, v0);
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), v0 + 20u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), f0 + 20u);
	EXPECT_EQ(nb_connected_components(m), 2u);
	EXPECT_EQ(euler(m), 2);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
}

TEST(VolumeBuilder, GeneratedGrids)
{
	for (auto [nx, ny, nz] : {std::array<uint32, 3>{1, 1, 1}, {3, 2, 2}, {4, 4, 4}})
	{
		CMap3 tets, hexes;
		BuildReport rt = build_volume(tets, tet_grid_soup(nx, ny, nz));
		BuildReport rh = build_volume(hexes, hex_grid_soup(nx, ny, nz));
		const uint32 cubes = nx * ny * nz, V = (nx + 1) * (ny + 1) * (nz + 1);
		EXPECT_EQ(nb_cells<CMap3::Volume>(tets), 6u * cubes);
		EXPECT_EQ(nb_cells<CMap3::Volume>(hexes), cubes);
		EXPECT_EQ(nb_cells<CMap3::Vertex>(tets), V);
		EXPECT_EQ(nb_cells<CMap3::Vertex>(hexes), V);
		EXPECT_EQ(euler(tets), 1);
		EXPECT_EQ(euler(hexes), 1);
		EXPECT_EQ(rt.nb_boundary_cells, 1u);
		EXPECT_EQ(rh.nb_boundary_cells, 1u);
		EXPECT_EQ(rt.nb_nonmanifold_vertices + rt.nb_nonmanifold_faces, 0u);
		EXPECT_TRUE(check_integrity(tets).ok());
		EXPECT_TRUE(check_integrity(hexes).ok());
	}
}

TEST(VolumeBuilder, MixedCellsShareFaces)
{
	CMap3 m;
	// a hex, a pyramid on its top quad, a prism on its front quad, a tet on a
	// triangle of the pyramid
	BuildReport r = build(m, 12, {{0, 1, 2, 3, 4, 5, 6, 7}, {4, 5, 6, 7, 8}, {1, 0, 9, 5, 4, 10}, {5, 4, 11, 8}});
	EXPECT_EQ(r.nb_cells_built, 4u);
	EXPECT_EQ(r.nb_nonmanifold_vertices, 0u);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 4u);
	uint32 inner = 0, faces = 0;
	foreach_cell(m, [&](CMap3::Face f) {
		inner += degree(m, f) == 2;
		++faces;
	});
	EXPECT_EQ(inner, 3u);
	EXPECT_EQ(faces, 6u + 5u + 5u + 4u - 3u);
	EXPECT_EQ(euler(m), 1);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
}

TEST(VolumeBuilder, NonManifoldVertexIsSplit)
{
	CMap3 m;
	BuildReport r = build(m, 7, {{0, 1, 2, 3}, {0, 4, 5, 6}});
	EXPECT_EQ(r.nb_nonmanifold_vertices, 1u);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), 8u);
	EXPECT_EQ(r.nb_boundary_cells, 2u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(VolumeBuilder, SharedFaceAndBadCells)
{
	CMap3 m;
	// two tets on face (0 1 2), apexes on both sides; a cell of 7 vertices; a repeated vertex
	BuildReport r = build(m, 5, {{0, 1, 2, 3}, {0, 2, 1, 4}, {0, 1, 2, 3, 4, 0, 1}, {0, 1, 1, 2}});
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(r.nb_cells_invalid, 1u);
	EXPECT_EQ(r.nb_cells_degenerate, 1u);
	EXPECT_EQ(nb_cells<CMap3::Face>(m), 7u);
	EXPECT_EQ(nb_cells<CMap3::Edge>(m), 9u);
	EXPECT_EQ(euler(m), 1);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(VolumeBuilder, FacesAreOrientedOutward)
{
	// signed volume from the faces of each cell = +volume when faces point outward
	VolumeSoup s = tet_grid_soup(1, 1, 1);
	CMap3 m;
	BuildReport r = build_volume(m, s);
	auto p = [&](Dart d) { return s.positions[index_of(m, CMap3::Vertex(d)) - r.vertex_offset]; };
	double total = 0;
	foreach_cell(m, [&](CMap3::Volume w) {
		double vol = 0;
		foreach_incident_face(m, w, [&](CMap3::Face f) {
			// f.dart is in w: fan triangles of the face with the origin
			Dart d0 = f.dart;
			for (Dart d = phi1(m, d0); phi1(m, d) != d0; d = phi1(m, d))
			{
				auto a = p(d0), b = p(d), c = p(phi1(m, d));
				vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
						a[2] * (b[0] * c[1] - b[1] * c[0])) /
					   6.0;
			}
		});
		EXPECT_NEAR(vol, 1.0 / 6.0, 1e-12);
		total += vol;
	});
	EXPECT_NEAR(total, 1.0, 1e-12);
	VolumeSoup h = hex_grid_soup(1, 1, 1);
	CMap3 mh;
	BuildReport rh = build_volume(mh, h);
	foreach_cell(mh, [&](CMap3::Volume w) {
		double vol = 0;
		foreach_incident_face(mh, w, [&](CMap3::Face f) {
			Dart d0 = f.dart;
			for (Dart d = phi1(mh, d0); phi1(mh, d) != d0; d = phi1(mh, d))
			{
				auto a = h.positions[index_of(mh, CMap3::Vertex(d0)) - rh.vertex_offset];
				auto b = h.positions[index_of(mh, CMap3::Vertex(d)) - rh.vertex_offset];
				auto c = h.positions[index_of(mh, CMap3::Vertex(phi1(mh, d))) - rh.vertex_offset];
				vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
						a[2] * (b[0] * c[1] - b[1] * c[0])) /
					   6.0;
			}
		});
		EXPECT_NEAR(vol, 1.0, 1e-12);
	});
}

// A build leaves no idle pooled mark behind: the map holds its attributes
// and its boundary mark only (the bytes per face of the benchmarks).
TEST(Builder, LeavesNoIdleMarkAllocated)
{
	CMap2 m;
	build_surface(m, torus_soup(40, 30, true));
	std::size_t expected = 0;
	for (const AttributeContainer* c :
		 {cgogn::detail::state_of(m).darts.get(), cgogn::detail::state_of(m).cells[orbit_index(Orbit::PHI21)].get()})
	{
		std::size_t attributes = 0;
		for (const auto& a : c->attributes())
			attributes += a->memory_bytes();
		expected += attributes;
	}
	// the darts' boundary mark: one bit per dart line, in whole chunks, in
	// whole pages
	const std::size_t mark_bytes =
		(cgogn::detail::state_of(m).darts->end_index() + CHUNK_SIZE - 1) / CHUNK_SIZE * (CHUNK_SIZE / 8);
	const std::size_t page = detail::page_size();
	expected += (mark_bytes + page - 1) / page * page;
	std::size_t held = cgogn::detail::state_of(m).darts->memory_bytes() +
					   cgogn::detail::state_of(m).cells[orbit_index(Orbit::PHI21)]->memory_bytes();
	held -= cgogn::detail::state_of(m).darts->free_lines().capacity() * sizeof(uint32);
	held -= cgogn::detail::state_of(m).cells[orbit_index(Orbit::PHI21)]->free_lines().capacity() * sizeof(uint32);
	EXPECT_EQ(held, expected);
}

} // namespace cgogn_test_builder
