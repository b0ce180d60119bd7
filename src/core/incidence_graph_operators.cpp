// SPDX-License-Identifier: MIT
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/operators/incidence_graph.h>
#include <cgogn/core/utils/error.h>

#include "incidence_graph_records.h"
#include "index_lines.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace cgogn
{

namespace
{

using Vertex = IncidenceGraph::Vertex;
using Edge = IncidenceGraph::Edge;
using Face = IncidenceGraph::Face;
constexpr Orbit FACE = Orbit::PHI1;

bool is_live_vertex(const IncidenceGraph& ig, Vertex v)
{
	return is_valid(ig, v);
}

// Removes the face of use u: its uses leave their edges' rings and are
// freed, and its line is released.
void drop_face(IncidenceGraph& ig, const detail::IgRecords& r, Dart u)
{
	detail::release_index<FACE>(ig, detail::index_or_invalid<FACE>(ig, u));
	Dart it = u;
	do
	{
		const Dart next = r.next_in_face(it);
		r.radial_remove(it);
		detail::remove_dart(ig, it);
		it = next;
	} while (it != u);
}

// Releases edge e, whose ends are already out of their rings and which has
// no use.
void drop_edge_record(const detail::IgRecords& r, uint32 e)
{
	r.edges().release_line(e);
}

// Builds the face of k sides, side_of(i) giving the edge end of side i
// (consecutive in this order; it may add the edge, so that a caller finds or
// makes its sides without a buffer), and indexes it when faces are indexed.
// Returns its first use.
template <typename SIDE_OF>
Dart build_face_of(IncidenceGraph& ig, const detail::IgRecords& r, std::size_t k, const SIDE_OF& side_of)
{
	Dart first, prev;
	for (std::size_t i = 0; i < k; ++i)
	{
		const Dart u = r.new_use(side_of(i));
		if (first.is_valid())
			r.set_next_in_face(prev, u);
		else
			first = u;
		prev = u;
	}
	r.set_next_in_face(prev, first);
	detail::index_new_cell(ig, Face(first));
	return first;
}

// The same for sides given in a list.
Dart build_face(IncidenceGraph& ig, const detail::IgRecords& r, std::span<const uint32> sides)
{
	return build_face_of(ig, r, sides.size(), [&](std::size_t i) { return sides[i]; });
}

// The sides (edge ends) of a face bounded by `edges` in any order, ordered
// into its cycle, starting with edges[0] from its first vertex; empty when
// they are not one simple cycle of at least 3 distinct live edges.
std::vector<uint32> cycle_sides(const IncidenceGraph& ig, const detail::IgRecords& r, std::span<const Edge> edges)
{
	const std::size_t k = edges.size();
	std::vector<uint32> sides;
	if (k < 3)
		return sides;
	// every vertex is the end of exactly two edges
	std::vector<uint32> ends;
	ends.reserve(2 * k);
	for (std::size_t i = 0; i < k; ++i)
	{
		if (!is_valid(ig, edges[i]))
			return sides;
		for (std::size_t j = 0; j < i; ++j)
			if (edges[j] == edges[i])
				return sides;
		ends.push_back(r.end_vertex(2 * edges[i].dart.index));
		ends.push_back(r.end_vertex(2 * edges[i].dart.index + 1));
	}
	std::sort(ends.begin(), ends.end());
	for (std::size_t i = 0; i < ends.size(); i += 2)
		if (ends[i] != ends[i + 1] || (i + 2 < ends.size() && ends[i + 2] == ends[i]))
			return sides;
	// walk the cycle from edges[0], toward the vertex it shares with edges[1]
	// when it shares one (edges given in cycle order keep their order)
	std::vector<bool> used(k, false);
	used[0] = true;
	const uint32 e0 = edges[0].dart.index, e1 = edges[1].dart.index;
	const uint32 backward =
		r.end_vertex(2 * e0) == r.end_vertex(2 * e1) || r.end_vertex(2 * e0) == r.end_vertex(2 * e1 + 1) ? 1u : 0u;
	const uint32 start = r.end_vertex(2 * e0 + backward);
	uint32 at = r.end_vertex(2 * e0 + 1 - backward);
	sides.push_back(2 * e0 + backward);
	for (std::size_t step = 1; step < k; ++step)
	{
		std::size_t j = 0;
		while (j < k && (used[j] || (r.end_vertex(2 * edges[j].dart.index) != at &&
									 r.end_vertex(2 * edges[j].dart.index + 1) != at)))
			++j;
		if (j == k)
			return {}; // two cycles: not connected
		used[j] = true;
		const uint32 e = edges[j].dart.index;
		const uint32 side = r.end_vertex(2 * e) == at ? 0u : 1u;
		sides.push_back(2 * e + side);
		at = r.end_vertex(2 * e + 1 - side);
	}
	if (at != start)
		return {};
	return sides;
}

// The use of face f that starts at vertex v; invalid when v is not in f.
Dart use_from(const detail::IgRecords& r, Face f, uint32 v)
{
	Dart it = f.dart;
	do
	{
		if (r.origin(it) == v)
			return it;
		it = r.next_in_face(it);
	} while (it != f.dart);
	return Dart();
}

} // namespace

Dart detail::ig_build_face(IncidenceGraph& ig, std::span<const uint32> sides)
{
	return build_face(ig, detail::IgRecords(ig), sides);
}

Vertex add_vertex(IncidenceGraph& ig)
{
	return Vertex(Dart(detail::IgRecords(ig).vertices().new_line(detail::NO_EDGE_END)));
}

bool can_add_edge(const IncidenceGraph& ig, Vertex v0, Vertex v1)
{
	return is_live_vertex(ig, v0) && is_live_vertex(ig, v1) && v0 != v1;
}

Edge add_edge(IncidenceGraph& ig, Vertex v0, Vertex v1)
{
	if (!can_add_edge(ig, v0, v1))
		throw TopologyError("add_edge: an edge joins two different live vertices");
	const detail::IgRecords r(ig);
	const uint32 e = r.edges().new_line(v0.dart.index);
	r.set_end_vertex(2 * e + 1, v1.dart.index);
	r.ring_insert(v0.dart.index, 2 * e);
	r.ring_insert(v1.dart.index, 2 * e + 1);
	return Edge(Dart(e));
}

Edge find_edge(const IncidenceGraph& ig, Vertex v0, Vertex v1)
{
	const detail::IgRecords r(ig);
	Edge found;
	r.foreach_end(v0.dart.index, [&](uint32 end) {
		if (r.end_vertex(end ^ 1u) != v1.dart.index)
			return true;
		found = Edge(Dart(end >> 1));
		return false;
	});
	return found;
}

bool can_add_face(const IncidenceGraph& ig, std::span<const Edge> edges)
{
	return !cycle_sides(ig, detail::IgRecords(ig), edges).empty();
}

Face add_face(IncidenceGraph& ig, std::span<const Edge> edges)
{
	const detail::IgRecords r(ig);
	const std::vector<uint32> sides = cycle_sides(ig, r, edges);
	if (sides.empty())
		throw TopologyError("add_face: the edges are not one simple cycle of at least 3 distinct edges");
	return Face(build_face(ig, r, sides));
}

Face add_face_through_vertices(IncidenceGraph& ig, std::span<const Vertex> vertices)
{
	const std::size_t k = vertices.size();
	if (k < 3)
		throw TopologyError("add_face_through_vertices: a face has at least 3 vertices");
	for (std::size_t i = 0; i < k; ++i)
		if (!is_live_vertex(ig, vertices[i]))
			throw TopologyError("add_face_through_vertices: vertex " + std::to_string(i) + " is not live");
	// a repeated vertex: pairwise for the usual small faces, sorted for large ones
	bool repeated = false;
	if (k <= 32)
	{
		for (std::size_t i = 1; i < k && !repeated; ++i)
			for (std::size_t j = 0; j < i && !repeated; ++j)
				repeated = vertices[j] == vertices[i];
	}
	else
	{
		std::vector<uint32> sorted(k);
		for (std::size_t i = 0; i < k; ++i)
			sorted[i] = vertices[i].dart.index;
		std::sort(sorted.begin(), sorted.end());
		repeated = std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
	}
	if (repeated)
		throw TopologyError("add_face_through_vertices: a vertex repeats");
	// the sides, found or added as they come (no buffer)
	const detail::IgRecords r(ig);
	return Face(build_face_of(ig, r, k, [&](std::size_t i) {
		const Vertex a = vertices[i], b = vertices[(i + 1) % k];
		Edge e = find_edge(ig, a, b);
		if (!e.is_valid())
			e = add_edge(ig, a, b);
		return 2 * e.dart.index + (r.end_vertex(2 * e.dart.index) == a.dart.index ? 0u : 1u);
	}));
}

void remove_face(IncidenceGraph& ig, Face f)
{
	drop_face(ig, detail::IgRecords(ig), f.dart);
}

void remove_edge(IncidenceGraph& ig, Edge e)
{
	const detail::IgRecords r(ig);
	const uint32 x = e.dart.index;
	while (r.first_use(x) != INVALID_INDEX)
		drop_face(ig, r, Dart(r.first_use(x)));
	r.ring_remove(r.end_vertex(2 * x), 2 * x);
	r.ring_remove(r.end_vertex(2 * x + 1), 2 * x + 1);
	drop_edge_record(r, x);
}

void remove_vertex(IncidenceGraph& ig, Vertex v)
{
	const detail::IgRecords r(ig);
	while (r.first_end(v.dart.index) != detail::NO_EDGE_END)
		remove_edge(ig, Edge(Dart(r.first_end(v.dart.index) >> 1)));
	r.vertices().release_line(v.dart.index);
}

Vertex cut_edge(IncidenceGraph& ig, Edge e)
{
	const detail::IgRecords r(ig);
	const uint32 x = e.dart.index;
	const uint32 b = r.end_vertex(2 * x + 1);
	const uint32 w = add_vertex(ig).dart.index;
	// the new edge y = (w, b) takes e's place in b's ring
	const uint32 y = r.edges().new_line(w);
	r.set_end_vertex(2 * y + 1, b);
	const uint32 p = r.ring_previous(2 * x + 1);
	if (p == 2 * x + 1)
		r.set_next_end(2 * y + 1, 2 * y + 1);
	else
	{
		r.set_next_end(2 * y + 1, r.next_end(2 * x + 1));
		r.set_next_end(p, 2 * y + 1);
	}
	if (r.first_end(b) == 2 * x + 1)
		r.set_first_end(b, 2 * y + 1);
	// e now ends at w, whose ring holds e's end and y's start
	r.set_end_vertex(2 * x + 1, w);
	r.ring_insert(w, 2 * x + 1);
	r.ring_insert(w, 2 * y);
	// each face on e gets y beside it: a side a -> b becomes a -> w -> b, a
	// side b -> a becomes b -> w -> a
	std::vector<Dart> uses;
	r.foreach_use(x, [&](Dart u) { uses.push_back(u); });
	for (Dart u : uses)
		r.radial_remove(u);
	for (Dart u : uses)
	{
		const bool forward = (r.use_edge_end(u) & 1u) == 0;
		if (!forward)
			r.set_use_edge_end(u, 2 * y + 1); // b -> w
		r.radial_insert(u);
		const Dart n = r.new_use(forward ? 2 * y : 2 * x + 1); // w -> b, or w -> a
		r.set_next_in_face(n, r.next_in_face(u));
		r.set_next_in_face(u, n);
		detail::copy_dart_index<FACE>(ig, n, u);
	}
	return Vertex(Dart(w));
}

bool can_cut_face(const IncidenceGraph& ig, Face f, Vertex v0, Vertex v1)
{
	const detail::IgRecords r(ig);
	if (v0 == v1)
		return false;
	const Dart a = use_from(r, f, v0.dart.index);
	const Dart b = use_from(r, f, v1.dart.index);
	return a.is_valid() && b.is_valid() && r.target(a) != v1.dart.index && r.target(b) != v0.dart.index;
}

Edge cut_face(IncidenceGraph& ig, Face f, Vertex v0, Vertex v1)
{
	if (!can_cut_face(ig, f, v0, v1))
		throw TopologyError("cut_face: the vertices are not two non-consecutive vertices of the face");
	const detail::IgRecords r(ig);
	const Dart a = use_from(r, f, v0.dart.index);
	const Dart b = use_from(r, f, v1.dart.index);
	const Dart pa = r.previous_in_face(a);
	const Dart pb = r.previous_in_face(b);
	Edge e = find_edge(ig, v0, v1);
	if (!e.is_valid())
		e = add_edge(ig, v0, v1);
	const uint32 forward = 2 * e.dart.index + (r.end_vertex(2 * e.dart.index) == v0.dart.index ? 0u : 1u);
	// the part from a: a ... pb, then v1 -> v0; the part from b: b ... pa, then v0 -> v1
	const Dart x = r.new_use(forward ^ 1u);
	const Dart y = r.new_use(forward);
	r.set_next_in_face(pb, x);
	r.set_next_in_face(x, a);
	r.set_next_in_face(pa, y);
	r.set_next_in_face(y, b);
	if (is_indexed<Face>(ig))
	{
		detail::copy_dart_index<FACE>(ig, x, a);
		detail::set_representative<FACE>(ig, a);
		detail::new_index(ig, Face(b));
	}
	return e;
}

Face face_to_cut(const IncidenceGraph& ig, Vertex v0, Vertex v1)
{
	if (v0 == v1 || !is_live_vertex(ig, v0) || !is_live_vertex(ig, v1))
		return Face();
	const detail::IgRecords r(ig);
	Face found;
	uint32 n = 0;
	// each face around v0 once: by its side that leaves v0
	r.foreach_end(v0.dart.index, [&](uint32 end) {
		return r.foreach_use(end >> 1, [&](Dart u) {
			if (r.origin(u) == v0.dart.index && can_cut_face(ig, Face(u), v0, v1))
			{
				found = Face(u);
				++n;
			}
			return n < 2;
		});
	});
	return n == 1 ? found : Face();
}

bool can_cut_face(const IncidenceGraph& ig, Vertex v0, Vertex v1)
{
	return face_to_cut(ig, v0, v1).is_valid();
}

Edge cut_face(IncidenceGraph& ig, Vertex v0, Vertex v1)
{
	const Face f = face_to_cut(ig, v0, v1);
	if (!f.is_valid())
		throw TopologyError("cut_face: no single face has v0 and v1 as non-consecutive vertices");
	return cut_face(ig, f, v0, v1);
}

bool can_collapse_edge(const IncidenceGraph& ig, Edge e)
{
	const detail::IgRecords r(ig);
	const uint32 x = e.dart.index;
	const uint32 a = r.end_vertex(2 * x), b = r.end_vertex(2 * x + 1);
	// another edge between a and b must have no face
	bool ok = r.foreach_end(a, [&](uint32 end) {
		const uint32 y = end >> 1;
		return y == x || r.end_vertex(end ^ 1u) != b || r.first_use(y) == INVALID_INDEX;
	});
	// a face at a that holds b holds e
	ok = ok && r.foreach_end(a, [&](uint32 end) {
		return r.foreach_use(end >> 1, [&](Dart u) {
			if (r.origin(u) != a)
				return true;
			bool has_b = false, has_e = false;
			Dart it = u;
			do
			{
				has_b = has_b || r.origin(it) == b;
				has_e = has_e || (r.use_edge_end(it) >> 1) == x;
				it = r.next_in_face(it);
			} while (it != u);
			return !has_b || has_e;
		});
	});
	return ok;
}

Vertex collapse_edge(IncidenceGraph& ig, Edge e)
{
	if (!can_collapse_edge(ig, e))
		throw TopologyError("collapse_edge: a face or an edge with faces would be pinched (see can_collapse_edge)");
	const detail::IgRecords r(ig);
	const uint32 x = e.dart.index;
	const uint32 a = r.end_vertex(2 * x), b = r.end_vertex(2 * x + 1);
	// 1. the faces on e lose their side along it
	std::vector<Dart> shrunk; // a remaining use of each face that lost a side
	std::vector<Dart> uses;
	r.foreach_use(x, [&](Dart u) { uses.push_back(u); });
	for (Dart u : uses)
	{
		const Dart p = r.previous_in_face(u);
		const Dart n = r.next_in_face(u);
		r.set_next_in_face(p, n);
		detail::set_representative<FACE>(ig, n);
		r.radial_remove(u);
		detail::remove_dart(ig, u);
		shrunk.push_back(n);
	}
	// 2. e leaves the rings, b's ring joins a's, b goes
	r.ring_remove(a, 2 * x);
	r.ring_remove(b, 2 * x + 1);
	drop_edge_record(r, x);
	r.foreach_end(b, [&](uint32 end) { r.set_end_vertex(end, a); });
	const uint32 fa = r.first_end(a), fb = r.first_end(b);
	if (fa == detail::NO_EDGE_END)
		r.set_first_end(a, fb);
	else if (fb != detail::NO_EDGE_END)
	{
		const uint32 na = r.next_end(fa);
		r.set_next_end(fa, r.next_end(fb));
		r.set_next_end(fb, na);
	}
	r.vertices().release_line(b);
	// 3. faces left with 2 sides go (a triangle on e)
	for (Dart n : shrunk)
		if (r.next_in_face(r.next_in_face(n)) == n)
			drop_face(ig, r, n);
	// 4. edges joining the same two vertices merge; an edge that joined a and b
	// (faceless: see can_collapse_edge) is now a loop and goes
	std::vector<std::pair<uint32, uint32>> around; // (other vertex, edge end at a)
	r.foreach_end(a, [&](uint32 end) { around.emplace_back(r.end_vertex(end ^ 1u), end); });
	for (const auto& [other, end] : around)
		if (other == a && (end & 1u) == 0)
		{
			const uint32 y = end >> 1;
			r.ring_remove(a, 2 * y);
			r.ring_remove(a, 2 * y + 1);
			drop_edge_record(r, y);
		}
	std::erase_if(around, [&](const auto& p) { return p.first == a; });
	std::stable_sort(around.begin(), around.end(), [](const auto& p, const auto& q) { return p.first < q.first; });
	for (std::size_t i = 1; i < around.size(); ++i)
	{
		if (around[i].first != around[i - 1].first)
			continue;
		// merge edge y into the kept edge k (the first of its run)
		std::size_t k = i - 1;
		while (k > 0 && around[k - 1].first == around[i].first)
			--k;
		const uint32 kept = around[k].second >> 1;
		const uint32 y = around[i].second >> 1;
		const uint32 kept_first = r.end_vertex(2 * kept);
		std::vector<Dart> moved;
		r.foreach_use(y, [&](Dart u) { moved.push_back(u); });
		for (Dart u : moved)
		{
			const uint32 from = r.origin(u);
			r.radial_remove(u);
			r.set_use_edge_end(u, 2 * kept + (from == kept_first ? 0u : 1u));
			r.radial_insert(u);
		}
		r.ring_remove(r.end_vertex(2 * y), 2 * y);
		r.ring_remove(r.end_vertex(2 * y + 1), 2 * y + 1);
		drop_edge_record(r, y);
	}
	return Vertex(Dart(a));
}

} // namespace cgogn
