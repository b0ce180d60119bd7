// SPDX-License-Identifier: MIT
// The multiresolution 3-map: hexahedral and tetrahedral-octahedral levels,
// the positions and cells of a level as NumPy arrays (rows in the level's
// vertex order), adaptive refinement and coarsening of chosen hexahedra,
// extraction of a level as a CMap3.
#include <cgogn/io/map_file.h>

#include "py_map.h"

#include <algorithm>
#include <array>
#include <memory>
#include <stdexcept>
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

	explicit PyMRMap3(CMap3&& base) : PyMRMap3(MRMap3(std::move(base)))
	{
	}
	explicit PyMRMap3(MRMap3&& h) : m(std::move(h))
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
	/// The volumes of level l in traversal order (the rows of hexahedra(l)).
	std::vector<MRMap3::Volume> volumes(uint32 l) const
	{
		std::vector<MRMap3::Volume> r;
		foreach_cell(level(l), [&](MRMap3::Volume x) { r.push_back(x); });
		return r;
	}
	/// The (n, k) array of the vertex rows of the volumes of level l with k
	/// corners (4: tetrahedra, 6: octahedra), oriented by the positions: a
	/// tetrahedron's fourth corner on the side of the normal of its first
	/// three; an octahedron's first three corners counterclockwise seen from
	/// outside, column j + 3 opposite to column j.
	py::array_t<uint32> corner_rows(uint32 l, uint32 k) const
	{
		const MRLevelView3 v = level(l);
		const std::vector<uint32> row = vertices(l).second;
		std::vector<std::array<uint32, 6>> cells;
		for (MRMap3::Volume w : volumes(l))
		{
			uint32 faces = 0;
			foreach_incident_face(v, w, [&](MRMap3::Face) { ++faces; });
			if (faces != 2 * k - 4)
				continue;
			const Dart d = w.dart;
			const auto opposite = [&](Dart x) { return phi_1(v, phi2(v, x)); };
			std::array<Dart, 6> c{d, phi1(v, d), phi_1(v, d)};
			if (k == 4)
				c[3] = opposite(d);
			else
				c = {c[0], c[1], c[2], opposite(c[1]), opposite(c[2]), opposite(c[0])};
			const auto p = [&](Dart x) { return value<Vec3>(v, *pos, MRVertex3(x)); };
			const Vec3 normal = (p(c[1]) - p(c[0])).cross(p(c[2]) - p(c[0]));
			// > 0: the fourth corner on the normal's side; the normal outwards
			const double side = k == 4 ? normal.dot(p(c[3]) - p(c[0]))
									   : -normal.dot(p(c[3]) + p(c[4]) + p(c[5]) - p(c[0]) - p(c[1]) - p(c[2]));
			if (side < 0)
			{
				std::swap(c[1], c[2]);
				std::swap(c[4], c[5]);
			}
			std::array<uint32, 6> r{};
			for (uint32 j = 0; j < k; ++j)
				r[j] = row[index_of(v, MRVertex3(c[j]))];
			cells.push_back(r);
		}
		py::array_t<uint32> out({py::ssize_t(cells.size()), py::ssize_t(k)});
		auto a = out.mutable_unchecked<2>();
		for (std::size_t i = 0; i < cells.size(); ++i)
			for (uint32 j = 0; j < k; ++j)
				a(py::ssize_t(i), py::ssize_t(j)) = cells[i][j];
		return out;
	}
	/// The volumes of level l of the given rows; IndexError for a row out of range.
	std::vector<MRMap3::Volume> chosen(uint32 l, const std::vector<uint32>& rows) const
	{
		const std::vector<MRMap3::Volume> all = volumes(l);
		std::vector<MRMap3::Volume> r;
		for (uint32 i : rows)
		{
			if (i >= all.size())
				throw py::index_error("no volume of row " + std::to_string(i) + " at level " + std::to_string(l));
			r.push_back(all[i]);
		}
		return r;
	}
};

} // namespace

py::object mrmap3_from_bytes(std::string_view bytes, const std::string& name)
{
	MRMap3 h{CMap3()};
	io::load_map_from_bytes(h, bytes, name);
	return py::cast(std::make_unique<PyMRMap3>(std::move(h)));
}

