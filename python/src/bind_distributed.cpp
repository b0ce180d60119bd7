// SPDX-License-Identifier: MIT
// The distributed layer on Python maps (built with it only): partitioning.
#include <cgogn/distributed/partition.h>

#include "py_map.h"

#include <pybind11/stl.h>

namespace cgogn::python
{

namespace
{

template <typename MAP>
void bind_partition(py::class_<PyMap<MAP>>& c, const char* cells)
{
	c.def(
		"partition",
		[](PyMap<MAP>& w, uint32 parts, const std::string& attribute, double tolerance, int seed) {
			dist::PartitionOptions o;
			o.attribute = attribute;
			o.imbalance_tolerance = tolerance;
			o.seed = seed;
			dist::PartitionReport r;
			{
				py::gil_scoped_release release;
				r = dist::partition(w.m, parts, o);
			}
			py::dict d;
			d["part_sizes"] = r.part_sizes;
			d["imbalance"] = r.imbalance;
			d["interior_facets"] = r.nb_interior_facets;
			d["cut_facets"] = r.nb_cut_facets;
			d["cut_ratio"] = r.cut_ratio();
			d["part_components"] = r.part_components;
			d["parts_connected"] = r.parts_connected();
			d["map_components"] = r.nb_map_components;
			return d;
		},
		py::arg("parts"), py::arg("attribute") = "part", py::arg("tolerance") = 1.03, py::arg("seed") = 0,
		(std::string("Splits the ") + cells +
		 " into parts with METIS (fewest facets between parts, parts in one piece when the mesh is), writes each "
		 "one's part to the uint32 attribute `attribute` of that kind, and returns the report: part_sizes, "
		 "imbalance (largest part over the mean), interior_facets, cut_facets, cut_ratio, part_components, "
		 "parts_connected, map_components. ValueError on bad arguments (the map is then unchanged).")
			.c_str());
}

} // namespace

void bind_distributed(py::module_& mod)
{
	auto surface = py::class_<PyMap<CMap2>>(mod.attr("CMap2"));
	bind_partition(surface, "faces");
	auto volume = py::class_<PyMap<CMap3>>(mod.attr("CMap3"));
	bind_partition(volume, "volumes");
}

} // namespace cgogn::python
