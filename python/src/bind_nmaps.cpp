// SPDX-License-Identifier: MIT
// The maps of any dimension, the part written once for all of them (the base
// class NMap): counts, cell ids, incidence relations as CSR arrays,
// integrity, attributes of the cells of every dimension as NumPy arrays,
// .nmap and .vtu files. The classes of each model: bind_cmapn.cpp and
// bind_gmapn.cpp.
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/darts.h>
#include <cgogn/io/nmap.h>

#include "py_map.h"
#include "py_nmap.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <optional>
#include <pybind11/stl.h>
#include <tuple>
#include <utility>

namespace cgogn::python
{

bool has_nmap_extension(const std::string& path)
{
	if (path.size() < 5)
		return false;
	std::string ext = path.substr(path.size() - 5);
	std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	return ext == ".nmap";
}

py::object load_nmap_file(const std::string& path, bool gmap)
{
	io::NMapHeader h;
	{
		py::gil_scoped_release release;
		h = io::read_nmap_header(path);
	}
	if (h.dimension > MAX_PY_DIMENSION)
		throw io::Error(path, "the file holds a map of dimension " + std::to_string(h.dimension) +
								  "; Python has the maps of dimension 1 to " + std::to_string(MAX_PY_DIMENSION));
	py::object o = h.gmap ? new_gmapn(h.dimension) : new_cmapn(h.dimension);
	NMap& w = o.cast<NMap&>();
	{
		py::gil_scoped_release release;
		w.load_nmap(path);
	}
	if (gmap && !h.gmap)
		return w.convert();
	return o;
}

namespace
{

// ---- cell dimensions and their containers

// The dimension of the cells named by k: an integer 0 ... D, or "vertex",
// "edge", "face", "volume" (plurals accepted); ValueError otherwise.
uint32 cell_dimension(const NMap& w, const py::handle& k)
{
	int64 d = -1;
	if (py::isinstance<py::str>(k))
	{
		const std::string name = k.cast<std::string>();
		const char* names[] = {"vertex", "edge", "face", "volume"};
		const char* plurals[] = {"vertices", "edges", "faces", "volumes"};
		for (int64 i = 0; i < 4; ++i)
			if (name == names[i] || name == plurals[i])
				d = i;
		if (d < 0)
			throw py::value_error("unknown cell kind '" + name +
								  "': use a dimension, or \"vertex\", \"edge\", \"face\", \"volume\"");
	}
	else
	{
		py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(k.ptr()));
		if (!i)
			throw py::error_already_set();
		d = i.cast<int64>();
	}
	if (d < 0 || d > int64(w.dimension()))
		throw py::value_error("cell dimension " + std::to_string(d) + " out of 0.." + std::to_string(w.dimension()) +
							  " for a map of dimension " + std::to_string(w.dimension()));
	return uint32(d);
}

// Calls f.template operator()<O>() with the orbit of the k-cells, k <= MAX_PY_DIMENSION.
template <typename F>
void with_orbit(uint32 k, F&& f)
{
	[&]<std::size_t... K>(std::index_sequence<K...>)
	{
		(void)((k == K ? (f.template operator()<cell_orbit(uint32(K))>(), true) : false) || ...);
	}
	(std::make_index_sequence<MAX_PY_DIMENSION + 1>{});
}

AttributeContainer& container(const NMap& w, uint32 k)
{
	AttributeContainer* c = nullptr;
	with_orbit(k, [&]<Orbit O>() { c = &container_of<O>(w.map()); });
	return *c;
}

// One past the largest id of the k-cells: the rows of their attribute arrays.
uint32 id_bound(const NMap& w, uint32 k)
{
	return container(w, k).end_index();
}

// ---- value types

// The value types of the attributes Python reads and writes: those of the
// .nmap files.
using Types = std::tuple<double, float, int32, uint32, int64, uint64, std::array<double, 1>, std::array<double, 2>,
						 std::array<double, 3>, std::array<double, 4>, std::array<double, 5>, std::array<double, 6>,
						 std::array<double, 7>, std::array<double, 8>>;

// The attributes Python creates have fewer value types than those it reads
// (Types): each value type made on the cells of each dimension costs a
// class (CellAttribute<T, O>) to compile.

// Calls f.template operator()<T>() with std::array<double, n>, 1 <= n <=
// MAX_PY_DIMENSION (the positions of every dimension).
template <typename F>
void with_array(int n, F&& f)
{
	[&]<std::size_t... K>(std::index_sequence<K...>)
	{
		(void)((n == int(K) + 1 ? (f.template operator()<std::array<double, K + 1>>(), true) : false) || ...);
	}
	(std::make_index_sequence<MAX_PY_DIMENSION>{});
}

// Calls f.template operator()<T>() for the value type of (dtype, components)
// of a new attribute; ValueError when there is none.
template <typename F>
void with_type(const std::string& dtype, int components, F&& f)
{
	const bool float64 = dtype == "float64" || dtype == "double" || dtype == "float";
	if (components == 1)
	{
		if (float64)
			return f.template operator()<double>();
		if (dtype == "float32")
			return f.template operator()<float>();
		if (dtype == "int32")
			return f.template operator()<int32>();
		if (dtype == "int64" || dtype == "int")
			return f.template operator()<int64>();
	}
	else if (float64 && components >= 2 && components <= int(MAX_PY_DIMENSION))
		return with_array(components, f);
	throw py::value_error("unsupported attribute type: dtype '" + dtype + "' with " + std::to_string(components) +
						  " component(s) (float64 with 1 to " + std::to_string(MAX_PY_DIMENSION) +
						  ", or float32, int32, int64 with 1)");
}

// Calls f(attribute) with the typed attribute of this name in c, if any;
// returns false when there is none (or when it holds another value type).
template <typename F>
bool with_existing(const AttributeContainer& c, const std::string& name, F&& f)
{
	if (name.rfind("__", 0) == 0)
		return false;
	bool found = false;
	std::apply(
		[&](auto... t) {
			(
				[&] {
					using T = decltype(t);
					if (found)
						return;
					if (auto a = c.get_attribute<T>(name))
					{
						found = true;
						f(std::move(a));
					}
				}(),
				...);
		},
		Types{});
	return found;
}

py::key_error no_attribute(const std::string& name, uint32 k)
{
	return py::key_error("no attribute named '" + name + "' on the " + std::to_string(k) + "-cells");
}

py::array get_array(NMap& w, const std::string& name, uint32 k)
{
	const AttributeContainer& c = container(w, k);
	py::array out;
	if (!with_existing(c, name, [&](auto a) { out = attribute_array(a, c.end_index(), w.views); }))
		throw no_attribute(name, k);
	return out;
}

// Adds an attribute of type T on the k-cells (indexed first).
template <typename T>
void add_typed(NMap& w, const std::string& name, uint32 k)
{
	w.index(k);
	with_orbit(k, [&]<Orbit O>() {
		container(w, k).add_attribute<T, CellAttribute<T, O>>(name, detail::default_attribute_value<T>());
	});
}

void set_values(NMap& w, const std::string& name, uint32 k, const py::object& values)
{
	const AttributeContainer& c = container(w, k);
	const py::array a = py::array::ensure(values);
	if (!a)
		throw py::type_error("values must be an array of numbers");
	if (!with_existing(c, name, [&](auto x) { assign_attribute(*x, c.end_index(), a); }))
		throw no_attribute(name, k);
}

// ---- relations

// The CSR arrays of the relation i -> j: one row per i-cell id (rows of ids
// without a live i-cell are empty), as (indptr, indices, (rows, columns)).
py::tuple incidence(NMap& w, uint32 i, uint32 j)
{
	std::vector<uint32> offsets, indices;
	uint32 nb_rows = 0, nb_columns = 0;
	{
		py::gil_scoped_release release;
		IncidenceRows r = w.incidence(i, j);
		nb_rows = id_bound(w, i);
		nb_columns = id_bound(w, j);
		offsets.assign(std::size_t(nb_rows) + 1, 0);
		bool in_order = r.rows.size() == nb_rows;
		for (std::size_t x = 0; x < r.rows.size(); ++x)
		{
			offsets[r.rows[x] + 1] = r.offsets[x + 1] - r.offsets[x];
			in_order = in_order && r.rows[x] == x;
		}
		for (std::size_t x = 0; x < nb_rows; ++x)
			offsets[x + 1] += offsets[x];
		if (in_order)
			indices = std::move(r.indices);
		else
		{
			indices.resize(r.indices.size());
			for (std::size_t x = 0; x < r.rows.size(); ++x)
				std::copy(r.indices.begin() + r.offsets[x], r.indices.begin() + r.offsets[x + 1],
						  indices.begin() + offsets[r.rows[x]]);
		}
	}
	return py::make_tuple(to_numpy(std::move(offsets)), to_numpy(std::move(indices)),
						  py::make_tuple(nb_rows, nb_columns));
}

std::vector<uint32> f_vector(const NMap& w)
{
	py::gil_scoped_release release;
	std::vector<uint32> f;
	for (uint32 k = 0; k <= w.dimension(); ++k)
		f.push_back(w.nb_cells(k));
	return f;
}

} // namespace

