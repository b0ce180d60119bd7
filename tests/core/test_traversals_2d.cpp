#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <set>
#include <vector>

namespace cgogn_test_traversals_2d
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;
using Volume = CMap2::Volume;

// 3x3 quads, vertex (i, j) has id 4j + i.
struct Grid : ::testing::Test
{
	CMap2 m;
	void SetUp() override
	{
		build_surface(m, grid_soup(3, 3));
	}
	uint32 id(Vertex v) const
	{
		return index_of(m, v);
	}
	Vertex vertex(uint32 id) const
	{
		Vertex r;
		foreach_cell(m, [&](Vertex v) {
			if (index_of(m, v) != id)
				return true;
			r = v;
			return false;
		});
		return r;
	}
	// the face of quad (i, j): the one whose vertex ids sum to the expected value and contain (i, j)
	Face face(uint32 i, uint32 j) const
	{
		const std::set<uint32> want = {4 * j + i, 4 * j + i + 1, 4 * (j + 1) + i, 4 * (j + 1) + i + 1};
		Face r;
		foreach_cell(m, [&](Face f) {
			std::set<uint32> got;
			foreach_incident_vertex(m, f, [&](Vertex v) { got.insert(id(v)); });
			if (got != want)
				return true;
			r = f;
			return false;
		});
		return r;
	}
	Edge edge(uint32 a, uint32 b) const
	{
		Edge r;
		foreach_incident_edge(m, vertex(a), [&](Edge e) {
			if (id(Vertex(phi2(m, e.dart))) != b)
				return true;
			r = e;
			return false;
		});
		return r;
	}
	template <typename CELL, typename F>
	std::multiset<uint32> ids(F traversal) const
	{
		std::multiset<uint32> s;
		traversal([&](CELL c) { s.insert(id(c)); });
		return s;
	}
};

TEST_F(Grid, GlobalCounts)
{
	EXPECT_EQ(nb_cells<Vertex>(m), 16u);
	EXPECT_EQ(nb_cells<Edge>(m), 24u);
	EXPECT_EQ(nb_cells<Face>(m), 9u);
	EXPECT_EQ(nb_cells<Volume>(m), 1u);
	uint32 darts = 0;
	foreach_dart(m, [&](Dart) { ++darts; });
	EXPECT_EQ(darts, 2u * 24u); // 36 in faces + 12 on the boundary
	EXPECT_EQ(nb_cells<CMap2::HalfEdge>(m), 36u);
}

TEST_F(Grid, EarlyStop)
{
	uint32 visited = 0;
	foreach_cell(m, [&](Vertex) { return ++visited < 5; });
	EXPECT_EQ(visited, 5u);
	visited = 0;
	foreach_cell(m, [&](Edge) { return ++visited < 3; });
	EXPECT_EQ(visited, 3u);
	visited = 0;
	foreach_dart(m, [&](Dart) { return ++visited < 7; });
	EXPECT_EQ(visited, 7u);
	visited = 0;
	foreach_incident_edge(m, vertex(5), [&](Edge) { return ++visited < 2; });
	EXPECT_EQ(visited, 2u);
}

TEST_F(Grid, AroundAnInteriorVertex)
{
	const Vertex v = vertex(5);
	std::vector<Face> faces;
	foreach_incident_face(m, v, [&](Face f) { faces.push_back(f); });
	ASSERT_EQ(faces.size(), 4u);
	// cyclic order: consecutive faces share an edge
	for (std::size_t k = 0; k < 4; ++k)
	{
		bool shared = false;
		foreach_adjacent_face_through_edge(m, faces[k],
										   [&](Face g) { shared = shared || same_cell(m, g, faces[(k + 1) % 4]); });
		EXPECT_TRUE(shared);
	}
	uint32 edges = 0;
	foreach_incident_edge(m, v, [&](Edge) { ++edges; });
	EXPECT_EQ(edges, 4u);
	EXPECT_EQ(ids<Vertex>([&](auto f) { foreach_adjacent_vertex_through_edge(m, v, f); }),
			  (std::multiset<uint32>{1, 4, 6, 9}));
	EXPECT_EQ(ids<Vertex>([&](auto f) { foreach_adjacent_vertex_through_face(m, v, f); }),
			  (std::multiset<uint32>{0, 1, 2, 4, 6, 8, 9, 10}));
	uint32 volumes = 0;
	foreach_incident_volume(m, v, [&](Volume) { ++volumes; });
	EXPECT_EQ(volumes, 1u);
}

