// Views and quick incidence caches on 2-G-maps: CellFilter and CellCache
// traverse what the CMap2's do on the same surface; every supported cache
// reports what the dart walks report, in the same order, and is read.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace cgogn_test_gmap2_views
{

using namespace cgogn;

namespace
{

using V = GMap2::Vertex;
using E = GMap2::Edge;
using F = GMap2::Face;
using W = GMap2::Volume;

// Every neighbour reported by trav from every FROM cell, in order.
template <typename FROM, typename TO, typename TRAV>
std::vector<uint32> neighbours(const GMap2& m, TRAV trav)
{
	std::vector<uint32> r;
	foreach_cell(m, [&](FROM c) {
		r.push_back(INVALID_INDEX); // row separator
		trav(c, [&](TO x) { r.push_back(x.dart.index); });
	});
	return r;
}

// Builds the cache of FROM -> TO (through THROUGH), checks that the
// traversal reports the same neighbours through it, that check_integrity
// accepts it and that the table is read (a corrupted row shows).
template <typename FROM, typename TO, typename THROUGH, typename TRAV>
void expect_cached_equal(GMap2& m, TRAV trav)
{
	using Cache = IncidenceCache<GMap2, FROM, TO, THROUGH>;
	const std::vector<uint32> walked = neighbours<FROM, TO>(m, trav);
	Cache::build(m);
	EXPECT_EQ((neighbours<FROM, TO>(m, trav)), walked);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	auto& t = **cgogn::detail::state_of(m).incidence_tables.begin();
	ASSERT_GT(t.targets.size(), 1u);
	std::swap(t.targets[0], t.targets[t.targets.size() - 1]);
	if (t.targets[0] != t.targets[t.targets.size() - 1])
	{
		EXPECT_NE((neighbours<FROM, TO>(m, trav)), walked) << "the table is read";
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::IncidenceCacheStale));
	}
	Cache::remove(m);
	EXPECT_EQ((neighbours<FROM, TO>(m, trav)), walked);
}

} // namespace

TEST(GMap2Views, IncidenceCachesReportTheWalks)
{
	for (const SurfaceSoup& s : {klein_bottle_soup(6, 5, true), mobius_soup(7), grid_soup(4, 3)})
	{
		GMap2 m;
		build_surface(m, s);
		expect_cached_equal<V, E, void>(m, [&](V c, auto f) { foreach_incident_edge(m, c, f); });
		expect_cached_equal<V, F, void>(m, [&](V c, auto f) { foreach_incident_face(m, c, f); });
		expect_cached_equal<V, V, E>(m, [&](V c, auto f) { foreach_adjacent_vertex_through_edge(m, c, f); });
		expect_cached_equal<V, V, F>(m, [&](V c, auto f) { foreach_adjacent_vertex_through_face(m, c, f); });
		expect_cached_equal<E, E, V>(m, [&](E c, auto f) { foreach_adjacent_edge_through_vertex(m, c, f); });
		expect_cached_equal<E, E, F>(m, [&](E c, auto f) { foreach_adjacent_edge_through_face(m, c, f); });
		expect_cached_equal<F, V, void>(m, [&](F c, auto f) { foreach_incident_vertex(m, c, f); });
		expect_cached_equal<F, E, void>(m, [&](F c, auto f) { foreach_incident_edge(m, c, f); });
		expect_cached_equal<F, F, E>(m, [&](F c, auto f) { foreach_adjacent_face_through_edge(m, c, f); });
		expect_cached_equal<F, F, V>(m, [&](F c, auto f) { foreach_adjacent_face_through_vertex(m, c, f); });
		expect_cached_equal<W, V, void>(m, [&](W c, auto f) { foreach_incident_vertex(m, c, f); });
		expect_cached_equal<W, F, void>(m, [&](W c, auto f) { foreach_incident_face(m, c, f); });
		// a topological change drops the tables
		IncidenceCache<GMap2, V, F>::build(m);
		cut_edge(m, E(Dart(0)));
		EXPECT_FALSE((IncidenceCache<GMap2, V, F>::is_built(m)));
		EXPECT_TRUE(check_integrity(m).ok());
	}
}

TEST(GMap2Views, FilterAndCacheTraverseTheCMap2sCells)
{
	const SurfaceSoup s = grid_soup(5, 4);
	CMap2 c;
	GMap2 g;
	build_surface(c, s);
	build_surface(g, s);
	add_attribute<int, CMap2::Face>(c, "f"); // faces indexed: lines 0 .. 19 in both
	add_attribute<int, F>(g, "f");
	// the vertices on the boundary and the faces with an even line, in both
	CellFilter<CMap2> cf(c);
	CellFilter<GMap2> gf(g);
	cf.set_filter<CMap2::Vertex>([&](CMap2::Vertex v) { return is_incident_to_boundary(c, v); });
	gf.set_filter<V>([&](V v) { return is_incident_to_boundary(g, v); });
	cf.set_filter<CMap2::Face>([&](CMap2::Face f) { return index_of(c, f) % 2 == 0; });
	gf.set_filter<F>([&](F f) { return index_of(g, f) % 2 == 0; });
	EXPECT_EQ(nb_cells<V>(gf), nb_cells<CMap2::Vertex>(cf));
	EXPECT_EQ(nb_cells<V>(gf), 18u);
	EXPECT_EQ(nb_cells<F>(gf), nb_cells<CMap2::Face>(cf));
	EXPECT_EQ(nb_cells<E>(gf), nb_cells<E>(g));
	std::vector<uint32> lc, lg;
	foreach_cell(cf, [&](CMap2::Vertex v) { lc.push_back(index_of(c, v)); });
	foreach_cell(gf, [&](V v) { lg.push_back(index_of(g, v)); });
	std::sort(lc.begin(), lc.end());
	std::sort(lg.begin(), lg.end());
	EXPECT_EQ(lc, lg);
	// a cache of the filtered cells, then of the whole map
	CellCache<CellFilter<GMap2>> gc(gf);
	gc.build<V>();
	gc.build<F>();
	EXPECT_EQ(nb_cells<V>(gc), 18u);
	EXPECT_EQ(nb_cells<F>(gc), nb_cells<F>(gf));
	CellCache whole(g);
	whole.build<E>();
	EXPECT_EQ(nb_cells<E>(whole), 49u);
	uint32 n = 0;
	foreach_cell(whole, [&](E e) {
		n += degree(g, e);
		return true;
	});
	EXPECT_EQ(n, 4u * 20u); // 20 quads: 80 edge-face incidences
}

} // namespace cgogn_test_gmap2_views
