// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/operators/graph.h>
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/modeling/graph_resampling.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cgogn::modeling
{

namespace
{

// A bound on the edges of one resampled branch: a spacing far below the
// branch's length is a mistake, not a request for billions of vertices.
constexpr uint32 MAX_EDGES_PER_BRANCH = 1u << 26;

// The vertex attribute `name` of out, created when missing (its type was
// checked before anything was added).
template <typename T>
std::shared_ptr<AttributeArray<T>> vertex_attribute_of(Graph& out, const std::string& name)
{
	if (auto existing = get_attribute<T, Graph::Vertex>(out, name))
		return existing;
	return add_attribute<T, Graph::Vertex>(out, name);
}

} // namespace

std::shared_ptr<AttributeArray<Vec3>> resample_graph(const Graph& g, const AttributeArray<Vec3>& pos, double spacing,
													 Graph& out)
{
	if (!(spacing > 0.0) || !std::isfinite(spacing))
		throw Error("resample_graph: the spacing must be a positive finite number, not " + std::to_string(spacing));
	const auto radius = get_attribute<double, Graph::Vertex>(g, "radius");
	for (const char* name : {"position", "radius"})
	{
		auto a = container_of<Orbit::ALPHA1>(out).find(name);
		const std::type_index expected = name[0] == 'p' ? typeid(Vec3) : typeid(double);
		if (a != nullptr && a->type() != expected)
			throw Error(std::string("resample_graph: the output graph has a vertex attribute '") + name +
						"' of another type");
	}
	auto p = [&](Dart d) { return pos[index_of(g, Graph::Vertex(d))]; };
	auto r = [&](Dart d) { return radius ? (*radius)[index_of(g, Graph::Vertex(d))] : 0.0; };
	// every branch as a polyline (its vertices' darts and cumulated lengths)
	// and its number of edges, all checked before anything is added
	struct Polyline
	{
		std::vector<Dart> at;
		std::vector<double> length;
		uint32 nb_edges = 1;
		Dart last;
	};
	std::vector<Polyline> polylines;
	for (const GraphBranch& b : branches(g))
	{
		Polyline pl;
		pl.at.push_back(b.first);
		pl.length.push_back(0.0);
		Dart x = b.first;
		for (uint32 i = 0; i < b.nb_edges; ++i)
		{
			const Dart y = alpha0(g, x);
			pl.at.push_back(y);
			pl.length.push_back(pl.length.back() + (p(y) - p(x)).norm());
			x = alpha1(g, y);
		}
		const double n = std::round(pl.length.back() / spacing);
		if (!(n <= double(MAX_EDGES_PER_BRANCH)))
			throw Error("resample_graph: a branch of length " + std::to_string(pl.length.back()) + " at spacing " +
						std::to_string(spacing) + " would need more than " + std::to_string(MAX_EDGES_PER_BRANCH) +
						" edges");
		pl.nb_edges = uint32(std::max(1.0, n));
		pl.last = b.last;
		polylines.push_back(std::move(pl));
	}
	auto out_pos = vertex_attribute_of<Vec3>(out, "position");
	std::shared_ptr<AttributeArray<double>> out_radius;
	if (radius)
		out_radius = vertex_attribute_of<double>(out, "radius");
	auto new_vertex = [&](const Vec3& x, double rad) {
		const Graph::Vertex v = add_vertex(out);
		(*out_pos)[index_of(out, v)] = x;
		if (out_radius)
			(*out_radius)[index_of(out, v)] = rad;
		return v;
	};
	// the kept vertices (ends of branches, isolated vertices), by line of g
	std::vector<Graph::Vertex> kept(container_of<Orbit::ALPHA1>(g).end_index());
	auto kept_vertex = [&](Dart d) {
		Graph::Vertex& v = kept[index_of(g, Graph::Vertex(d))];
		if (!v.is_valid())
			v = new_vertex(p(d), r(d));
		return v;
	};
	foreach_cell(g, [&](Graph::Vertex v) {
		if (degree(g, v) == 0)
			kept_vertex(v.dart);
	});
	for (const Polyline& pl : polylines)
	{
		const double total = pl.length.back();
		const uint32 k = pl.nb_edges;
		Graph::Vertex previous = kept_vertex(pl.at.front());
		std::size_t seg = 0;
		for (uint32 j = 1; j < k; ++j)
		{
			const double t = total * double(j) / double(k);
			while (seg + 2 < pl.length.size() && pl.length[seg + 1] < t)
				++seg;
			const double span = pl.length[seg + 1] - pl.length[seg];
			const double u = span > 0.0 ? std::clamp((t - pl.length[seg]) / span, 0.0, 1.0) : 0.0;
			const Dart a = pl.at[seg], c = pl.at[seg + 1];
			const Graph::Vertex v = new_vertex((1.0 - u) * p(a) + u * p(c), (1.0 - u) * r(a) + u * r(c));
			connect_vertices(out, previous, v);
			previous = v;
		}
		connect_vertices(out, previous, kept_vertex(pl.last));
	}
	return out_pos;
}

Graph resample_graph(const Graph& g, const AttributeArray<Vec3>& pos, double spacing)
{
	Graph out;
	resample_graph(g, pos, spacing, out);
	return out;
}

} // namespace cgogn::modeling
