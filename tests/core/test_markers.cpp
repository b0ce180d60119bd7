#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <memory>
#include <type_traits>

namespace cgogn_test_markers
{

using namespace cgogn;

namespace
{
CMap2 make_torus()
{
	CMap2 m;
	build_surface(m, torus_soup(5, 4));
	return m;
}
} // namespace

TEST(DartMarker, MarkUnmarkOrbitsAndClearOnDestruction)
{
	CMap2 m = make_torus();
	Dart d(0);
	{
		DartMarker dm(m);
		EXPECT_FALSE(dm.is_marked(d));
		dm.mark(d);
		EXPECT_TRUE(dm.is_marked(d));
		dm.unmark(d);
		EXPECT_FALSE(dm.is_marked(d));
		dm.mark_orbit(CMap2::Vertex(d));
		uint32 n = 0;
		foreach_dart(m, [&](Dart x) { n += dm.is_marked(x); });
		EXPECT_EQ(n, 4u); // valence 4 on a quad torus
		dm.unmark_orbit(CMap2::Vertex(d));
		dm.mark_orbit(CMap2::Face(d));
		dm.unmark_all();
		foreach_dart(m, [&](Dart x) { EXPECT_FALSE(dm.is_marked(x)); });
		dm.mark_orbit(CMap2::Volume(d)); // left marked on purpose
	}
	// a new marker may reuse the same bits: they must have been cleared
	for (int k = 0; k < 3; ++k)
	{
		DartMarker dm(m);
		foreach_dart(m, [&](Dart x) { EXPECT_FALSE(dm.is_marked(x)); });
	}
}

TEST(DartMarkerStore, RecordsMarkedDarts)
{
	CMap2 m = make_torus();
	{
		DartMarkerStore dm(m);
		dm.mark_orbit(CMap2::Face(Dart(0)));
		dm.mark(Dart(0)); // twice: recorded once
		EXPECT_EQ(dm.marked_darts().size(), 4u);
		dm.unmark(Dart(0));
		EXPECT_EQ(dm.marked_darts().size(), 3u);
		EXPECT_FALSE(dm.is_marked(Dart(0)));
	}
	DartMarker check(m);
	foreach_dart(m, [&](Dart x) { EXPECT_FALSE(check.is_marked(x)); });
}

TEST(CellMarker, IndexedAndUnindexedOrbitsBehaveAlike)
{
	CMap2 m = make_torus();
	for (bool indexed : {false, true})
	{
		if (indexed)
			add_attribute<int, CMap2::Face>(m, "f");
		CellMarker<CMap2, CMap2::Face> cm(m);
		uint32 marked = 0;
		foreach_cell(m, [&](CMap2::Face f) {
			if (index_of(m, CMap2::Vertex(f.dart)) % 2 == 0)
			{
				cm.mark(f);
				++marked;
			}
		});
		uint32 seen = 0;
		foreach_cell(m, [&](CMap2::Face f) {
			// any dart of the face answers for it
			bool all = true;
			foreach_dart_of_orbit(m, f, [&](Dart d) { all = all && cm.is_marked(CMap2::Face(d)) == cm.is_marked(f); });
			EXPECT_TRUE(all);
			seen += cm.is_marked(f);
		});
		EXPECT_EQ(seen, marked);
		EXPECT_GT(marked, 0u);
		cm.unmark_all();
		foreach_cell(m, [&](CMap2::Face f) { EXPECT_FALSE(cm.is_marked(f)); });
	}
}

TEST(CellMarkerStore, MarkedCellsAndUnmark)
{
	CMap2 m = make_torus();
	add_attribute<int, CMap2::Vertex>(m, "v");
	CellMarkerStore<CMap2, CMap2::Vertex> cm(m);
	std::vector<CMap2::Vertex> some;
	foreach_cell(m, [&](CMap2::Vertex v) {
		if (some.size() < 5)
			some.push_back(v);
	});
	for (auto v : some)
		cm.mark(v);
	cm.mark(CMap2::Vertex(phi1(m, phi2(m, some[0].dart)))); // same vertex, another dart
	EXPECT_EQ(cm.marked_cells().size(), 5u);
	cm.unmark(CMap2::Vertex(phi1(m, phi2(m, some[1].dart))));
	EXPECT_EQ(cm.marked_cells().size(), 4u);
	EXPECT_FALSE(cm.is_marked(some[1]));
	cm.unmark_all();
	EXPECT_TRUE(cm.marked_cells().empty());
	for (auto v : some)
		EXPECT_FALSE(cm.is_marked(v));
}

TEST(Markers, ManyMarkersAliveAtOnce)
{
	CMap2 m = make_torus();
	std::vector<std::unique_ptr<DartMarker<CMap2>>> markers;
	for (int i = 0; i < 150; ++i)
	{
		markers.push_back(std::make_unique<DartMarker<CMap2>>(m));
		markers.back()->mark(Dart(uint32(i % nb_darts(m))));
	}
	for (int i = 0; i < 150; ++i)
	{
		uint32 n = 0;
		foreach_dart(m, [&](Dart x) { n += markers[i]->is_marked(x); });
		EXPECT_EQ(n, 1u);
	}
}

// a copy would give the same reserved bit back twice
static_assert(!std::is_copy_constructible_v<DartMarker<CMap2>> && !std::is_copy_assignable_v<DartMarker<CMap2>>);
static_assert(!std::is_copy_constructible_v<DartMarkerStore<CMap2>>);
static_assert(!std::is_copy_constructible_v<CellMarker<CMap2, CMap2::Vertex>>);
static_assert(!std::is_copy_constructible_v<CellMarkerStore<CMap3, CMap3::Volume>>);

} // namespace cgogn_test_markers
