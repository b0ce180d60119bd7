// Quick incidence caches: the cached traversals report exactly what the dart
// walks report, in the same order; update, removal, staleness detection.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace cgogn_test_incidence_cache
{

using namespace cgogn;

namespace
{
// Every neighbour reported by trav from every FROM cell, in order.
template <typename FROM, typename TO, typename MESH, typename TRAV>
std::vector<uint32> neighbours(const MESH& m, TRAV trav)
{
	std::vector<uint32> r;
	foreach_cell(m, [&](FROM c) {
		r.push_back(INVALID_INDEX); // row separator
		trav(c, [&](TO x) { r.push_back(x.dart.index); });
	});
	return r;
}
} // namespace

TEST(IncidenceCache, SurfaceVertexFaceAndVertexVertex)
{
	CMap2 m;
	build_surface(m, grid_soup(6, 5, true));
	using V = CMap2::Vertex;
	using E = CMap2::Edge;
	using F = CMap2::Face;
	auto vf = [&](V v, auto f) { foreach_incident_face(m, v, f); };
	auto vve = [&](V v, auto f) { foreach_adjacent_vertex_through_edge(m, v, f); };
	auto vvf = [&](V v, auto f) { foreach_adjacent_vertex_through_face(m, v, f); };
	const auto vf0 = neighbours<V, F>(m, vf);
	const auto vve0 = neighbours<V, V>(m, vve);
	const auto vvf0 = neighbours<V, V>(m, vvf);

	using VF = IncidenceCache<CMap2, V, F>;
	using VVE = IncidenceCache<CMap2, V, V, E>;
	using VVF = IncidenceCache<CMap2, V, V, F>;
	EXPECT_FALSE(VF::is_built(m));
	VF::build(m);
	VVE::build(m);
	VVF::build(m);
	EXPECT_TRUE(VF::is_built(m));
	EXPECT_GT(VF::memory_bytes(m), 0u);
	EXPECT_EQ(cgogn::detail::state_of(m).incidence_tables.size(), 3u);
	EXPECT_EQ((neighbours<V, F>(m, vf)), vf0);
	EXPECT_EQ((neighbours<V, V>(m, vve)), vve0);
	EXPECT_EQ((neighbours<V, V>(m, vvf)), vvf0);
	// 60 triangles: 180 vertex-face incidences
	EXPECT_EQ(vf0.size() - nb_cells<V>(m), 180u);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();

	// early stop through the cache
	uint32 n = 0;
	foreach_cell(m, [&](V v) {
		foreach_incident_face(m, v, [&](F) { return ++n % 2 != 0; });
		return false;
	});
	EXPECT_LE(n, 2u);

	// the table really is read: a corrupted row is reported and traversed
	auto& t = **cgogn::detail::state_of(m).incidence_tables.begin();
	ASSERT_GT(t.targets.size(), 1u);
	std::swap(t.targets[0], t.targets[1]);
	IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.has(IntegrityError::Kind::IncidenceCacheStale));
	EXPECT_NE((neighbours<V, F>(m, vf)), vf0);
	VF::update(m);
	EXPECT_EQ((neighbours<V, F>(m, vf)), vf0);
	EXPECT_TRUE(check_integrity(m).ok());

	// a topological change drops every table (none can be read stale)
	F added = add_face(m, 3);
	EXPECT_TRUE(cgogn::detail::state_of(m).incidence_tables.empty());
	EXPECT_FALSE(VF::is_built(m));
	EXPECT_TRUE(check_integrity(m).ok());
	uint32 faces_of_new_vertex = 0;
	foreach_incident_face(m, V(added.dart), [&](F) { ++faces_of_new_vertex; });
	EXPECT_EQ(faces_of_new_vertex, 1u);
	VF::update(m);
	VVE::update(m);
	VVF::update(m);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	VF::remove(m);
	EXPECT_FALSE(VF::is_built(m));
	EXPECT_EQ(cgogn::detail::state_of(m).incidence_tables.size(), 2u);
}

