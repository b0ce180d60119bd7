// SPDX-License-Identifier: MIT
// The common topological operators, on cells named by their ids.
#include "py_map.h"

namespace cgogn::python
{

namespace
{

// The cell of kind CELL with this id; IndexError when no live cell has it.
template <typename CELL, typename MAP>
CELL cell(MAP& m, int64 id)
{
	using Cell = CELL;
	if constexpr (Cell::ORBIT != Orbit::DART)
		if (!is_indexed<CELL>(m))
			index_cells<CELL>(m);
	const AttributeContainer& c = container_of<CELL::ORBIT>(m);
	if (id < 0 || id >= int64(c.end_index()) || !c.is_live(uint32(id)))
		throw py::index_error("no live cell with id " + std::to_string(id));
	Dart d(c.key()[uint32(id)]);
	// the operators of 3-maps take a dart of a real volume (the cell's
	// representative may lie in a boundary volume)
	if constexpr (MAP::dimension == 3)
		if (is_boundary(m, d))
			foreach_dart_of_orbit(m, CELL(d), [&](Dart x) {
				if (is_boundary(m, x))
					return true;
				d = x;
				return false;
			});
	return CELL(d);
}

// The id of cell c (indexes its kind first when it is not).
template <typename MAP, typename CELL>
uint32 id_of(MAP& m, CELL c)
{
	if (!is_indexed<CELL>(m))
		index_cells<CELL>(m);
	return index_of(m, c);
}

// The dart of face f whose origin is vertex v; ValueError when v is not on f.
template <typename MAP>
Dart corner(const MAP& m, typename mesh_traits<MAP>::Face f, int64 v)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	Dart d = f.dart;
	do
	{
		if (index_of(m, Vertex(d)) == uint64(v))
			return d;
		d = phi1(m, d);
	} while (d != f.dart);
	throw py::value_error("vertex " + std::to_string(v) + " is not a corner of that face");
}

// can_cut_face between two corners of a face, for either map type.
template <typename MAP>
bool can_cut(const MAP& m, Dart a, Dart b)
{
	if constexpr (MAP::dimension == 2)
		return can_cut_face(m, CMap2::Vertex(a), CMap2::Vertex(b));
	else
		return can_cut_face(m, a, b);
}

// The edge's dart whose origin is not `keep` (so that collapsing it keeps
// `keep`); the representative when keep < 0.
template <typename MAP>
typename mesh_traits<MAP>::Edge directed(const MAP& m, typename mesh_traits<MAP>::Edge e, int64 keep)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Edge = typename mesh_traits<MAP>::Edge;
	if (keep < 0)
		return e;
	if (index_of(m, Vertex(phi1(m, e.dart))) == uint64(keep))
		return e;
	if (index_of(m, Vertex(e.dart)) == uint64(keep))
		return Edge(phi2(m, e.dart));
	throw py::value_error("vertex " + std::to_string(keep) + " is not an end of that edge");
}

