// The cell-list builder of 3-G-maps: the same cells as the CMap3 builder
// (and as to_gmap of its result) on every mesh the CMap3 builder builds
// whole, cells listed in the opposite orientation glued, the same report on
// bad input, and the meshes no 3-map can hold.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "volume_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace cgogn_test_gmap3_builder
{

using namespace cgogn;

namespace
{

void expect_same_report(const BuildReport& g, const BuildReport& c)
{
	EXPECT_EQ(g.vertex_offset, c.vertex_offset);
	EXPECT_EQ(g.nb_cells_read, c.nb_cells_read);
	EXPECT_EQ(g.nb_cells_built, c.nb_cells_built);
	EXPECT_EQ(g.nb_cells_degenerate, c.nb_cells_degenerate);
	EXPECT_EQ(g.nb_cells_invalid, c.nb_cells_invalid);
	EXPECT_EQ(g.nb_isolated_vertices, c.nb_isolated_vertices);
	EXPECT_EQ(g.nb_nonmanifold_edges, c.nb_nonmanifold_edges);
	EXPECT_EQ(g.nb_nonmanifold_faces, c.nb_nonmanifold_faces);
	EXPECT_EQ(g.nb_boundary_cells, c.nb_boundary_cells);
	EXPECT_EQ(g.nb_nonmanifold_vertices, c.nb_nonmanifold_vertices);
	EXPECT_EQ(g.split_vertices.size(), c.split_vertices.size());
	EXPECT_EQ(g.orientable, c.orientable);
}

// Two soups side by side, the second's vertices numbered after the first's.
VolumeSoup side_by_side(const VolumeSoup& a, const VolumeSoup& b)
{
	VolumeSoup s = a;
	s.cell_sizes.insert(s.cell_sizes.end(), b.cell_sizes.begin(), b.cell_sizes.end());
	for (uint32 v : b.cell_vertices)
		s.cell_vertices.push_back(a.nb_vertices + v);
	s.nb_vertices += b.nb_vertices;
	s.positions.insert(s.positions.end(), b.positions.begin(), b.positions.end());
	return s;
}

std::vector<std::pair<std::string, VolumeSoup>> soups()
{
	return {{"tet grid 1", tet_grid_soup(1, 1, 1)},
			{"tet grid 3x2x2", tet_grid_soup(3, 2, 2)},
			{"hex grid 1", hex_grid_soup(1, 1, 1)},
			{"hex grid 2x3x2", hex_grid_soup(2, 3, 2)},
			{"mixed", test::mixed_volume_soup()},
			{"tets and hexes apart", side_by_side(tet_grid_soup(2, 1, 1), hex_grid_soup(1, 2, 1))}};
}

} // namespace

TEST(GMap3Builder, SameCellsAsTheCMap3BuilderAndToGmap)
{
	for (const auto& [name, s] : soups())
	{
		SCOPED_TRACE(name);
		CMap3 c;
		const BuildReport rc = build_volume(c, s);
		GMap3 g;
		const BuildReport rg = build_volume(g, s);
		expect_same_report(rg, rc);
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_TRUE(is_orientable(g));
		EXPECT_EQ(nb_darts(g), 2 * nb_darts(c));
		EXPECT_EQ(test::halved(test::volume_counts(g)), test::volume_counts(c));
		EXPECT_EQ(test::volume_counts(g), test::volume_counts(to_gmap(c)));
		EXPECT_EQ(nb_cells<GMap3::Face2>(g), nb_cells<CMap3::Face2>(c));
		EXPECT_EQ(nb_cells<GMap3::Edge2>(g), nb_cells<CMap3::Edge2>(c));
		EXPECT_EQ(nb_cells<GMap3::Vertex2>(g), nb_cells<CMap3::Vertex2>(c));
		// and back: the 3-map of the G-map is the 3-map built
		const CMap3 back = to_cmap(g);
		EXPECT_TRUE(check_integrity(back).ok());
		EXPECT_EQ(test::volume_counts(back), test::volume_counts(c));
	}
}

TEST(GMap3Builder, VolumeFilesGiveTheCellsOfTheCMap3)
{
	for (const char* file : {"volume/armadillo_tet_4k.mesh", "volume/liver_hex_624.mesh", "volume/elephant_tet_8k.mesh",
							 "volume/hex_dominant_11k.mesh"})
	{
		SCOPED_TRACE(file);
		const std::string path = std::string(CGOGN_DATA_DIR) + "/" + file;
		CMap3 c;
		const io::LoadReport rc = io::load_volume(c, path);
		GMap3 g;
		const io::LoadReport rg = io::load_volume(g, path);
		expect_same_report(rg.build, rc.build);
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_TRUE(is_orientable(g));
		EXPECT_EQ(test::halved(test::volume_counts(g)), test::volume_counts(c));
		EXPECT_EQ(test::volume_counts(g), test::volume_counts(to_gmap(c)));
	}
}

TEST(GMap3Builder, DartsOfACellAreConsecutiveFromItsFirstVertex)
{
	const VolumeSoup s = test::mixed_volume_soup();
	GMap3 g;
	const BuildReport r = build_volume(g, s);
	// the prism meets the rest at vertices only: those are split for it
	EXPECT_GT(r.split_vertices.size(), 0u);
	auto soup_vertex = [&](uint32 line) {
		for (const auto& [l, v] : r.split_vertices)
			if (l == line)
				return v;
		return line;
	};
	// cell after cell, the darts of a cell, the first one at one of its vertices
	uint32 first = 0, k = 0;
	for (uint32 n : s.cell_sizes)
	{
		const Dart d(first);
		EXPECT_FALSE(is_boundary(g, d));
		const auto cv = s.cell_vertices.begin() + k;
		EXPECT_NE(std::find(cv, cv + n, soup_vertex(index_of(g, GMap3::Vertex(d)))), cv + n);
		uint32 size = 0;
		uint32 last = first;
		foreach_dart_of_orbit(g, GMap3::Volume(d), [&](Dart x) {
			EXPECT_GE(x.index, first);
			last = std::max(last, x.index);
			++size;
		});
		EXPECT_EQ(last, first + size - 1);
		first += size;
		k += n;
	}
}

TEST(GMap3Builder, CellsListedInTheOppositeOrientationAreGlued)
{
	const VolumeSoup s = tet_grid_soup(2, 2, 2);
	CMap3 reference;
	build_volume(reference, s);
	for (uint32 cell : {0u, 5u, 17u, 47u})
	{
		VolumeSoup t = s;
		std::swap(t.cell_vertices[4 * cell], t.cell_vertices[4 * cell + 1]);
		GMap3 g;
		const BuildReport r = build_volume(g, t);
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_EQ(test::halved(test::volume_counts(g)), test::volume_counts(reference)) << "cell " << cell;
		EXPECT_TRUE(r.orientable);
		EXPECT_TRUE(is_orientable(g));
		EXPECT_EQ(r.nb_nonmanifold_faces, 0u);
		// the 3-map builder cannot sew the turned cell to its neighbours
		CMap3 c;
		build_volume(c, t);
		EXPECT_GT(nb_cells<CMap3::Face>(c), nb_cells<CMap3::Face>(reference));
	}
	// a hexahedron turned over (bottom and top reversed) in a hex grid
	const VolumeSoup h = hex_grid_soup(2, 2, 2);
	CMap3 hc;
	build_volume(hc, h);
	VolumeSoup t = h;
	std::swap(t.cell_vertices[8 * 3 + 1], t.cell_vertices[8 * 3 + 3]);
	std::swap(t.cell_vertices[8 * 3 + 5], t.cell_vertices[8 * 3 + 7]);
	GMap3 g;
	build_volume(g, t);
	EXPECT_TRUE(check_integrity(g).ok());
	EXPECT_EQ(test::halved(test::volume_counts(g)), test::volume_counts(hc));
}

TEST(GMap3Builder, InvalidAndDegenerateCellsAreReportedAsForCMap3)
{
	VolumeSoup s = tet_grid_soup(1, 1, 1);
	const uint32 nv = s.nb_vertices;
	auto add = [&](std::vector<uint32> cell) {
		s.cell_sizes.push_back(uint32(cell.size()));
		s.cell_vertices.insert(s.cell_vertices.end(), cell.begin(), cell.end());
	};
	add({0, 1, 2, 3, 4, 5, 6});    // no such cell kind: invalid
	add({0, 1, 2, nv});            // a vertex out of range: invalid
	add({0, 1, 1, 3});             // a repeated vertex: degenerate
	add({0, 1, 2, 3, 4, 5, 6, 6}); // degenerate hexahedron
	s.cell_sizes.push_back(8);     // runs past the end: invalid
	s.cell_vertices.push_back(0);
	CMap3 c;
	const BuildReport rc = build_volume(c, s);
	GMap3 g;
	const BuildReport rg = build_volume(g, s);
	expect_same_report(rg, rc);
	EXPECT_EQ(rg.nb_cells_invalid, 3u);
	EXPECT_EQ(rg.nb_cells_degenerate, 2u);
	EXPECT_EQ(rg.nb_cells_built, 6u);
	EXPECT_TRUE(check_integrity(g).ok());
	EXPECT_EQ(test::volume_counts(g), test::volume_counts(to_gmap(c)));

	// nothing buildable: an empty map, every vertex isolated
	GMap3 e;
	const BuildReport re = build_volume(e, 3, std::vector<uint32>{4}, std::vector<uint32>{0, 1, 2, 7});
	EXPECT_EQ(re.nb_cells_invalid, 1u);
	EXPECT_EQ(re.nb_isolated_vertices, 3u);
	EXPECT_EQ(nb_darts(e), 0u);
	EXPECT_EQ(nb_cells<GMap3::Vertex>(e), 0u);
}

TEST(GMap3Builder, NonManifoldFacesAndVerticesAsForCMap3)
{
	// three tetrahedra on one triangle: one above it, two below, in every
	// order; the one above is glued to a tetrahedron below, as in the CMap3
	const std::vector<uint32> sizes = {4, 4, 4};
	for (const std::vector<uint32>& ids : {std::vector<uint32>{0, 1, 2, 3, 0, 2, 1, 4, 0, 2, 1, 5},
										   std::vector<uint32>{0, 2, 1, 4, 0, 2, 1, 5, 0, 1, 2, 3},
										   std::vector<uint32>{0, 2, 1, 4, 0, 1, 2, 3, 0, 2, 1, 5}})
	{
		CMap3 c;
		const BuildReport rc = build_volume(c, 6, sizes, ids);
		GMap3 g;
		const BuildReport rg = build_volume(g, 6, sizes, ids);
		expect_same_report(rg, rc);
		EXPECT_EQ(rg.nb_nonmanifold_faces, 1u);
		EXPECT_TRUE(rg.orientable);
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_EQ(test::volume_counts(g), test::volume_counts(to_gmap(c)));
	}

	// two tetrahedra sharing a vertex only, then an edge only
	for (const std::vector<uint32>& two :
		 {std::vector<uint32>{0, 1, 2, 3, 0, 4, 5, 6}, std::vector<uint32>{0, 1, 2, 3, 0, 1, 4, 5}})
	{
		CMap3 c2;
		const BuildReport r2c = build_volume(c2, 7, std::vector<uint32>{4, 4}, two);
		GMap3 g2;
		const BuildReport r2g = build_volume(g2, 7, std::vector<uint32>{4, 4}, two);
		expect_same_report(r2g, r2c);
		EXPECT_EQ(r2g.split_vertices, r2c.split_vertices);
		EXPECT_TRUE(check_integrity(g2).ok()) << check_integrity(g2).to_string();
		EXPECT_EQ(test::volume_counts(g2), test::volume_counts(to_gmap(c2)));
	}
}

TEST(GMap3Builder, AppendsWithAVertexOffset)
{
	const VolumeSoup s = hex_grid_soup(2, 1, 1);
	GMap3 g;
	const BuildReport r1 = build_volume(g, s);
	const test::VolumeCounts one = test::volume_counts(g);
	const BuildReport r2 = build_volume(g, s);
	EXPECT_EQ(r1.vertex_offset, 0u);
	EXPECT_EQ(r2.vertex_offset, s.nb_vertices);
	EXPECT_TRUE(check_integrity(g).ok());
	const test::VolumeCounts two = test::volume_counts(g);
	EXPECT_EQ(two.darts, 2 * one.darts);
	EXPECT_EQ(two.v, 2 * one.v);
	EXPECT_EQ(two.w, 2 * one.w);
	EXPECT_EQ(two.cc, 2 * one.cc);
	// the second copy's vertices are the lines after the first's
	foreach_dart(g, [&](Dart d) {
		const uint32 line = index_of(g, GMap3::Vertex(d));
		EXPECT_EQ(line >= s.nb_vertices, d.index >= one.darts);
	});
	// other indexed orbits get the new cells
	GMap3 h;
	index_cells<GMap3::Edge>(h);
	index_cells<GMap3::Volume>(h);
	build_volume(h, s);
	EXPECT_TRUE(check_integrity(h).ok()) << check_integrity(h).to_string();
	EXPECT_EQ(container_of<Orbit::BETA0_BETA2_BETA3>(h).nb_lines(), one.e);
	EXPECT_EQ(container_of<Orbit::BETA0_BETA1_BETA2>(h).nb_lines(), one.w);
}

TEST(GMap3Builder, ASolidKleinBottleStaysWhole)
{
	const uint32 n = 5;
	const VolumeSoup s = solid_klein_bottle_soup(n);
	GMap3 g;
	const BuildReport r = build_volume(g, s);
	EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
	EXPECT_FALSE(r.orientable);
	EXPECT_FALSE(is_orientable(g));
	EXPECT_EQ(r.nb_cells_built, n);
	EXPECT_EQ(r.nb_nonmanifold_faces, 0u);
	EXPECT_EQ(nb_cells<GMap3::Vertex>(g), 4 * n);
	EXPECT_EQ(nb_cells<GMap3::Edge>(g), 8 * n);
	EXPECT_EQ(nb_cells<GMap3::Face>(g), 5 * n);
	EXPECT_EQ(nb_cells<GMap3::Volume>(g), n);
	EXPECT_EQ(nb_boundary_components(g), 1u);
	EXPECT_EQ(euler_characteristic(g), 0);
	EXPECT_THROW(to_cmap(g), TopologyError);
	// the 3-map builder leaves the twisted face open on both sides
	CMap3 c;
	build_volume(c, s);
	EXPECT_EQ(nb_cells<CMap3::Face>(c), 5 * n + 1);
}

} // namespace cgogn_test_gmap3_builder
