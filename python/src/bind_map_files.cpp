// SPDX-License-Identifier: MIT
// Whole maps in .cgmap bytes: pickle and copy.deepcopy of every map class,
// and map_from_bytes, which pickle calls to rebuild one.
#include <cgogn/io/map_file.h>

#include "py_map.h"
#include "py_nmap.h"

#include <algorithm>

namespace cgogn::python
{

namespace
{

// A CMap2, CMap3, GMap2 or GMap3 loaded from bytes, with its positions.
template <typename MAP>
py::object map_file_wrapped(std::string_view bytes, const std::string& name)
{
	auto w = std::make_unique<PyMap<MAP>>();
	io::load_map_from_bytes(w->m, bytes, name);
	w->ensure_position();
	return py::cast(std::move(w));
}

template <typename MAP>
MAP map_file_loaded(std::string_view bytes, const std::string& name)
{
	MAP m;
	io::load_map_from_bytes(m, bytes, name);
	return m;
}

template <typename MAP>
void bind_map_file_methods(const py::module_& mod, const char* cls)
{
	using W = PyMap<MAP>;
	py::class_<W>(mod.attr(cls))
		.def(
			"to_bytes", [](const W& w) { return py::bytes(io::save_map_to_bytes(w.m)); },
			"The map as the bytes of a .cgmap file: darts, relations, boundary, cell ids and every attribute of a "
			"type the format holds. O(size of the map).")
		.def("__reduce__", [](const W& w) { return map_file_reduce(io::save_map_to_bytes(w.m)); });
}

} // namespace

// __reduce__: pickle stores the package's cgogn._from_bytes (which calls
// map_from_bytes: pickle cannot name a compiled function) and the bytes.
py::tuple map_file_reduce(std::string bytes)
{
	return py::make_tuple(py::module_::import("cgogn").attr("_from_bytes"), py::make_tuple(py::bytes(bytes)));
}

bool has_map_file_extension(const std::string& path)
{
	std::string ext = path.substr(std::min(path.size(), path.find_last_of('.')));
	std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char ch) { return char(std::tolower(ch)); });
	return ext == ".cgmap";
}

py::object map_from_bytes(std::string_view bytes, const std::string& name)
{
	const io::MapFileHeader h = io::read_map_header_from_bytes(bytes, name);
	if (h.map_type == "CMap2")
		return map_file_wrapped<CMap2>(bytes, name);
	if (h.map_type == "CMap3")
		return map_file_wrapped<CMap3>(bytes, name);
	if (h.map_type == "GMap2")
		return map_file_wrapped<GMap2>(bytes, name);
	if (h.map_type == "GMap3")
		return map_file_wrapped<GMap3>(bytes, name);
	if (h.map_type == "Graph")
		return wrap_graph(map_file_loaded<Graph>(bytes, name));
	if (h.map_type == io::map_type_name<MRMap2>())
		return mrmap2_from_bytes(bytes, name);
	if (h.map_type == io::map_type_name<MRMap3>())
		return mrmap3_from_bytes(bytes, name);
	py::object r;
	[&]<uint32... D>(std::integer_sequence<uint32, D...>)
	{
		(
			[&] {
				if (h.map_type == io::map_type_name<CMapN<D + 1>>())
					r = wrap_nmap(map_file_loaded<CMapN<D + 1>>(bytes, name));
				else if (h.map_type == io::map_type_name<GMapN<D + 1>>())
					r = wrap_nmap(map_file_loaded<GMapN<D + 1>>(bytes, name));
			}(),
			...);
	}
	(std::make_integer_sequence<uint32, 4>{});
	if (!r)
		throw io::Error(name, "a map of type " + h.map_type + ", which has no Python class");
	return r;
}

void bind_map_files(py::module_& mod)
{
	bind_map_file_methods<CMap2>(mod, "CMap2");
	bind_map_file_methods<CMap3>(mod, "CMap3");
	bind_map_file_methods<GMap2>(mod, "GMap2");
	bind_map_file_methods<GMap3>(mod, "GMap3");
	py::class_<NMap>(mod.attr("NMap"))
		.def(
			"to_bytes", [](const NMap& w) { return py::bytes(w.map_bytes()); },
			"The map as the bytes of a .cgmap file (see CMap2.to_bytes).")
		.def("__reduce__", [](const NMap& w) { return map_file_reduce(w.map_bytes()); });
	mod.def(
		"map_from_bytes",
		[](const py::bytes& b) {
			const std::string_view bytes(b);
			return map_from_bytes(bytes, "(bytes)");
		},
		py::arg("data"),
		"The map of .cgmap bytes (to_bytes(), or a file's content) as an instance of its class (CMap2, CMap3, "
		"GMap2, GMap3, Graph, CMapN1 ... GMapN4, MRMap2, MRMap3). pickle and copy.deepcopy go through it. Raises "
		"cgogn.IOError "
		"for bytes that are not a valid map.");
}

} // namespace cgogn::python