TEST(IncidenceCache, FromCellsGetIndexed)
{
	CMap2 m;
	build_surface(m, torus_soup(5, 4, true));
	using F = CMap2::Face;
	using V = CMap2::Vertex;
	EXPECT_FALSE(is_indexed<F>(m));
	auto ff = [&](F f, auto fn) { foreach_adjacent_face_through_vertex(m, f, fn); };
	const auto before = neighbours<F, F>(m, ff);
	IncidenceCache<CMap2, F, F, V>::build(m);
	EXPECT_TRUE(is_indexed<F>(m));
	EXPECT_EQ((neighbours<F, F>(m, ff)), before);
	// a torus: every triangle has 12 neighbours through its vertices
	EXPECT_EQ(before.size(), 40u * 13);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(IncidenceCache, VolumeVertexVolumeAndVertexThroughVolume)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(2, 2, 2));
	using V = CMap3::Vertex;
	using W = CMap3::Volume;
	using E = CMap3::Edge;
	using F = CMap3::Face;
	auto vw = [&](V v, auto f) { foreach_incident_volume(m, v, f); };
	auto vvw = [&](V v, auto f) { foreach_adjacent_vertex_through_volume(m, v, f); };
	auto wv = [&](W w, auto f) { foreach_incident_vertex(m, w, f); };
	auto ve = [&](V v, auto f) { foreach_incident_edge(m, v, f); };
	auto ef = [&](E e, auto f) { foreach_incident_face(m, e, f); };
	const auto vw0 = neighbours<V, W>(m, vw);
	const auto vvw0 = neighbours<V, V>(m, vvw);
	const auto wv0 = neighbours<W, V>(m, wv);
	const auto ve0 = neighbours<V, E>(m, ve);
	const auto ef0 = neighbours<E, F>(m, ef);
	EXPECT_EQ(vw0.size() - 27, 64u); // 8 hexahedra x 8 vertices
	EXPECT_EQ(wv0.size() - 8, 64u);

	IncidenceCache<CMap3, V, W>::build(m);
	IncidenceCache<CMap3, W, V>::build(m);
	IncidenceCache<CMap3, V, V, W>::build(m); // built from the two caches above
	IncidenceCache<CMap3, V, E>::build(m);
	IncidenceCache<CMap3, E, F>::build(m);
	EXPECT_EQ((neighbours<V, W>(m, vw)), vw0);
	EXPECT_EQ((neighbours<V, V>(m, vvw)), vvw0);
	EXPECT_EQ((neighbours<W, V>(m, wv)), wv0);
	EXPECT_EQ((neighbours<V, E>(m, ve)), ve0);
	EXPECT_EQ((neighbours<E, F>(m, ef)), ef0);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();

	// the centre vertex sees the 26 other vertices through its 8 volumes
	uint32 best = 0;
	foreach_cell(m, [&](V v) {
		uint32 n = 0;
		foreach_adjacent_vertex_through_volume(m, v, [&](V) { ++n; });
		best = std::max(best, n);
	});
	EXPECT_EQ(best, 26u);
	// without its own table, the adjacency walks the cached incidences: the
	// same vertices (maybe through other darts)
	IncidenceCache<CMap3, V, V, W>::remove(m);
	auto ids = [&](const std::vector<uint32>& darts) {
		std::vector<uint32> r;
		for (uint32 d : darts)
			r.push_back(d == INVALID_INDEX ? d : index_of(m, V(Dart(d))));
		std::sort(r.begin(), r.end());
		return r;
	};
	EXPECT_EQ(ids(neighbours<V, V>(m, vvw)), ids(vvw0));
}

