// SPDX-License-Identifier: MIT
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/operators/graph.h>
#include <cgogn/core/utils/error.h>

#include "index_lines.h"

#include <cassert>
#include <vector>

namespace cgogn
{

namespace
{

// The relations' slots in the map's state (see Graph): alpha1 is the key
// (relation 1), alpha0 relation 2, alpha_1 relation 3.
constexpr uint32 ALPHA1 = 1, ALPHA0 = 2, ALPHA_1 = 3;

using Vertex = Graph::Vertex;
using Edge = Graph::Edge;

void link_alpha0(Graph& g, Dart a, Dart b)
{
	detail::set_relation(g, ALPHA0, a, b);
	detail::set_relation(g, ALPHA0, b, a);
}

// alpha1(a) = b, and alpha_1(b) = a
void link_alpha1(Graph& g, Dart a, Dart b)
{
	detail::set_relation(g, ALPHA1, a, b);
	detail::set_relation(g, ALPHA_1, b, a);
}

// Puts x, alone in its alpha1 cycle, after d around d's vertex.
void insert_after(Graph& g, Dart d, Dart x)
{
	const Dart next = alpha1(g, d);
	link_alpha1(g, d, x);
	link_alpha1(g, x, next);
}

// Takes x out of its alpha1 cycle (x is then alone in its own).
void unlink(Graph& g, Dart x)
{
	link_alpha1(g, alpha_1(g, x), alpha1(g, x));
	link_alpha1(g, x, x);
}

// Joins the alpha1 cycles of d and e (two different cycles) into one: e's
// cycle comes after d.
void splice(Graph& g, Dart d, Dart e)
{
	const Dart d_next = alpha1(g, d);
	const Dart e_prev = alpha_1(g, e);
	link_alpha1(g, d, e);
	link_alpha1(g, e_prev, d_next);
}

// A new dart after `after` around its vertex, on the vertex's line.
Dart add_half_edge(Graph& g, Dart after, bool set_indices)
{
	const Dart x = detail::add_dart(g);
	insert_after(g, after, x);
	if (set_indices)
		detail::copy_dart_index<Orbit::ALPHA1>(g, x, after);
	return x;
}

// A half-edge for a new edge at the vertex of d: d itself when the vertex is
// isolated (d has no edge yet), otherwise a new dart after d.
Dart half_edge_for_new_edge(Graph& g, Dart d, bool set_indices)
{
	return is_isolated(g, d) ? d : add_half_edge(g, d, set_indices);
}

// Removes half-edge x, whose edge is already undone (alpha0(x) == x), from
// its vertex; when x is the vertex's last dart it stays, as the isolated
// vertex.
void drop_half_edge(Graph& g, Dart x)
{
	if (alpha1(g, x) == x)
		return;
	detail::set_representative<Orbit::ALPHA1>(g, alpha1(g, x));
	unlink(g, x);
	detail::remove_dart(g, x);
}

} // namespace

Graph::Vertex add_vertex(Graph& g, bool set_indices)
{
	const Dart d = detail::add_dart(g);
	if (set_indices)
		detail::index_new_cell(g, Vertex(d));
	return Vertex(d);
}

void remove_vertex(Graph& g, Graph::Vertex v, bool set_indices)
{
	std::vector<Dart> darts;
	foreach_dart_of_orbit(g, v, [&](Dart d) { darts.push_back(d); });
	// undo the edges; the vertex keeps one dart, isolated
	for (Dart d : darts)
		if (is_dart_valid(g, d) && !is_isolated(g, d))
			disconnect_vertices(g, Edge(d), set_indices);
	for (Dart d : darts)
		if (is_dart_valid(g, d))
		{
			if (set_indices)
				detail::release_index<Orbit::ALPHA1>(g, detail::index_or_invalid<Orbit::ALPHA1>(g, d));
			detail::remove_dart(g, d);
			return;
		}
}

Graph::Edge connect_vertices(Graph& g, Graph::Vertex v1, Graph::Vertex v2, bool set_indices)
{
	const bool loop = same_cell(g, v1, v2);
	const Dart a = half_edge_for_new_edge(g, v1.dart, set_indices);
	// a self-loop's second half-edge comes right after its first
	const Dart b = loop ? add_half_edge(g, a, set_indices) : half_edge_for_new_edge(g, v2.dart, set_indices);
	link_alpha0(g, a, b);
	if (set_indices)
		detail::index_new_cell(g, Edge(a));
	return Edge(a);
}

void disconnect_vertices(Graph& g, Graph::Edge e, bool set_indices)
{
	const Dart a = e.dart;
	const Dart b = alpha0(g, a);
	assert(a != b && "disconnect_vertices: not an edge");
	if (set_indices)
		detail::release_index<Orbit::ALPHA0>(g, detail::index_or_invalid<Orbit::ALPHA0>(g, a));
	// a dart that stays as an isolated vertex has no edge, so no edge line
	detail::set_dart_index<Orbit::ALPHA0>(g, a, INVALID_INDEX);
	detail::set_dart_index<Orbit::ALPHA0>(g, b, INVALID_INDEX);
	link_alpha0(g, a, a);
	link_alpha0(g, b, b);
	drop_half_edge(g, a);
	drop_half_edge(g, b);
}

bool can_merge_vertices(const Graph& g, Graph::Vertex v1, Graph::Vertex v2)
{
	return !same_cell(g, v1, v2);
}

Graph::Vertex merge_vertices(Graph& g, Graph::Vertex v1, Graph::Vertex v2, bool set_indices)
{
	if (!can_merge_vertices(g, v1, v2))
		return v1; // a vertex merged with itself: nothing to do
	const Dart d1 = v1.dart, d2 = v2.dart;
	const uint32 line1 = detail::index_or_invalid<Orbit::ALPHA1>(g, d1);
	const uint32 line2 = detail::index_or_invalid<Orbit::ALPHA1>(g, d2);
	// an isolated vertex brings no half-edge: its dart goes
	Dart kept = d1;
	if (is_isolated(g, d2))
		detail::remove_dart(g, d2);
	else if (is_isolated(g, d1))
	{
		detail::remove_dart(g, d1);
		kept = d2;
	}
	else
		splice(g, d1, d2);
	if (set_indices)
		detail::merge_cell_indices(g, Vertex(kept), line1, line2);
	return Vertex(kept);
}

Graph::Vertex cut_edge(Graph& g, Graph::Edge e, bool set_indices)
{
	const Dart a = e.dart;
	const Dart b = alpha0(g, a);
	assert(a != b && "cut_edge: not an edge");
	const Dart x = detail::add_dart(g);
	const Dart y = detail::add_dart(g);
	link_alpha1(g, x, y);
	link_alpha1(g, y, x);
	link_alpha0(g, a, x);
	link_alpha0(g, y, b);
	// {a, x} keeps the edge line (a represents it), {y, b} is a new edge
	detail::set_representative<Orbit::ALPHA0>(g, a);
	detail::copy_dart_index<Orbit::ALPHA0>(g, x, a);
	detail::set_dart_index<Orbit::ALPHA0>(g, b, INVALID_INDEX);
	if (set_indices)
	{
		detail::index_new_cell(g, Edge(y));
		detail::index_new_cell(g, Vertex(x));
	}
	return Vertex(x);
}

bool can_collapse_edge(const Graph& g, Graph::Edge e)
{
	const Dart a = e.dart;
	const Dart b = alpha0(g, a);
	return a != b && !same_cell(g, Vertex(a), Vertex(b));
}

Graph::Vertex collapse_edge(Graph& g, Graph::Edge e, bool set_indices)
{
	if (!can_collapse_edge(g, e))
		throw TopologyError("collapse_edge: a self-loop cannot be collapsed (its two ends are one vertex)");
	const Dart a = e.dart;
	const Dart b = alpha0(g, a);
	const Dart next_a = alpha1(g, a), next_b = alpha1(g, b);
	const uint32 line1 = detail::index_or_invalid<Orbit::ALPHA1>(g, a);
	const uint32 line2 = detail::index_or_invalid<Orbit::ALPHA1>(g, b);
	if (set_indices)
		detail::release_index<Orbit::ALPHA0>(g, detail::index_or_invalid<Orbit::ALPHA0>(g, a));
	// a and b leave their vertices, and what remains of the two is one vertex;
	// of a lone edge, a stays as an isolated vertex
	Dart kept = a;
	if (next_a == a && next_b == b)
	{
		detail::set_dart_index<Orbit::ALPHA0>(g, a, INVALID_INDEX);
		link_alpha0(g, a, a);
	}
	else
	{
		if (next_a != a)
			unlink(g, a);
		if (next_b != b)
			unlink(g, b);
		if (next_a != a && next_b != b)
			splice(g, next_a, next_b);
		kept = next_a != a ? next_a : next_b;
		detail::remove_dart(g, a);
	}
	detail::remove_dart(g, b);
	if (set_indices)
		detail::merge_cell_indices(g, Vertex(kept), line1, line2);
	return Vertex(kept);
}

} // namespace cgogn