TEST_F(Grid, AroundBoundaryVertices)
{
	uint32 n = 0;
	foreach_incident_face(m, vertex(0), [&](Face) { ++n; });
	EXPECT_EQ(n, 1u); // the boundary face is not reported
	EXPECT_EQ(degree(m, vertex(0)), 2u);
	EXPECT_EQ(ids<Vertex>([&](auto f) { foreach_adjacent_vertex_through_face(m, vertex(0), f); }),
			  (std::multiset<uint32>{1, 4, 5}));
	EXPECT_EQ(ids<Vertex>([&](auto f) { foreach_adjacent_vertex_through_face(m, vertex(1), f); }),
			  (std::multiset<uint32>{0, 2, 4, 5, 6}));
	n = 0;
	foreach_incident_face(m, vertex(1), [&](Face) { ++n; });
	EXPECT_EQ(n, 2u);
}

TEST_F(Grid, FaceCyclesFollowTheSoupOrder)
{
	const Face f = face(0, 0);
	ASSERT_TRUE(f.is_valid());
	std::vector<uint32> cycle;
	foreach_incident_vertex(m, f, [&](Vertex v) { cycle.push_back(id(v)); });
	ASSERT_EQ(cycle.size(), 4u);
	std::rotate(cycle.begin(), std::find(cycle.begin(), cycle.end(), 0u), cycle.end());
	EXPECT_EQ(cycle, (std::vector<uint32>{0, 1, 5, 4}));
	std::vector<uint32> edge_starts;
	foreach_incident_edge(m, f, [&](Edge e) { edge_starts.push_back(id(Vertex(e.dart))); });
	std::rotate(edge_starts.begin(), std::find(edge_starts.begin(), edge_starts.end(), 0u), edge_starts.end());
	EXPECT_EQ(edge_starts, (std::vector<uint32>{0, 1, 5, 4}));
}

TEST_F(Grid, FaceAdjacencies)
{
	auto count = [&](Face f, bool through_edge) {
		uint32 n = 0;
		if (through_edge)
			foreach_adjacent_face_through_edge(m, f, [&](Face) { ++n; });
		else
			foreach_adjacent_face_through_vertex(m, f, [&](Face g) {
				EXPECT_FALSE(same_cell(m, g, f));
				++n;
			});
		return n;
	};
	EXPECT_EQ(count(face(1, 1), true), 4u);
	EXPECT_EQ(count(face(1, 1), false), 8u);
	EXPECT_EQ(count(face(0, 0), true), 2u);
	EXPECT_EQ(count(face(0, 0), false), 3u);
	EXPECT_EQ(count(face(1, 0), false), 5u);
}

TEST_F(Grid, EdgeIncidencesAndAdjacencies)
{
	const Edge inner = edge(5, 6), border = edge(0, 1);
	ASSERT_TRUE(inner.is_valid() && border.is_valid());
	EXPECT_EQ(ids<Vertex>([&](auto f) { foreach_incident_vertex(m, inner, f); }), (std::multiset<uint32>{5, 6}));
	uint32 n = 0;
	foreach_incident_face(m, inner, [&](Face) { ++n; });
	EXPECT_EQ(n, 2u);
	n = 0;
	foreach_incident_face(m, border, [&](Face) { ++n; });
	EXPECT_EQ(n, 1u);
	n = 0;
	foreach_adjacent_edge_through_vertex(m, inner, [&](Edge) { ++n; });
	EXPECT_EQ(n, 6u);
	n = 0;
	foreach_adjacent_edge_through_face(m, inner, [&](Edge) { ++n; });
	EXPECT_EQ(n, 6u);
	n = 0;
	foreach_adjacent_edge_through_face(m, border, [&](Edge) { ++n; });
	EXPECT_EQ(n, 3u);
	n = 0;
	foreach_adjacent_edge_through_vertex(m, border, [&](Edge) { ++n; });
	EXPECT_EQ(n, 1u + 2u);
}

