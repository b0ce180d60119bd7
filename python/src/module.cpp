// SPDX-License-Identifier: MIT
// The compiled part of the `cgogn` Python package (cgogn._cgogn): the library's
// errors become Python exceptions carrying its messages.
#include <cgogn/io.h>
#include <cgogn/render.h>

#include "py_map.h"
#include "py_nmap.h"

PYBIND11_MODULE(_cgogn, m)
{
	m.doc() = "cgogn: combinatorial maps for mesh processing (compiled core; use the `cgogn` package)";
	static py::exception<cgogn::Error> error(m, "Error", PyExc_RuntimeError);
	static py::exception<cgogn::io::Error> io_error(m, "IOError", error.ptr());
	static py::exception<cgogn::render::RenderError> render_error(m, "RenderError", error.ptr());
	py::register_exception_translator([](std::exception_ptr p) {
		try
		{
			if (p)
				std::rethrow_exception(p);
		}
		catch (const cgogn::io::Error& e)
		{
			io_error(e.what());
		}
		catch (const cgogn::render::RenderError& e)
		{
			render_error(e.what());
		}
		catch (const cgogn::Error& e)
		{
			error(e.what());
		}
	});
	cgogn::python::bind_maps(m);
	cgogn::python::bind_incidence_graph(m); // before the attribute methods, which it gets too
	cgogn::python::bind_attributes(m);
	cgogn::python::bind_operators(m);
	cgogn::python::bind_algorithms(m);
	cgogn::python::bind_nmaps(m);
	cgogn::python::bind_graph(m);
	cgogn::python::bind_mrmap(m);
	cgogn::python::bind_mrmap3(m);
	cgogn::python::bind_map_files(m); // methods of the classes bound above
#ifdef CGOGN_PYTHON_HAS_DISTRIBUTED
	cgogn::python::bind_distributed(m);
#endif
}
