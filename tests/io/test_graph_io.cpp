#include <cgogn/cgogn.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>
#include <vector>

namespace cgogn_test_graph_io
{

using namespace cgogn;
using cgogn::io_test::read_text;
using cgogn::io_test::TempDir;
using cgogn::io_test::write_text;
using Vertex = Graph::Vertex;
using Edge = Graph::Edge;

// A random graph with positions and radii: a tree, extra edges, self-loops,
// a repeated edge and isolated vertices.
Graph random_graph(uint32 n, uint32 seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> coord(-1e3, 1e3);
	Graph g;
	auto position = add_attribute<Vec3, Vertex>(g, "position");
	auto radius = add_attribute<double, Vertex>(g, "radius");
	std::vector<Vertex> v;
	for (uint32 i = 0; i < n; ++i)
	{
		v.push_back(add_vertex(g));
		value<Vec3>(g, position, v.back()) = Vec3(coord(rng), coord(rng), coord(rng)) / 3.0;
		value<double>(g, radius, v.back()) = std::abs(coord(rng)) / 7.0;
	}
	for (uint32 i = 1; i + 3 < n; ++i)
		connect_vertices(g, v[i], v[std::uniform_int_distribution<uint32>(0, i - 1)(rng)]);
	connect_vertices(g, v[1], v[1]);
	connect_vertices(g, v[2], v[3]);
	connect_vertices(g, v[2], v[3]);
	return g;
}

// Vertices in line order with their position and radius, and edges as
// pairs of those numbers: what a file holds.
struct Content
{
	std::vector<Vec3> positions;
	std::vector<double> radii;
	std::multiset<std::pair<uint32, uint32>> edges;
};

Content content_of(const Graph& g)
{
	Content c;
	auto position = get_attribute<Vec3, Vertex>(g, "position");
	auto radius = get_attribute<double, Vertex>(g, "radius");
	std::map<uint32, uint32> number;
	foreach_cell(g, [&](Vertex v) {
		number[index_of(g, v)] = uint32(c.positions.size());
		c.positions.push_back(value<Vec3>(g, position, v));
		if (radius)
			c.radii.push_back(value<double>(g, radius, v));
	});
	foreach_cell(g, [&](Edge e) {
		const uint32 a = number[index_of(g, Vertex(e.dart))], b = number[index_of(g, Vertex(alpha0(g, e.dart)))];
		c.edges.insert({std::min(a, b), std::max(a, b)});
	});
	return c;
}

TEST(GraphFiles, CgrRoundTripIsExact)
{
	TempDir dir;
	const Graph g = random_graph(200, 5);
	const std::string path = dir.file("tree.cgr");
	io::save_graph(g, path);
	Graph h;
	const io::GraphLoadReport r = io::load_graph(h, path);
	EXPECT_TRUE(check_integrity(h).ok());
	EXPECT_EQ(r.nb_vertices_read, 200u);
	EXPECT_EQ(r.nb_edges_read, nb_cells<Edge>(g));
	EXPECT_TRUE(r.radius);
	const Content a = content_of(g), b = content_of(h);
	EXPECT_EQ(a.positions, b.positions); // bit for bit
	EXPECT_EQ(a.radii, b.radii);
	EXPECT_EQ(a.edges, b.edges);
	EXPECT_EQ(nb_connected_components(h), nb_connected_components(g));
	EXPECT_EQ(cycle_rank(h), cycle_rank(g));
	// saving what was loaded writes the same file
	io::save_graph(h, dir.file("again.cgr"));
	EXPECT_EQ(read_text(path), read_text(dir.file("again.cgr")));
}

TEST(GraphFiles, CgKeepsIsolatedVerticesAndAppends)
{
	TempDir dir;
	const std::string path = dir.file("g.cg");
	write_text(path,
			   "# D:3 NV:4 NE:2\nv 0 0 0\nv 1 0 0\nv 2 0 0 extra tokens\n# a comment\nv 3 0 0\ne 0 1 # first\ne 1 1\n");
	Graph g;
	const io::GraphLoadReport r = io::load_graph(g, path);
	EXPECT_FALSE(r.radius);
	EXPECT_EQ(nb_cells<Vertex>(g), 4u);
	EXPECT_EQ(nb_cells<Edge>(g), 2u);
	EXPECT_EQ(cycle_rank(g), 1u); // the self-loop
	EXPECT_EQ(nb_connected_components(g), 3u);
	io::load_graph(g, path); // appended
	EXPECT_EQ(nb_cells<Vertex>(g), 8u);
	EXPECT_EQ(nb_connected_components(g), 6u);
	EXPECT_TRUE(check_integrity(g).ok());
	EXPECT_THROW(io::save_graph(g, dir.file("g.cgr")), io::Error); // no radius
}

TEST(GraphFiles, OneBasedFilesOfOlderTools)
{
	TempDir dir;
	const std::string path = dir.file("old.cg");
	write_text(path, "# D:2 NV:3 NE:2\nv 0 0\nv 1 0\nv 1 1\ne 1 2\ne 2 3\n");
	Graph g;
	EXPECT_THROW(io::load_graph(g, path), io::Error); // 3 is out of range from 0
	EXPECT_EQ(nb_darts(g), 0u);
	io::load_graph(g, path, {.index_base = 1});
	EXPECT_EQ(nb_cells<Edge>(g), 2u);
	EXPECT_EQ(branches(g).size(), 1u);
}

TEST(GraphFiles, SkelListsAreSymmetrised)
{
	TempDir dir;
	const std::string path = dir.file("s.skel");
	// 0-1 listed by both ends, 1-2 by vertex 2 only, 3 isolated
	write_text(path, "ID Cx Cy Cz RADIUS #NEIGHBORS NEIGHBORS_LIST\n4\n"
					 "0 0 0 0 0.5 1 1\n"
					 "2 2 0 0 0.25 1 1\n"
					 "1 1 0 0 0.75 1 0\n"
					 "3 5 5 5 1 0\n");
	Graph g;
	const io::GraphLoadReport r = io::load_graph(g, path);
	EXPECT_TRUE(r.radius);
	EXPECT_EQ(r.nb_vertices_read, 4u);
	EXPECT_EQ(r.nb_edges_read, 2u);
	EXPECT_EQ(r.nb_one_sided_edges, 1u);
	EXPECT_EQ(nb_connected_components(g), 2u);
	const Content c = content_of(g);
	EXPECT_EQ(c.radii, (std::vector<double>{0.5, 0.75, 0.25, 1.0}));
	EXPECT_EQ(c.positions[2], Vec3(2, 0, 0));
}

TEST(GraphFiles, ObjPolylines)
{
	TempDir dir;
	const std::string path = dir.file("lines.obj");
	// a triangle as one closed polyline, a tail by relative indices, a face
	write_text(path, "# lines\nv 0 0 0\nv 1 0 0\nv 1 1 0\nl 1 2 3 1\nv 2 2 0 1.0\nl -1 -2\nvt 0 0\nf 1 2 3\no x\n");
	Graph g;
	const io::GraphLoadReport r = io::load_graph(g, path);
	EXPECT_EQ(r.nb_vertices_read, 4u);
	EXPECT_EQ(r.nb_edges_read, 4u);
	EXPECT_EQ(r.nb_faces_ignored, 1u);
	EXPECT_EQ(cycle_rank(g), 1u);
	EXPECT_EQ(nb_connected_components(g), 1u);
	// written one `l` per edge, and read back the same
	io::save_graph(g, dir.file("out.obj"));
	Graph h;
	io::load_graph(h, dir.file("out.obj"));
	const Content a = content_of(g), b = content_of(h);
	EXPECT_EQ(a.positions, b.positions);
	EXPECT_EQ(a.edges, b.edges);
	io::save_graph(h, dir.file("again.obj"));
	EXPECT_EQ(read_text(dir.file("out.obj")), read_text(dir.file("again.obj")));
	for (const auto& [text, cause] :
		 std::vector<std::pair<std::string, std::string>>{{"v 0 0 0\nl 1\n", "at least 2"},
														  {"v 0 0 0\nv 1 0 0\nl 0 1\n", "out of range"},
														  {"v 0 0 0\nl 1 -2\n", "out of range"},
														  {"v 0 0 0\nv 1 0 0\nl 1 3\n", "out of range"},
														  {"v 0 0 0\ncurv 1 2\n", "unknown OBJ statement"},
														  {"v 0 nan 0\n", "not finite"}})
	{
		write_text(dir.file("bad.obj"), text);
		Graph x;
		try
		{
			io::load_graph(x, dir.file("bad.obj"));
			ADD_FAILURE() << text;
		}
		catch (const io::Error& e)
		{
			EXPECT_NE(std::string(e.what()).find(cause), std::string::npos) << e.what();
			EXPECT_EQ(e.where(), io::Error::Where::Line);
		}
		EXPECT_EQ(nb_darts(x), 0u);
	}
}

TEST(GraphFiles, VtkAndVtuPolylinesRoundTripExactly)
{
	TempDir dir;
	const Graph g = random_graph(150, 11);
	for (const char* ext : {".vtk", ".vtu"})
	{
		SCOPED_TRACE(ext);
		const std::string path = dir.file(std::string("tree") + ext);
		io::save_graph(g, path);
		Graph h;
		const io::GraphLoadReport r = io::load_graph(h, path);
		EXPECT_TRUE(check_integrity(h).ok());
		EXPECT_EQ(r.nb_vertices_read, 150u);
		EXPECT_EQ(r.nb_edges_read, nb_cells<Edge>(g));
		EXPECT_EQ(r.nb_cells_ignored, 0u);
		EXPECT_TRUE(r.radius);
		const Content a = content_of(g), b = content_of(h);
		EXPECT_EQ(a.positions, b.positions); // bit for bit
		EXPECT_EQ(a.radii, b.radii);
		EXPECT_EQ(a.edges, b.edges);
		EXPECT_EQ(cycle_rank(h), cycle_rank(g));
	}
}

TEST(GraphFiles, VtkPolylinesBesideOtherCells)
{
	TempDir dir;
	// a polyline of 3 points, a line, a tetrahedron (ignored, counted)
	write_text(dir.file("mixed.vtk"), "# vtk DataFile Version 3.0\nmixed\nASCII\nDATASET UNSTRUCTURED_GRID\n"
									  "POINTS 5 double\n0 0 0 1 0 0 2 0 0 0 1 0 0 0 1\n"
									  "CELLS 3 12\n3 0 1 2\n2 2 3\n4 0 1 3 4\nCELL_TYPES 3\n4\n3\n10\n");
	Graph g;
	const io::GraphLoadReport r = io::load_graph(g, dir.file("mixed.vtk"));
	EXPECT_EQ(r.nb_vertices_read, 5u);
	EXPECT_EQ(r.nb_edges_read, 3u);
	EXPECT_EQ(r.nb_cells_ignored, 1u);
	EXPECT_FALSE(r.radius);
	EXPECT_EQ(nb_connected_components(g), 2u); // the fifth point is alone
	// a line of one point, and a point index out of range
	for (const std::string& cells :
		 {std::string("CELLS 1 2\n1 0\nCELL_TYPES 1\n3\n"), std::string("CELLS 1 3\n2 0 9\nCELL_TYPES 1\n3\n")})
	{
		write_text(dir.file("bad.vtk"), "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET UNSTRUCTURED_GRID\n"
										"POINTS 2 double\n0 0 0 1 0 0\n" +
											cells);
		Graph x;
		EXPECT_THROW(io::load_graph(x, dir.file("bad.vtk")), io::Error);
		EXPECT_EQ(nb_darts(x), 0u);
	}
}

TEST(GraphFiles, MalformedFilesGiveTypedErrorsAndLeaveTheGraph)
{
	TempDir dir;
	struct Case
	{
		const char* name;
		const char* text;
		const char* cause; // a part of the message
		uint64 line;
	};
	const std::vector<Case> cases = {
		{"no_header.cg", "v 0 0 0\n", "header", 1},
		{"missing_key.cg", "# D:3 NV:1\nv 0 0 0\n", "D, NV and NE", 1},
		{"twice_key.cg", "# D:3 NV:1 NE:0 NV:2\nv 0 0 0\n", "given twice", 1},
		{"bad_dim.cg", "# D:4 NV:1 NE:0\nv 0 0 0 0\n", "dimension", 1},
		{"few_vertices.cg", "# D:3 NV:3 NE:1\nv 0.0 0.0 0.0\nv 1.0 0.0 0.0\ne 0 1\n", "expected vertex 2", 4},
		{"out_of_range.cg", "# D:3 NV:2 NE:1\nv 0 0 0\nv 1 0 0\ne 0 2\n", "out of range", 4},
		{"negative.cg", "# D:3 NV:2 NE:1\nv 0 0 0\nv 1 0 0\ne -1 0\n", "out of range", 4},
		{"nan.cg", "# D:3 NV:1 NE:0\nv 0 nan 0\n", "not finite", 2},
		{"extra.cg", "# D:3 NV:1 NE:0\nv 0 0 0\ne 0 0\n", "more lines", 3},
		{"three_ends.cg", "# D:3 NV:2 NE:1\nv 0 0 0\nv 1 0 0\ne 0 1 1\n", "after an edge", 4},
		{"huge.cg", "# D:3 NV:4000000000 NE:0\n", "bytes remain", 2},
		{"no_radius.cgr", "# D:3 NV:1 NE:0\nv 0 0 0\n", "radius", 2},
		{"skel_range.skel", "header\n2\n0 0 0 0 1 1 5\n1 0 0 0 1 0\n", "out of range", 3},
		{"skel_twice.skel", "header\n2\n0 0 0 0 1 0\n0 0 0 0 1 0\n", "twice", 4},
		{"skel_short.skel", "header\n2\n0 0.000 0.000 0.000 1.000 0\n", "end of file", 4},
	};
	for (const Case& c : cases)
	{
		const std::string path = dir.file(c.name);
		write_text(path, c.text);
		Graph g;
		add_vertex(g);
		try
		{
			io::load_graph(g, path);
			ADD_FAILURE() << c.name << ": no error";
		}
		catch (const io::Error& e)
		{
			EXPECT_NE(std::string(e.what()).find(c.cause), std::string::npos) << c.name << ": " << e.what();
			EXPECT_EQ(e.where(), io::Error::Where::Line) << c.name;
			EXPECT_EQ(e.position(), c.line) << c.name << ": " << e.what();
			EXPECT_EQ(e.path(), path);
		}
		EXPECT_EQ(nb_darts(g), 1u) << c.name;
		EXPECT_FALSE((get_attribute<Vec3, Vertex>(g, "position"))) << c.name;
	}
	Graph g;
	EXPECT_THROW(io::load_graph(g, dir.file("missing.cg")), io::Error);
	EXPECT_THROW(io::load_graph(g, dir.file("x.graph")), io::Error);
	EXPECT_THROW(io::save_graph(g, dir.file("x.off")), io::Error);
	add_attribute<double, Vertex>(g, "position");
	write_text(dir.file("ok.cg"), "# D:3 NV:1 NE:0\nv 0 0 0\n");
	EXPECT_THROW(io::load_graph(g, dir.file("ok.cg")), io::Error);
	EXPECT_THROW(io::save_graph(g, dir.file("out.cg")), io::Error);
	EXPECT_EQ(nb_darts(g), 0u);
	// a vertex without index (set_indices = false) is not silently left out
	Graph h;
	add_attribute<Vec3, Vertex>(h, "position");
	add_vertex(h);
	add_vertex(h, false);
	EXPECT_THROW(io::save_graph(h, dir.file("h.cg")), io::Error);
	index_cells<Vertex>(h);
	io::save_graph(h, dir.file("h.cg"));
	Graph back;
	EXPECT_EQ(io::load_graph(back, dir.file("h.cg")).nb_vertices_read, 2u);
}

} // namespace cgogn_test_graph_io
