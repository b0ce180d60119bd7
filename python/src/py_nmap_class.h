// SPDX-License-Identifier: MIT
// The class of one map type of any dimension (CMapN<D> or GMapN<D>): the
// virtual functions of NMap for that type, and its generators and builders
// as static methods. Included by bind_cmapn.cpp and bind_gmapn.cpp only,
// each instantiating it for its model and D = 1 ... MAX_PY_DIMENSION.
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/build/nmap_boundary.h>
#include <cgogn/core/build/nmap_builder.h>
#include <cgogn/core/build/nmap_generators.h>
#include <cgogn/core/properties/dimension_properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_dimension.h>
#include <cgogn/io/nmap.h>

#include "py_nmap.h"

#include <cmath>
#include <limits>
#include <utility>

namespace cgogn::python
{

/// Calls f.template operator()<K>() for the runtime dimension k <= D.
template <uint32 D, typename F>
void with_dimension(uint32 k, F&& f)
{
	[&]<std::size_t... K>(std::index_sequence<K...>)
	{
		(void)((k == K ? (f.template operator()<uint32(K)>(), true) : false) || ...);
	}
	(std::make_index_sequence<D + 1>{});
}

template <typename MAP>
struct PyNMap final : NMap
{
	static constexpr uint32 D = MAP::dimension;
	MAP m;

