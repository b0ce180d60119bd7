// SPDX-License-Identifier: MIT
// The incidence graph class: construction from arrays and files, counts,
// positions as an array, edges as an array of vertex ids, faces as CSR, the
// operators and the queries. Vertex, edge and face ids are lines (faces are
// indexed on creation).
#include <cgogn/io.h>

#include "py_map.h"

#include <functional>
#include <memory>
#include <pybind11/stl.h>
#include <string>
#include <vector>

namespace cgogn::python
{

namespace
{

using IG = IncidenceGraph;
using IgVertex = IG::Vertex;
using IgEdge = IG::Edge;
using IgFace = IG::Face;

/// An incidence graph as Python sees it: a PyMap (the `position` vertex
/// attribute, the arrays that alias attributes), with its faces indexed
/// (their ids are their lines).
using PyIncidenceGraph = PyMap<IG>;

template <typename CELL>
CELL ig_cell(const PyIncidenceGraph& w, uint32 id, const char* what)
{
	const AttributeContainer& c = container_of<CELL::ORBIT>(w.m);
	if (id >= c.end_index() || !c.is_live(id))
		throw py::index_error(std::string("no ") + what + " of id " + std::to_string(id));
	if constexpr (is_direct_orbit(CELL::ORBIT))
		return CELL(Dart(id));
	else
		return CELL(Dart(c.key()[id]));
}

void index_faces(PyIncidenceGraph& w)
{
	index_cells<IgFace>(w.m);
}

IgVertex ig_vertex(const PyIncidenceGraph& w, uint32 id)
{
	return ig_cell<IgVertex>(w, id, "vertex");
}
IgEdge ig_edge(const PyIncidenceGraph& w, uint32 id)
{
	return ig_cell<IgEdge>(w, id, "edge");
}
IgFace ig_face(const PyIncidenceGraph& w, uint32 id)
{
	return ig_cell<IgFace>(w, id, "face");
}

template <typename CELL>
py::array ig_ids_of(const PyIncidenceGraph& w)
{
	std::vector<uint32> out;
	foreach_cell(w.m, [&](CELL c) { out.push_back(index_of(w.m, c)); });
	return to_numpy(std::move(out));
}

/// Runs f, turning a refused operation (TopologyError) into ValueError, as
/// the other classes' operators do.
template <typename FUNC>
auto refusing(const FUNC& f)
{
	try
	{
		return f();
	}
	catch (const TopologyError& e)
	{
		throw py::value_error(e.what());
	}
}

template <typename T>
std::vector<T> cells_of_ids(const py::array_t<int64, py::array::c_style | py::array::forcecast>& ids,
							const std::function<T(uint32)>& cell)
{
	if (ids.ndim() != 1)
		throw py::value_error("expected a 1-D array of ids");
	std::vector<T> out;
	for (py::ssize_t i = 0; i < ids.shape(0); ++i)
	{
		if (ids.at(i) < 0)
			throw py::index_error("negative id");
		out.push_back(cell(uint32(ids.at(i))));
	}
	return out;
}

} // namespace

void bind_incidence_graph(py::module_& m)
{
	using W = PyIncidenceGraph;
	using Ids = py::array_t<int64, py::array::c_style | py::array::forcecast>;
	py::class_<W>(m, "IncidenceGraph",
				  "Vertices, edges and faces with no manifold constraint: any number of faces on an edge, edges "
				  "without face, vertices without edge. Cells are named by integer ids: after from_arrays or "
				  "load, 0..n-1 in the file's order; operators keep the ids of what they keep.")
		.def(py::init([] {
				 auto w = std::make_unique<W>();
				 index_faces(*w);
				 return w;
			 }),
			 "An empty incidence graph.")
		.def_static(
			"from_arrays",
			[](const py::array_t<double, py::array::c_style | py::array::forcecast>& points, const Ids& offsets,
			   const Ids& indices) {
				if (points.ndim() != 2 || points.shape(1) != 3)
					throw py::value_error("points must be an (n, 3) array");
				if (offsets.ndim() != 1 || indices.ndim() != 1 || offsets.shape(0) < 1 || offsets.at(0) != 0 ||
					offsets.at(offsets.shape(0) - 1) != indices.shape(0))
					throw py::value_error("faces as CSR: offsets[0] == 0, offsets[-1] == len(indices)");
				const auto p = points.unchecked<2>();
				const py::ssize_t n = p.shape(0);
				auto w = std::make_unique<W>();
				index_faces(*w);
				std::vector<IgVertex> v;
				for (py::ssize_t i = 0; i < n; ++i)
				{
					v.push_back(add_vertex(w->m));
					value<Vec3>(w->m, w->pos, v.back()) = Vec3(p(i, 0), p(i, 1), p(i, 2));
				}
				std::vector<IgVertex> face;
				for (py::ssize_t f = 0; f + 1 < offsets.shape(0); ++f)
				{
					face.clear();
					if (offsets.at(f + 1) < offsets.at(f))
						throw py::value_error("offsets must not decrease");
					for (int64 k = offsets.at(f); k < offsets.at(f + 1); ++k)
					{
						const int64 x = indices.at(k);
						if (x < 0 || x >= n)
							throw py::value_error("face " + std::to_string(f) + " refers to point " +
												  std::to_string(x) + ", but there are " + std::to_string(n) +
												  " points");
						face.push_back(v[std::size_t(x)]);
					}
					refusing([&] { return add_face_through_vertices(w->m, face); });
				}
				return w;
			},
			py::arg("points"), py::arg("offsets"), py::arg("indices"),
			"An incidence graph of n vertices at the rows of `points` and a face per CSR row (face f: "
			"indices[offsets[f]:offsets[f+1]], at least 3 different vertices); edges are shared by every face "
			"on them. Raises ValueError for a face that repeats a vertex.")
		.def_static(
			"load",
			[](const std::string& path) {
				auto w = std::make_unique<W>();
				index_faces(*w);
				const std::size_t dot = path.find_last_of('.');
				std::string ext = dot == std::string::npos ? "" : path.substr(dot);
				for (char& c : ext)
					c = char(std::tolower(static_cast<unsigned char>(c)));
				if (ext == ".ig")
					io::load_incidence_graph(w->m, path);
				else
					io::load_surface(w->m, path);
				w->ensure_position();
				return w;
			},
			py::arg("path"),
			"Loads an .ig file, or a surface file (OFF, OBJ, PLY, STL) exactly as written (no vertex split, no face "
			"dropped or turned over). Raises cgogn.IOError naming the file, line and problem on bad input.")
		.def(
			"save",
			[](const W& w, const std::string& path) {
				const std::size_t dot = path.find_last_of('.');
				if (dot != std::string::npos && (path.substr(dot) == ".ig" || path.substr(dot) == ".IG"))
					io::save_incidence_graph(w.m, path);
				else
					io::save_surface(w.m, path);
			},
			py::arg("path"), "Writes an .ig file, or the faces to a surface file, in the vertex and face order.")
		.def_property_readonly(
			"nb_vertices", [](const W& w) { return nb_cells<IgVertex>(w.m); }, "Number of vertices.")
		.def_property_readonly(
			"nb_edges", [](const W& w) { return nb_cells<IgEdge>(w.m); }, "Number of edges.")
		.def_property_readonly(
			"nb_faces", [](const W& w) { return nb_cells<IgFace>(w.m); }, "Number of faces.")
		.def_property_readonly(
			"positions",
			[](W& w) { return attribute_array(w.pos, container_of<Orbit::IG_VERTEX>(w.m).end_index(), w.views); },
			"The vertex positions, an (id_bound, 3) float64 array aliasing the complex's memory (row = vertex id).")
		.def(
			"vertex_ids", [](const W& w) { return ig_ids_of<IgVertex>(w); },
			"The ids of the live vertices, in id order.")
		.def(
			"edge_ids", [](const W& w) { return ig_ids_of<IgEdge>(w); }, "The ids of the live edges, in id order.")
		.def(
			"face_ids", [](const W& w) { return ig_ids_of<IgFace>(w); }, "The ids of the live faces, in id order.")
		.def(
			"edges",
			[](const W& w) {
				std::vector<uint32> out;
				foreach_cell(w.m, [&](IgEdge e) {
					out.push_back(first_vertex(w.m, e).dart.index);
					out.push_back(second_vertex(w.m, e).dart.index);
				});
				py::array_t<uint32> a = to_numpy(std::move(out));
				return a.reshape({py::ssize_t(a.size() / 2), py::ssize_t(2)});
			},
			"The live edges in id order, an (E, 2) array of their first and second vertex ids.")
		.def(
			"faces",
			[](const W& w) {
				std::vector<uint32> offsets{0}, indices;
				foreach_cell(w.m, [&](IgFace f) {
					foreach_incident_vertex(w.m, f, [&](IgVertex v) { indices.push_back(v.dart.index); });
					offsets.push_back(uint32(indices.size()));
				});
				return py::make_tuple(to_numpy(std::move(offsets)), to_numpy(std::move(indices)));
			},
			"The live faces in id order as CSR (offsets, indices): face k's vertex ids in cycle order are "
			"indices[offsets[k]:offsets[k+1]].")
		.def(
			"vertex_degree", [](const W& w, uint32 v) { return degree(w.m, ig_vertex(w, v)); }, py::arg("vertex"),
			"Number of edges of the vertex.")
		.def(
			"edge_degree", [](const W& w, uint32 e) { return degree(w.m, ig_edge(w, e)); }, py::arg("edge"),
			"Number of faces on the edge (3 or more: non-manifold).")
		.def(
			"is_manifold_vertex", [](const W& w, uint32 v) { return is_manifold_vertex(w.m, ig_vertex(w, v)); },
			py::arg("vertex"), "Whether the faces around the vertex form one fan.")
		.def(
			"add_vertex",
			[](W& w, const py::object& position) {
				const IgVertex v = add_vertex(w.m);
				if (!position.is_none())
				{
					const auto p = position.cast<std::vector<double>>();
					if (p.size() != 3)
						throw py::value_error("a position has 3 coordinates");
					value<Vec3>(w.m, w.pos, v) = Vec3(p[0], p[1], p[2]);
				}
				return index_of(w.m, v);
			},
			py::arg("position") = py::none(), "A new vertex without edge; returns its id.")
		.def(
			"add_edge",
			[](W& w, uint32 a, uint32 b) {
				return index_of(w.m, refusing([&] { return add_edge(w.m, ig_vertex(w, a), ig_vertex(w, b)); }));
			},
			py::arg("v0"), py::arg("v1"), "A new edge from v0 to v1 (different vertices); returns its id.")
		.def(
			"add_face",
			[](W& w, const Ids& edges) {
				const auto e = cells_of_ids<IgEdge>(edges, [&](uint32 id) { return ig_edge(w, id); });
				return index_of(w.m, refusing([&] { return add_face(w.m, e); }));
			},
			py::arg("edges"),
			"A new face on the given edge ids, in any order (one simple cycle of 3 or more); returns its id. "
			"Raises ValueError otherwise, changing nothing.")
		.def(
			"add_face_through_vertices",
			[](W& w, const Ids& vertices) {
				const auto v = cells_of_ids<IgVertex>(vertices, [&](uint32 id) { return ig_vertex(w, id); });
				return index_of(w.m, refusing([&] { return add_face_through_vertices(w.m, v); }));
			},
			py::arg("vertices"), "A new face through the vertex ids in this order, adding the missing edges.")
		.def(
			"remove_vertex", [](W& w, uint32 v) { remove_vertex(w.m, ig_vertex(w, v)); }, py::arg("vertex"),
			"Removes the vertex, its edges and their faces.")
		.def(
			"remove_edge", [](W& w, uint32 e) { remove_edge(w.m, ig_edge(w, e)); }, py::arg("edge"),
			"Removes the edge and its faces.")
		.def(
			"remove_face", [](W& w, uint32 f) { remove_face(w.m, ig_face(w, f)); }, py::arg("face"),
			"Removes the face only.")
		.def(
			"cut_edge", [](W& w, uint32 e) { return index_of(w.m, cut_edge(w.m, ig_edge(w, e))); }, py::arg("edge"),
			"Splits the edge by a new vertex; returns its id.")
		.def(
			"cut_face",
			[](W& w, uint32 f, uint32 a, uint32 b) {
				return index_of(
					w.m, refusing([&] { return cut_face(w.m, ig_face(w, f), ig_vertex(w, a), ig_vertex(w, b)); }));
			},
			py::arg("face"), py::arg("v0"), py::arg("v1"),
			"Cuts the face along an edge between two of its non-consecutive vertices; returns the edge's id.")
		.def(
			"collapse_edge",
			[](W& w, uint32 e) { return index_of(w.m, refusing([&] { return collapse_edge(w.m, ig_edge(w, e)); })); },
			py::arg("edge"),
			"Merges the edge's second vertex into its first; returns the survivor's id. Raises "
			"ValueError when a face would be pinched.")
		.def(
			"nb_connected_components", [](const W& w) { return nb_connected_components(w.m); },
			"Number of connected components.")
		.def(
			"euler_characteristic", [](const W& w) { return euler_characteristic(w.m); }, "V - E + F.")
		.def(
			"nb_non_manifold_edges", [](const W& w) { return nb_non_manifold_edges(w.m); },
			"Number of edges with three faces or more.")
		.def(
			"nb_non_manifold_vertices", [](const W& w) { return nb_non_manifold_vertices(w.m); },
			"Number of vertices whose faces are not one fan (vertices without face included).")
		.def(
			"to_cmap2",
			[](const W& w) {
				auto s = std::make_unique<Surface>();
				s->m = to_cmap2(w.m);
				s->ensure_position();
				return s;
			},
			"The CMap2 of the faces: exact on a manifold complex, repaired (faces detached, vertices split) "
			"otherwise.")
		.def_static(
			"from_cmap2",
			[](const Surface& map) {
				auto w = std::make_unique<W>();
				w->m = to_incidence_graph(map.m);
				w->ensure_position();
				index_faces(*w);
				return w;
			},
			py::arg("map"), "The incidence graph of a CMap2's vertices, edges and faces, with their attributes.")
		.def(
			"check_integrity", [](const W& w) { return integrity_report(check_integrity(w.m)); },
			"Checks every invariant; returns {'ok': bool, 'nb_errors': int, 'messages': [str]}.")
		.def("__repr__", [](const W& w) {
			return "<cgogn.IncidenceGraph vertices=" + std::to_string(nb_cells<IgVertex>(w.m)) +
				   " edges=" + std::to_string(nb_cells<IgEdge>(w.m)) +
				   " faces=" + std::to_string(nb_cells<IgFace>(w.m)) + ">";
		});
}

} // namespace cgogn::python
