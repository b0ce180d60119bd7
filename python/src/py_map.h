// SPDX-License-Identifier: MIT
// What the bindings of the maps of dimension 2 and 3 share: the map wrapper (a
// map, its positions and the NumPy views handed out), cell kinds by name, and
// the layout of their vector attributes (arrays over attributes: py_arrays.h).
#pragma once

#include <cgogn/cgogn.h>

#include "py_arrays.h"

#include <memory>
#include <string>
#include <vector>

namespace cgogn::python
{

/// A map as Python sees it: the map, its `position` vertex attribute (created
/// when missing) and weak references to the NumPy arrays that alias its
/// attributes' memory (so that compaction, which gives memory back, can
/// refuse to run while one of them is alive).
template <typename MAP>
struct PyMap
{
	MAP m;
	std::shared_ptr<AttributeArray<Vec3>> pos;
	std::vector<py::object> views; // weakrefs

	PyMap()
	{
		ensure_position();
	}
	PyMap(const PyMap&) = delete;
	PyMap& operator=(const PyMap&) = delete;

	void ensure_position()
	{
		using Vertex = typename mesh_traits<MAP>::Vertex;
		pos = get_attribute<Vec3, Vertex>(m, "position");
		if (!pos)
			pos = add_attribute<Vec3, Vertex>(m, "position");
	}
	/// Throws RuntimeError when a view is alive: `what` (compaction, a
	/// rebuild) gives memory back, and the view would point to it.
	void refuse_while_aliased(const char* what)
	{
		if (const std::size_t n = live_views(); n > 0)
			throw std::runtime_error(std::string(what) + ": " + std::to_string(n) +
									 " NumPy array(s) still alias this map's attributes (positions or attribute "
									 "arrays); they would point to released memory. Delete them (del a) or keep "
									 "copies (a.copy()) first.");
	}
	/// Number of views still alive (drops the dead weakrefs).
	std::size_t live_views()
	{
		std::vector<py::object> alive;
		for (auto& w : views)
			if (!w().is_none())
				alive.push_back(w);
		views = std::move(alive);
		return views.size();
	}
};

using Surface = PyMap<CMap2>;
using VolumeMesh = PyMap<CMap3>;
using GSurface = PyMap<GMap2>;
using GVolumeMesh = PyMap<GMap3>;

/// The cell kinds Python names.
enum class Kind
{
	Vertex,
	Edge,
	Face,
	Volume,
	Corner ///< a dart: a corner of a face (per-corner data: texture seams, split normals)
};

/// "vertex", "edge", "face", "volume" or "corner" (plurals accepted);
/// ValueError otherwise.
Kind kind_of(const std::string& name);
const char* kind_name(Kind k);

/// Calls f.template operator()<CELL>() with the cell type of kind k in MAP.
template <typename MAP, typename FUNC>
decltype(auto) with_kind(Kind k, FUNC&& f)
{
	using T = mesh_traits<MAP>;
	switch (k)
	{
	case Kind::Vertex:
		return f.template operator()<typename T::Vertex>();
	case Kind::Edge:
		return f.template operator()<typename T::Edge>();
	case Kind::Face:
		return f.template operator()<typename T::Face>();
	case Kind::Corner:
		return f.template operator()<Cell<Orbit::DART>>();
	default:
		if constexpr (requires { typename T::Volume; })
			return f.template operator()<typename T::Volume>();
		else
			throw py::value_error("this mesh has no volumes");
	}
}

/// The orbit of kind k is indexed (indexes it when it is not: O(darts)).
template <typename MAP>
void ensure_indexed(MAP& m, Kind k)
{
	with_kind<MAP>(k, [&]<typename CELL>() {
		if (!is_indexed<CELL>(m))
			index_cells<CELL>(m);
	});
}

/// Number of rows of the arrays of kind k: one past the largest cell id.
template <typename MAP>
uint32 id_bound(const MAP& m, Kind k)
{
	return with_kind<MAP>(k, [&]<typename CELL>() { return container_of<CELL::ORBIT>(m).end_index(); });
}

/// The Eigen vectors of the maps of dimension 2 and 3: rows of 2 to 4 float64.
template <>
struct ValueLayout<Vec2>
{
	using Scalar = double;
	static constexpr int components = 2;
	static constexpr bool vector = true;
};
template <>
struct ValueLayout<Vec3>
{
	using Scalar = double;
	static constexpr int components = 3;
	static constexpr bool vector = true;
};
template <>
struct ValueLayout<Vec4>
{
	using Scalar = double;
	static constexpr int components = 4;
	static constexpr bool vector = true;
};

void bind_maps(py::module_& m);
void bind_attributes(py::module_& m);
void bind_operators(py::module_& m);
void bind_algorithms(py::module_& m);
void bind_graph(py::module_& m);
void bind_incidence_graph(py::module_& m);
/// The multiresolution 2-map (bind_mrmap.cpp).
void bind_mrmap(py::module_& m);
/// The multiresolution 3-map (bind_mrmap3.cpp).
void bind_mrmap3(py::module_& m);
/// Whole-map files (.cgmap) and pickling of every map class (bind_map_files.cpp);
/// bound last, once the classes exist.
void bind_map_files(py::module_& m);
#ifdef CGOGN_PYTHON_HAS_DISTRIBUTED
void bind_distributed(py::module_& m); // with the distributed layer only
#endif
/// Whether path ends with .cgmap (any case).
bool has_map_file_extension(const std::string& path);
/// The map of .cgmap bytes as an instance of its Python class; io::Error for
/// bad bytes or a type Python has no class of. `name` stands for the file.
py::object map_from_bytes(std::string_view bytes, const std::string& name);
/// What a map's __reduce__ returns: cgogn._from_bytes and the map's .cgmap
/// bytes (bind_map_files.cpp).
py::tuple map_file_reduce(std::string bytes);

/// Adds save, to_bytes and __reduce__ (the whole hierarchy as a .cgmap
/// file) to the class of a multiresolution map wrapper W (its map in W::m).
template <typename W>
void bind_hierarchy_file_methods(py::class_<W>& c)
{
	c.def(
		 "save",
		 [](const W& w, const std::string& path) {
			 if (!has_map_file_extension(path))
				 throw py::value_error(path + ": a multiresolution map is saved to a .cgmap file");
			 py::gil_scoped_release release;
			 io::save_map(w.m, path);
		 },
		 py::arg("path"),
		 "Writes the whole hierarchy to a .cgmap file (every level, the current level, every attribute), "
		 "which cgogn.load reads back. O(size of the finest map).")
		.def(
			"to_bytes", [](const W& w) { return py::bytes(io::save_map_to_bytes(w.m)); },
			"The whole hierarchy as .cgmap bytes; pickle and copy.deepcopy use them. O(size of the finest map).")
		.def("__reduce__", [](const W& w) { return map_file_reduce(io::save_map_to_bytes(w.m)); });
}
/// A graph moved into an instance of cgogn.Graph (bind_graph.cpp).
py::object wrap_graph(Graph&& g);
/// The cgogn.MRMap2 of .cgmap bytes holding an MRMap2 (bind_mrmap.cpp);
/// io::Error for bad bytes. `name` stands for the file.
py::object mrmap2_from_bytes(std::string_view bytes, const std::string& name);
/// The cgogn.MRMap3 of .cgmap bytes holding an MRMap3 (bind_mrmap3.cpp);
/// io::Error for bad bytes. `name` stands for the file.
py::object mrmap3_from_bytes(std::string_view bytes, const std::string& name);

} // namespace cgogn::python