	uint32 dimension() const override
	{
		return D;
	}
	bool is_gmap() const override
	{
		return is_gmap_v<MAP>;
	}
	CMapBase& map() override
	{
		return m;
	}
	const CMapBase& map() const override
	{
		return m;
	}
	void index(uint32 k) override
	{
		with_dimension<D>(k, [&]<uint32 K>() {
			using C = cell_of_dimension_t<MAP, K>;
			if (!is_indexed<C>(m))
				index_cells<C>(m);
		});
	}
	uint32 nb_cells(uint32 k) const override
	{
		uint32 n = 0;
		with_dimension<D>(k, [&]<uint32 K>() { n = cgogn::nb_cells<K>(m); });
		return n;
	}
	std::vector<uint32> cell_ids(uint32 k) override
	{
		index(k);
		std::vector<uint32> ids;
		with_dimension<D>(k, [&]<uint32 K>() {
			ids.reserve(cgogn::nb_cells<K>(m));
			foreach_cell(m, [&](cell_of_dimension_t<MAP, K> c) { ids.push_back(index_of(m, c)); });
		});
		return ids;
	}
	IncidenceRows incidence(uint32 i, uint32 j) override
	{
		index(i);
		index(j);
		IncidenceRows r;
		with_dimension<D>(i, [&]<uint32 I>() {
			r.rows.reserve(cgogn::nb_cells<I>(m));
			r.offsets.reserve(cgogn::nb_cells<I>(m) + 1);
			with_dimension<D>(j, [&]<uint32 J>() {
				foreach_cell(m, [&](cell_of_dimension_t<MAP, I> c) {
					r.rows.push_back(index_of(m, c));
					foreach_incident_cell<J>(
						m, c, [&](cell_of_dimension_t<MAP, J> x) { r.indices.push_back(index_of(m, x)); });
					r.offsets.push_back(uint32(r.indices.size()));
				});
			});
		});
		return r;
	}
	uint32 nb_connected_components() const override
	{
		return cgogn::nb_connected_components(m);
	}
	IntegrityReport check_integrity() const override
	{
		return cgogn::check_integrity(m);
	}
	void load_nmap(const std::string& path) override
	{
		io::load_nmap(m, path);
	}
	std::vector<std::string> save_nmap(const std::string& path) const override
	{
		return io::save_nmap(m, path);
	}
	std::string map_bytes(std::vector<std::string>* skipped) const override
	{
		io::MapFileReport r;
		std::string bytes = io::save_map_to_bytes(m, &r);
		if (skipped != nullptr)
			for (const io::SkippedAttribute& a : r.skipped)
				skipped->push_back(a.name);
		return bytes;
	}
	void save_vtu(const std::string& path, const std::vector<uint32>& dimensions) const override
	{
		io::save_vtu(m, path, dimensions);
	}
	py::object boundary() const override
	{
		if constexpr (D >= 2)
		{
			auto b = [&] {
				py::gil_scoped_release release;
				return extract_boundary(m);
			}();
			return wrap_nmap(std::move(b));
		}
		else
			throw py::value_error("a map of dimension 1 has no boundary map (its boundary would be of dimension 0)");
	}
	py::object convert() const override
	{
		auto other = [&] {
			py::gil_scoped_release release;
			if constexpr (is_gmap_v<MAP>)
				return to_cmap(m);
			else
				return to_gmap(m);
		}();
		return wrap_nmap(std::move(other));
	}
};

/// The map of a simplicial (cubes = false) or cubical complex: cells an (C,
/// D + 1) or (C, 2^D) integer array of vertex ids, points None or an (N, D)
/// array of the vertices' positions (then the `position` attribute).
template <typename MAP>
std::unique_ptr<PyNMap<MAP>> from_complex(const py::object& cells, const py::object& points, bool cubes)
{
	constexpr uint32 D = MAP::dimension;
	const py::ssize_t width = cubes ? py::ssize_t(1) << D : D + 1;
	const char* what = cubes ? "cubes" : "simplices";
	auto c = py::array_t<int64, py::array::c_style | py::array::forcecast>::ensure(cells);
	if (!c || c.ndim() != 2 || c.shape(1) != width)
		throw py::value_error(std::string("the ") + what + " of a map of dimension " + std::to_string(D) +
							  " must be a (C, " + std::to_string(width) + ") integer array");
	std::vector<uint32> ids(std::size_t(c.size()));
	uint32 nb_vertices = 0;
	for (std::size_t i = 0; i < ids.size(); ++i)
	{
		const int64 v = c.data()[i];
		if (v < 0 || v >= int64(std::numeric_limits<uint32>::max()))
			throw py::value_error("the vertex id " + std::to_string(v) + " is out of range");
		ids[i] = uint32(v);
		nb_vertices = std::max(nb_vertices, ids[i] + 1);
	}
	std::vector<PointD<D>> p;
	if (!points.is_none())
	{
		auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
		if (!a || a.ndim() != 2 || a.shape(1) != py::ssize_t(D))
			throw py::value_error("points must be an (N, " + std::to_string(D) + ") array of numbers");
		p.resize(std::size_t(a.shape(0)));
		for (std::size_t i = 0; i < p.size(); ++i)
			for (uint32 k = 0; k < D; ++k)
			{
				p[i][k] = a.data()[i * D + k];
				if (!std::isfinite(p[i][k]))
					throw py::value_error("point " + std::to_string(i) + " is not finite");
			}
		if (nb_vertices > p.size())
			throw py::value_error("a cell refers to point " + std::to_string(nb_vertices - 1) + ", but there are " +
								  std::to_string(p.size()) + " points");
		nb_vertices = uint32(p.size());
	}
	auto w = std::make_unique<PyNMap<MAP>>();
	{
		py::gil_scoped_release release;
		const std::vector<CellD<0>> vertices =
			cubes ? build_cubical_complex(w->m, nb_vertices, ids) : build_simplicial_complex(w->m, nb_vertices, ids);
		if (!p.empty())
		{
			auto position = add_attribute<PointD<D>, CellD<0>>(w->m, "position");
			for (std::size_t i = 0; i < vertices.size(); ++i)
				if (vertices[i].is_valid())
					(*position)[vertices[i]] = p[i];
		}
	}
	return w;
}

/// A map made by a generator: generate(m) on an empty map, without the GIL.
template <typename MAP, typename F>
std::unique_ptr<PyNMap<MAP>> generated(const F& generate)
{
	auto w = std::make_unique<PyNMap<MAP>>();
	py::gil_scoped_release release;
	generate(w->m);
	return w;
}

/// The Python class of MAP, named CMapN<D> or GMapN<D> ("CMapN3"), derived
/// from NMap.
template <typename MAP>
py::class_<PyNMap<MAP>, NMap> bind_nmap_class(py::module_& mod)
{
	constexpr uint32 D = MAP::dimension;
	using W = PyNMap<MAP>;
	const std::string model = is_gmap_v<MAP> ? "GMapN" : "CMapN";
	const std::string name = model + std::to_string(D);
	const std::string doc = std::string(is_gmap_v<MAP> ? "A generalized map" : "A combinatorial (oriented) map") +
							" of dimension " + std::to_string(D) + " (cgogn::" + model + "<" + std::to_string(D) +
							">), closed by boundary " + std::to_string(D) + "-cells. Make one with cgogn." + model +
							"(" + std::to_string(D) + "), a generator or a builder.";
	py::class_<W, NMap> c(mod, name.c_str(), doc.c_str());
	c.def(py::init<>(), "An empty map (no dart, no attribute).")
		.def_property_readonly_static("dimension", [](py::object) { return D; })
		.def_static(
			"simplex", [] { return generated<MAP>([](MAP& m) { generate_simplex(m); }); },
			"The D-simplex of vertices the origin and the unit vectors: C(D + 1, k + 1) k-cells, positions in the "
			"vertex attribute `position`.")
		.def_static(
			"cube", [] { return generated<MAP>([](MAP& m) { generate_cube(m); }); },
			"The unit D-cube [0, 1]^D: C(D, k) 2^(D - k) k-cells, with positions.")
		.def_static(
			"cube_grid", [](uint32 n) { return generated<MAP>([n](MAP& m) { generate_cube_grid(m, n); }); },
			py::arg("n"),
			"The grid of n^D cubes filling [0, 1]^D (n >= 1): C(D, k) n^k (n + 1)^(D - k) k-cells, with positions. "
			"O(n^D 2^D D!).")
		.def_static(
			"freudenthal_grid",
			[](uint32 n) { return generated<MAP>([n](MAP& m) { generate_freudenthal_grid(m, n); }); }, py::arg("n"),
			"The grid of cube_grid(n), each cube cut into the D! simplices around its main diagonal (Freudenthal, "
			"Kuhn): (n + 1)^D vertices, n^D D! D-simplices, with positions.")
		.def_static(
			"simplicial_complex",
			[](const py::object& cells, const py::object& points) { return from_complex<MAP>(cells, points, false); },
			py::arg("cells"), py::arg("points") = py::none(),
			"The map of a pure simplicial complex: cells a (C, D + 1) array of vertex ids, in any order; simplices "
			"sharing a facet are sewn, the other facets closed by the boundary. points: None or an (N, D) array, "
			"stored in the vertex attribute `position`. Raises cgogn.Error for an id repeated in a cell, a facet "
			"of more than two cells, or (CMapN) a complex that cannot be oriented.")
		.def_static(
			"cubical_complex",
			[](const py::object& cells, const py::object& points) { return from_complex<MAP>(cells, points, true); },
			py::arg("cells"), py::arg("points") = py::none(),
			"The map of a pure cubical complex: cells a (C, 2^D) array of vertex ids, vertex k of a cube at the "
			"coordinates given by the bits of k (a square: (0,0) (1,0) (0,1) (1,1)); points as in "
			"simplicial_complex. Raises cgogn.Error as simplicial_complex, and for cubes naming a shared facet in "
			"orders no gluing gives.");
	return c;
}

} // namespace cgogn::python