void bind_nmaps(py::module_& mod)
{
	py::class_<NMap> c(mod, "NMap",
					   "A map of any dimension: the base of CMapN1 ... CMapN4 and GMapN1 ... GMapN4 (make them with "
					   "cgogn.CMapN(D), cgogn.GMapN(D), the generators or cgogn.load). Cells are named by their "
					   "dimension k (0 = vertices ... D; \"vertex\", \"edge\", \"face\", \"volume\" also) and, "
					   "within a dimension, by integer ids; boundary cells are not counted, listed or given ids.");
	c.def(
		 "nb_darts", [](const NMap& w) { return nb_darts(w.map()); }, "Number of darts, boundary darts included.")
		.def(
			"nb_cells", [](const NMap& w, const py::object& k) { return w.nb_cells(cell_dimension(w, k)); },
			py::arg("k"), "Number of k-cells, boundary cells excluded. O(1) when they are indexed, O(darts) otherwise.")
		.def(
			"f_vector", [](const NMap& w) { return f_vector(w); },
			"[f_0, ..., f_D]: the number of cells of each dimension, boundary cells excluded. O(D x darts) at "
			"most.")
		.def(
			"euler_characteristic",
			[](const NMap& w) {
				int64 chi = 0, sign = 1;
				for (uint32 n : f_vector(w))
				{
					chi += sign * int64(n);
					sign = -sign;
				}
				return chi;
			},
			"f_0 - f_1 + f_2 - ...: 1 for a ball, 1 + (-1)^(D - 1) for the boundary of one.")
		.def(
			"nb_connected_components", [](const NMap& w) { return w.nb_connected_components(); },
			"Number of connected components holding a real dart. O(darts).")
		.def(
			"cells",
			[](NMap& w, const py::object& k) {
				const uint32 d = cell_dimension(w, k);
				std::vector<uint32> ids;
				{
					py::gil_scoped_release release;
					ids = w.cell_ids(d);
				}
				return to_numpy(std::move(ids));
			},
			py::arg("k"),
			"The ids of the k-cells, a uint32 array in traversal order (0..f_k-1 on a map just built or loaded). "
			"Indexes the k-cells if they are not.")
		.def(
			"id_bound",
			[](NMap& w, const py::object& k) {
				const uint32 d = cell_dimension(w, k);
				w.index(d);
				return id_bound(w, d);
			},
			py::arg("k"), "One past the largest k-cell id: the number of rows of the k-cells' attribute arrays.")
		.def(
			"_incidence",
			[](NMap& w, const py::object& i, const py::object& j) {
				return incidence(w, cell_dimension(w, i), cell_dimension(w, j));
			},
			py::arg("i"), py::arg("j"), "(indptr, indices, shape) of incidence(i, j).")
		.def(
			"check_integrity",
			[](const NMap& w) {
				IntegrityReport r;
				{
					py::gil_scoped_release release;
					r = w.check_integrity();
				}
				return integrity_report(r);
			},
			"Checks every invariant of the map; returns {'ok': bool, 'nb_errors': int, 'messages': [str]}.")
		.def_property(
			"positions",
			[](NMap& w) -> py::object {
				const AttributeContainer& v = container(w, 0);
				py::object out = py::none();
				with_existing(v, "position", [&](auto a) { out = attribute_array(a, v.end_index(), w.views); });
				return out;
			},
			[](NMap& w, const py::object& values) {
				if (!container(w, 0).find("position"))
					with_array(int(w.dimension()), [&]<typename T>() { add_typed<T>(w, "position", 0); });
				set_values(w, "position", 0, values);
			},
			"The vertex attribute `position`: an (id_bound(0), D) float64 array indexed by vertex id, aliasing "
			"the map's memory (writes go to the map); None when the map has none (an empty map, a map built "
			"without points). Assigning an (id_bound(0), D) array copies it in, creating the attribute if needed.")
		.def(
			"add_attribute",
			[](NMap& w, const std::string& name, const py::object& k, const std::string& dtype, int components) {
				const uint32 d = cell_dimension(w, k);
				if (name.rfind("__", 0) == 0)
					throw py::value_error("names starting with '__' are the library's own");
				w.index(d);
				if (container(w, d).find(name) != nullptr)
					throw py::value_error("an attribute named '" + name + "' exists already on the " +
										  std::to_string(d) + "-cells");
				with_type(dtype, components, [&]<typename T>() { add_typed<T>(w, name, d); });
				return get_array(w, name, d);
			},
			py::arg("name"), py::arg("k"), py::arg("dtype") = "float64", py::arg("components") = 1,
			"Adds an attribute (values 0) on the k-cells, indexing them if needed, and returns its array (see "
			"attribute()). dtype: float64 (1 to 4 components: an (id_bound(k), components) array above 1), "
			"float32, int32 or int64. The attributes of a .nmap file may also be uint32, uint64 or float64 "
			"vectors of up to 8 components: they are read, written and saved as the others.")
		.def(
			"attribute",
			[](NMap& w, const std::string& name, const py::object& k) {
				return get_array(w, name, cell_dimension(w, k));
			},
			py::arg("name"), py::arg("k"),
			"The values of an attribute of the k-cells, one row per k-cell id (id_bound(k) rows): an array "
			"aliasing the map's memory (writes go to the map). KeyError when absent.")
		.def(
			"set_attribute",
			[](NMap& w, const std::string& name, const py::object& k, const py::object& values) {
				set_values(w, name, cell_dimension(w, k), values);
			},
			py::arg("name"), py::arg("k"), py::arg("values"),
			"Copies values (id_bound(k) rows, cast to the attribute's type) into an attribute.")
		.def(
			"remove_attribute",
			[](NMap& w, const std::string& name, const py::object& k) {
				const uint32 d = cell_dimension(w, k);
				AttributeContainer& c = container(w, d);
				if (!with_existing(c, name, [&](auto a) { c.remove_attribute(a.get()); }))
					throw no_attribute(name, d);
			},
			py::arg("name"), py::arg("k"),
			"Removes an attribute. Arrays already returned keep the values (they own a reference).")
		.def(
			"attributes",
			[](NMap& w, const py::object& k) {
				const AttributeContainer& c = container(w, cell_dimension(w, k));
				py::list out;
				for (const auto& a : c.attributes())
					with_existing(c, a->name(), [&](auto typed) {
						using T = typename std::decay_t<decltype(*typed)>::value_type;
						out.append(py::make_tuple(a->name(), dtype_name<T>(), ValueLayout<T>::components));
					});
				return out;
			},
			py::arg("k"), "The attributes of the k-cells Python can read: [(name, dtype, components)].")
		.def(
			"save",
			[](const NMap& w, const std::string& path, std::optional<std::vector<uint32>> dimensions) {
				std::string ext = path.substr(std::min(path.size(), path.find_last_of('.')));
				std::transform(ext.begin(), ext.end(), ext.begin(),
							   [](unsigned char ch) { return char(std::tolower(ch)); });
				if (has_map_file_extension(path))
				{
					std::vector<std::string> skipped;
					const std::string bytes = w.map_bytes(&skipped);
					std::ofstream f(path, std::ios::binary);
					if (!f.write(bytes.data(), std::streamsize(bytes.size())))
						throw io::Error(path, "cannot write the file");
					return skipped;
				}
				if (ext != ".vtu" && !has_nmap_extension(path))
					throw io::Error(path, "unknown extension '" + ext +
											  "': a map of any dimension is written as .nmap, .vtu or .cgmap");
				if (ext != ".vtu" && dimensions)
					throw py::value_error("dimensions: for .vtu files only");
				py::gil_scoped_release release;
				if (ext != ".vtu")
					return w.save_nmap(path);
				w.save_vtu(path, dimensions ? *dimensions : std::vector<uint32>{std::min(w.dimension(), 3u)});
				return std::vector<std::string>{};
			},
			py::arg("path"), py::arg("dimensions") = py::none(),
			"Writes the map: a .nmap file (darts, relations, boundary and the attributes of every cell "
			"dimension; returns the names of the attributes whose type the format has not), a .cgmap file (the "
			"whole map, exactly; returns the names of the attributes left out), or a .vtu file (VTK "
			"XML, which ParaView opens) of the cells of the given dimensions (0 to 3; by default min(D, 3)) on "
			"the first three coordinates of the positions. Raises cgogn.IOError on failure.")
		.def(
			"boundary", [](const NMap& w) { return w.boundary(); },
			"The boundary D-cells as a closed map of dimension D - 1 (D >= 2), the same model, vertex attributes "
			"carried. O(boundary darts x vertex attributes).")
		.def("__repr__", [](const py::object& self) {
			const NMap& w = self.cast<const NMap&>();
			std::string s = "<cgogn.";
			s += self.attr("__class__").attr("__name__").cast<std::string>();
			s += " f_vector=(";
			const std::vector<uint32> f = f_vector(w);
			for (std::size_t k = 0; k < f.size(); ++k)
			{
				if (k > 0)
					s += ", ";
				s += std::to_string(f[k]);
			}
			s += ") darts=";
			s += std::to_string(nb_darts(w.map()));
			s += ">";
			return s;
		});
	bind_cmapn(mod);
	bind_gmapn(mod);
}

} // namespace cgogn::python
