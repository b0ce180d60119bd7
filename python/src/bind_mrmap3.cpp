// SPDX-License-Identifier: MIT
// The multiresolution 3-map: hexahedral levels, the positions, faces and
// hexahedra of a level as NumPy arrays (rows in the level's vertex order),
// extraction of a level as a CMap3.
#include <cgogn/io/map_file.h>

#include "py_map.h"

#include <memory>
#include <string>
#include <vector>

namespace cgogn::python
{

namespace
{

using MRVertex3 = MRMap3::Vertex;

/// A multiresolution volume mesh as Python sees it: the map and its
/// `position` vertex attribute.
struct PyMRMap3
{
	MRMap3 m;
	std::shared_ptr<AttributeArray<Vec3>> pos;

	explicit PyMRMap3(CMap3&& base) : m(std::move(base))
	{
		pos = get_attribute<Vec3, MRVertex3>(m, "position");
		if (!pos)
			pos = add_attribute<Vec3, MRVertex3>(m, "position");
	}
	MRLevelView3 level(uint32 l) const
	{
		if (l > max_level(m))
			throw py::index_error("level " + std::to_string(l) + " above the finest level " +
								  std::to_string(max_level(m)));
		return MRLevelView3(m, l);
	}
	/// The vertices of level l in traversal order, and each one's row by line.
	std::pair<std::vector<MRVertex3>, std::vector<uint32>> vertices(uint32 l) const
	{
		const MRLevelView3 v = level(l);
		std::vector<MRVertex3> order;
		std::vector<uint32> row(detail::mr3_container<Orbit::PHI21_PHI31>(detail::mr_state_of(m)).end_index(),
								INVALID_INDEX);
		foreach_cell(v, [&](MRVertex3 x) {
			row[index_of(v, x)] = uint32(order.size());
			order.push_back(x);
		});
		return {std::move(order), std::move(row)};
	}
};

} // namespace

void bind_mrmap3(py::module_& mod)
{
	using W = PyMRMap3;
	py::class_<W>(mod, "MRMap3",
				  "A multiresolution hexahedral mesh: level 0 and its hexahedral refinements, stored as the finest "
				  "map with a level, an edge id and a face id per dart. Vertices have a position at every level "
				  "(a new vertex starts at the centroid of the edge, face or hexahedron it is the middle of); "
				  "arrays of a level list its vertices in the order of positions(level).")
		.def(py::init([](const VolumeMesh& s) {
				 CMap3 copy;
				 io::load_map_from_bytes(copy, io::save_map_to_bytes(s.m));
				 return std::make_unique<W>(std::move(copy));
			 }),
			 py::arg("volume"),
			 "The hierarchy whose level 0 is a copy of `volume` (its attributes included). ValueError when "
			 "the mesh has attributes on the cells of one volume.")
		.def_property_readonly(
			"max_level", [](const W& w) { return max_level(w.m); }, "The finest level.")
		.def_property(
			"current_level", [](const W& w) { return current_level(w.m); },
			[](W& w, uint32 l) {
				w.level(l);
				set_current_level(w.m, l);
			},
			"The level read by default; setting it above max_level raises IndexError.")
		.def(
			"add_level",
			[](W& w, const std::string& r) {
				if (r != "hexahedral")
					throw py::value_error("refinement must be 'hexahedral', not '" + r + "'");
				add_level(w.m, Refinement::Hexahedral);
			},
			py::arg("refinement") = "hexahedral",
			"Cuts every hexahedron of the finest level into 8 ('hexahedral'); ValueError when a volume is not "
			"a hexahedron. O(darts).")
		.def(
			"remove_finest_level", [](W& w) { remove_finest_level(w.m); }, "Undoes the last level. O(darts).")
		.def(
			"nb_darts_at_level", [](const W& w, uint32 l) { return nb_darts_at_level(w.m, l); }, py::arg("level"),
			"The darts made at a level.")
		.def(
			"counts", [](const W& w, uint32 l) { return py::cast(f_vector(w.level(l))); }, py::arg("level"),
			"[vertices, edges, faces, volumes] of a level.")
		.def(
			"positions",
			[](const W& w, uint32 l) {
				const MRLevelView3 v = w.level(l);
				const std::vector<MRVertex3> order = w.vertices(l).first;
				py::array_t<double> out({py::ssize_t(order.size()), py::ssize_t(3)});
				auto a = out.mutable_unchecked<2>();
				for (std::size_t i = 0; i < order.size(); ++i)
				{
					const Vec3& p = value<Vec3>(v, *w.pos, order[i]);
					for (int c = 0; c < 3; ++c)
						a(py::ssize_t(i), c) = p[c];
				}
				return out;
			},
			py::arg("level"), "(V, 3) float64 copy of the vertex positions of a level, one row per vertex.")
		.def(
			"set_positions",
			[](W& w, uint32 l, const py::array_t<double, py::array::c_style | py::array::forcecast>& values) {
				const MRLevelView3 v = w.level(l);
				const std::vector<MRVertex3> order = w.vertices(l).first;
				if (values.ndim() != 2 || std::size_t(values.shape(0)) != order.size() || values.shape(1) != 3)
					throw py::value_error("positions must have shape (" + std::to_string(order.size()) + ", 3)");
				auto a = values.unchecked<2>();
				for (std::size_t i = 0; i < order.size(); ++i)
					(*w.pos)[index_of(v, order[i])] =
						Vec3(a(py::ssize_t(i), 0), a(py::ssize_t(i), 1), a(py::ssize_t(i), 2));
			},
			py::arg("level"), py::arg("positions"),
			"Writes the vertex positions of a level (the rows of positions(level)); other levels keep theirs.")
		.def(
			"hexahedra",
			[](const W& w, uint32 l) {
				const MRLevelView3 v = w.level(l);
				const std::vector<uint32> row = w.vertices(l).second;
				std::vector<MRMap3::Volume> volumes;
				foreach_cell(v, [&](MRMap3::Volume x) { volumes.push_back(x); });
				py::array_t<uint32> out({py::ssize_t(volumes.size()), py::ssize_t(8)});
				auto a = out.mutable_unchecked<2>();
				for (std::size_t i = 0; i < volumes.size(); ++i)
				{
					// a face's corners in phi1 order, then the corner joined to each by an edge
					Dart d = volumes[i].dart;
					for (py::ssize_t j = 0; j < 4; ++j, d = phi1(v, d))
					{
						const Dart up = phi1(v, phi1(v, phi2(v, d)));
						a(py::ssize_t(i), j) = row[index_of(v, MRVertex3(d))];
						a(py::ssize_t(i), j + 4) = row[index_of(v, MRVertex3(up))];
					}
				}
				return out;
			},
			py::arg("level"),
			"(W, 8) uint32 array of the vertex rows of the hexahedra of a level: the corners of one face in "
			"order, then the opposite corners, column j + 4 joined to column j by an edge.")
		.def(
			"extract_level",
			[](const W& w, uint32 l) {
				w.level(l);
				auto s = std::make_unique<VolumeMesh>();
				s->m = extract_level(w.m, l);
				s->ensure_position();
				return s;
			},
			py::arg("level"), "Level l as a CMap3, with every attribute's values at that level.")
		.def(
			"check_integrity", [](const W& w) { return integrity_report(check_integrity(w.m)); },
			"Checks every invariant at every level; returns {'ok': bool, 'nb_errors': int, 'messages': [str]}.")
		.def("__repr__", [](const W& w) {
			return "<cgogn.MRMap3 levels=0.." + std::to_string(max_level(w.m)) +
				   " current=" + std::to_string(current_level(w.m)) + ">";
		});
}

} // namespace cgogn::python
