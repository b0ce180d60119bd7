// SPDX-License-Identifier: MIT
// The combinatorial maps of any dimension: the classes CMapN1 ... CMapN4.
#include "py_nmap_class.h"

namespace cgogn::python
{

template <uint32 D>
py::object wrap_nmap(CMapN<D>&& m)
{
	auto w = std::make_unique<PyNMap<CMapN<D>>>();
	w->m = std::move(m);
	return py::cast(std::move(w));
}
template py::object wrap_nmap(CMapN<1>&&);
template py::object wrap_nmap(CMapN<2>&&);
template py::object wrap_nmap(CMapN<3>&&);
template py::object wrap_nmap(CMapN<4>&&);

py::object new_cmapn(uint32 D)
{
	py::object out;
	with_dimension<MAX_PY_DIMENSION>(D, [&]<uint32 K>() {
		if constexpr (K >= 1)
			out = py::cast(std::make_unique<PyNMap<CMapN<K>>>());
	});
	return out;
}

namespace
{

template <uint32 D>
void bind_cmapn_class(py::module_& mod)
{
	bind_nmap_class<CMapN<D>>(mod).def(
		"to_gmap", [](const PyNMap<CMapN<D>>& w) { return w.convert(); },
		"The generalized map of this map (twice the darts), with every attribute. O(darts x attributes).");
}

} // namespace

void bind_cmapn(py::module_& mod)
{
	bind_cmapn_class<1>(mod);
	bind_cmapn_class<2>(mod);
	bind_cmapn_class<3>(mod);
	bind_cmapn_class<4>(mod);
}

} // namespace cgogn::python
