// SPDX-License-Identifier: MIT
// The graph class: construction from arrays, files, counts, positions and
// radii as arrays, edges as an array of vertex ids, the operators and the
// queries. Vertex and edge ids are the lines of the two indexed orbits.
#include <cgogn/io.h>

#include "py_map.h"

#include <memory>
#include <pybind11/stl.h>
#include <string>
#include <vector>

namespace cgogn::python
{

namespace
{

using Vertex = Graph::Vertex;
using Edge = Graph::Edge;

/// A graph as Python sees it: vertices and edges always indexed (their ids
/// are their lines), the `position` vertex attribute, and the arrays that
/// alias attributes.
struct PyGraph
{
	Graph g;
	std::shared_ptr<AttributeArray<Vec3>> pos;
	std::vector<py::object> views; // weakrefs (see attribute_array)

	PyGraph()
	{
		attach();
	}
	// after a load: index the edges, take the position attribute
	void attach()
	{
		index_cells<Edge>(g);
		pos = get_attribute<Vec3, Vertex>(g, "position");
		if (!pos)
			pos = add_attribute<Vec3, Vertex>(g, "position");
	}
	template <typename CELL>
	CELL cell(uint32 id) const
	{
		const AttributeContainer& c = container_of<CELL::ORBIT>(g);
		if (id >= c.end_index() || !c.is_live(id))
			throw py::index_error(std::string("no ") + (CELL::ORBIT == Orbit::ALPHA1 ? "vertex" : "edge") + " of id " +
								  std::to_string(id));
		return CELL(Dart(c.key()[id]));
	}
	Vertex vertex(uint32 id) const
	{
		return cell<Vertex>(id);
	}
	Edge edge(uint32 id) const
	{
		return cell<Edge>(id);
	}
	uint32 id(Vertex v) const
	{
		return index_of(g, v);
	}
	uint32 id(Edge e) const
	{
		return index_of(g, e);
	}
};

template <typename CELL>
py::array ids_of(const PyGraph& w)
{
	std::vector<uint32> out;
	foreach_cell(w.g, [&](CELL c) { out.push_back(index_of(w.g, c)); });
	return to_numpy(std::move(out));
}

} // namespace

py::object wrap_graph(Graph&& g)
{
	auto w = std::make_unique<PyGraph>();
	w->g = std::move(g);
	w->attach();
	return py::cast(std::move(w));
}

void bind_graph(py::module_& m)
{
	using W = PyGraph;
	py::class_<W>(m, "Graph",
				  "A graph: vertices and edges, any number of edges per vertex, self-loops and repeated edges "
				  "allowed (skeletons, curve networks). Vertices and edges are named by integer ids: after "
				  "from_arrays or load, 0..n-1 in the file's order; operators keep the ids of what they keep.")
		.def(py::init<>(), "An empty graph.")
		.def_static(
			"from_arrays",
			[](const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
			   const py::array_t<int64, py::array::c_style | py::array::forcecast>& edges) {
				if (points.ndim() != 2 || points.shape(1) != 3)
					throw py::value_error("points must be an (n, 3) array");
				if (edges.ndim() != 2 || edges.shape(1) != 2)
					throw py::value_error("edges must be an (m, 2) array of vertex indices");
				const auto p = points.unchecked<2>();
				const auto e = edges.unchecked<2>();
				const py::ssize_t n = p.shape(0);
				for (py::ssize_t i = 0; i < e.shape(0); ++i)
					for (py::ssize_t k = 0; k < 2; ++k)
						if (e(i, k) < 0 || e(i, k) >= n)
							throw py::value_error("edge " + std::to_string(i) + " refers to point " +
												  std::to_string(e(i, k)) + ", but there are " + std::to_string(n) +
												  " points");
				auto w = std::make_unique<W>();
				std::vector<Vertex> v;
				for (py::ssize_t i = 0; i < n; ++i)
				{
					v.push_back(add_vertex(w->g));
					value<Vec3>(w->g, w->pos, v.back()) = Vec3(p(i, 0), p(i, 1), p(i, 2));
				}
				for (py::ssize_t i = 0; i < e.shape(0); ++i)
					connect_vertices(w->g, v[std::size_t(e(i, 0))], v[std::size_t(e(i, 1))]);
				return w;
			},
			py::arg("points"), py::arg("edges"),
			"A graph of n vertices at the rows of `points` and an edge per row of `edges` (vertex indices; "
			"a row (i, i) is a self-loop). Vertex and edge ids are the row numbers. O(n + m).")
		.def_static(
			"load",
			[](const std::string& path, uint32 index_base) {
				auto w = std::make_unique<W>();
				io::GraphLoadOptions options;
				options.index_base = index_base;
				io::load_graph(w->g, path, options);
				w->attach();
				return w;
			},
			py::arg("path"), py::arg("index_base") = 0,
			"Loads a .cg, .cgr (radii in the attribute 'radius'), .skel, .obj (v and l lines) or .vtk/.vtu (line "
			"and polyline cells) file; index_base=1 "
			"for the .cg files "
			"of CGoGN 2. Raises cgogn.IOError naming the file, line and problem on bad input.")
		.def(
			"save",
			[](const W& w, const std::string& path) {
				if (has_map_file_extension(path))
					io::save_map(w.g, path);
				else
					io::save_graph(w.g, path);
			},
			py::arg("path"),
			"Writes a .cg, .obj, .vtk or .vtu file, a .cgr file (needs the vertex attribute 'radius'), or a .cgmap "
			"file (the whole graph, every attribute: cgogn.load reads it back).")
		.def(
			"to_bytes", [](const W& w) { return py::bytes(io::save_map_to_bytes(w.g)); },
			"The graph as the bytes of a .cgmap file (see CMap2.to_bytes).")
		.def("__reduce__", [](const W& w) { return map_file_reduce(io::save_map_to_bytes(w.g)); })
		.def_property_readonly(
			"nb_vertices", [](const W& w) { return nb_cells<Vertex>(w.g); }, "Number of vertices.")
		.def_property_readonly(
			"nb_edges", [](const W& w) { return nb_cells<Edge>(w.g); }, "Number of edges.")
		.def_property_readonly(
			"positions",
			[](W& w) { return attribute_array(w.pos, container_of<Orbit::ALPHA1>(w.g).end_index(), w.views); },
			"The vertex positions, an (id_bound, 3) float64 array aliasing the graph's memory (row = vertex id).")
		.def(
			"radii",
			[](W& w) -> py::object {
				std::shared_ptr<AttributeArray<double>> r = get_attribute<double, Vertex>(w.g, "radius");
				if (!r)
					return py::none();
				return attribute_array(r, container_of<Orbit::ALPHA1>(w.g).end_index(), w.views);
			},
			"The vertex radii (row = vertex id), or None without a 'radius' attribute.")
		.def(
			"set_radii",
			[](W& w, const py::array_t<double, py::array::c_style | py::array::forcecast>& r) {
				const uint32 rows = container_of<Orbit::ALPHA1>(w.g).end_index();
				if (r.ndim() != 1 || r.shape(0) != py::ssize_t(rows))
					throw py::value_error("radii must be a 1-D array of id_bound = " + std::to_string(rows) +
										  " values");
				auto a = get_attribute<double, Vertex>(w.g, "radius");
				if (!a)
					a = add_attribute<double, Vertex>(w.g, "radius");
				for (uint32 i = 0; i < rows; ++i)
					(*a)[i] = r.at(i);
			},
			py::arg("radii"), "Sets (creating it if needed) the vertex attribute 'radius', one value per vertex id.")
		.def(
			"vertex_ids", [](const W& w) { return ids_of<Vertex>(w); }, "The ids of the live vertices, in id order.")
		.def(
			"edge_ids", [](const W& w) { return ids_of<Edge>(w); }, "The ids of the live edges, in id order.")
		.def(
			"edges",
			[](const W& w) {
				std::vector<uint32> out;
				foreach_cell(w.g, [&](Edge e) {
					out.push_back(w.id(Vertex(e.dart)));
					out.push_back(w.id(Vertex(alpha0(w.g, e.dart))));
				});
				py::array_t<uint32> a = to_numpy(std::move(out));
				return a.reshape({py::ssize_t(a.size() / 2), py::ssize_t(2)});
			},
			"The live edges in id order, an (E, 2) array of their vertex ids (the first at the edge's dart).")
		.def(
			"degree", [](const W& w, uint32 v) { return degree(w.g, w.vertex(v)); }, py::arg("vertex"),
			"Number of edges at the vertex, a self-loop counting twice. O(degree).")
		.def(
			"add_vertex",
			[](W& w, const py::object& position) {
				const Vertex v = add_vertex(w.g);
				if (!position.is_none())
				{
					const auto p = position.cast<std::vector<double>>();
					if (p.size() != 3)
						throw py::value_error("a position has 3 coordinates");
					value<Vec3>(w.g, w.pos, v) = Vec3(p[0], p[1], p[2]);
				}
				return w.id(v);
			},
			py::arg("position") = py::none(), "A new isolated vertex; returns its id. O(1).")
		.def(
			"connect", [](W& w, uint32 a, uint32 b) { return w.id(connect_vertices(w.g, w.vertex(a), w.vertex(b))); },
			py::arg("v1"), py::arg("v2"), "A new edge from v1 to v2 (a self-loop when equal); returns its id. O(1).")
		.def(
			"disconnect", [](W& w, uint32 e) { disconnect_vertices(w.g, w.edge(e)); }, py::arg("edge"),
			"Removes the edge; its ends stay. O(1).")
		.def(
			"remove_vertex", [](W& w, uint32 v) { remove_vertex(w.g, w.vertex(v)); }, py::arg("vertex"),
			"Removes the vertex and its edges. O(degree).")
		.def(
			"merge_vertices",
			[](W& w, uint32 a, uint32 b) {
				if (!can_merge_vertices(w.g, w.vertex(a), w.vertex(b)))
					throw py::value_error("merge_vertices: the vertices are the same");
				return w.id(merge_vertices(w.g, w.vertex(a), w.vertex(b)));
			},
			py::arg("v1"), py::arg("v2"), "Merges v2 into v1, which keeps its id; returns it.")
		.def(
			"cut_edge", [](W& w, uint32 e) { return w.id(cut_edge(w.g, w.edge(e))); }, py::arg("edge"),
			"Splits the edge by a new vertex of degree 2; returns its id (the new edge part gets a new id). O(1).")
		.def(
			"collapse_edge",
			[](W& w, uint32 e) {
				if (!can_collapse_edge(w.g, w.edge(e)))
					throw py::value_error("collapse_edge: a self-loop cannot be collapsed");
				return w.id(collapse_edge(w.g, w.edge(e)));
			},
			py::arg("edge"),
			"Removes the edge and merges its ends into its first vertex (see edges()); returns that vertex's id.")
		.def(
			"nb_connected_components", [](const W& w) { return nb_connected_components(w.g); },
			"Number of connected components, an isolated vertex being one.")
		.def(
			"cycle_rank", [](const W& w) { return cycle_rank(w.g); }, "E - V + C: the number of independent cycles.")
		.def(
			"branches",
			[](const W& w) {
				py::list out;
				for (const GraphBranch& b : branches(w.g))
				{
					std::vector<uint32> vertices{w.id(Vertex(b.first))};
					Dart x = b.first;
					for (uint32 i = 0; i < b.nb_edges; ++i)
					{
						const Dart y = alpha0(w.g, x);
						vertices.push_back(w.id(Vertex(y)));
						x = alpha1(w.g, y);
					}
					py::dict d;
					d["vertices"] = vertices;
					d["closed"] = b.closed;
					out.append(d);
				}
				return out;
			},
			"The maximal chains through vertices of degree 2, each as {'vertices': [ids, from end to end], "
			"'closed': bool} (a closed branch repeats its first vertex at the end).")
		.def(
			"check_integrity", [](const W& w) { return integrity_report(check_integrity(w.g)); },
			"Checks every invariant; returns {'ok': bool, 'nb_errors': int, 'messages': [str]}.")
		.def("__repr__", [](const W& w) {
			return "<cgogn.Graph vertices=" + std::to_string(nb_cells<Vertex>(w.g)) +
				   " edges=" + std::to_string(nb_cells<Edge>(w.g)) + ">";
		});
}

} // namespace cgogn::python