TEST_F(Grid, VolumeIncidences)
{
	const Volume w(vertex(0).dart);
	uint32 v = 0, e = 0, f = 0;
	foreach_incident_vertex(m, w, [&](Vertex) { ++v; });
	foreach_incident_edge(m, w, [&](Edge) { ++e; });
	foreach_incident_face(m, w, [&](Face) { ++f; });
	EXPECT_EQ(v, 16u);
	EXPECT_EQ(e, 24u);
	EXPECT_EQ(f, 9u);
}

TEST_F(Grid, GuideEarlyStopLookup)
{
	// the CGoGN API guide's example: the first vertex with a negative x
	auto position = add_attribute<std::array<double, 3>, Vertex>(m, "position");
	foreach_cell(m, [&](Vertex v) { value<std::array<double, 3>>(m, position, v) = {double(id(v) % 4) - 2.5, 0, 0}; });
	Vertex looked_up_v;
	foreach_cell(m, [&](Vertex v) -> bool {
		if (value<std::array<double, 3>>(m, position, v)[0] < 0.0)
		{
			looked_up_v = v;
			return false;
		}
		return true;
	});
	ASSERT_TRUE(looked_up_v.is_valid());
	EXPECT_LT(id(looked_up_v) % 4, 3u);
	Vertex none;
	foreach_cell(m, [&](Vertex v) -> bool {
		if (value<std::array<double, 3>>(m, position, v)[0] > 100.0)
		{
			none = v;
			return false;
		}
		return true;
	});
	EXPECT_FALSE(none.is_valid());
}

TEST(Traversals2D, TrianglesOfASphere)
{
	CMap2 m;
	build_surface(m, sphere_soup(10, 6, true));
	// sum of degrees = 2E, sum of face sizes = 2E, incidences vertex->face = face->vertex
	uint64 deg = 0, vf = 0, fv = 0, vv_face = 0;
	foreach_cell(m, [&](Vertex v) {
		deg += degree(m, v);
		foreach_incident_face(m, v, [&](Face) { ++vf; });
		foreach_adjacent_vertex_through_face(m, v, [&](Vertex) { ++vv_face; });
	});
	foreach_cell(m, [&](Face f) { foreach_incident_vertex(m, f, [&](Vertex) { ++fv; }); });
	const uint32 E = nb_cells<Edge>(m);
	EXPECT_EQ(deg, 2u * E);
	EXPECT_EQ(vf, fv);
	EXPECT_EQ(vv_face, 2u * E); // triangles: the neighbours through faces are the edge neighbours
	EXPECT_EQ(int64(nb_cells<Vertex>(m)) - E + nb_cells<Face>(m), 2);
}

// Faces around a vertex on a closed map (no boundary bit read) and on the
// same map once a face is removed (the boundary face is skipped): every
// vertex-face incidence once, from both sides.
TEST(Traversals2D, IncidentFacesOfVerticesClosedAndOpen)
{
	CMap2 m;
	build_surface(m, torus_soup(6, 5, true));
	auto incidences = [&] {
		uint32 from_vertices = 0, from_faces = 0;
		foreach_cell(m, [&](Vertex v) { foreach_incident_face(m, v, [&](Face) { ++from_vertices; }); });
		foreach_cell(m, [&](Face f) { from_faces += codegree(m, f); });
		EXPECT_EQ(from_vertices, from_faces);
		return from_vertices;
	};
	ASSERT_FALSE(has_boundary(m));
	EXPECT_EQ(incidences(), 3u * 60u);
	Face first;
	foreach_cell(m, [&](Face f) {
		first = f;
		return false;
	});
	remove_face(m, first);
	ASSERT_TRUE(has_boundary(m));
	EXPECT_EQ(incidences(), 3u * 59u);
	EXPECT_TRUE(check_integrity(m).ok());
}

