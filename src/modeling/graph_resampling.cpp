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
	auto out_pos = vertex_attribute_of<Vec3>(out, "position");
	std::shared_ptr<AttributeArray<double>> out_radius;
	if (radius)
		out_radius = vertex_attribute_of<double>(out, "radius");

	auto p = [&](Dart d) { return pos[index_of(g, Graph::Vertex(d))]; };
	auto r = [&](Dart d) { return radius ? (*radius)[index_of(g, Graph::Vertex(d))] : 0.0; };
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
	for (const GraphBranch& b : branches(g))
	{
		// the branch as a polyline: its vertices' darts and cumulated lengths
		std::vector<Dart> at{b.first};
		std::vector<double> length{0.0};
		Dart x = b.first;
		for (uint32 i = 0; i < b.nb_edges; ++i)
		{
			const Dart y = alpha0(g, x);
			at.push_back(y);
			length.push_back(length.back() + (p(y) - p(x)).norm());
			x = alpha1(g, y);
		}
		const double total = length.back();
		const uint32 k = uint32(std::max(1.0, std::round(total / spacing)));
		Graph::Vertex previous = kept_vertex(b.first);
		std::size_t seg = 0;
		for (uint32 j = 1; j < k; ++j)
		{
			const double t = total * double(j) / double(k);
			while (seg + 2 < length.size() && length[seg + 1] < t)
				++seg;
			const double span = length[seg + 1] - length[seg];
			const double u = span > 0.0 ? std::clamp((t - length[seg]) / span, 0.0, 1.0) : 0.0;
			const Dart a = at[seg], c = at[seg + 1];
			const Graph::Vertex v = new_vertex((1.0 - u) * p(a) + u * p(c), (1.0 - u) * r(a) + u * r(c));
			connect_vertices(out, previous, v);
			previous = v;
		}
		connect_vertices(out, previous, kept_vertex(b.last));
	}
	return out_pos;
}

} // namespace cgogn::modeling
