// CellFilter and CellCache on known meshes: exact counts, use as a mesh in
// global and local traversals and generic code, snapshot semantics.
#include <cgogn/core.h>

#include <gtest/gtest.h>

namespace cgogn_test_views
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

// 4 x 3 quads: 20 vertices (6 inner of degree 4, 10 border of degree 3, 4
// corners of degree 2), 31 edges (14 on the border), 12 faces.
struct ViewGrid : ::testing::Test
{
	CMap2 m;
	std::shared_ptr<AttributeArray<uint32>> face_id;
	void SetUp() override
	{
		build_surface(m, grid_soup(4, 3));
		face_id = add_attribute<uint32, Face>(m, "id");
		uint32 k = 0;
		foreach_cell(m, [&](Face f) { value<uint32>(m, face_id, f) = k++; });
	}
};

// generic code written against mesh_traits, as in the CGoGN API guide
template <typename MESH>
uint32 count_vertices_and_faces(const MESH& m)
{
	using V = typename mesh_traits<MESH>::Vertex;
	using F = typename mesh_traits<MESH>::Face;
	return nb_cells<V>(m) * 100 + nb_cells<F>(m);
}

TEST_F(ViewGrid, FilterWithoutPredicateTraversesEverything)
{
	CellFilter<CMap2> cf(m);
	EXPECT_FALSE(cf.has_filter<Face>());
	EXPECT_EQ(count_vertices_and_faces(cf), 20u * 100 + 12);
	EXPECT_EQ(nb_cells<Edge>(cf), 31u);
}

TEST_F(ViewGrid, FilterPerCellType)
{
	CellFilter<CMap2> cf(m);
	cf.set_filter<Face>([&](Face f) { return value<uint32>(cf, face_id, f) % 2 == 0; });
	cf.set_filter<Vertex>([&](Vertex v) { return is_incident_to_boundary(m, v); });
	cf.set_filter<Edge>([&](Edge e) { return is_incident_to_boundary(m, e); });
	EXPECT_EQ(nb_cells<Face>(cf), 6u);
	EXPECT_EQ(nb_cells<Vertex>(cf), 14u);
	EXPECT_EQ(nb_cells<Edge>(cf), 14u);
	EXPECT_EQ(count_vertices_and_faces(cf), 14u * 100 + 6);
	// early stop
	uint32 n = 0;
	foreach_cell(cf, [&](Face) { return ++n < 2; });
	EXPECT_EQ(n, 2u);
	// index_of and value through the view
	foreach_cell(cf, [&](Face f) { EXPECT_EQ(index_of(cf, f), index_of(m, f)); });
	// removing a predicate
	cf.clear_filter<Face>();
	EXPECT_EQ(nb_cells<Face>(cf), 12u);
}

TEST_F(ViewGrid, FilterRestrictsLocalTraversals)
{
	CellFilter<CMap2> cf(m);
	cf.set_filter<Vertex>([&](Vertex v) { return is_incident_to_boundary(m, v); });
	// each inner vertex next to the border has border neighbours only on that side
	uint32 border_neighbours = 0, all_neighbours = 0;
	foreach_cell(m, [&](Vertex v) {
		foreach_adjacent_vertex_through_edge(cf, v, [&](Vertex) { ++border_neighbours; });
		foreach_adjacent_vertex_through_edge(m, v, [&](Vertex) { ++all_neighbours; });
	});
	EXPECT_EQ(all_neighbours, 2u * 31);
	// border edges count twice (14 x 2) and edges from inner to border vertices once (10)
	EXPECT_EQ(border_neighbours, 14u * 2 + 10);
	// a filter of a filter applies both predicates
	CellFilter<CellFilter<CMap2>> cf2(cf);
	cf2.set_filter<Vertex>([&](Vertex v) { return degree(m, v) == 2; }); // corners
	EXPECT_EQ(nb_cells<Vertex>(cf2), 4u);
	uint32 corner_neighbours = 0;
	foreach_cell(m,
				 [&](Vertex v) { foreach_adjacent_vertex_through_edge(cf2, v, [&](Vertex) { ++corner_neighbours; }); });
	EXPECT_EQ(corner_neighbours, 8u);
	// markers on a view mark the map's cells
	CellMarker<CellFilter<CMap2>, Vertex> cm(cf);
	foreach_cell(cf, [&](Vertex v) { cm.mark(v); });
	uint32 marked = 0;
	foreach_cell(m, [&](Vertex v) { marked += cm.is_marked(v); });
	EXPECT_EQ(marked, 14u);
}

