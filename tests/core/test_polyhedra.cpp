// SPDX-License-Identifier: MIT
// Volume meshes of any polyhedra (build_polyhedra): prisms on any polygon
// stacked and sewn, the standard cells given by their faces against
// build_volume, and the cells the builder refuses.
#include <cgogn/core.h>

#include <gtest/gtest.h>

namespace cgogn_test_polyhedra
{

using namespace cgogn;

namespace
{

std::vector<uint32> counts(const CMap3& m)
{
	return {nb_cells<CMap3::Vertex>(m), nb_cells<CMap3::Edge>(m), nb_cells<CMap3::Face>(m), nb_cells<CMap3::Volume>(m)};
}

} // namespace

TEST(Polyhedra, PrismsOnAnyPolygonAreBuiltAndSewn)
{
	for (uint32 n : {3u, 4u, 5u, 6u, 11u})
	{
		SCOPED_TRACE(n);
		CMap3 m;
		const BuildReport r = build_polyhedra(m, prism_column_soup(n, 3));
		EXPECT_EQ(r.nb_cells_read, 3u);
		EXPECT_EQ(r.nb_cells_built, 3u);
		EXPECT_EQ(r.nb_cells_invalid + r.nb_cells_degenerate, 0u);
		EXPECT_EQ(r.nb_nonmanifold_faces, 0u);
		EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
		// 4 rings of n vertices, 4 n ring edges and 3 n posts, 4 n-gons and 3 n quads
		EXPECT_EQ(counts(m), (std::vector<uint32>{4 * n, 7 * n, 4 + 3 * n, 3}));
		uint32 ngons = 0, quads = 0;
		foreach_cell(m, [&](CMap3::Face f) {
			const uint32 k = codegree(m, f);
			ngons += k == n;
			quads += k == 4;
		});
		if (n != 4)
		{
			EXPECT_EQ(ngons, 4u);
			EXPECT_EQ(quads, 3 * n);
		}
		foreach_cell(m, [&](CMap3::Volume w) {
			uint32 faces = 0;
			foreach_incident_face(m, w, [&](CMap3::Face) { return ++faces, true; });
			EXPECT_EQ(faces, n + 2);
		});
		// the two inner n-gons are shared: not on the boundary
		uint32 inner = 0;
		foreach_cell(m, [&](CMap3::Face f) { inner += !is_incident_to_boundary(m, f); });
		EXPECT_EQ(inner, 2u);
	}
}

TEST(Polyhedra, GMap3HoldsThemWithTwiceTheDarts)
{
	for (uint32 n : {3u, 4u, 7u, 12u})
	{
		SCOPED_TRACE(n);
		CMap3 c;
		GMap3 g;
		const PolyhedronSoup s = prism_column_soup(n, 4);
		build_polyhedra(c, s);
		const BuildReport r = build_polyhedra(g, s);
		EXPECT_EQ(r.nb_cells_built, 4u);
		EXPECT_TRUE(r.orientable);
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_EQ(nb_darts(g), 2 * nb_darts(c));
		EXPECT_EQ((std::vector<uint32>{nb_cells<GMap3::Vertex>(g), nb_cells<GMap3::Edge>(g), nb_cells<GMap3::Face>(g),
									   nb_cells<GMap3::Volume>(g)}),
				  counts(c));
	}
	// a G-map glues a cell listed in the other orientation to its neighbours;
	// a 3-map cannot
	PolyhedronSoup s = prism_column_soup(5, 2);
	std::size_t k = 2 * 5 + 5 * 4; // the vertices of the first cell's faces
	for (std::size_t f = 7; f < s.face_sizes.size(); ++f)
	{
		std::reverse(s.face_vertices.begin() + std::ptrdiff_t(k),
					 s.face_vertices.begin() + std::ptrdiff_t(k + s.face_sizes[f]));
		k += s.face_sizes[f];
	}
	GMap3 g;
	CMap3 c;
	build_polyhedra(g, s);
	build_polyhedra(c, s);
	EXPECT_TRUE(check_integrity(g).ok());
	EXPECT_EQ(nb_cells<GMap3::Face>(g), 2 + 1 + 2 * 5u); // the middle pentagon shared
	EXPECT_EQ(nb_cells<CMap3::Face>(c), 2 + 2 + 2 * 5u); // not sewn there: two faces
}

TEST(Polyhedra, StandardCellsGivenByTheirFacesBuildTheSameMap)
{
	for (const VolumeSoup& v : {hex_grid_soup(3, 2, 2), tet_grid_soup(2, 2, 3)})
	{
		GMap3 gcells, gfaces;
		build_volume(gcells, v);
		build_polyhedra(gfaces, polyhedra_of(v));
		EXPECT_TRUE(check_integrity(gfaces).ok());
		EXPECT_EQ(nb_darts(gfaces), nb_darts(gcells));
		EXPECT_EQ(nb_cells<GMap3::Face>(gfaces), nb_cells<GMap3::Face>(gcells));
		CMap3 cells, faces;
		build_volume(cells, v);
		const PolyhedronSoup p = polyhedra_of(v);
		EXPECT_EQ(p.cell_nb_faces.size(), v.cell_sizes.size());
		const BuildReport r = build_polyhedra(faces, p);
		EXPECT_EQ(r.nb_cells_built, uint32(v.cell_sizes.size()));
		EXPECT_TRUE(check_integrity(faces).ok());
		EXPECT_EQ(counts(faces), counts(cells));
		EXPECT_EQ(nb_darts(faces), nb_darts(cells));
		EXPECT_EQ(nb_boundary_components(faces), 1u);
	}
}

TEST(Polyhedra, CellsThatDoNotCloseASurfaceAreSkippedAndCounted)
{
	const PolyhedronSoup good = prism_column_soup(5, 1); // faces: bottom, top, 5 sides
	const auto one_cell = [&](const std::vector<std::vector<uint32>>& faces) {
		PolyhedronSoup s;
		s.nb_vertices = good.nb_vertices;
		s.cell_nb_faces = {uint32(faces.size())};
		for (const auto& f : faces)
		{
			s.face_sizes.push_back(uint32(f.size()));
			s.face_vertices.insert(s.face_vertices.end(), f.begin(), f.end());
		}
		CMap3 m;
		const BuildReport r = build_polyhedra(m, s);
		EXPECT_TRUE(check_integrity(m).ok());
		EXPECT_EQ(nb_cells<CMap3::Volume>(m), r.nb_cells_built);
		return r;
	};
	std::vector<std::vector<uint32>> faces = {{0, 4, 3, 2, 1}, {5, 6, 7, 8, 9}};
	for (uint32 i = 0; i < 5; ++i)
		faces.push_back({i, (i + 1) % 5, 5 + (i + 1) % 5, 5 + i});
	EXPECT_EQ(one_cell(faces).nb_cells_built, 1u);

	auto open = faces;
	open.pop_back(); // a side missing
	EXPECT_EQ(one_cell(open).nb_cells_invalid, 1u);
	auto turned = faces;
	std::reverse(turned[1].begin(), turned[1].end()); // the top listed inward
	EXPECT_EQ(one_cell(turned).nb_cells_invalid, 1u);
	auto out_of_range = faces;
	out_of_range[0][0] = 10;
	EXPECT_EQ(one_cell(out_of_range).nb_cells_invalid, 1u);
	auto repeated = faces;
	repeated[0] = {0, 4, 3, 3, 1};
	EXPECT_EQ(one_cell(repeated).nb_cells_degenerate, 1u);
	EXPECT_EQ(one_cell({{0, 1, 2}, {0, 2, 1}}).nb_cells_degenerate, 1u); // two faces
	// the same surface listed twice: each directed edge met twice
	auto twice = faces;
	twice.insert(twice.end(), faces.begin(), faces.end());
	EXPECT_EQ(one_cell(twice).nb_cells_invalid, 1u);

	// lists that stop short: the cell is invalid, the cells before it built
	PolyhedronSoup s = prism_column_soup(4, 2);
	s.face_vertices.resize(s.face_vertices.size() - 3);
	CMap3 m;
	const BuildReport r = build_polyhedra(m, s);
	EXPECT_EQ(r.nb_cells_built, 1u);
	EXPECT_EQ(r.nb_cells_invalid, 1u);
	EXPECT_TRUE(check_integrity(m).ok());
	s.cell_nb_faces.push_back(7); // no face left for it
	CMap3 k;
	EXPECT_EQ(build_polyhedra(k, s).nb_cells_invalid, 2u);
}

} // namespace cgogn_test_polyhedra
