// SPDX-License-Identifier: MIT
// The geometry, modeling and rendering layers on Python maps. Long calls
// release the GIL.
#include <cgogn/geometry.h>
#include <cgogn/modeling.h>
#include <cgogn/render.h>

#include "py_map.h"

#include <pybind11/stl.h>

namespace cgogn::python
{

namespace
{

// Runs fill(attribute) on a temporary attribute of kind CELL and returns its
// values as a NumPy array (one row per cell id, a copy).
template <typename T, typename CELL, typename MAP, typename FILL>
py::array computed(MAP& m, const FILL& fill)
{
	// a name no user attribute can take: the library's own names start with
	// "__", which add_attribute refuses, so a long unlikely name is used
	std::string name = "python result";
	while (container_of<CELL::ORBIT>(m).find(name) != nullptr)
		name += "'";
	auto a = add_attribute<T, CELL>(m, name);
	{
		py::gil_scoped_release release;
		fill(*a);
	}
	std::vector<py::object> no_views;
	py::array view =
		attribute_array(std::shared_ptr<AttributeArray<T>>(a), container_of<CELL::ORBIT>(m).end_index(), no_views);
	py::array out = view.attr("copy")();
	remove_attribute(m, a);
	return out;
}

// "curvature", "gaussian", "area", "quality" or an attribute's name (set in `attribute`).
render::ColorSource color_source(const std::string& v, std::string& attribute)
{
	if (v == "curvature")
		return render::ColorSource::MeanCurvature;
	if (v == "gaussian")
		return render::ColorSource::GaussianCurvature;
	if (v == "area")
		return render::ColorSource::Area;
	if (v == "quality")
		return render::ColorSource::Quality;
	if (v == "uniform")
		return render::ColorSource::Uniform;
	attribute = v;
	return render::ColorSource::Attribute;
}

render::ViewerOptions viewer_options(const std::string& color, bool edges, bool show_defects, const std::string& title)
{
	render::ViewerOptions o;
	o.color = color_source(color, o.attribute);
	o.edges = edges;
	o.show_defects = show_defects;
	o.title = title;
	return o;
}

render::RenderOptions render_options(const py::dict& o)
{
	render::RenderOptions r;
	for (auto [key, value] : o)
	{
		const std::string k = py::str(key);
		if (value.is_none())
			continue;
		if (k == "size")
		{
			auto s = value.cast<std::pair<uint32, uint32>>();
			r.width = s.first;
			r.height = s.second;
		}
		else if (k == "view")
		{
			const std::string v = value.cast<std::string>();
			if (v == "x")
				r.view = render::View::X;
			else if (v == "y")
				r.view = render::View::Y;
			else if (v == "z")
				r.view = render::View::Z;
			else if (v == "iso")
				r.view = render::View::Iso;
			else
				throw py::value_error("view must be 'x', 'y', 'z' or 'iso'");
		}
		else if (k == "azimuth")
			r.azimuth = value.cast<double>();
		else if (k == "elevation")
			r.elevation = value.cast<double>();
		else if (k == "shading")
		{
			const std::string v = value.cast<std::string>();
			if (v != "flat" && v != "smooth")
				throw py::value_error("shading must be 'flat' or 'smooth'");
			r.shading = v == "flat" ? render::Shading::Flat : render::Shading::Smooth;
		}
		else if (k == "ssaa")
			r.supersampling = value.cast<uint32>();
		else if (k == "edges")
			r.edges = value.cast<bool>();
		else if (k == "show_defects")
			r.show_defects = value.cast<bool>();
		else if (k == "legend")
			r.legend = value.cast<bool>();
		else if (k == "range")
		{
			auto range = value.cast<std::pair<double, double>>();
			r.range_min = range.first;
			r.range_max = range.second;
		}
		else if (k == "color")
			r.color = color_source(value.cast<std::string>(), r.attribute);
		else
			throw py::type_error("render() got an unexpected option '" + k + "'");
	}
	return r;
}

void bind_surface_algorithms(py::class_<Surface>& c)
{
	using V = CMap2::Vertex;
	using F = CMap2::Face;
	c.def(
		 "vertex_normals",
		 [](Surface& w) {
			 return computed<Vec3, V>(
				 w.m, [&](AttributeArray<Vec3>& n) { geometry::compute_vertex_normals(w.m, *w.pos, n); });
		 },
		 "Unit vertex normals (angle-weighted), one row per vertex id. O(darts).")
		.def(
			"face_normals",
			[](Surface& w) {
				return computed<Vec3, F>(
					w.m, [&](AttributeArray<Vec3>& n) { geometry::compute_face_normals(w.m, *w.pos, n); });
			},
			"Unit face normals (Newell), one row per face id (indexes faces). O(darts).")
		.def(
			"face_areas",
			[](Surface& w) {
				return computed<double, F>(
					w.m, [&](AttributeArray<double>& a) { geometry::compute_face_areas(w.m, *w.pos, a); });
			},
			"Face areas, one per face id. O(darts).")
		.def(
			"mean_curvature",
			[](Surface& w) {
				return computed<double, V>(
					w.m, [&](AttributeArray<double>& h) { geometry::compute_mean_curvatures(w.m, *w.pos, h); });
			},
			"Mean curvature per vertex id (cotangent Laplacian over the mixed Voronoi area). O(darts).")
		.def(
			"gaussian_curvature",
			[](Surface& w, bool integrated) {
				return computed<double, V>(w.m, [&](AttributeArray<double>& k) {
					geometry::compute_gaussian_curvatures(w.m, *w.pos, k, integrated);
				});
			},
			py::arg("integrated") = false,
			"Gaussian curvature per vertex id (angle defect over the mixed Voronoi area; integrated=True: the "
			"angle defect itself). O(darts).")
		.def(
			"_laplacian",
			[](Surface& w, const std::string& kind) {
				geometry::SparseMatrix L;
				const geometry::VertexNumbering num = geometry::vertex_numbering(w.m);
				{
					py::gil_scoped_release release;
					if (kind == "cotan")
						L = geometry::cotan_laplacian(w.m, *w.pos, num);
					else if (kind == "uniform")
						L = geometry::uniform_laplacian(w.m, num);
					else if (kind == "mass")
						L = geometry::mass_matrix(w.m, *w.pos, num);
					else
						throw py::value_error("kind must be 'cotan', 'uniform' or 'mass'");
				}
				L.makeCompressed();
				std::vector<uint32> rows, cols;
				std::vector<double> values;
				rows.reserve(std::size_t(L.nonZeros()));
				cols.reserve(std::size_t(L.nonZeros()));
				values.reserve(std::size_t(L.nonZeros()));
				for (int k = 0; k < L.outerSize(); ++k)
					for (geometry::SparseMatrix::InnerIterator it(L, k); it; ++it)
					{
						rows.push_back(uint32(it.row()));
						cols.push_back(uint32(it.col()));
						values.push_back(it.value());
					}
				std::vector<uint32> ids = num.line_of_dense_;
				return py::make_tuple(to_numpy(std::move(rows)), to_numpy(std::move(cols)), to_numpy(std::move(values)),
									  num.size(), to_numpy(std::move(ids)));
			},
			py::arg("kind"))
		.def(
			"smooth",
			[](Surface& w, const std::string& method, uint32 iterations, double lam, double mu, bool move_boundary) {
				py::gil_scoped_release release;
				if (method == "laplacian")
					geometry::laplacian_smoothing(w.m, *w.pos, iterations > 0 ? iterations : 10, lam, !move_boundary);
				else if (method == "taubin")
					geometry::taubin_smoothing(w.m, *w.pos, iterations > 0 ? iterations : 10, lam, mu, !move_boundary);
				else if (method == "bilateral")
				{
					geometry::BilateralNormalFilteringParams p;
					p.normal_iterations = iterations > 0 ? iterations : 10;
					p.fix_boundary = !move_boundary;
					geometry::bilateral_normal_filtering(w.m, *w.pos, p);
				}
				else if (method == "implicit")
				{
					const double l = geometry::mean_edge_length(w.m, *w.pos);
					geometry::implicit_smoothing(w.m, *w.pos, l * l, iterations > 0 ? iterations : 1, false,
												 !move_boundary);
				}
				else
				{
					py::gil_scoped_acquire acquire;
					throw py::value_error("method must be 'laplacian', 'taubin', 'bilateral' or 'implicit'");
				}
			},
			py::arg("method") = "taubin", py::arg("iterations") = 0, py::arg("lam") = 0.5, py::arg("mu") = -0.53,
			py::arg("move_boundary") = false,
			"Smooths the positions in place, as `cgogn smooth` (iterations 0: the method's default, 10 passes "
			"or 1 implicit step of time mean_edge_length^2).")
		.def(
			"subdivide",
			[](Surface& w, const std::string& scheme, uint32 iterations) {
				modeling::SurfaceScheme s;
				if (scheme == "loop")
					s = modeling::SurfaceScheme::Loop;
				else if (scheme == "catmull-clark" || scheme == "catmull_clark")
					s = modeling::SurfaceScheme::CatmullClark;
				else if (scheme == "sqrt3")
					s = modeling::SurfaceScheme::Sqrt3;
				else
					throw py::value_error("scheme must be 'loop', 'catmull-clark' or 'sqrt3'");
				py::gil_scoped_release release;
				modeling::subdivide(w.m, *w.pos, s, iterations);
			},
			py::arg("scheme") = "loop", py::arg("iterations") = 1,
			"Subdivides in place (Loop and sqrt3 need triangles). Old vertices keep their ids. Raises "
			"cgogn.Error when the scheme does not apply.")
		.def(
			"decimate",
			[](Surface& w, uint32 target_faces, double max_error, const std::string& placement, bool keep_boundary) {
				modeling::DecimationOptions o;
				o.target_faces = target_faces;
				o.max_error = max_error;
				o.keep_boundary = keep_boundary;
				if (placement == "optimal")
					o.placement = modeling::CollapsePlacement::Optimal;
				else if (placement == "midpoint")
					o.placement = modeling::CollapsePlacement::Midpoint;
				else
					throw py::value_error("placement must be 'optimal' or 'midpoint'");
				modeling::DecimationResult r;
				{
					py::gil_scoped_release release;
					r = modeling::decimate(w.m, *w.pos, o);
				}
				py::dict d;
				d["faces"] = r.faces;
				d["collapses"] = r.collapses;
				d["max_error"] = r.max_error;
				return d;
			},
			py::arg("target_faces") = 0, py::arg("max_error") = std::numeric_limits<double>::infinity(),
			py::arg("placement") = "optimal", py::arg("keep_boundary") = false,
			"Garland-Heckbert decimation of a triangle surface, as `cgogn decimate`. Returns {'faces', "
			"'collapses', 'max_error'}.")
		.def(
			"remesh",
			[](Surface& w, double target_edge_length, uint32 iterations, double feature_angle, bool project) {
				modeling::RemeshingOptions o;
				o.target_edge_length = target_edge_length;
				o.iterations = iterations;
				o.feature_angle = feature_angle;
				o.project = project;
				modeling::RemeshingResult r;
				{
					py::gil_scoped_release release;
					r = modeling::isotropic_remeshing(w.m, *w.pos, o);
				}
				py::dict d;
				d["iterations"] = r.iterations;
				d["splits"] = r.splits;
				d["collapses"] = r.collapses;
				d["flips"] = r.flips;
				d["target_edge_length"] = r.target_edge_length;
				return d;
			},
			py::arg("target_edge_length") = 0.0, py::arg("iterations") = 10, py::arg("feature_angle") = 0.0,
			py::arg("project") = true,
			"Isotropic remeshing of a triangle surface, as `cgogn remesh` (target 0: the mean edge length).")
		.def(
			"fill_holes",
			[](Surface& w, uint32 max_hole_size, bool refine, bool fair) {
				modeling::HoleFillingOptions o;
				if (max_hole_size > 0)
					o.max_hole_size = max_hole_size;
				o.refine = refine;
				o.fair = fair && refine;
				modeling::HoleFillingResult r;
				{
					py::gil_scoped_release release;
					r = modeling::fill_holes(w.m, *w.pos, o);
				}
				py::dict d;
				d["holes_found"] = r.holes_found;
				d["holes_filled"] = r.holes_filled;
				d["holes_skipped"] = r.holes_skipped;
				d["faces_added"] = r.faces_added;
				d["vertices_added"] = r.vertices_added;
				return d;
			},
			py::arg("max_hole_size") = 0, py::arg("refine") = true, py::arg("fair") = true,
			"Fills the holes (Liepa), as `cgogn fill-holes` (max_hole_size 0: no limit).")
		.def(
			"triangulate",
			[](Surface& w) {
				py::gil_scoped_release release;
				return modeling::triangulate_faces(w.m, *w.pos);
			},
			"Ear-clips every face of degree > 3; returns the number of faces cut.")
		.def(
			"dual",
			[](Surface& w) {
				auto out = std::make_unique<Surface>();
				{
					py::gil_scoped_release release;
					remove_attribute(out->m, out->pos);
					out->pos = modeling::dual(w.m, *w.pos, out->m);
				}
				return out;
			},
			"The dual of a closed surface, as a new CMap2 (a vertex per face at its centroid).")
		.def(
			"render",
			[](Surface& w, const std::string& path, const py::kwargs& options) {
				const render::RenderOptions o = render_options(options);
				py::gil_scoped_release release;
				render::write_png(render::render_surface(w.m, *w.pos, o), path);
			},
			py::arg("path"),
			"Writes a PNG picture of the surface, as `cgogn render`: size=(w, h), view='x'|'y'|'z'|'iso', "
			"azimuth, elevation, shading='flat'|'smooth', ssaa, edges, show_defects, legend, color='curvature'|"
			"'gaussian'|'area'|'quality'|ATTRIBUTE, range=(min, max) (default: the 2nd to 98th percentile). "
			"Raises cgogn.Error on bad input (empty mesh, NaN positions), "
			"writing no file.")
		.def(
			"view",
			[](Surface& w, const std::string& path, const std::string& color, bool edges, bool show_defects,
			   const std::string& title) {
				const render::ViewerOptions o = viewer_options(color, edges, show_defects, title);
				py::gil_scoped_release release;
				render::write_viewer_html(w.m, *w.pos, path, o);
			},
			py::arg("path"), py::arg("color") = "uniform", py::arg("edges") = false, py::arg("show_defects") = false,
			py::arg("title") = "",
			"Writes a self-contained HTML page showing the surface in a browser (WebGL), as `cgogn view`: "
			"rotate, zoom, pan, edges, boundary, defects and colourings. Raises cgogn.RenderError on bad input, "
			"writing no file.");
}

void bind_volume_algorithms(py::class_<VolumeMesh>& c)
{
	c.def(
		 "subdivide",
		 [](VolumeMesh& w, uint32 iterations) {
			 w.refuse_while_aliased("subdivide");
			 for (uint32 i = 0; i < iterations; ++i)
			 {
				 py::gil_scoped_release release;
				 if (modeling::is_tet_mesh(w.m))
					 modeling::tet_subdivision(w.m, *w.pos);
				 else
					 modeling::hex_subdivision(w.m, *w.pos);
			 }
		 },
		 py::arg("iterations") = 1,
		 "Subdivides every tetrahedron (or every hexahedron) into 8. The map is rebuilt: ids change, other "
		 "attributes keep their names with default values. Refused while NumPy arrays alias the map.")
		.def(
			"render",
			[](VolumeMesh& w, const std::string& path, const py::kwargs& options) {
				const render::RenderOptions o = render_options(options);
				py::gil_scoped_release release;
				render::write_png(render::render_volume_boundary(w.m, *w.pos, o), path);
			},
			py::arg("path"), "Writes a PNG picture of the boundary of the volume mesh (options as CMap2.render).")
		.def(
			"view",
			[](VolumeMesh& w, const std::string& path, const std::string& color, bool edges, bool show_defects,
			   const std::string& title) {
				const render::ViewerOptions o = viewer_options(color, edges, show_defects, title);
				py::gil_scoped_release release;
				render::write_viewer_html(w.m, *w.pos, path, o);
			},
			py::arg("path"), py::arg("color") = "uniform", py::arg("edges") = false, py::arg("show_defects") = false,
			py::arg("title") = "",
			"Writes a self-contained HTML page of the volume mesh, with a clipping plane that shows the cells "
			"it cuts, as `cgogn view`.");
}

} // namespace

void bind_algorithms(py::module_& mod)
{
	auto surface = py::class_<Surface>(mod.attr("CMap2"));
	bind_surface_algorithms(surface);
	auto volume = py::class_<VolumeMesh>(mod.attr("CMap3"));
	bind_volume_algorithms(volume);
	mod.def(
		"set_nb_workers", [](uint32 n) { set_nb_workers(n); }, py::arg("n"),
		"Number of threads of the library's parallel traversals (1: sequential).");
	mod.def(
		"nb_workers", [] { return thread_pool()->nb_workers(); }, "Number of threads of the parallel traversals.");
}

} // namespace cgogn::python