// Traversals that report cells with their lines (an incidence cache, or a
// callable taking `auto` on an indexed orbit) are filtered as plain ones.
TEST_F(ViewGrid, FilterAppliesToLocatedNeighbours)
{
	CellFilter<CMap2> cf(m);
	cf.set_filter<Vertex>([&](Vertex v) { return is_incident_to_boundary(m, v); });
	auto count = [&]() {
		uint32 as_vertex = 0, as_auto = 0;
		foreach_cell(m, [&](Vertex v) {
			foreach_adjacent_vertex_through_edge(cf, v, [&](Vertex) { ++as_vertex; });
			foreach_adjacent_vertex_through_edge(cf, v, [&](auto) { ++as_auto; });
		});
		EXPECT_EQ(as_vertex, as_auto);
		return as_vertex;
	};
	EXPECT_EQ(count(), 14u * 2 + 10);              // as in FilterRestrictsLocalTraversals
	add_attribute<uint32, Vertex>(m, "vertex_id"); // neighbours come with their lines
	EXPECT_EQ(count(), 14u * 2 + 10);
	IncidenceCache<CMap2, Vertex, Vertex, Edge>::build(m);
	EXPECT_EQ(count(), 14u * 2 + 10);
}

TEST_F(ViewGrid, CacheBuildAddClear)
{
	CellCache cache(m); // class template argument deduction, as in the CGoGN API guide
	cache.build<Vertex>([&](Vertex v) { return degree(m, v) == 3; });
	EXPECT_EQ(cache.size<Vertex>(), 10u);
	EXPECT_EQ(nb_cells<Vertex>(cache), 10u);
	cache.build<Face>();
	EXPECT_EQ(nb_cells<Face>(cache), 12u);
	EXPECT_EQ(nb_cells<Edge>(cache), 0u); // never built: empty
	cache.clear<Vertex>();
	EXPECT_EQ(cache.size<Vertex>(), 0u);
	EXPECT_EQ(cache.size<Face>(), 12u);
	Face first = cache.cells<Face>().front();
	cache.add(first);
	EXPECT_EQ(cache.size<Face>(), 13u);
	cache.clear();
	EXPECT_EQ(cache.size<Face>(), 0u);
	// a cache of a filter
	CellFilter<CMap2> cf(m);
	cf.set_filter<Face>([&](Face f) { return value<uint32>(m, face_id, f) < 5; });
	CellCache<CellFilter<CMap2>> cc(cf);
	cc.build<Face>();
	EXPECT_EQ(cc.size<Face>(), 5u);
	cc.build<Face>([&](Face f) { return value<uint32>(m, face_id, f) % 2 == 1; });
	EXPECT_EQ(cc.size<Face>(), 2u);
	EXPECT_EQ(count_vertices_and_faces(cc), 2u); // no vertex stored
}

TEST_F(ViewGrid, CacheIsASnapshot)
{
	CellCache<CMap2> cache(m);
	cache.build<Face>();
	uint32 visited = 0;
	foreach_cell(cache, [&](Face f) {
		EXPECT_LT(value<uint32>(m, face_id, f), 12u);
		add_face(m, 3); // a new face of the map: not visited
		cache.add(f);   // added to the cache during the traversal: not visited
		++visited;
	});
	EXPECT_EQ(visited, 12u);
	EXPECT_EQ(nb_cells<Face>(m), 24u);
	EXPECT_EQ(cache.size<Face>(), 24u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CacheVolume, DegreeFiveLikeSelection)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(2, 2, 2));
	using V3 = CMap3::Vertex;
	using W3 = CMap3::Volume;
	CellCache<CMap3> cache(m);
	// vertices with 8 incident hexahedra: the centre only
	cache.build<V3>([&](V3 v) {
		uint32 n = 0;
		foreach_incident_volume(m, v, [&](W3) { ++n; });
		return n == 8;
	});
	EXPECT_EQ(cache.size<V3>(), 1u);
	uint32 around = 0;
	foreach_cell(cache, [&](V3 v) { foreach_incident_volume(cache, v, [&](W3) { ++around; }); });
	EXPECT_EQ(around, 8u);
	CellFilter<CMap3> cf(m);
	cf.set_filter<W3>([&](W3 w) { return index_of(m, V3(w.dart)) % 2 == 0; });
	EXPECT_LE(nb_cells<W3>(cf), 8u);
	EXPECT_EQ(nb_cells<CMap3::Face>(cf), 36u);
}

