// SPDX-License-Identifier: MIT
// The multiresolution 2-map: levels, the positions and faces of a level as
// NumPy arrays (rows in the level's vertex order), extraction of a level as
// a CMap2, adaptive refinement by face row, analysis, synthesis and filters,
// .cgmap files and pickling.
#include <cgogn/io/map_file.h>
#include <cgogn/modeling/multiresolution.h>

#include "py_map.h"

#include <memory>
#include <string>
#include <vector>

namespace cgogn::python
{

namespace
{

using MRVertex = MRMap2::Vertex;
using MRFace = MRMap2::Face;

/// A multiresolution map as Python sees it: the map, its `position` and
/// `details` vertex attributes.
struct PyMRMap2
{
	MRMap2 m;
	std::shared_ptr<AttributeArray<Vec3>> pos, details;

	explicit PyMRMap2(CMap2&& base) : m(std::move(base))
	{
		attach();
	}
	/// A hierarchy read from a file (one without `position` or `details`
	/// gets them).
	explicit PyMRMap2(MRMap2&& h) : m(std::move(h))
	{
		attach();
	}
	void attach()
	{
		pos = get_attribute<Vec3, MRVertex>(m, "position");
		if (!pos)
			pos = add_attribute<Vec3, MRVertex>(m, "position");
		details = get_attribute<Vec3, MRVertex>(m, "details");
		if (!details)
			details = add_attribute<Vec3, MRVertex>(m, "details");
	}
	MRLevelView2 level(uint32 l) const
	{
		if (l > max_level(m))
			throw py::index_error("level " + std::to_string(l) + " above the finest level " +
								  std::to_string(max_level(m)));
		return MRLevelView2(m, l);
	}
	/// The vertices of level l in traversal order, and each one's row by line.
	std::pair<std::vector<MRVertex>, std::vector<uint32>> vertices(uint32 l) const
	{
		const MRLevelView2 v = level(l);
		std::vector<MRVertex> order;
		std::vector<uint32> row(detail::mr_container<Orbit::PHI21>(detail::mr_state_of(m)).end_index(), INVALID_INDEX);
		foreach_cell(v, [&](MRVertex x) {
			row[index_of(v, x)] = uint32(order.size());
			order.push_back(x);
		});
		return {std::move(order), std::move(row)};
	}
	/// (V, 3) copy of the values of a vertex attribute at level l, one row per
	/// vertex in the order of vertices(l).
	py::array_t<double> rows(const AttributeArray<Vec3>& attr, uint32 l) const
	{
		const MRLevelView2 v = level(l);
		const std::vector<MRVertex> order = vertices(l).first;
		py::array_t<double> out({py::ssize_t(order.size()), py::ssize_t(3)});
		auto a = out.mutable_unchecked<2>();
		for (std::size_t i = 0; i < order.size(); ++i)
		{
			const Vec3& p = value<Vec3>(v, attr, order[i]);
			for (int c = 0; c < 3; ++c)
				a(py::ssize_t(i), c) = p[c];
		}
		return out;
	}
	std::vector<MRFace> faces(uint32 l) const
	{
		std::vector<MRFace> out;
		foreach_cell(level(l), [&](MRFace f) { out.push_back(f); });
		return out;
	}
};

Refinement refinement_of(const std::string& name)
{
	if (name == "triangular")
		return Refinement::Triangular;
	if (name == "quadrangular")
		return Refinement::Quadrangular;
	if (name == "mixed")
		return Refinement::Mixed;
	throw py::value_error("refinement must be 'triangular', 'quadrangular' or 'mixed', not '" + name + "'");
}

modeling::MRBank bank_of(const std::string& name)
{
	if (name == "linear")
		return modeling::MRBank::Linear;
	if (name == "loop")
		return modeling::MRBank::Loop;
	if (name == "catmull_clark")
		return modeling::MRBank::CatmullClark;
	throw py::value_error("bank must be 'linear', 'loop' or 'catmull_clark', not '" + name + "'");
}

} // namespace

py::object mrmap2_from_bytes(std::string_view bytes, const std::string& name)
{
	MRMap2 h{CMap2()};
	io::load_map_from_bytes(h, bytes, name);
	return py::cast(std::make_unique<PyMRMap2>(std::move(h)));
}

void bind_mrmap(py::module_& mod)
{
	using W = PyMRMap2;
	py::class_<W> cls(mod, "MRMap2",
					  "A multiresolution surface: level 0 and its refinements, stored as the finest map with a level "
					  "and an edge id per dart. Vertices have a position at every level; arrays of a level list its "
					  "vertices in the order of positions(level).");
	bind_hierarchy_file_methods(cls);
	cls.def(py::init([](const Surface& s) {
				CMap2 copy;
				merge(copy, s.m);
				return std::make_unique<W>(std::move(copy));
			}),
			py::arg("surface"), "The hierarchy whose level 0 is a copy of `surface` (its attributes included).")
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
			"add_level", [](W& w, const std::string& r) { add_level(w.m, refinement_of(r)); },
			py::arg("refinement") = "quadrangular",
			"Refines every face of the finest level: 'triangular' (1 to 4), 'quadrangular' (a k-gon to k quads) "
			"or 'mixed'. New vertices get the midpoints and centroids of the level below. O(darts).")
		.def(
			"remove_finest_level", [](W& w) { remove_finest_level(w.m); }, "Undoes the last level. O(darts).")
		.def(
			"nb_darts_at_level", [](const W& w, uint32 l) { return nb_darts_at_level(w.m, l); }, py::arg("level"),
			"The darts made at a level.")
		.def(
			"counts",
			[](const W& w, uint32 l) {
				const MRLevelView2 v = w.level(l);
				return py::make_tuple(nb_cells<MRVertex>(v), nb_cells<MRMap2::Edge>(v), nb_cells<MRFace>(v));
			},
			py::arg("level"), "(vertices, edges, faces) of a level.")
		.def(
			"positions", [](const W& w, uint32 l) { return w.rows(*w.pos, l); }, py::arg("level"),
			"(V, 3) float64 copy of the vertex positions of a level, one row per vertex.")
		.def(
			"set_positions",
			[](W& w, uint32 l, const py::array_t<double, py::array::c_style | py::array::forcecast>& values) {
				const MRLevelView2 v = w.level(l);
				const auto vertices = w.vertices(l);
				const auto& order = vertices.first;
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
			"faces_csr",
			[](const W& w, uint32 l) {
				const MRLevelView2 v = w.level(l);
				const auto vertices = w.vertices(l);
				const auto& row = vertices.second;
				std::vector<uint32> offsets{0}, indices;
				for (MRFace f : w.faces(l))
				{
					foreach_incident_vertex(v, f, [&](MRVertex x) { indices.push_back(row[index_of(v, x)]); });
					offsets.push_back(uint32(indices.size()));
				}
				return csr(std::move(offsets), std::move(indices));
			},
			py::arg("level"), "(offsets, indices): the vertex rows of every face of a level. O(darts).")
		.def(
			"faces",
			[](const W& w, uint32 l) {
				const MRLevelView2 v = w.level(l);
				const auto vertices = w.vertices(l);
				const auto& row = vertices.second;
				const std::vector<MRFace> faces = w.faces(l);
				const uint32 k = faces.empty() ? 3 : codegree(v, faces.front());
				py::array_t<uint32> out({py::ssize_t(faces.size()), py::ssize_t(k)});
				auto a = out.mutable_unchecked<2>();
				for (std::size_t i = 0; i < faces.size(); ++i)
				{
					if (codegree(v, faces[i]) != k)
						throw py::value_error("the faces of this level have different degrees: use faces_csr");
					py::ssize_t j = 0;
					foreach_incident_vertex(v, faces[i],
											[&](MRVertex x) { a(py::ssize_t(i), j++) = row[index_of(v, x)]; });
				}
				return out;
			},
			py::arg("level"),
			"(F, k) uint32 array of the vertex rows of the faces of a level, all of degree k; ValueError otherwise.")
		.def(
			"face_levels",
			[](const W& w, uint32 l) {
				const MRLevelView2 v = w.level(l);
				std::vector<uint32> out;
				for (MRFace f : w.faces(l))
					out.push_back(face_level(v, f));
				return to_numpy(std::move(out));
			},
			py::arg("level"), "The level at which each face of a level (rows of faces_csr) was made.")
		.def(
			"subdivide_faces",
			[](W& w, uint32 l, const std::vector<uint32>& rows, const std::string& r, bool balance) {
				const std::vector<MRFace> faces = w.faces(l);
				std::vector<MRFace> chosen;
				for (uint32 i : rows)
				{
					if (i >= faces.size())
						throw py::index_error("no face of row " + std::to_string(i) + " at level " + std::to_string(l));
					chosen.push_back(faces[i]);
				}
				const uint32 before = current_level(w.m);
				set_current_level(w.m, l);
				for (MRFace f : chosen)
					if (!face_is_subdivided(w.m, f))
						subdivide_face(w.m, f, refinement_of(r), balance);
				set_current_level(w.m, std::min(before, max_level(w.m)));
			},
			py::arg("level"), py::arg("rows"), py::arg("refinement") = "quadrangular", py::arg("balance") = true,
			"Subdivides the faces of a level given by their rows in faces_csr(level) (adaptive refinement, "
			"with 2:1 balance by default). Faces subdivided already are skipped.")
		.def(
			"extract_level",
			[](const W& w, uint32 l) {
				w.level(l);
				auto s = std::make_unique<Surface>();
				s->m = extract_level(w.m, l);
				s->ensure_position();
				return s;
			},
			py::arg("level"), "Level l as a CMap2, with every attribute's values at that level.")
		.def(
			"synthesis",
			[](W& w, const std::string& bank, uint32 from) {
				modeling::synthesis(w.m, *w.pos, *w.details, bank_of(bank), from);
			},
			py::arg("bank") = "catmull_clark", py::arg("from_level") = 0,
			"Rebuilds the finer levels' positions: the bank's prediction ('linear', 'loop', 'catmull_clark') "
			"plus the details.")
		.def(
			"analysis",
			[](W& w, const std::string& bank, uint32 to) {
				modeling::analysis(w.m, *w.pos, *w.details, bank_of(bank), to);
			},
			py::arg("bank") = "catmull_clark", py::arg("to_level") = 0,
			"Computes the coarser levels' positions and the details from the finest positions.")
		.def(
			"details", [](const W& w, uint32 l) { return w.rows(*w.details, l); }, py::arg("level"),
			"(V, 3) copy of the detail vectors of a level (rows of positions(level)).")
		.def(
			"filter_low_pass",
			[](W& w, const std::string& bank, uint32 l) { modeling::filter_low_pass(w.m, *w.pos, bank_of(bank), l); },
			py::arg("bank"), py::arg("level"), "Keeps levels 0 ... level, drops the finer details.")
		.def(
			"filter_high_pass",
			[](W& w, const std::string& bank, uint32 l) { modeling::filter_high_pass(w.m, *w.pos, bank_of(bank), l); },
			py::arg("bank"), py::arg("level"), "Drops the details of levels 1 ... level, keeps the finer ones.")
		.def(
			"check_integrity", [](const W& w) { return integrity_report(check_integrity(w.m)); },
			"Checks every invariant at every level; returns {'ok': bool, 'nb_errors': int, 'messages': [str]}.")
		.def("__repr__", [](const W& w) {
			return "<cgogn.MRMap2 levels=0.." + std::to_string(max_level(w.m)) +
				   " current=" + std::to_string(current_level(w.m)) + ">";
		});
}

} // namespace cgogn::python