// What `traversal(v, f)` reports from every vertex v: the darts given to a
// callable taking TO, the darts given to a callable taking `auto` as a
// LocatedCell (whose line is checked against index_of), and how many cells
// the latter got without a line.
struct Reported
{
	std::vector<uint32> plain, located;
	uint32 without_line = 0;
};
template <typename TO, typename TRAVERSAL>
Reported reported(const CMap2& m, const TRAVERSAL& traversal)
{
	Reported r;
	foreach_cell(m, [&](Vertex v) { traversal(v, [&](TO c) { r.plain.push_back(c.dart.index); }); });
	foreach_cell(m, [&](Vertex v) {
		traversal(v, [&](auto c) {
			if constexpr (requires { c.line; })
			{
				r.located.push_back(c.dart.index);
				EXPECT_EQ(c.line, index_of(m, TO(c.dart)));
			}
			else
				++r.without_line;
		});
	});
	return r;
}

// Without caches, the traversals around a vertex and of a face give a callable
// taking `auto` each neighbour with its line (LocatedCell) when the
// neighbour's orbit is indexed, the plain cell otherwise; the neighbours and
// their order are those a callable taking the cell type gets.
TEST(Traversals2D, UncachedTraversalsGiveLinesToAutoCallables)
{
	for (bool closed : {true, false})
	{
		CMap2 m;
		build_surface(m, closed ? torus_soup(6, 5, true) : grid_soup(6, 5, true));
		add_attribute<uint32, Vertex>(m, "v");
		auto ring = [&](Vertex v, const auto& f) { foreach_adjacent_vertex_through_edge(m, v, f); };
		auto faces = [&](Vertex v, const auto& f) { foreach_incident_face(m, v, f); };
		auto corners = [&](Vertex v, const auto& f) {
			foreach_incident_face(m, v, [&](Face x) { foreach_incident_vertex(m, x, f); });
		};
		// vertices indexed: located neighbours, in the plain order
		const Reported r1 = reported<Vertex>(m, ring);
		EXPECT_FALSE(r1.plain.empty());
		EXPECT_EQ(r1.located, r1.plain);
		EXPECT_EQ(r1.without_line, 0u);
		// faces not indexed yet: plain faces
		const Reported r2 = reported<Face>(m, faces);
		EXPECT_TRUE(r2.located.empty());
		EXPECT_EQ(r2.without_line, r2.plain.size());
		// faces indexed: located faces, boundary faces still skipped
		add_attribute<uint32, Face>(m, "f");
		const Reported r3 = reported<Face>(m, faces);
		EXPECT_EQ(r3.plain, r2.plain);
		EXPECT_EQ(r3.located, r3.plain);
		EXPECT_EQ(r3.without_line, 0u);
		// the vertices of each of those faces: three per triangle
		const Reported r4 = reported<Vertex>(m, corners);
		EXPECT_EQ(r4.plain.size(), 3 * r3.plain.size());
		EXPECT_EQ(r4.located, r4.plain);
		EXPECT_EQ(r4.without_line, 0u);
	}
}

// What foreach_cell reports for CELL on m: every dart must lie in exactly one
// reported cell (none for the boundary darts when CELL is Face), and located
// cells must carry their line (or INVALID_INDEX when the orbit has no index).
template <typename CELL>
void expect_each_cell_once(const CMap2& m)
{
	std::vector<uint32> covered(cgogn::detail::state_of(m).darts->end_index(), 0);
	uint32 cells = 0, located = 0;
	foreach_cell(m, [&](CELL c) {
		++cells;
		foreach_dart_of_orbit(m, c, [&](Dart d) { ++covered[d.index]; });
	});
	foreach_cell(m, [&](Located<CELL> c) {
		++located;
		EXPECT_EQ(c.line, is_indexed<CELL>(m) ? index_of(m, CELL(c.dart)) : INVALID_INDEX);
	});
	EXPECT_GT(cells, 0u);
	EXPECT_EQ(located, cells);
	EXPECT_EQ(nb_cells<CELL>(m), cells);
	// boundary darts lie in the vertices, edges and volumes, not in the faces
	constexpr bool faces = std::is_same_v<CELL, Face>;
	foreach_dart(m, [&](Dart d) { EXPECT_EQ(covered[d.index], faces && is_boundary(m, d) ? 0u : 1u) << d.index; });
	// a stopped traversal leaves nothing behind (marks given back): the next one sees every cell
	uint32 visited = 0;
	foreach_cell(m, [&](CELL) { return ++visited < 2; });
	EXPECT_EQ(visited, std::min(cells, 2u));
	EXPECT_EQ(nb_cells<CELL>(m), cells);
}