// generic code that asks topological questions: works on maps and views
template <typename MESH>
uint32 sum_of_vertex_degrees(const MESH& m)
{
	uint32 s = 0;
	foreach_cell(m, [&](typename mesh_traits<MESH>::Vertex v) { s += degree(m, v); });
	return s;
}

// A view hides cells from traversals, not from the topology: phi, degree,
// codegree, is_boundary, is_incident_to_boundary and same_cell answer for the
// map under the view.
TEST_F(ViewGrid, TopologicalQueriesPassThroughViews)
{
	CellFilter<CMap2> cf(m);
	cf.set_filter<Face>([&](Face f) { return value<uint32>(m, face_id, f) % 2 == 0; });
	cf.set_filter<Vertex>([&](Vertex v) { return !is_incident_to_boundary(cf, v); }); // the 6 inner vertices
	CellCache<CMap2> cache(m);
	cache.build<Vertex>();
	uint32 inner = 0;
	foreach_cell(cf, [&](Vertex v) {
		++inner;
		EXPECT_EQ(degree(cf, v), 4u); // all 4 edges, though half the faces are filtered out
		EXPECT_EQ(degree(cache, v), 4u);
		EXPECT_FALSE(is_incident_to_boundary(cache, v));
	});
	EXPECT_EQ(inner, 6u);
	// sum of degrees = 2 * edges; the filter keeps the inner vertices only
	EXPECT_EQ(sum_of_vertex_degrees(m), 62u);
	EXPECT_EQ(sum_of_vertex_degrees(cache), 62u);
	EXPECT_EQ(sum_of_vertex_degrees(cf), 24u);
	foreach_dart(m, [&](Dart d) {
		EXPECT_EQ(phi1(cf, d), phi1(m, d));
		EXPECT_EQ(phi_1(cache, d), phi_1(m, d));
		EXPECT_EQ(phi2(cf, d), phi2(m, d));
		EXPECT_EQ((phi<1, 2, -1>(cache, d)), (phi<1, 2, -1>(m, d)));
		EXPECT_EQ(is_boundary(cf, d), is_boundary(m, d));
		EXPECT_TRUE(same_cell(cf, Vertex(d), Vertex(phi<2, 1>(cf, d))));
		EXPECT_FALSE(same_cell(cache, Face(d), Face(phi2(m, d))));
		return true;
	});
	foreach_cell(m, [&](Face f) { EXPECT_EQ(codegree(cf, f), 4u); });
	foreach_cell(m, [&](Edge e) {
		EXPECT_EQ(codegree(cache, e), 2u);
		EXPECT_EQ(degree(cf, e), degree(m, e));
	});
}

TEST(CacheVolume, TopologicalQueriesPassThroughViews)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(2, 2, 2));
	using V3 = CMap3::Vertex;
	using E3 = CMap3::Edge;
	using F3 = CMap3::Face;
	using W3 = CMap3::Volume;
	CellFilter<CMap3> cf(m);
	cf.set_filter<W3>([&](W3) { return false; }); // no volume at all
	uint32 centre = 0;
	foreach_cell(m, [&](V3 v) {
		if (!is_incident_to_boundary(cf, v))
		{
			++centre;
			EXPECT_EQ(degree(cf, v), 6u); // the centre of the 2x2x2 grid
		}
	});
	EXPECT_EQ(centre, 1u);
	foreach_cell(m, [&](E3 e) { EXPECT_EQ(degree(cf, e), degree(m, e)); });
	foreach_cell(m, [&](F3 f) {
		EXPECT_EQ(codegree(cf, f), 4u);
		EXPECT_EQ(degree(cf, f), degree(m, f));
	});
	foreach_cell(m, [&](W3 w) {
		EXPECT_EQ(codegree(cf, w), 6u);
		EXPECT_EQ(phi3(cf, w.dart), phi3(m, w.dart));
	});
	EXPECT_EQ(nb_cells<W3>(cf), 0u);
}

} // namespace cgogn_test_views