template <typename MAP>
void bind_shared(py::class_<PyMap<MAP>>& c)
{
	using W = PyMap<MAP>;
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Edge = typename mesh_traits<MAP>::Edge;
	using Face = typename mesh_traits<MAP>::Face;
	c.def(
		 "cut_edge",
		 [](W& w, int64 edge) {
			 const Vertex v = cut_edge(w.m, cell<Edge>(w.m, edge));
			 return id_of(w.m, v);
		 },
		 py::arg("edge"),
		 "Inserts a vertex in the middle of an edge (its position is the default, (0, 0, 0): set it). Returns "
		 "the new vertex id. O(degree of the edge).")
		.def(
			"can_cut_face",
			[](W& w, int64 face, int64 a, int64 b) {
				const Face f = cell<Face>(w.m, face);
				return can_cut(w.m, corner(w.m, f, a), corner(w.m, f, b));
			},
			py::arg("face"), py::arg("a"), py::arg("b"), "True when cut_face(face, a, b) is allowed.")
		.def(
			"cut_face",
			[](W& w, int64 face, int64 a, int64 b) {
				const Face f = cell<Face>(w.m, face);
				const Dart da = corner(w.m, f, a), db = corner(w.m, f, b);
				if (!can_cut(w.m, da, db))
					throw py::value_error("cut_face: the corners are equal or adjacent, or the face is boundary");
				if constexpr (MAP::dimension == 2)
					return id_of(w.m, cut_face(w.m, Vertex(da), Vertex(db)));
				else
					return id_of(w.m, cut_face(w.m, da, db));
			},
			py::arg("face"), py::arg("a"), py::arg("b"),
			"Cuts a face by a new edge between its corners a and b (vertex ids); returns the new edge id.")
		.def(
			"can_collapse_edge", [](W& w, int64 edge) { return can_collapse_edge(w.m, cell<Edge>(w.m, edge)); },
			py::arg("edge"), "True when collapse_edge(edge) keeps the map a manifold (link condition).")
		.def(
			"collapse_edge",
			[](W& w, int64 edge, int64 keep) {
				const Edge e = directed(w.m, cell<Edge>(w.m, edge), keep);
				if (!can_collapse_edge(w.m, e))
					throw py::value_error("collapse_edge: refused by can_collapse_edge");
				return id_of(w.m, collapse_edge(w.m, e));
			},
			py::arg("edge"), py::arg("keep") = -1,
			"Contracts an edge; the vertex `keep` (an end of it; by default one of them) survives with its id and "
			"values. Returns the surviving vertex id. ValueError when can_collapse_edge refuses it.")
		.def(
			"can_flip_edge", [](W& w, int64 edge) { return can_flip_edge(w.m, cell<Edge>(w.m, edge)); },
			py::arg("edge"), "True when flip_edge(edge) is allowed.");
}

} // namespace

void bind_operators(py::module_& mod)
{
	auto surface = py::class_<Surface>(mod.attr("CMap2"));
	bind_shared(surface);
	surface
		.def(
			"flip_edge",
			[](Surface& w, int64 edge) {
				const CMap2::Edge e = cell<CMap2::Edge>(w.m, edge);
				if (!can_flip_edge(w.m, e))
					throw py::value_error("flip_edge: refused by can_flip_edge");
				flip_edge(w.m, e);
			},
			py::arg("edge"),
			"Turns an inner edge to join the next corners of its two faces; the edge keeps its id. ValueError when "
			"can_flip_edge refuses it.")
		.def(
			"triangulate_face",
			[](Surface& w, int64 face) {
				const CMap2::Face f = cell<CMap2::Face>(w.m, face);
				return id_of(w.m, triangulate_face(w.m, f));
			},
			py::arg("face"),
			"Splits a face into triangles around a new vertex (position left at (0, 0, 0)); returns its id.");

	auto volume = py::class_<VolumeMesh>(mod.attr("CMap3"));
	bind_shared(volume);
	volume
		.def(
			"flip_edge",
			[](VolumeMesh& w, int64 edge) {
				const CMap3::Edge e = cell<CMap3::Edge>(w.m, edge);
				if (!can_flip_edge(w.m, e))
					throw py::value_error("flip_edge: refused by can_flip_edge");
				flip_edge(w.m, e);
			},
			py::arg("edge"), "3-2 (degree 3) or 4-4 (degree 4) flip of an inner edge of tetrahedra.")
		.def(
			"can_flip_face", [](VolumeMesh& w, int64 face) { return can_flip_face(w.m, cell<CMap3::Face>(w.m, face)); },
			py::arg("face"), "True when flip_face(face) (2-3 flip) is allowed.")
		.def(
			"flip_face",
			[](VolumeMesh& w, int64 face) {
				const CMap3::Face f = cell<CMap3::Face>(w.m, face);
				if (!can_flip_face(w.m, f))
					throw py::value_error("flip_face: refused by can_flip_face");
				return id_of(w.m, flip_face(w.m, f));
			},
			py::arg("face"), "2-3 flip of the face between two tetrahedra; returns the new edge id.")
		.def(
			"split_tetra",
			[](VolumeMesh& w, int64 volume_id) {
				try
				{
					return id_of(w.m, split_tetra(w.m, cell<CMap3::Volume>(w.m, volume_id)));
				}
				catch (const TopologyError& e)
				{
					throw py::value_error(e.what());
				}
			},
			py::arg("volume"),
			"Splits a tetrahedron into 4 at a new vertex (position left at (0, 0, 0)); returns its id. ValueError "
			"when the volume is not a tetrahedron.");
}

} // namespace cgogn::python
