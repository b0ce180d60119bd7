#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <vector>

namespace cgogn_test_graph
{

using namespace cgogn;
using Vertex = Graph::Vertex;
using Edge = Graph::Edge;

std::vector<Vertex> add_vertices(Graph& g, uint32 n)
{
	std::vector<Vertex> v;
	for (uint32 i = 0; i < n; ++i)
		v.push_back(add_vertex(g));
	return v;
}

void expect_valid(const Graph& g)
{
	const IntegrityReport r = check_integrity(g);
	EXPECT_TRUE(r.ok()) << r.to_string();
}

TEST(Graph, PathOfTenVertices)
{
	Graph g;
	const std::vector<Vertex> v = add_vertices(g, 10);
	for (uint32 i = 0; i + 1 < 10; ++i)
		connect_vertices(g, v[i], v[i + 1]);
	expect_valid(g);
	EXPECT_EQ(nb_cells<Vertex>(g), 10u);
	EXPECT_EQ(nb_cells<Edge>(g), 9u);
	EXPECT_EQ(nb_connected_components(g), 1u);
	EXPECT_EQ(cycle_rank(g), 0u);
	EXPECT_EQ(degree(g, v[0]), 1u);
	EXPECT_EQ(degree(g, v[5]), 2u);
	const std::vector<GraphBranch> b = branches(g);
	ASSERT_EQ(b.size(), 1u);
	EXPECT_EQ(b[0].nb_edges, 9u);
	EXPECT_FALSE(b[0].closed);
	// the branch runs from one end of the path to the other
	std::set<uint32> ends = {degree(g, Vertex(b[0].first)), degree(g, Vertex(b[0].last))};
	EXPECT_EQ(ends, std::set<uint32>({1u}));
	EXPECT_FALSE(same_cell(g, Vertex(b[0].first), Vertex(b[0].last)));
}

TEST(Graph, CycleOfEightIsOneClosedBranch)
{
	Graph g;
	const std::vector<Vertex> v = add_vertices(g, 8);
	for (uint32 i = 0; i < 8; ++i)
		connect_vertices(g, v[i], v[(i + 1) % 8]);
	expect_valid(g);
	EXPECT_EQ(cycle_rank(g), 1u);
	const std::vector<GraphBranch> b = branches(g); // returns: no endless walk
	ASSERT_EQ(b.size(), 1u);
	EXPECT_TRUE(b[0].closed);
	EXPECT_EQ(b[0].nb_edges, 8u);
	EXPECT_TRUE(same_cell(g, Vertex(b[0].first), Vertex(b[0].last)));
}

TEST(Graph, StarOfFive)
{
	Graph g;
	const Vertex centre = add_vertex(g);
	for (uint32 i = 0; i < 5; ++i)
		connect_vertices(g, centre, add_vertex(g));
	expect_valid(g);
	EXPECT_EQ(degree(g, centre), 5u);
	EXPECT_EQ(branches(g).size(), 5u);
	for (const GraphBranch& b : branches(g))
		EXPECT_EQ(b.nb_edges, 1u);
	uint32 n = 0;
	foreach_incident_edge(g, centre, [&](Edge) { ++n; });
	EXPECT_EQ(n, 5u);
	foreach_adjacent_vertex_through_edge(g, centre, [&](Vertex w) { EXPECT_EQ(degree(g, w), 1u); });
}

TEST(Graph, IsolatedVerticesHaveNoEdge)
{
	Graph g;
	const std::vector<Vertex> v = add_vertices(g, 3);
	expect_valid(g);
	EXPECT_EQ(nb_cells<Vertex>(g), 3u);
	EXPECT_EQ(nb_cells<Edge>(g), 0u);
	EXPECT_EQ(nb_darts(g), 3u);
	for (Vertex x : v)
		EXPECT_EQ(degree(g, x), 0u);
	EXPECT_EQ(nb_connected_components(g), 3u);
	EXPECT_EQ(cycle_rank(g), 0u);
	EXPECT_TRUE(branches(g).empty());
	uint32 n = 0;
	foreach_cell(g, [&](Edge) { ++n; });
	EXPECT_EQ(n, 0u);
	// the same with edges indexed: no phantom edge gets a line
	index_cells<Edge>(g);
	EXPECT_EQ(nb_cells<Edge>(g), 0u);
	expect_valid(g);
}

TEST(Graph, SelfLoopAddsTwoToTheDegreeAndOneToTheCycleRank)
{
	Graph g;
	const std::vector<Vertex> v = add_vertices(g, 2);
	connect_vertices(g, v[0], v[1]);
	const uint32 degree_before = degree(g, v[0]);
	const uint32 rank_before = cycle_rank(g);
	const Edge loop = connect_vertices(g, v[0], v[0]);
	expect_valid(g);
	EXPECT_EQ(degree(g, v[0]), degree_before + 2);
	EXPECT_EQ(cycle_rank(g), rank_before + 1);
	EXPECT_FALSE(can_collapse_edge(g, loop));
	// a loop on an isolated vertex reuses its dart
	const Vertex w = add_vertex(g);
	connect_vertices(g, w, w);
	expect_valid(g);
	EXPECT_EQ(degree(g, w), 2u);
	EXPECT_EQ(nb_darts_of_orbit(g, w), 2u);
	// a vertex with only a loop is a closed branch of one edge
	uint32 closed = 0;
	for (const GraphBranch& b : branches(g))
		closed += b.closed && b.nb_edges == 1;
	EXPECT_EQ(closed, 1u);
	disconnect_vertices(g, Edge(w.dart));
	expect_valid(g);
	EXPECT_EQ(degree(g, w), 0u);
}

TEST(Graph, OperatorsKeepTheLinesOfWhatSurvives)
{
	Graph g;
	auto vid = add_attribute<int, Vertex>(g, "vid");
	auto eid = add_attribute<int, Edge>(g, "eid");
	const std::vector<Vertex> v = add_vertices(g, 3);
	for (int i = 0; i < 3; ++i)
		value<int>(g, vid, v[i]) = i;
	const Edge e01 = connect_vertices(g, v[0], v[1]);
	value<int>(g, eid, e01) = 10;
	const Vertex m = cut_edge(g, e01);
	expect_valid(g);
	EXPECT_EQ(value<int>(g, vid, m), 0); // a new vertex: the default value
	EXPECT_EQ(value<int>(g, eid, e01), 10);
	EXPECT_EQ(value<int>(g, vid, Vertex(e01.dart)), 0);
	value<int>(g, vid, m) = 7;
	EXPECT_EQ(nb_cells<Edge>(g), 2u);
	// collapsing the first part keeps the vertex of its dart (v0)
	const Vertex kept = collapse_edge(g, e01);
	expect_valid(g);
	EXPECT_EQ(value<int>(g, vid, kept), 0);
	EXPECT_EQ(degree(g, kept), 1u);
	EXPECT_EQ(nb_cells<Vertex>(g), 3u);
	const Vertex merged = merge_vertices(g, v[2], kept);
	expect_valid(g);
	EXPECT_EQ(value<int>(g, vid, merged), 2);
	EXPECT_EQ(nb_cells<Vertex>(g), 2u);
	EXPECT_FALSE(can_merge_vertices(g, merged, merged));
	remove_vertex(g, merged);
	expect_valid(g);
	EXPECT_EQ(nb_cells<Vertex>(g), 1u);
	EXPECT_EQ(nb_cells<Edge>(g), 0u);
}

TEST(Graph, MisuseLeavesTheGraphValid)
{
	Graph g;
	auto vid = add_attribute<int, Vertex>(g, "vid");
	const Vertex lone = add_vertex(g);
	const std::vector<Vertex> v = add_vertices(g, 2);
	const Edge e = connect_vertices(g, v[0], v[1]);
	const Edge loop = connect_vertices(g, v[0], v[0]);
	// a vertex merged with itself is left as it is
	EXPECT_EQ(merge_vertices(g, lone, lone), lone);
	EXPECT_EQ(merge_vertices(g, v[0], Vertex(alpha1(g, v[0].dart))), v[0]);
	expect_valid(g);
	EXPECT_EQ(nb_cells<Vertex>(g), 3u);
	EXPECT_EQ(degree(g, v[0]), 3u);
	// a self-loop is not collapsed
	EXPECT_THROW(collapse_edge(g, loop), TopologyError);
	expect_valid(g);
	EXPECT_EQ(nb_cells<Edge>(g), 2u);
	// cut_edge without indices keeps e's line on both its darts
	auto eid = add_attribute<int, Edge>(g, "eid");
	value<int>(g, eid, e) = 5;
	const Vertex m = cut_edge(g, e, false);
	index_cells<Vertex>(g);
	index_cells<Edge>(g);
	expect_valid(g);
	EXPECT_EQ(value<int>(g, eid, e), 5);
	EXPECT_EQ(degree(g, m), 2u);
}

TEST(Graph, MarkersAndGlobalTraversals)
{
	Graph g;
	const std::vector<Vertex> v = add_vertices(g, 6);
	for (uint32 i = 0; i + 1 < 6; ++i)
		connect_vertices(g, v[i], v[i + 1]);
	add_vertex(g); // isolated
	for (bool indexed : {false, true})
	{
		if (indexed)
		{
			index_cells<Vertex>(g);
			index_cells<Edge>(g);
		}
		CellMarker<Graph, Vertex> marked(g);
		uint32 nv = 0, ne = 0;
		foreach_cell(g, [&](Vertex x) {
			EXPECT_FALSE(marked.is_marked(x));
			marked.mark(x);
			++nv;
		});
		foreach_cell(g, [&](Edge) { ++ne; });
		EXPECT_EQ(nv, 7u);
		EXPECT_EQ(ne, 5u);
		std::atomic<uint32> pv = 0, pe = 0;
		parallel_foreach_cell(g, [&](Vertex) { ++pv; });
		parallel_foreach_cell(g, [&](Edge) { ++pe; });
		EXPECT_EQ(pv.load(), 7u);
		EXPECT_EQ(pe.load(), 5u);
		uint32 ends = 0;
		foreach_incident_vertex(g, Edge(v[0].dart), [&](Vertex) { ++ends; });
		EXPECT_EQ(ends, 2u);
	}
	expect_valid(g);
}

TEST(Graph, BrokenRelationsAreReported)
{
	Graph g;
	const std::vector<Vertex> v = add_vertices(g, 3);
	connect_vertices(g, v[0], v[1]);
	connect_vertices(g, v[0], v[2]);
	expect_valid(g);
	// an isolated dart spliced into a vertex with edges
	const Dart x = add_vertex(g).dart;
	detail::set_relation(g, 1, x, alpha1(g, v[0].dart));
	detail::set_relation(g, 3, alpha1(g, v[0].dart), x);
	detail::set_relation(g, 1, v[0].dart, x);
	detail::set_relation(g, 3, x, v[0].dart);
	const IntegrityReport r = check_integrity(g);
	EXPECT_TRUE(r.has(IntegrityError::Kind::EdgelessDartNotAlone)) << r.to_string();
	// alpha_1 out of step with alpha1
	Graph h;
	const std::vector<Vertex> w = add_vertices(h, 3);
	connect_vertices(h, w[0], w[1]);
	connect_vertices(h, w[0], w[2]);
	detail::set_relation(h, 3, w[0].dart, w[0].dart);
	EXPECT_TRUE(check_integrity(h).has(IntegrityError::Kind::InverseRelationWrong));
}

TEST(Graph, SkeletonOfMapsCarriesVertexAndEdgeAttributes)
{
	CMap2 m;
	build_surface(m, torus_soup(6, 4));
	auto id = add_attribute<double, CMap2::Vertex>(m, "id");
	auto sum = add_attribute<double, CMap2::Edge>(m, "sum");
	double next = 1.0;
	foreach_cell(m, [&](CMap2::Vertex v) { value<double>(m, id, v) = (next *= 1.5); });
	foreach_cell(m, [&](CMap2::Edge e) {
		value<double>(m, sum, e) =
			value<double>(m, id, CMap2::Vertex(e.dart)) + value<double>(m, id, CMap2::Vertex(phi2(m, e.dart)));
	});
	const Graph g = to_graph(m);
	expect_valid(g);
	EXPECT_EQ(nb_cells<Vertex>(g), nb_cells<CMap2::Vertex>(m));
	EXPECT_EQ(nb_cells<Edge>(g), nb_cells<CMap2::Edge>(m));
	EXPECT_EQ(nb_connected_components(g), 1u);
	EXPECT_EQ(cycle_rank(g), nb_cells<CMap2::Edge>(m) - nb_cells<CMap2::Vertex>(m) + 1);
	auto gid = get_attribute<double, Vertex>(g, "id");
	auto gsum = get_attribute<double, Edge>(g, "sum");
	ASSERT_TRUE(gid && gsum);
	// each edge's value is the sum of its ends' values: the attributes came
	// to the right vertices and edges
	foreach_cell(g, [&](Edge e) {
		EXPECT_EQ(value<double>(g, gsum, e),
				  value<double>(g, gid, Vertex(e.dart)) + value<double>(g, gid, Vertex(alpha0(g, e.dart))));
	});
	std::multiset<uint32> map_degrees, graph_degrees;
	foreach_cell(m, [&](CMap2::Vertex v) { map_degrees.insert(degree(m, v)); });
	foreach_cell(g, [&](Vertex v) { graph_degrees.insert(degree(g, v)); });
	EXPECT_EQ(map_degrees, graph_degrees);

	GMap2 gm;
	build_surface(gm, grid_soup(3, 2)); // 4 x 3 vertices, 9 + 8 edges
	const Graph gg = to_graph(gm);
	expect_valid(gg);
	EXPECT_EQ(nb_cells<Vertex>(gg), 12u);
	EXPECT_EQ(nb_cells<Edge>(gg), 17u);
	CMap3 v;
	build_volume(v, tet_grid_soup(2, 2, 2));
	const Graph gv = to_graph(v);
	expect_valid(gv);
	EXPECT_EQ(nb_cells<Vertex>(gv), nb_cells<CMap3::Vertex>(v));
	EXPECT_EQ(nb_cells<Edge>(gv), nb_cells<CMap3::Edge>(v));
}

// ---- randomized editing against a plain adjacency-list model

struct Model
{
	std::map<int, int> vertices;              // id -> number of edge ends (degree)
	std::map<int, std::pair<int, int>> edges; // id -> its two vertex ids
	uint32 components() const
	{
		std::map<int, int> parent;
		for (const auto& [id, d] : vertices)
			parent[id] = id;
		auto find = [&](int x) {
			while (parent[x] != x)
				x = parent[x] = parent[parent[x]];
			return x;
		};
		uint32 n = uint32(vertices.size());
		for (const auto& [id, e] : edges)
		{
			const int a = find(e.first), b = find(e.second);
			if (a != b)
			{
				parent[a] = b;
				--n;
			}
		}
		return n;
	}
	void add_edge(int id, int a, int b)
	{
		edges[id] = {a, b};
		++vertices[a];
		++vertices[b];
	}
	void remove_edge(int id)
	{
		--vertices[edges[id].first];
		--vertices[edges[id].second];
		edges.erase(id);
	}
};

TEST(Graph, ThousandRandomOperationsAgreeWithAnAdjacencyList)
{
	std::mt19937 rng(20261129);
	Graph g;
	auto vid = add_attribute<int, Vertex>(g, "vid");
	auto eid = add_attribute<int, Edge>(g, "eid");
	Model model;
	int next_id = 0;
	auto pick = [&](auto cell) {
		using CELL = decltype(cell);
		std::vector<CELL> cells;
		foreach_cell(g, [&](CELL c) { cells.push_back(c); });
		return cells.empty() ? CELL() : cells[std::uniform_int_distribution<std::size_t>(0, cells.size() - 1)(rng)];
	};
	auto new_vertex = [&] {
		const Vertex v = add_vertex(g);
		value<int>(g, vid, v) = next_id;
		model.vertices[next_id++] = 0;
		return v;
	};
	for (int i = 0; i < 5; ++i)
		new_vertex();
	for (int step = 0; step < 1000; ++step)
	{
		const int op = std::uniform_int_distribution<int>(0, 9)(rng);
		const Vertex v1 = pick(Vertex()), v2 = pick(Vertex());
		const Edge e = pick(Edge());
		if (op == 0 || !v1.is_valid())
			new_vertex();
		else if (op == 1 && model.vertices.size() > 3)
		{
			const int id = value<int>(g, vid, v1);
			std::vector<int> gone;
			for (const auto& [k, ends] : model.edges)
				if (ends.first == id || ends.second == id)
					gone.push_back(k);
			for (int k : gone)
				model.remove_edge(k);
			model.vertices.erase(id);
			remove_vertex(g, v1);
		}
		else if (op <= 4)
		{
			const Edge n = connect_vertices(g, v1, v2);
			value<int>(g, eid, n) = next_id;
			model.add_edge(next_id++, value<int>(g, vid, v1), value<int>(g, vid, v2));
		}
		else if (op == 5 && e.is_valid())
		{
			model.remove_edge(value<int>(g, eid, e));
			disconnect_vertices(g, e);
		}
		else if (op == 6 && can_merge_vertices(g, v1, v2))
		{
			const int keep = value<int>(g, vid, v1), gone = value<int>(g, vid, v2);
			for (auto& [k, ends] : model.edges)
			{
				ends.first = ends.first == gone ? keep : ends.first;
				ends.second = ends.second == gone ? keep : ends.second;
			}
			model.vertices[keep] += model.vertices[gone];
			model.vertices.erase(gone);
			merge_vertices(g, v1, v2);
		}
		else if (op == 7 && e.is_valid())
		{
			const int id = value<int>(g, eid, e);
			const int a = value<int>(g, vid, Vertex(e.dart));
			const int b = value<int>(g, vid, Vertex(alpha0(g, e.dart)));
			const Vertex m = cut_edge(g, e);
			value<int>(g, vid, m) = next_id;
			model.vertices[next_id] = 0;
			model.remove_edge(id);
			model.add_edge(id, a, next_id);
			// the new edge is the one at m that is not e
			Edge other;
			foreach_incident_edge(g, m, [&](Edge x) {
				if (!same_cell(g, x, e))
					other = x;
			});
			value<int>(g, eid, other) = next_id + 1;
			model.add_edge(next_id + 1, next_id, b);
			next_id += 2;
		}
		else if (op >= 8 && e.is_valid() && can_collapse_edge(g, e))
		{
			const int id = value<int>(g, eid, e);
			const int keep = value<int>(g, vid, Vertex(e.dart));
			const int gone = value<int>(g, vid, Vertex(alpha0(g, e.dart)));
			model.remove_edge(id);
			for (auto& [k, ends] : model.edges)
			{
				ends.first = ends.first == gone ? keep : ends.first;
				ends.second = ends.second == gone ? keep : ends.second;
			}
			model.vertices[keep] += model.vertices[gone];
			model.vertices.erase(gone);
			const Vertex kept = collapse_edge(g, e);
			ASSERT_EQ(value<int>(g, vid, kept), keep);
		}
		const IntegrityReport r = check_integrity(g);
		ASSERT_TRUE(r.ok()) << "step " << step << ", operation " << op << ":\n" << r.to_string();
		ASSERT_EQ(nb_cells<Vertex>(g), model.vertices.size()) << "step " << step;
		ASSERT_EQ(nb_cells<Edge>(g), model.edges.size()) << "step " << step;
		ASSERT_EQ(nb_connected_components(g), model.components()) << "step " << step;
		ASSERT_EQ(cycle_rank(g), model.edges.size() + model.components() - model.vertices.size());
		std::map<int, int> degrees;
		foreach_cell(g, [&](Vertex v) { degrees[value<int>(g, vid, v)] = int(degree(g, v)); });
		ASSERT_EQ(degrees, model.vertices) << "step " << step;
		std::map<int, std::pair<int, int>> ends;
		foreach_cell(g, [&](Edge x) {
			const int a = value<int>(g, vid, Vertex(x.dart)), b = value<int>(g, vid, Vertex(alpha0(g, x.dart)));
			ends[value<int>(g, eid, x)] = {std::min(a, b), std::max(a, b)};
		});
		for (auto& [k, ab] : model.edges)
			ab = {std::min(ab.first, ab.second), std::max(ab.first, ab.second)};
		ASSERT_EQ(ends, model.edges) << "step " << step;
		uint32 branch_edges = 0;
		for (const GraphBranch& b : branches(g))
			branch_edges += b.nb_edges;
		ASSERT_EQ(branch_edges, model.edges.size()) << "step " << step;
	}
}

TEST(Graph, RandomOperationsWithoutIndices)
{
	// the same operators on a graph with no attribute: the counts from the
	// traversals against counts from the darts alone
	std::mt19937 rng(7);
	Graph g;
	for (int i = 0; i < 4; ++i)
		add_vertex(g);
	for (int step = 0; step < 500; ++step)
	{
		std::vector<Vertex> vs;
		std::vector<Edge> es;
		foreach_cell(g, [&](Vertex v) { vs.push_back(v); });
		foreach_cell(g, [&](Edge e) { es.push_back(e); });
		auto any = [&](const auto& cells) {
			return cells[std::uniform_int_distribution<std::size_t>(0, cells.size() - 1)(rng)];
		};
		const int op = std::uniform_int_distribution<int>(0, 6)(rng);
		if (op == 0 || vs.size() < 2)
			add_vertex(g);
		else if (op == 1 && vs.size() > 3)
			remove_vertex(g, any(vs));
		else if (op <= 3)
			connect_vertices(g, any(vs), any(vs));
		else if (op == 4 && !es.empty())
			cut_edge(g, any(es));
		else if (op == 5 && !es.empty())
		{
			const Edge e = any(es);
			if (can_collapse_edge(g, e))
				collapse_edge(g, e);
		}
		else if (op == 6)
		{
			const Vertex a = any(vs), b = any(vs);
			if (can_merge_vertices(g, a, b))
				merge_vertices(g, a, b);
		}
		ASSERT_TRUE(check_integrity(g).ok()) << "step " << step;
		uint32 darts = 0, edgeless = 0;
		foreach_dart(g, [&](Dart d) {
			++darts;
			edgeless += is_isolated(g, d);
		});
		ASSERT_EQ(nb_cells<Edge>(g), (darts - edgeless) / 2);
		uint32 sum_of_degrees = 0;
		foreach_cell(g, [&](Vertex v) { sum_of_degrees += degree(g, v); });
		ASSERT_EQ(sum_of_degrees, 2 * nb_cells<Edge>(g));
	}
	index_cells<Vertex>(g);
	index_cells<Edge>(g);
	expect_valid(g);
}

} // namespace cgogn_test_graph
