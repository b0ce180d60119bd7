// SPDX-License-Identifier: MIT
// The generalized maps of any dimension: the classes GMapN1 ... GMapN4.
#include <cgogn/core/properties/gmap_properties.h>

#include "py_nmap_class.h"

namespace cgogn::python
{

template <uint32 D>
py::object wrap_nmap(GMapN<D>&& m)
{
	auto w = std::make_unique<PyNMap<GMapN<D>>>();
	w->m = std::move(m);
	return py::cast(std::move(w));
}
template py::object wrap_nmap(GMapN<1>&&);
template py::object wrap_nmap(GMapN<2>&&);
template py::object wrap_nmap(GMapN<3>&&);
template py::object wrap_nmap(GMapN<4>&&);

py::object new_gmapn(uint32 D)
{
	py::object out;
	with_dimension<MAX_PY_DIMENSION>(D, [&]<uint32 K>() {
		if constexpr (K >= 1)
			out = py::cast(std::make_unique<PyNMap<GMapN<K>>>());
	});
	return out;
}

namespace
{

template <uint32 D>
void bind_gmapn_class(py::module_& mod)
{
	using W = PyNMap<GMapN<D>>;
	bind_nmap_class<GMapN<D>>(mod)
		.def(
			"is_orientable", [](const W& w) { return is_orientable(w.m); },
			"True when every connected component can be oriented (two-colouring of the darts). O(darts).")
		.def(
			"to_cmap", [](const W& w) { return w.convert(); },
			"The combinatorial map of an orientable G-map (half the darts), with every attribute; raises "
			"cgogn.Error when the map is not orientable. O(darts x attributes).");
}

} // namespace

void bind_gmapn(py::module_& mod)
{
	bind_gmapn_class<1>(mod);
	bind_gmapn_class<2>(mod);
	bind_gmapn_class<3>(mod);
	bind_gmapn_class<4>(mod);
}

} // namespace cgogn::python
