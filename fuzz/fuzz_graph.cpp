// SPDX-License-Identifier: MIT
// The libFuzzer target of the graph readers: the input's first byte chooses
// the format (.cg, .cgr, .skel, .obj, .vtk, .vtu) and the index base, the rest is the file. Any
// input must either throw io::Error or give a graph that passes
// check_integrity with the counts read, whether loaded into an empty graph or
// appended to one. Loading into a graph whose `position` has another type
// must throw and leave it as it was. Crashes, leaks and sanitizer reports are
// bugs.
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/operators/graph.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/io/error.h>

#include "graph_data.h"

#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

using namespace cgogn;

namespace
{

void require(bool ok)
{
	if (!ok)
		std::abort();
}

void check_load(Graph& g, const io::detail::GraphData& d)
{
	const uint32 vertices = nb_cells<Graph::Vertex>(g), edges = nb_cells<Graph::Edge>(g);
	const io::GraphLoadReport r = io::detail::build_graph(g, d, "fuzz");
	require(check_integrity(g).ok());
	require(nb_cells<Graph::Vertex>(g) == vertices + r.nb_vertices_read);
	require(nb_cells<Graph::Edge>(g) == edges + r.nb_edges_read);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
	if (size == 0)
		return 0;
	const auto format = io::detail::GraphFormat(data[0] % 6);
	const uint32 base = (data[0] / 6) % 2;
	const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
	io::detail::GraphData d;
	try
	{
		d = io::detail::read_graph(text, "fuzz", format, base);
	}
	catch (const io::Error&)
	{
		return 0;
	}
	for (const auto& [a, b] : d.edges)
		require(a < d.positions.size() && b < d.positions.size());
	{
		Graph g;
		check_load(g, d);
	}
	{
		// appended to a graph with an isolated vertex and a self-loop
		Graph g;
		add_attribute<Vec3, Graph::Vertex>(g, "position");
		add_attribute<int, Graph::Edge>(g, "tag");
		add_vertex(g);
		const Graph::Vertex v = add_vertex(g);
		connect_vertices(g, v, v);
		check_load(g, d);
	}
	{
		Graph g;
		add_attribute<double, Graph::Vertex>(g, "position");
		add_vertex(g);
		bool thrown = false;
		try
		{
			io::detail::build_graph(g, d, "fuzz");
		}
		catch (const io::Error&)
		{
			thrown = true;
		}
		require(thrown && nb_darts(g) == 1 && check_integrity(g).ok());
	}
	return 0;
}
