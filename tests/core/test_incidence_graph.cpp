#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <random>
#include <set>
#include <vector>

namespace cgogn_test_incidence_graph
{

using namespace cgogn;
using IG = IncidenceGraph;
using Vertex = IG::Vertex;
using Edge = IG::Edge;
using Face = IG::Face;

void expect_valid(const IG& ig)
{
	const IntegrityReport r = check_integrity(ig);
	EXPECT_TRUE(r.ok()) << r.to_string();
}

std::array<uint32, 3> counts(const IG& ig)
{
	return {nb_cells<Vertex>(ig), nb_cells<Edge>(ig), nb_cells<Face>(ig)};
}

// Three triangles on one spine (0, 1), with apexes 2, 3 and 4.
struct Book
{
	IG ig;
	std::vector<Vertex> v;
	Edge spine;
	Book()
	{
		for (int i = 0; i < 5; ++i)
			v.push_back(add_vertex(ig));
		for (int apex = 2; apex <= 4; ++apex)
		{
			const std::vector<Vertex> tri = {v[0], v[1], v[apex]};
			add_face_through_vertices(ig, tri);
		}
		spine = find_edge(ig, v[0], v[1]);
	}
};

TEST(IncidenceGraph, BookOfThreeTriangles)
{
	Book b;
	expect_valid(b.ig);
	EXPECT_EQ(counts(b.ig), (std::array<uint32, 3>{5, 7, 3}));
	ASSERT_TRUE(b.spine.is_valid());
	EXPECT_EQ(degree(b.ig, b.spine), 3u);
	EXPECT_FALSE(is_manifold_edge(b.ig, b.spine));
	EXPECT_EQ(nb_non_manifold_edges(b.ig), 1u);
	EXPECT_FALSE(is_manifold_vertex(b.ig, b.v[0]));
	EXPECT_TRUE(is_manifold_vertex(b.ig, b.v[2]));
	EXPECT_EQ(degree(b.ig, b.v[0]), 4u);
	EXPECT_EQ(euler_characteristic(b.ig), 1);
	EXPECT_EQ(nb_connected_components(b.ig), 1u);

	const Vertex w = cut_edge(b.ig, b.spine);
	expect_valid(b.ig);
	EXPECT_EQ(counts(b.ig), (std::array<uint32, 3>{6, 8, 3}));
	EXPECT_EQ(degree(b.ig, w), 2u);
	EXPECT_EQ(degree(b.ig, b.spine), 3u);
	foreach_cell(b.ig, [&](Face f) { EXPECT_EQ(codegree(b.ig, f), 4u); });
	EXPECT_EQ(second_vertex(b.ig, b.spine), w);
}

TEST(IncidenceGraph, AddFaceOrdersShuffledEdges)
{
	IG ig;
	std::vector<Vertex> v;
	for (int i = 0; i < 5; ++i)
		v.push_back(add_vertex(ig));
	std::vector<Edge> cycle;
	for (int i = 0; i < 5; ++i)
		cycle.push_back(add_edge(ig, v[i], v[(i + 1) % 5]));
	std::vector<Edge> shuffled = {cycle[3], cycle[0], cycle[4], cycle[2], cycle[1]};
	ASSERT_TRUE(can_add_face(ig, shuffled));
	const Face f = add_face(ig, shuffled);
	expect_valid(ig);
	EXPECT_EQ(codegree(ig, f), 5u);
	// the face runs along its cycle from cycle[3]'s first vertex
	std::vector<Vertex> around;
	foreach_incident_vertex(ig, f, [&](Vertex x) { around.push_back(x); });
	EXPECT_EQ(around, (std::vector<Vertex>{v[3], v[4], v[0], v[1], v[2]}));
	foreach_incident_edge(ig, f, [&](Edge e) { EXPECT_EQ(degree(ig, e), 1u); });

	// a path of three edges is no face; counts unchanged
	IG p;
	std::vector<Vertex> w;
	for (int i = 0; i < 4; ++i)
		w.push_back(add_vertex(p));
	const std::vector<Edge> path = {add_edge(p, w[0], w[1]), add_edge(p, w[1], w[2]), add_edge(p, w[2], w[3])};
	EXPECT_FALSE(can_add_face(p, path));
	EXPECT_THROW(add_face(p, path), TopologyError);
	EXPECT_EQ(counts(p), (std::array<uint32, 3>{4, 3, 0}));
	expect_valid(p);
	// two triangles sharing a vertex (a figure eight) and a repeated edge are refused too
	const std::vector<Edge> repeated = {path[0], path[0], path[1]};
	EXPECT_FALSE(can_add_face(p, repeated));
	EXPECT_FALSE(can_add_edge(p, w[0], w[0]));
	EXPECT_THROW(add_edge(p, w[1], w[1]), TopologyError);
	const std::vector<Vertex> twice = {w[0], w[1], w[0]};
	EXPECT_THROW(add_face_through_vertices(p, twice), TopologyError);
	EXPECT_EQ(counts(p), (std::array<uint32, 3>{4, 3, 0}));
}

TEST(IncidenceGraph, RemovalsTakeWhatTheySay)
{
	Book b;
	remove_face(b.ig, Face(Dart((*b.ig.links().edge_use)[b.spine.dart.index])));
	expect_valid(b.ig);
	EXPECT_EQ(counts(b.ig), (std::array<uint32, 3>{5, 7, 2}));
	remove_edge(b.ig, b.spine);
	expect_valid(b.ig);
	EXPECT_EQ(counts(b.ig), (std::array<uint32, 3>{5, 6, 0}));
	remove_vertex(b.ig, b.v[2]);
	expect_valid(b.ig);
	EXPECT_EQ(counts(b.ig), (std::array<uint32, 3>{4, 4, 0}));
	EXPECT_EQ(degree(b.ig, b.v[0]), 2u);
}

TEST(IncidenceGraph, CutFace)
{
	IG ig;
	std::vector<Vertex> v;
	for (int i = 0; i < 4; ++i)
		v.push_back(add_vertex(ig));
	auto area = add_attribute<int, Face>(ig, "tag");
	const Face f = add_face_through_vertices(ig, v);
	value<int>(ig, area, f) = 7;
	EXPECT_FALSE(can_cut_face(ig, f, v[0], v[1]));
	EXPECT_THROW(cut_face(ig, f, v[1], v[2]), TopologyError);
	const Edge e = cut_face(ig, f, v[0], v[2]);
	expect_valid(ig);
	EXPECT_EQ(counts(ig), (std::array<uint32, 3>{4, 5, 2}));
	EXPECT_EQ(degree(ig, e), 2u);
	int kept = 0;
	foreach_cell(ig, [&](Face g) {
		EXPECT_EQ(codegree(ig, g), 3u);
		kept += value<int>(ig, area, g) == 7;
	});
	EXPECT_EQ(kept, 1);
	EXPECT_EQ(euler_characteristic(ig), 1);

	// without naming the face: the one face where the vertices are not consecutive
	IG h;
	std::vector<Vertex> w;
	for (int i = 0; i < 5; ++i)
		w.push_back(add_vertex(h));
	add_face_through_vertices(h, w); // a pentagon
	EXPECT_FALSE(can_cut_face(h, w[0], w[1]));
	EXPECT_THROW(cut_face(h, w[0], w[1]), TopologyError);
	ASSERT_TRUE(can_cut_face(h, w[0], w[2]));
	cut_face(h, w[0], w[2]);
	expect_valid(h);
	EXPECT_EQ(counts(h), (std::array<uint32, 3>{5, 6, 2}));
	// w[0] and w[3] now share only the quadrangle w0 w2 w3 w4
	ASSERT_TRUE(can_cut_face(h, w[0], w[3]));
	cut_face(h, w[0], w[3]);
	EXPECT_EQ(counts(h), (std::array<uint32, 3>{5, 7, 3}));
	expect_valid(h);
	// two faces qualify: ambiguous
	IG two;
	std::vector<Vertex> x;
	for (int i = 0; i < 6; ++i)
		x.push_back(add_vertex(two));
	const std::vector<Vertex> q1 = {x[0], x[1], x[2], x[3]}, q2 = {x[0], x[4], x[2], x[5]};
	add_face_through_vertices(two, q1);
	add_face_through_vertices(two, q2);
	EXPECT_FALSE(can_cut_face(two, x[0], x[2]));
	EXPECT_FALSE(face_to_cut(two, x[0], x[2]).is_valid());
}

TEST(IncidenceGraph, CollapseRemovesDigonsAndMergesEdges)
{
	// a tetrahedron's surface: collapsing an edge leaves two triangles on one
	// triangle's edges (a doubled face), 3 vertices and 3 edges
	IG ig;
	std::vector<Vertex> v;
	for (int i = 0; i < 4; ++i)
		v.push_back(add_vertex(ig));
	const int tris[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};
	for (const auto& t : tris)
	{
		const std::vector<Vertex> f = {v[t[0]], v[t[1]], v[t[2]]};
		add_face_through_vertices(ig, f);
	}
	expect_valid(ig);
	EXPECT_EQ(euler_characteristic(ig), 2);
	const Edge e = find_edge(ig, v[0], v[1]);
	ASSERT_TRUE(can_collapse_edge(ig, e));
	const Vertex s = collapse_edge(ig, e);
	expect_valid(ig);
	EXPECT_EQ(s, v[0]);
	EXPECT_EQ(counts(ig), (std::array<uint32, 3>{3, 3, 2}));
	foreach_cell(ig, [&](Edge x) { EXPECT_EQ(degree(ig, x), 2u); });

	// a chord: a face holding both ends of an edge that is not its own
	IG q;
	std::vector<Vertex> w;
	for (int i = 0; i < 4; ++i)
		w.push_back(add_vertex(q));
	add_face_through_vertices(q, w);
	const Edge chord = add_edge(q, w[0], w[2]);
	EXPECT_FALSE(can_collapse_edge(q, chord));
	EXPECT_THROW(collapse_edge(q, chord), TopologyError);
	expect_valid(q);
	EXPECT_EQ(counts(q), (std::array<uint32, 3>{4, 5, 1}));
}

TEST(IncidenceGraph, TraversalsAroundABook)
{
	Book b;
	std::multiset<uint32> faces_of_v0, neighbours;
	uint32 n = 0;
	foreach_incident_face(b.ig, b.v[0], [&](Face) { ++n; });
	EXPECT_EQ(n, 3u);
	foreach_adjacent_vertex_through_edge(b.ig, b.v[0], [&](Vertex x) { neighbours.insert(x.dart.index); });
	EXPECT_EQ(neighbours, (std::multiset<uint32>{1, 2, 3, 4}));
	n = 0;
	foreach_incident_face(b.ig, b.spine, [&](Face) { ++n; });
	EXPECT_EQ(n, 3u);
	n = 0;
	foreach_adjacent_edge_through_vertex(b.ig, b.spine, [&](Edge) { ++n; });
	EXPECT_EQ(n, 6u);
	n = 0;
	foreach_adjacent_edge_through_face(b.ig, b.spine, [&](Edge) { ++n; });
	EXPECT_EQ(n, 6u);
	Face f;
	foreach_incident_face(b.ig, b.spine, [&](Face x) {
		f = x;
		return false;
	});
	n = 0;
	foreach_adjacent_face_through_edge(b.ig, f, [&](Face) { ++n; });
	EXPECT_EQ(n, 2u);
	n = 0;
	foreach_adjacent_face_through_vertex(b.ig, f, [&](Face) { ++n; });
	EXPECT_EQ(n, 4u); // the two others, met at v0 and at v1
	std::set<uint32> others;
	foreach_adjacent_vertex_through_face(b.ig, b.v[2], [&](Vertex x) { others.insert(x.dart.index); });
	EXPECT_EQ(others, (std::set<uint32>{0, 1}));
	// stopping early
	n = 0;
	foreach_incident_edge(b.ig, b.v[0], [&](Edge) { return ++n < 2; });
	EXPECT_EQ(n, 2u);
}

TEST(IncidenceGraph, AttributesMarkersAndParallel)
{
	Book b;
	auto pos = add_attribute<double, Vertex>(b.ig, "x");
	auto len = add_attribute<float, Edge>(b.ig, "len");
	ASSERT_TRUE(pos && len);
	foreach_cell(b.ig, [&](Vertex v) { value<double>(b.ig, pos, v) = double(v.dart.index); });
	std::atomic<uint32> visited = 0;
	parallel_foreach_cell(b.ig, [&](Edge e) {
		value<float>(b.ig, len, e) =
			float(value<double>(b.ig, pos, second_vertex(b.ig, e)) - value<double>(b.ig, pos, first_vertex(b.ig, e)));
		++visited;
	});
	EXPECT_EQ(visited.load(), 7u);
	EXPECT_EQ(value<float>(b.ig, len, b.spine), 1.0f);
	EXPECT_EQ((*len)[b.spine], 1.0f); // a record is its own line
	EXPECT_EQ((*pos)[b.v[3]], 3.0);
	CellMarker<IG, Vertex> marked(b.ig);
	foreach_incident_vertex(b.ig, b.spine, [&](Vertex v) { marked.mark(v); });
	uint32 n = 0;
	foreach_cell(b.ig, [&](Vertex v) { n += marked.is_marked(v); });
	EXPECT_EQ(n, 2u);
	CellMarker<IG, Face> faces(b.ig);
	foreach_incident_face(b.ig, b.spine, [&](Face f) {
		EXPECT_FALSE(faces.is_marked(f));
		faces.mark(f);
	});
	// a removed vertex's line is reused with default values
	remove_vertex(b.ig, b.v[4]);
	const Vertex again = add_vertex(b.ig);
	EXPECT_EQ(again, b.v[4]);
	EXPECT_EQ(value<double>(b.ig, pos, again), 0.0);
	EXPECT_EQ(nb_connected_components(b.ig), 2u);
}

// Randomized editing, checked after every step: the invariants, and the
// counts against a plain model (vertex set, edge set, faces as vertex cycles).
TEST(IncidenceGraph, RandomEditingKeepsInvariants)
{
	std::mt19937 rng(20261129);
	IG ig;
	auto pick = [&](auto cell_tag) {
		using C = decltype(cell_tag);
		std::vector<C> all;
		foreach_cell(ig, [&](C c) { all.push_back(c); });
		return all.empty() ? C() : all[rng() % all.size()];
	};
	uint32 refused = 0, done = 0;
	for (int step = 0; step < 1500; ++step)
	{
		const uint32 op = rng() % 10;
		if (op <= 1 || nb_cells<Vertex>(ig) < 4)
			add_vertex(ig);
		else if (op == 2)
		{
			const Vertex a = pick(Vertex()), c = pick(Vertex());
			if (can_add_edge(ig, a, c))
				add_edge(ig, a, c);
		}
		else if (op == 3)
		{
			std::vector<Vertex> tri = {pick(Vertex()), pick(Vertex()), pick(Vertex())};
			if (tri[0] != tri[1] && tri[1] != tri[2] && tri[0] != tri[2])
				add_face_through_vertices(ig, tri);
		}
		else if (op == 4 && nb_cells<Edge>(ig) > 0)
			cut_edge(ig, pick(Edge()));
		else if (op == 5 && nb_cells<Face>(ig) > 0)
		{
			const Face f = pick(Face());
			std::vector<Vertex> fv;
			foreach_incident_vertex(ig, f, [&](Vertex v) { fv.push_back(v); });
			const Vertex a = fv[rng() % fv.size()], c = fv[rng() % fv.size()];
			if (can_cut_face(ig, f, a, c))
				cut_face(ig, f, a, c);
			else
				EXPECT_THROW(cut_face(ig, f, a, c), TopologyError);
		}
		else if (op == 6 && nb_cells<Edge>(ig) > 0)
		{
			const Edge e = pick(Edge());
			const auto before = counts(ig);
			if (can_collapse_edge(ig, e))
			{
				collapse_edge(ig, e);
				++done;
				EXPECT_EQ(nb_cells<Vertex>(ig), before[0] - 1);
			}
			else
			{
				EXPECT_THROW(collapse_edge(ig, e), TopologyError);
				EXPECT_EQ(counts(ig), before);
				++refused;
			}
		}
		else if (op == 7 && nb_cells<Face>(ig) > 0 && rng() % 3 == 0)
			remove_face(ig, pick(Face()));
		else if (op == 8 && nb_cells<Edge>(ig) > 0 && rng() % 3 == 0)
			remove_edge(ig, pick(Edge()));
		else if (op == 9 && rng() % 4 == 0)
			remove_vertex(ig, pick(Vertex()));
		const IntegrityReport r = check_integrity(ig);
		ASSERT_TRUE(r.ok()) << "step " << step << ": " << r.to_string();
		// degrees against the records: the ends of all edges are 2E, the uses F's sizes
		uint32 ends = 0, uses = 0, sides = 0;
		foreach_cell(ig, [&](Vertex v) { ends += degree(ig, v); });
		foreach_cell(ig, [&](Edge e) { uses += degree(ig, e); });
		foreach_cell(ig, [&](Face f) { sides += codegree(ig, f); });
		ASSERT_EQ(ends, 2 * nb_cells<Edge>(ig));
		ASSERT_EQ(uses, sides);
		ASSERT_EQ(uses, nb_darts(ig));
	}
	EXPECT_GT(done, 10u);
	EXPECT_GT(nb_cells<Face>(ig), 0u);
	(void)refused;
}

TEST(IncidenceGraph, CMap2RoundTripIsTheIdentity)
{
	for (const SurfaceSoup& soup : {torus_soup(8, 6, true), sphere_soup(7, 5), grid_soup(4, 3, true)})
	{
		CMap2 m;
		build_surface(m, soup);
		auto x = add_attribute<double, CMap2::Vertex>(m, "x");
		auto tag = add_attribute<int, CMap2::Face>(m, "tag");
		auto w = add_attribute<int, CMap2::Edge>(m, "w");
		foreach_cell(m, [&](CMap2::Vertex v) { value<double>(m, x, v) = soup.positions[index_of(m, v)][0]; });
		int k = 0;
		foreach_cell(m, [&](CMap2::Face f) { value<int>(m, tag, f) = k++; });
		foreach_cell(m, [&](CMap2::Edge e) { value<int>(m, w, e) = k++; });

		const IG ig = to_incidence_graph(m);
		expect_valid(ig);
		EXPECT_EQ(counts(ig), (std::array<uint32, 3>{nb_cells<CMap2::Vertex>(m), nb_cells<CMap2::Edge>(m),
													 nb_cells<CMap2::Face>(m)}));
		EXPECT_EQ(nb_non_manifold_edges(ig), 0u);
		EXPECT_EQ(nb_non_manifold_vertices(ig), 0u);
		EXPECT_EQ(euler_characteristic(ig), euler_characteristic(m));

		BuildReport report;
		const CMap2 back = to_cmap2(ig, &report);
		EXPECT_TRUE(check_integrity(back).ok());
		EXPECT_EQ(report.nb_nonmanifold_edges, 0u);
		EXPECT_TRUE(report.split_vertices.empty());
		EXPECT_EQ(nb_cells<CMap2::Vertex>(back), nb_cells<CMap2::Vertex>(m));
		EXPECT_EQ(nb_cells<CMap2::Edge>(back), nb_cells<CMap2::Edge>(m));
		EXPECT_EQ(nb_cells<CMap2::Face>(back), nb_cells<CMap2::Face>(m));
		EXPECT_EQ(nb_darts(back), nb_darts(m));
		// attributes: per face, the tag with the multiset of its vertices' x and edges' w
		auto signature = [](const CMap2& map) {
			auto bx = get_attribute<double, CMap2::Vertex>(map, "x");
			auto bt = get_attribute<int, CMap2::Face>(map, "tag");
			auto bw = get_attribute<int, CMap2::Edge>(map, "w");
			std::map<int, std::pair<std::multiset<double>, std::multiset<int>>> s;
			foreach_cell(map, [&](CMap2::Face f) {
				// no structured binding: clang 14 does not capture one in a lambda
				auto& entry = s[value<int>(map, bt, f)];
				foreach_incident_vertex(map, f,
										[&](CMap2::Vertex v) { entry.first.insert(value<double>(map, bx, v)); });
				foreach_incident_edge(map, f, [&](CMap2::Edge e) { entry.second.insert(value<int>(map, bw, e)); });
			});
			return s;
		};
		ASSERT_TRUE((get_attribute<double, CMap2::Vertex>(back, "x")));
		ASSERT_TRUE((get_attribute<int, CMap2::Face>(back, "tag")));
		ASSERT_TRUE((get_attribute<int, CMap2::Edge>(back, "w")));
		EXPECT_EQ(signature(back), signature(m));

		const Graph g = to_graph(ig);
		EXPECT_EQ(nb_cells<Graph::Vertex>(g), nb_cells<Vertex>(ig));
		EXPECT_EQ(nb_cells<Graph::Edge>(g), nb_cells<Edge>(ig));
		EXPECT_TRUE((get_attribute<double, Graph::Vertex>(g, "x")));
	}
}

TEST(IncidenceGraph, NonManifoldToCMap2IsRepairedWithAReport)
{
	Book b;
	BuildReport report;
	const CMap2 m = to_cmap2(b.ig, &report);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(report.nb_nonmanifold_edges, 1u);
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 3u);
}

} // namespace cgogn_test_incidence_graph