// foreach_cell finds the cells in the cell container when the orbit is
// indexed, by a scan of the darts otherwise (a mark, a flood, or the smaller
// dart of an edge): both ways report every cell once, boundary excluded.
TEST(Traversals2D, EveryCellOnceIndexedOrNot)
{
	for (bool closed : {true, false})
	{
		CMap2 m;
		build_surface(m, closed ? torus_soup(6, 5, true) : grid_soup(6, 5, true));
		expect_each_cell_once<Vertex>(m); // indexed by the builder
		EXPECT_FALSE(is_indexed<Edge>(m));
		EXPECT_FALSE(is_indexed<Face>(m));
		EXPECT_FALSE(is_indexed<Volume>(m));
		expect_each_cell_once<Edge>(m);
		expect_each_cell_once<Face>(m);
		expect_each_cell_once<Volume>(m);
		index_cells<Edge>(m);
		index_cells<Face>(m);
		index_cells<Volume>(m);
		expect_each_cell_once<Edge>(m);
		expect_each_cell_once<Face>(m);
		expect_each_cell_once<Volume>(m);
	}
}

// A callable that counts its copies (so it is not trivially copyable) and its calls.
template <typename CELL>
struct CopyCounting
{
	uint32* copies;
	std::atomic<uint32>* calls;
	CopyCounting(uint32* c, std::atomic<uint32>* n) : copies(c), calls(n)
	{
	}
	CopyCounting(const CopyCounting& o) : copies(o.copies), calls(o.calls)
	{
		++*copies;
	}
	CopyCounting& operator=(const CopyCounting&) = delete;
	void operator()(CELL) const
	{
		++*calls;
	}
};

std::atomic<uint32> function_calls = 0;
void count_vertex(Vertex)
{
	++function_calls;
}

struct LargeTrivial
{
	double weights[9];
	void operator()(Vertex) const
	{
	}
};

// The global traversals hold a small trivially copyable callable by value (its
// captures stay in registers) and any other one by reference: a callable
// with a user-defined copy is never copied, and each gets every cell once.
TEST(Traversals2D, CallablesCopiedOnlyWhenSmallAndTrivial)
{
	uint32 n = 0;
	auto capturing_n = [&](Vertex) { ++n; }; // captures a reference: small and trivial, held by copy
	static_assert(std::is_same_v<held_callable_t<decltype(capturing_n)>, const decltype(capturing_n)>);
	static_assert(std::is_same_v<held_callable_t<CopyCounting<Vertex>>, const CopyCounting<Vertex>&>);
	static_assert(std::is_same_v<held_callable_t<LargeTrivial>, const LargeTrivial&>);
	static_assert(std::is_same_v<held_callable_t<decltype(count_vertex)>, decltype(count_vertex)&>);

	CMap2 m;
	build_surface(m, torus_soup(6, 5, true));
	const uint32 nv = nb_cells<Vertex>(m);
	foreach_cell(m, capturing_n); // the copy updates the caller's n through its reference
	EXPECT_EQ(n, nv);

	uint32 copies = 0;
	std::atomic<uint32> calls = 0;
	const CopyCounting<Vertex> count_vertices(&copies, &calls);
	foreach_cell(m, count_vertices);
	EXPECT_EQ(calls, nv);
	parallel_foreach_cell(m, count_vertices);
	EXPECT_EQ(calls, 2 * nv);
	CellCache<CMap2> cache(m);
	cache.build<Vertex>();
	foreach_cell(cache, count_vertices);
	parallel_foreach_cell(cache, count_vertices);
	EXPECT_EQ(calls, 4 * nv);
	calls = 0;
	foreach_cell(m, CopyCounting<Face>(&copies, &calls)); // faces are not indexed: the dart scan
	EXPECT_EQ(calls, nb_cells<Face>(m));
	calls = 0;
	foreach_dart(m, CopyCounting<Dart>(&copies, &calls));
	EXPECT_EQ(calls, nb_darts(m));
	EXPECT_EQ(copies, 0u);
	function_calls = 0;
	foreach_cell(m, count_vertex); // a function, held by reference
	parallel_foreach_cell(m, count_vertex);
	EXPECT_EQ(function_calls, 2 * nv);
}

} // namespace cgogn_test_traversals_2d
