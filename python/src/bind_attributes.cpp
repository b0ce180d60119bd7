// SPDX-License-Identifier: MIT
// Attributes by name, cell kind and dtype, as NumPy arrays indexed by cell id.
#include "py_map.h"

#include <pybind11/stl.h>
#include <tuple>

namespace cgogn::python
{

namespace
{

// The value types Python can use, with their NumPy names.
using Types =
	std::tuple<double, float, int8, uint8, std::int16_t, uint16, int32, uint32, int64, uint64, bool, Vec2, Vec3, Vec4>;

// Calls f.template operator()<T>() for the value type of (dtype, components);
// ValueError when there is none.
template <typename F>
decltype(auto) with_type(const std::string& dtype, int components, F&& f)
{
	if (components == 1)
	{
		if (dtype == "float64" || dtype == "double" || dtype == "float")
			return f.template operator()<double>();
		if (dtype == "float32")
			return f.template operator()<float>();
		if (dtype == "int8")
			return f.template operator()<int8>();
		if (dtype == "uint8")
			return f.template operator()<uint8>();
		if (dtype == "int16")
			return f.template operator()<std::int16_t>();
		if (dtype == "uint16")
			return f.template operator()<uint16>();
		if (dtype == "int32")
			return f.template operator()<int32>();
		if (dtype == "uint32")
			return f.template operator()<uint32>();
		if (dtype == "int64" || dtype == "int")
			return f.template operator()<int64>();
		if (dtype == "uint64")
			return f.template operator()<uint64>();
		if (dtype == "bool")
			return f.template operator()<bool>();
	}
	else if (dtype == "float64" || dtype == "double" || dtype == "float")
	{
		if (components == 2)
			return f.template operator()<Vec2>();
		if (components == 3)
			return f.template operator()<Vec3>();
		if (components == 4)
			return f.template operator()<Vec4>();
	}
	throw py::value_error(
		"unsupported attribute type: dtype '" + dtype + "' with " + std::to_string(components) +
		" component(s) (float64 with 1 to 4, or float32, int8 to int64, uint8 to uint64, bool with 1)");
}

// Calls f(attribute) with the typed attribute of this name and kind, if any;
// returns false when there is none.
template <typename MAP, typename CELL, typename F>
bool with_existing(const MAP& m, const std::string& name, F&& f)
{
	bool found = false;
	std::apply(
		[&](auto... t) {
			(
				[&] {
					using T = decltype(t);
					if (found)
						return;
					if (auto a = get_attribute<T, CELL>(m, name))
					{
						found = true;
						f(std::shared_ptr<AttributeArray<T>>(a));
					}
				}(),
				...);
		},
		Types{});
	return found;
}

template <typename MAP>
py::array get_array(PyMap<MAP>& w, const std::string& name, Kind k)
{
	return with_kind<MAP>(k, [&]<typename CELL>() {
		py::array out;
		const uint32 rows = container_of<CELL::ORBIT>(w.m).end_index();
		if (!with_existing<MAP, CELL>(w.m, name, [&](auto a) { out = attribute_array(a, rows, w.views); }))
			throw py::key_error(std::string("no ") + kind_name(k) + " attribute named '" + name + "'");
		return out;
	});
}

AttributeRule rule_of(const std::string& name)
{
	if (name == "none")
		return AttributeRule::None;
	if (name == "copy")
		return AttributeRule::Copy;
	if (name == "interpolate")
		return AttributeRule::Interpolate;
	throw py::value_error("unknown attribute rule '" + name + "' (none, copy or interpolate)");
}

const char* rule_name(AttributeRule r)
{
	switch (r)
	{
	case AttributeRule::None:
		return "none";
	case AttributeRule::Copy:
		return "copy";
	case AttributeRule::Interpolate:
		return "interpolate";
	case AttributeRule::Callback:
		break;
	}
	return "callback";
}

template <typename MAP>
void bind_attribute_methods(py::class_<PyMap<MAP>>& c)
{
	using W = PyMap<MAP>;
	c.def(
		 "add_attribute",
		 [](W& w, const std::string& name, const std::string& kind, const std::string& dtype, int components) {
			 const Kind k = kind_of(kind);
			 if (name.rfind("__", 0) == 0)
				 throw py::value_error("names starting with '__' are the library's own");
			 with_kind<MAP>(k, [&]<typename CELL>() {
				 if (container_of<CELL::ORBIT>(w.m).find(name) != nullptr)
					 throw py::value_error(std::string("a ") + kind_name(k) + " attribute named '" + name +
										   "' exists already");
				 with_type(dtype, components, [&]<typename T>() { add_attribute<T, CELL>(w.m, name); });
			 });
			 return get_array(w, name, k);
		 },
		 py::arg("name"), py::arg("kind"), py::arg("dtype") = "float64", py::arg("components") = 1,
		 "Adds an attribute (values at their default: 0, False, zero vectors) on the cells of a kind, indexing "
		 "the kind if needed, and returns its array (see attribute()). dtype: float64 (1 to 4 components), "
		 "float32, int8, int16, int32, int64, uint8, uint16, uint32, uint64 or bool.")
		.def(
			"attribute",
			[](W& w, const std::string& name, const std::string& kind) { return get_array(w, name, kind_of(kind)); },
			py::arg("name"), py::arg("kind"),
			"The values of an attribute, one row per cell id (id_bound(kind) rows): an array aliasing the "
			"map's memory (writes go to the map) below 2^28 ids, a read-only copy beyond. KeyError when absent.")
		.def(
			"set_attribute",
			[](W& w, const std::string& name, const std::string& kind, const py::array& values) {
				const Kind k = kind_of(kind);
				with_kind<MAP>(k, [&]<typename CELL>() {
					const uint32 rows = container_of<CELL::ORBIT>(w.m).end_index();
					if (!with_existing<MAP, CELL>(w.m, name, [&](auto a) { assign_attribute(*a, rows, values); }))
						throw py::key_error(std::string("no ") + kind_name(k) + " attribute named '" + name + "'");
				});
			},
			py::arg("name"), py::arg("kind"), py::arg("values"),
			"Copies values (id_bound(kind) rows) into an attribute.")
		.def(
			"remove_attribute",
			[](W& w, const std::string& name, const std::string& kind) {
				const Kind k = kind_of(kind);
				if (k == Kind::Vertex && name == "position")
					throw py::value_error("the position attribute cannot be removed");
				with_kind<MAP>(k, [&]<typename CELL>() {
					if (!with_existing<MAP, CELL>(w.m, name, [&](auto a) { remove_attribute(w.m, a); }))
						throw py::key_error(std::string("no ") + kind_name(k) + " attribute named '" + name + "'");
				});
			},
			py::arg("name"), py::arg("kind"),
			"Removes an attribute. Arrays already returned keep the values (they own a reference).")
		.def(
			"set_attribute_rule",
			[](W& w, const std::string& name, const std::string& kind, const std::string& rule) {
				const Kind k = kind_of(kind);
				const AttributeRule r = rule_of(rule);
				with_kind<MAP>(k, [&]<typename CELL>() {
					if (!with_existing<MAP, CELL>(w.m, name, [&](auto a) { set_attribute_rule(w.m, a, r); }))
						throw py::key_error(std::string("no ") + kind_name(k) + " attribute named '" + name + "'");
				});
			},
			py::arg("name"), py::arg("kind"), py::arg("rule"),
			"Sets what cells made by the operators and algorithms get in an attribute: 'copy' (a part of a "
			"cell takes its value, a new vertex its edge's first end's), 'interpolate' (the weighted mean of "
			"the parents for float attributes, else copy) or 'none' (the default value). New attributes have "
			"'copy' for integers and bool, 'interpolate' for floats.")
		.def(
			"attribute_rule",
			[](W& w, const std::string& name, const std::string& kind) {
				const Kind k = kind_of(kind);
				std::string out;
				with_kind<MAP>(k, [&]<typename CELL>() {
					if (!with_existing<MAP, CELL>(w.m, name, [&](auto a) { out = rule_name(attribute_rule(*a)); }))
						throw py::key_error(std::string("no ") + kind_name(k) + " attribute named '" + name + "'");
				});
				return out;
			},
			py::arg("name"), py::arg("kind"),
			"The rule of an attribute: 'none', 'copy', 'interpolate' or 'callback' (set from C++).")
		.def(
			"record_origins",
			[](W& w, const std::string& kind, const std::string& name) {
				const Kind k = kind_of(kind);
				with_kind<MAP>(k, [&]<typename CELL>() {
					if (!record_origins<CELL>(w.m, name))
						throw py::value_error(std::string("a ") + kind_name(k) + " attribute named '" + name +
											  "' exists already (or the name is reserved)");
				});
				return get_array(w, name, k);
			},
			py::arg("kind") = "face", py::arg("name") = "origin",
			"Adds a uint32 attribute holding each cell's own id, which the cells made later by operators and "
			"algorithms copy from their parent: after an edit, it names the input cell each cell comes from "
			"(4294967295 for none, e.g. a face filling a hole). Returns its array.")
		.def(
			"attributes",
			[](W& w, const std::string& kind) {
				const Kind k = kind_of(kind);
				py::list out;
				with_kind<MAP>(k, [&]<typename CELL>() {
					for (const auto& a : container_of<CELL::ORBIT>(w.m).attributes())
					{
						const std::string& name = a->name();
						if (name.rfind("__", 0) == 0)
							continue;
						with_existing<MAP, CELL>(w.m, name, [&](auto typed) {
							using T = typename std::decay_t<decltype(*typed)>::value_type;
							out.append(py::make_tuple(name, dtype_name<T>(), ValueLayout<T>::components));
						});
					}
				});
				return out;
			},
			py::arg("kind"), "The attributes of a kind Python can read: [(name, dtype, components)].");
}

} // namespace

void bind_attributes(py::module_& mod)
{
	auto surface = py::class_<Surface>(mod.attr("CMap2"));
	bind_attribute_methods(surface);
	auto volume = py::class_<VolumeMesh>(mod.attr("CMap3"));
	bind_attribute_methods(volume);
	auto gsurface = py::class_<GSurface>(mod.attr("GMap2"));
	bind_attribute_methods(gsurface);
	auto gvolume = py::class_<GVolumeMesh>(mod.attr("GMap3"));
	bind_attribute_methods(gvolume);
	auto complex = py::class_<PyMap<IncidenceGraph>>(mod.attr("IncidenceGraph"));
	bind_attribute_methods(complex);
}

} // namespace cgogn::python