// Cached traversals report LocatedCell (cell + line) when the TO orbit is
// indexed: value() reads at the stored line, which must be the cell's index.
TEST(IncidenceCache, LocatedCellsCarryTheirLine)
{
	CMap2 m;
	build_surface(m, torus_soup(6, 5, true));
	using V = CMap2::Vertex;
	using E = CMap2::Edge;
	auto id = add_attribute<uint32, V>(m, "id");
	uint32 k = 0;
	foreach_cell(m, [&](V v) { value<uint32>(m, *id, v) = k++; });
	IncidenceCache<CMap2, V, V, E>::build(m);
	IncidenceCache<CMap2, V, E>::build(m); // edges not indexed: no lines, plain cells
	EXPECT_FALSE(is_indexed<E>(m));
	uint32 located = 0, plain_edges = 0, total = 0;
	foreach_cell(m, [&](V v) {
		foreach_adjacent_vertex_through_edge(m, v, [&](auto w) {
			if constexpr (std::is_same_v<decltype(w), LocatedCell<Orbit::PHI21>>)
			{
				++located;
				EXPECT_EQ(w.line, index_of(m, V(w.dart)));
				EXPECT_EQ(value<uint32>(m, *id, w), value<uint32>(m, *id, V(w.dart)));
			}
			++total;
		});
		foreach_incident_edge(m, v, [&](auto e) {
			// both forms are compiled; the table holds no lines, so the plain one runs
			plain_edges += std::is_same_v<decltype(e), E>;
		});
	});
	// 30 vertices of valence 6 on the torus
	EXPECT_EQ(total, 180u);
	EXPECT_EQ(located, 180u);
	EXPECT_EQ(plain_edges, 180u);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();

	// a wrong stored line is reported
	for (auto& t : cgogn::detail::state_of(m).incidence_tables)
		if (!t->target_lines.empty())
			std::swap(t->target_lines[0], t->target_lines[1]);
	EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::IncidenceCacheStale));

	// moving a cell to another line drops the tables (their lines would be stale)
	IncidenceCache<CMap2, V, V, E>::update(m);
	EXPECT_TRUE(check_integrity(m).ok());
	V first;
	foreach_cell(m, [&](V v) {
		first = v;
		return false;
	});
	const uint32 spare = container_of<V::ORBIT>(m).new_line(first.dart.index);
	set_index(m, first, spare);
	EXPECT_TRUE(cgogn::detail::state_of(m).incidence_tables.empty());
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();

	// so does compact (it renumbers every line)
	IncidenceCache<CMap2, V, V, E>::build(m);
	compact(m);
	EXPECT_TRUE(cgogn::detail::state_of(m).incidence_tables.empty());
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
}

// A callable taking exactly the plain cell type is served from the table's
// darts alone (the lines are not looked at), one taking `auto` or a
// LocatedCell gets the lines: both see the rows of the table, in its order.
TEST(IncidenceCache, PlainAndLocatedCallablesReadTheSameRows)
{
	CMap2 m;
	build_surface(m, torus_soup(6, 5, true));
	using V = CMap2::Vertex;
	using F = CMap2::Face;
	// a function pointer is not looked into: the lines are offered, as to `auto`
	static_assert(!detail::takes_plain_cell<void (*)(F), F>());
	auto takes_face = [](F) {};
	auto takes_located = [](Located<F>) {};
	auto takes_auto = [](auto) {};
	static_assert(detail::takes_plain_cell<decltype(takes_face), F>());
	static_assert(!detail::takes_plain_cell<decltype(takes_located), F>());
	static_assert(!detail::takes_plain_cell<decltype(takes_auto), F>());
	add_attribute<uint32, F>(m, "face id"); // indexes the faces: the table holds their lines
	IncidenceCache<CMap2, V, F>::build(m);
	// swap the first two entries of every row: the walk of the darts would not
	// give that order, so equal sequences prove both callables read the table
	for (auto& t : cgogn::detail::state_of(m).incidence_tables)
		for (std::size_t r = 0; r + 1 < t->offsets.size(); ++r)
		{
			ASSERT_FALSE(t->target_lines.empty());
			if (t->offsets[r + 1] - t->offsets[r] < 2) // a free line
				continue;
			std::swap(t->targets[t->offsets[r]], t->targets[t->offsets[r] + 1]);
			std::swap(t->target_lines[t->offsets[r]], t->target_lines[t->offsets[r] + 1]);
		}
	uint32 rows = 0, located = 0;
	foreach_cell(m, [&](V v) {
		std::vector<uint32> from_plain, from_auto, from_darts;
		foreach_incident_face(m, v, [&](F f) { from_plain.push_back(f.dart.index); });
		foreach_incident_face(m, v, [&](auto f) {
			// both forms are compiled; the table holds lines, so the located one runs
			if constexpr (std::is_same_v<decltype(f), Located<F>>)
			{
				EXPECT_EQ(f.line, index_of(m, F(f.dart)));
				++located;
			}
			from_auto.push_back(f.dart.index);
		});
		{
			detail::IncidenceCacheBypass bypass;
			foreach_incident_face(m, v, [&](F f) { from_darts.push_back(f.dart.index); });
		}
		EXPECT_EQ(from_plain, from_auto);
		ASSERT_EQ(from_plain.size(), 6u);
		std::swap(from_darts[0], from_darts[1]);
		EXPECT_EQ(from_plain, from_darts);
		++rows;
	});
	EXPECT_EQ(rows, 30u);
	EXPECT_EQ(located, 180u);
}