void bind_mrmap3(py::module_& mod)
{
	using W = PyMRMap3;
	py::class_<W> cls(
		mod, "MRMap3",
		"A multiresolution volume mesh: level 0 and its hexahedral or tetrahedral-octahedral refinements, "
		"stored as the finest map with a level, an edge id and a face id per dart. Vertices have a "
		"position at every level (a new vertex starts at the centroid of the edge, face or volume it "
		"is the middle of); "
		"arrays of a level list its vertices in the order of positions(level).");
	bind_hierarchy_file_methods(cls);
	cls.def(py::init([](const VolumeMesh& s) {
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
				if (r != "hexahedral" && r != "tetra-octa")
					throw py::value_error("refinement must be 'hexahedral' or 'tetra-octa', not '" + r + "'");
				try
				{
					add_level(w.m, r == "hexahedral" ? Refinement::Hexahedral : Refinement::TetraOcta);
				}
				catch (const std::invalid_argument& e)
				{
					throw py::value_error(e.what());
				}
			},
			py::arg("refinement") = "hexahedral",
			"Refines every volume of the finest level: 'hexahedral' cuts every hexahedron into 8; 'tetra-octa' "
			"cuts every tetrahedron into 4 tetrahedra and an octahedron and every octahedron into 6 octahedra "
			"and 8 tetrahedra. ValueError, the map unchanged, when a volume does not fit the pattern. O(darts).")
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
				const std::vector<MRMap3::Volume> volumes = w.volumes(l);
				py::array_t<uint32> out({py::ssize_t(volumes.size()), py::ssize_t(8)});
				auto a = out.mutable_unchecked<2>();
				for (std::size_t i = 0; i < volumes.size(); ++i)
				{
					// read at its own level, where a coarser hexahedron has no
					// midpoint of a finer neighbour on its edges: a face's corners
					// in order, then the corner joined to each by an edge
					const uint32 k = volume_level(v, volumes[i]);
					const MRLevelView3 vk(w.m, k);
					Dart d;
					foreach_dart_of_orbit(v, volumes[i], [&](Dart x) {
						d = x;
						return dart_level(w.m, x) > k;
					});
					uint32 nb = 0;
					foreach_dart_of_orbit(vk, MRMap3::Volume(d), [&](Dart) { ++nb; });
					if (nb != 24 || codegree(vk, MRMap3::Face(d)) != 4)
						throw py::value_error("the volume of row " + std::to_string(i) + " of level " +
											  std::to_string(l) +
											  " is not a hexahedron (see tetrahedra() and octahedra())");
					for (py::ssize_t j = 0; j < 4; ++j, d = phi1(vk, d))
					{
						const Dart up = phi1(vk, phi1(vk, phi2(vk, d)));
						a(py::ssize_t(i), j) = row[index_of(v, MRVertex3(d))];
						a(py::ssize_t(i), j + 4) = row[index_of(v, MRVertex3(up))];
					}
				}
				return out;
			},
			py::arg("level"),
			"(W, 8) uint32 array of the vertex rows of the hexahedra of a level: the corners of one face in "
			"order, then the opposite corners, column j + 4 joined to column j by an edge. A hexahedron of a "
			"coarser level (adaptive refinement) gives its own 8 corners. ValueError when a volume of the level "
			"is not a hexahedron.")
		.def(
			"tetrahedra", [](const W& w, uint32 l) { return w.corner_rows(l, 4); }, py::arg("level"),
			"(T, 4) uint32 array of the vertex rows of the tetrahedra of a level, in traversal order, the fourth "
			"corner on the side of the normal of the first three (positively oriented).")
		.def(
			"octahedra", [](const W& w, uint32 l) { return w.corner_rows(l, 6); }, py::arg("level"),
			"(O, 6) uint32 array of the vertex rows of the octahedra of a level, in traversal order: the "
			"corners of one face counterclockwise seen from outside, then the opposite corners, column j + 3 "
			"opposite to column j.")
		.def(
			"volume_levels",
			[](const W& w, uint32 l) {
				const MRLevelView3 v = w.level(l);
				std::vector<uint32> out;
				for (MRMap3::Volume x : w.volumes(l))
					out.push_back(volume_level(v, x));
				return to_numpy(std::move(out));
			},
			py::arg("level"), "The level at which each hexahedron of a level (rows of hexahedra) was made.")
		.def(
			"subdivide_volumes",
			[](W& w, uint32 l, const std::vector<uint32>& rows, bool balance) {
				const std::vector<MRMap3::Volume> chosen = w.chosen(l, rows);
				const uint32 before = current_level(w.m);
				set_current_level(w.m, l);
				try
				{
					for (MRMap3::Volume x : chosen)
						if (!volume_is_subdivided(w.m, x))
							subdivide_volume(w.m, x, balance);
				}
				catch (const std::invalid_argument& e)
				{
					set_current_level(w.m, std::min(before, max_level(w.m)));
					throw py::value_error(e.what());
				}
				set_current_level(w.m, std::min(before, max_level(w.m)));
			},
			py::arg("level"), py::arg("rows"), py::arg("balance") = true,
			"Cuts the hexahedra of a level given by their rows in hexahedra(level) into 8 (adaptive "
			"refinement; with balance, coarser neighbours sharing an edge are cut first). Hexahedra cut "
			"already are skipped; ValueError for a volume that is not a hexahedron.")
		.def(
			"coarsen_volumes",
			[](W& w, uint32 l, const std::vector<uint32>& rows) {
				const std::vector<MRMap3::Volume> chosen = w.chosen(l, rows);
				const uint32 before = current_level(w.m);
				set_current_level(w.m, l);
				uint32 done = 0;
				for (MRMap3::Volume x : chosen)
					if (can_coarsen_volume(w.m, x))
					{
						coarsen_volume(w.m, x);
						++done;
					}
				set_current_level(w.m, std::min(before, max_level(w.m)));
				return done;
			},
			py::arg("level"), py::arg("rows"),
			"Removes the children of the hexahedra of a level given by their rows (those that can be "
			"coarsened: children without children, no finer neighbour two levels down); returns how many.")
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
