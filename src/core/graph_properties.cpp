// SPDX-License-Identifier: MIT
#include <cgogn/core/map/orbits.h>
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
	std::vector<uint8> seen(detail::state_of(g).darts->end_index(), 0);
	std::vector<Dart> work;
	uint32 n = 0;
	foreach_dart(g, [&](Dart d) {
		if (seen[d.index])
			return;
		++n;
		seen[d.index] = 1;
		work.assign(1, d);
		while (!work.empty())
		{
			const Dart x = work.back();
			work.pop_back();
			for (const Dart y : {alpha0(g, x), alpha1(g, x)})
				if (!seen[y.index])
				{
					seen[y.index] = 1;
					work.push_back(y);
				}
		}
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
	std::vector<uint8> done(detail::state_of(g).darts->end_index(), 0);
	// from x, a half-edge leaving the branch's first vertex, along the branch
	// until a vertex of degree other than 2, or back to x (a closed branch)
	auto walk = [&](Dart start) {
		GraphBranch b;
		b.first = start;
		Dart x = start;
		while (true)
		{
			const Dart y = alpha0(g, x);
			done[x.index] = done[y.index] = 1;
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
		if (!done[d.index] && !is_isolated(g, d) && !at_degree_two(g, d))
			walk(d);
	});
	// what is left are the components whose vertices all have degree 2
	foreach_dart(g, [&](Dart d) {
		if (!done[d.index] && !is_isolated(g, d))
			walk(d);
	});
	return result;
}

} // namespace cgogn
