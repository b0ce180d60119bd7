// 3-G-maps: the G-map of a 3-map and back, with every cell and attribute;
// the generic core on them (cells, orbits, attributes, markers, parallel
// traversals, properties) and the integrity checks of the G-map relations.
#include <cgogn/core.h>

#include "volume_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <vector>

namespace cgogn_test_gmap3
{

using namespace cgogn;

namespace
{

// A tet grid, a hex grid and two separate hexahedra, with every orbit indexed
// and a value on every cell.
std::vector<CMap3> volume_meshes()
{
	std::vector<CMap3> out;
	for (const VolumeSoup& s : {tet_grid_soup(3, 2, 2), hex_grid_soup(2, 3, 2)})
	{
		CMap3 m;
		build_volume(m, s);
		out.push_back(std::move(m));
	}
	CMap3 two;
	add_hexa(two);
	add_hexa(two);
	close(two);
	out.push_back(std::move(two));
	for (CMap3& m : out)
	{
		auto v = add_attribute<double, CMap3::Vertex>(m, "v");
		auto e = add_attribute<uint32, CMap3::Edge>(m, "e");
		auto f = add_attribute<uint32, CMap3::Face>(m, "f");
		auto w = add_attribute<uint32, CMap3::Volume>(m, "w");
		add_attribute<uint32, CMap3::CC>(m, "cc");
		add_attribute<uint32, CMap3::Vertex2>(m, "v2");
		uint32 k = 0;
		foreach_cell(m, [&](CMap3::Vertex x) { value<double>(m, *v, x) = 0.5 * double(k++); });
		foreach_cell(m, [&](CMap3::Edge x) { value<uint32>(m, *e, x) = k++; });
		foreach_cell(m, [&](CMap3::Face x) { value<uint32>(m, *f, x) = k++; });
		foreach_cell(m, [&](CMap3::Volume x) { value<uint32>(m, *w, x) = k++; });
	}
	return out;
}

} // namespace

TEST(GMap3, TheGMapOfA3MapHasItsCellsAndValues)
{
	for (const CMap3& c : volume_meshes())
	{
		const GMap3 g = to_gmap(c);
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_EQ(nb_darts(g), 2 * nb_darts(c));
		EXPECT_EQ(test::halved(test::volume_counts(g)), test::volume_counts(c));
		EXPECT_TRUE(is_orientable(g));
		EXPECT_EQ(nb_connected_components(g), nb_connected_components(c));
		EXPECT_EQ(nb_cells<GMap3::Vertex2>(g), nb_cells<CMap3::Vertex2>(c));
		EXPECT_EQ(nb_cells<GMap3::Face2>(g), nb_cells<CMap3::Face2>(c));
		EXPECT_EQ(nb_cells<GMap3::Edge2>(g), nb_cells<CMap3::Edge2>(c));
		// the values: the maps are compact, so lines keep their numbers
		auto vc = get_attribute<double, CMap3::Vertex>(c, "v");
		auto vg = get_attribute<double, GMap3::Vertex>(g, "v");
		ASSERT_TRUE(vg);
		foreach_cell(c, [&](CMap3::Vertex x) { EXPECT_EQ((*vg)[index_of(c, x)], value<double>(c, *vc, x)); });
		auto wc = get_attribute<uint32, CMap3::Volume>(c, "w");
		auto wg = get_attribute<uint32, GMap3::Volume>(g, "w");
		ASSERT_TRUE(wg);
		std::vector<uint32> sc, sg;
		foreach_cell(c, [&](CMap3::Volume x) { sc.push_back(value<uint32>(c, *wc, x)); });
		foreach_cell(g, [&](GMap3::Volume x) { sg.push_back(value<uint32>(g, *wg, x)); });
		std::sort(sc.begin(), sc.end());
		std::sort(sg.begin(), sg.end());
		EXPECT_EQ(sc, sg);
		// every G-map cell has twice the darts of its 3-map cell
		foreach_cell(c, [&](CMap3::Vertex x) {
			uint32 n = 0;
			foreach_dart_of_orbit(c, x, [&](Dart) { ++n; });
			const Dart d(container_of<Orbit::BETA1_BETA2_BETA3>(g).key()[index_of(c, x)]);
			uint32 k = 0;
			foreach_dart_of_orbit(g, GMap3::Vertex(d), [&](Dart) { ++k; });
			EXPECT_EQ(k, 2 * n);
		});
	}
}

TEST(GMap3, BackTo3MapGivesTheSameMesh)
{
	for (const CMap3& c : volume_meshes())
	{
		const CMap3 back = to_cmap(to_gmap(c));
		EXPECT_TRUE(check_integrity(back).ok()) << check_integrity(back).to_string();
		EXPECT_EQ(nb_darts(back), nb_darts(c));
		EXPECT_EQ(test::volume_counts(back), test::volume_counts(c));
		auto vc = get_attribute<double, CMap3::Vertex>(c, "v");
		auto vb = get_attribute<double, CMap3::Vertex>(back, "v");
		ASSERT_TRUE(vb);
		foreach_cell(c, [&](CMap3::Vertex x) { EXPECT_EQ((*vb)[index_of(c, x)], value<double>(c, *vc, x)); });
		// the degrees of the vertices and the sizes of the volumes agree
		std::vector<uint32> dc, db;
		foreach_cell(c, [&](CMap3::Volume w) { dc.push_back(codegree(c, w)); });
		foreach_cell(back, [&](CMap3::Volume w) { db.push_back(codegree(back, w)); });
		std::sort(dc.begin(), dc.end());
		std::sort(db.begin(), db.end());
		EXPECT_EQ(dc, db);
	}
}

TEST(GMap3, ParallelAndUnindexedTraversalsCountTheCells)
{
	CMap3 c;
	build_volume(c, tet_grid_soup(4, 3, 3));
	const GMap3 g = to_gmap(c); // only the vertices indexed
	EXPECT_EQ(nb_cells<GMap3::Edge>(g), nb_cells<CMap3::Edge>(c));
	EXPECT_EQ(nb_cells<GMap3::Face>(g), nb_cells<CMap3::Face>(c));
	EXPECT_EQ(nb_cells<GMap3::Volume>(g), nb_cells<CMap3::Volume>(c));
	std::atomic<uint32> edges{0}, faces{0}, vertices{0};
	parallel_foreach_cell(g, [&](GMap3::Edge) { ++edges; });
	parallel_foreach_cell(g, [&](GMap3::Face) { ++faces; });
	parallel_foreach_cell(g, [&](GMap3::Vertex) { ++vertices; });
	EXPECT_EQ(edges.load(), nb_cells<CMap3::Edge>(c));
	EXPECT_EQ(faces.load(), nb_cells<CMap3::Face>(c));
	EXPECT_EQ(vertices.load(), nb_cells<CMap3::Vertex>(c));
	// markers on G-map cells
	CellMarker<GMap3, GMap3::Face> cm(g);
	uint32 marked = 0;
	foreach_cell(g, [&](GMap3::Volume w) {
		foreach_dart_of_orbit(g, w, [&](Dart d) {
			if (!cm.is_marked(GMap3::Face(d)))
			{
				cm.mark(GMap3::Face(d));
				++marked;
			}
		});
	});
	EXPECT_EQ(marked, nb_cells<CMap3::Face>(c));
}

TEST(GMap3, IntegrityFindsBrokenRelations)
{
	CMap3 c;
	add_tetra(c);
	add_tetra(c);
	close(c);
	GMap3 g = to_gmap(c);
	ASSERT_TRUE(check_integrity(g).ok());
	// beta3 o beta0 no longer an involution: beta3 of two darts of one edge
	// side exchanged
	const Dart d(0), d0 = beta0(g, d);
	const Dart e = beta3(g, d), e0 = beta3(g, d0);
	cgogn::detail::set_beta<3>(g, d, e0);
	cgogn::detail::set_beta<3>(g, e0, d);
	cgogn::detail::set_beta<3>(g, d0, e);
	cgogn::detail::set_beta<3>(g, e, d0);
	const IntegrityReport r = check_integrity(g);
	EXPECT_TRUE(r.has(IntegrityError::Kind::BetaCompositionNotInvolution)) << r.to_string();
	// a fixed point
	GMap3 h = to_gmap(c);
	beta_unsew<3>(h, Dart(0));
	EXPECT_TRUE(check_integrity(h).has(IntegrityError::Kind::PhiFixedPoint));
}

} // namespace cgogn_test_gmap3
