// SPDX-License-Identifier: MIT
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/marking/dart_marker.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/traversals/global.h>

#include <vector>

namespace cgogn
{

namespace
{

// Whether half-edge d (of an edge) is at a vertex of degree 2: its vertex
// holds exactly d and one other dart (which then has an edge too).
bool at_degree_two(const Graph& g, Dart d)
{
	const Dart next = alpha1(g, d);
	return next != d && alpha1(g, next) == d;
}

} // namespace

uint32 degree(const Graph& g, Graph::Vertex v)
{
	if (is_isolated(g, v.dart))
		return 0;
	return nb_darts_of_orbit(g, v);
}

uint32 nb_connected_components(const Graph& g)
{
	// each component flooded through alpha0 and alpha1 from its first dart
	uint32 n = 0;
	DartMarker seen(g);
	foreach_dart(g, [&](Dart d) {
		if (seen.is_marked(d))
			return;
		++n;
		detail::foreach_dart_flood(
			g, d, [&](Dart x) { seen.mark(x); }, [&](Dart x) { return alpha0(g, x); },
			[&](Dart x) { return alpha1(g, x); });
	});
	return n;
}

uint32 cycle_rank(const Graph& g)
{
	return nb_cells<Graph::Edge>(g) + nb_connected_components(g) - nb_cells<Graph::Vertex>(g);
}

std::vector<GraphBranch> branches(const Graph& g)
{
	std::vector<GraphBranch> result;
	DartMarker done(g);
	// from x, a half-edge leaving the branch's first vertex, along the branch
	// until a vertex of degree other than 2, or back to x (a closed branch)
	auto walk = [&](Dart start) {
		GraphBranch b;
		b.first = start;
		Dart x = start;
		while (true)
		{
			const Dart y = alpha0(g, x);
			done.mark(x);
			done.mark(y);
			++b.nb_edges;
			if (!at_degree_two(g, y))
			{
				b.last = y;
				break;
			}
			x = alpha1(g, y);
			if (x == start)
			{
				b.last = y;
				b.closed = true;
				break;
			}
		}
		result.push_back(b);
	};
	foreach_dart(g, [&](Dart d) {
		if (!done.is_marked(d) && !is_isolated(g, d) && !at_degree_two(g, d))
			walk(d);
	});
	// what is left are the components whose vertices all have degree 2
	foreach_dart(g, [&](Dart d) {
		if (!done.is_marked(d) && !is_isolated(g, d))
			walk(d);
	});
	return result;
}

} // namespace cgogn