// foreach_cell gives each cell with its line to a callable taking Located<CELL>;
// a cached traversal started from such a cell reads the row at that line.
TEST(IncidenceCache, ForeachCellGivesLocatedCellsToCachedTraversals)
{
	CMap2 m;
	build_surface(m, torus_soup(6, 5, true));
	using V = CMap2::Vertex;
	using E = CMap2::Edge;
	uint32 nb = 0;
	foreach_cell(m, [&](Located<V> v) {
		EXPECT_EQ(v.line, index_of(m, V(v.dart)));
		++nb;
	});
	EXPECT_EQ(nb, 30u);
	// edges are not indexed: their cells come without a line
	uint32 nb_edges = 0;
	foreach_cell(m, [&](Located<E> e) {
		EXPECT_EQ(e.line, INVALID_INDEX);
		++nb_edges;
	});
	EXPECT_EQ(nb_edges, 90u);
	// a dart's line is its index
	uint32 nb_darts_seen = 0;
	foreach_cell(m, [&](LocatedCell<Orbit::DART> d) {
		EXPECT_EQ(d.line, d.dart.index);
		++nb_darts_seen;
	});
	EXPECT_EQ(nb_darts_seen, 180u);

	IncidenceCache<CMap2, V, V, E>::build(m);
	auto around = [&](auto v) {
		std::vector<uint32> r;
		foreach_adjacent_vertex_through_edge(m, v, [&](V w) { r.push_back(index_of(m, w)); });
		return r;
	};
	std::vector<std::vector<uint32>> from_plain, from_located;
	foreach_cell(m, [&](V v) { from_plain.push_back(around(v)); });
	foreach_cell(m, [&](Located<V> v) { from_located.push_back(around(v)); });
	EXPECT_EQ(from_located, from_plain);

	// the row comes from the given line, not from the dart: a cell located at
	// another vertex's line gets that vertex's neighbours
	V a, b;
	uint32 k = 0;
	foreach_cell(m, [&](V v) {
		(k++ == 0 ? a : b) = v;
		return k < 2;
	});
	EXPECT_EQ(around(Located<V>(a.dart, index_of(m, b))), around(b));
	EXPECT_NE(around(a), around(b));
}

// The map's set of tables: one per relation key, found by key, and no lookup
// array left behind once the last table is gone (empty() is what every local
// traversal tests first).
TEST(IncidenceCache, TablesAreFoundByKeyAndReplacedPerKey)
{
	auto table = [](uint32 key, uint32 rows) {
		auto t = std::make_unique<IncidenceTable>();
		t->key = key;
		t->nb_rows = rows;
		return t;
	};
	IncidenceTables ts;
	EXPECT_TRUE(ts.empty());
	EXPECT_EQ(ts.find(0), nullptr);
	EXPECT_EQ(ts.find(NB_INCIDENCE_KEYS - 1), nullptr);
	ts.add(table(7, 1));
	ts.add(table(NB_INCIDENCE_KEYS - 1, 2));
	EXPECT_FALSE(ts.empty());
	EXPECT_EQ(ts.size(), 2u);
	ASSERT_NE(ts.find(7), nullptr);
	EXPECT_EQ(ts.find(7)->nb_rows, 1u);
	EXPECT_EQ(ts.find(NB_INCIDENCE_KEYS - 1)->nb_rows, 2u);
	EXPECT_EQ(ts.find(8), nullptr);
	// a second table of a key replaces the first
	ts.add(table(7, 3));
	EXPECT_EQ(ts.size(), 2u);
	EXPECT_EQ(ts.find(7)->nb_rows, 3u);
	ts.remove(7);
	ts.remove(7); // absent: nothing happens
	EXPECT_EQ(ts.find(7), nullptr);
	EXPECT_EQ(ts.size(), 1u);
	EXPECT_FALSE(ts.empty());
	ts.remove(NB_INCIDENCE_KEYS - 1);
	EXPECT_TRUE(ts.empty());
	ts.add(table(5, 1));
	ts.clear();
	EXPECT_TRUE(ts.empty());
	EXPECT_EQ(ts.size(), 0u);
	EXPECT_EQ(ts.find(5), nullptr);

	// every relation of the 2- and 3-maps has a key inside the array
	static_assert(detail::incidence_key<CMap3::Volume, CMap3::Volume, CMap3::Vertex>() < NB_INCIDENCE_KEYS);
	static_assert(detail::incidence_key<CMap3::Vertex, CMap3::Vertex, void>() < NB_INCIDENCE_KEYS);
}

} // namespace cgogn_test_incidence_cache
