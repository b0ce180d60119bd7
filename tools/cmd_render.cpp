// SPDX-License-Identifier: MIT
// `cgogn render`: a shaded PNG picture of a surface, or of the boundary of a
// volume mesh, drawn by the software rasterizer of cgogn::render.
#include <cgogn/io/graph.h>
#include <cgogn/io/incidence_graph.h>
#include <cgogn/io/surface.h>
#include <cgogn/render/render.h>

#include "commands.h"
#include "map_files.h"

#include <cstdio>
#include <map>
#include <vector>

namespace cgogn::tool
{

namespace
{

struct RenderCommandOptions
{
	std::string in, out;
	std::string size = "800x600";
	std::string color = "none";
	std::string background;
	std::vector<double> range;
	render::RenderOptions render;
	render::GraphDrawing graph;
	bool lines = false;
	std::optional<uint32> level; // a multiresolution map's level (.cgmap)
};

void parse_size(const std::string& text, render::RenderOptions& o)
{
	unsigned w = 0, h = 0;
	char tail = 0;
	if (std::sscanf(text.c_str(), "%ux%u%c", &w, &h, &tail) != 2 || w == 0 || h == 0)
		throw std::invalid_argument("--size: '" + text + "' is not WIDTHxHEIGHT (e.g. 800x600)");
	o.width = w;
	o.height = h;
}

int run_render(RenderCommandOptions o)
{
	parse_size(o.size, o.render);
	if (!o.background.empty())
		o.render.background = render::parse_color(o.background);
	if (o.range.size() == 2)
	{
		o.render.range_min = o.range[0];
		o.render.range_max = o.range[1];
		render::scalar_range({}, o.render.range_min, o.render.range_max); // checks it
	}
	const std::map<std::string, render::ColorSource> sources = {{"none", render::ColorSource::Uniform},
																{"curvature", render::ColorSource::MeanCurvature},
																{"gaussian", render::ColorSource::GaussianCurvature},
																{"area", render::ColorSource::Area},
																{"quality", render::ColorSource::Quality}};
	if (auto it = sources.find(o.color); it != sources.end())
		o.render.color = it->second;
	else
	{
		o.render.color = render::ColorSource::Attribute;
		o.render.attribute = o.color;
	}
	Progress progress;
	render::Image img;
	o.graph.tubes = !o.lines;
	// a graph, an .ig file, or a non-manifold surface (below) are drawn as
	// they are, without the repair a map would need
	auto render_complex = [&](const IncidenceGraph& ig) {
		auto pos = get_attribute<Vec3, IncidenceGraph::Vertex>(ig, "position");
		if (!pos)
			throw std::runtime_error(o.in + ": the complex has no vertex positions");
		progress.stage("rendering");
		img = render::render_surface(ig, *pos, o.render);
	};
	try
	{
		if (is_graph_file(o.in))
		{
			progress.stage("loading " + o.in);
			Graph g;
			io::load_graph(g, o.in);
			progress.stage("rendering");
			img = render::render_graph(g, *get_attribute<Vec3, Graph::Vertex>(g, "position"), o.render, o.graph);
		}
		else if (is_incidence_graph_file(o.in))
		{
			progress.stage("loading " + o.in);
			IncidenceGraph ig;
			io::load_incidence_graph(ig, o.in);
			render_complex(ig);
		}
	}
	catch (const render::RenderError& e)
	{
		throw render::RenderError(o.in + ": " + e.what());
	}
	if (is_graph_file(o.in) || is_incidence_graph_file(o.in))
	{
		progress.stage("writing " + o.out);
		render::write_png(img, o.out);
		return 0;
	}
	if (o.level.has_value() && !is_map_file(o.in))
		throw std::invalid_argument("--level: " + o.in +
									" is not a .cgmap file (levels are those of a "
									"multiresolution map)");
	if (is_map_file(o.in))
	{
		with_drawable_map_file(o.in, o.level, progress, [&](const auto& m) {
			using Vertex = typename mesh_traits<std::decay_t<decltype(m)>>::Vertex;
			auto pos = get_attribute<Vec3, Vertex>(m, "position");
			if (!pos)
				throw std::runtime_error(o.in + ": the map has no vertex positions");
			progress.stage("rendering");
			try
			{
				if constexpr (std::is_same_v<std::decay_t<decltype(m)>, CMap3>)
					img = render::render_volume_boundary(m, *pos, o.render);
				else
					img = render::render_surface(m, *pos, o.render);
			}
			catch (const render::RenderError& e)
			{
				throw render::RenderError(o.in + ": " + e.what());
			}
		});
		progress.stage("writing " + o.out);
		render::write_png(img, o.out);
		return 0;
	}
	with_loaded(o.in, progress, [&](auto& m, const io::LoadReport& report) {
		using Vertex = typename mesh_traits<std::decay_t<decltype(m)>>::Vertex;
		auto pos = get_attribute<Vec3, Vertex>(m, "position");
		if (!pos)
			throw std::runtime_error(o.in + ": the mesh has no vertex positions");
		progress.stage("rendering");
		try
		{
			if constexpr (std::is_same_v<std::decay_t<decltype(m)>, CMap3>)
				img = render::render_volume_boundary(m, *pos, o.render);
			else if (!report.manifold())
			{
				IncidenceGraph ig;
				io::load_surface(ig, o.in);
				render_complex(ig);
			}
			else
				img = render::render_surface(m, *pos, o.render);
		}
		catch (const render::RenderError& e)
		{
			throw render::RenderError(o.in + ": " + e.what());
		}
	});
	progress.stage("writing " + o.out);
	render::write_png(img, o.out);
	return 0;
}

} // namespace

Command add_render_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("render", "Draw a surface, the boundary of a volume mesh, or a graph into a PNG "
											 "picture (software rasterizer, orthographic camera)");
	auto o = std::make_shared<RenderCommandOptions>();
	sub->add_option("IN", o->in,
					"input mesh file (surface or volume format; a non-manifold surface is drawn as it is), .ig, "
					"graph (.cg .cgr .skel), or .cgmap (a CMap2, CMap3 or multiresolution MRMap2, MRMap3)")
		->required();
	sub->add_option("OUT", o->out, "output PNG file")->required();
	sub->add_option("--size", o->size, "picture size WIDTHxHEIGHT (default 800x600)");
	const std::map<std::string, render::View> views = {
		{"x", render::View::X}, {"y", render::View::Y}, {"z", render::View::Z}, {"iso", render::View::Iso}};
	sub->add_option("--view", o->render.view,
					"x: looks down -x (+z up), y: down -y (+z up), z: down -z (+y up, +x right), iso: down "
					"-(1,1,1) (+y up; default)")
		->transform(CLI::CheckedTransformer(views, CLI::ignore_case));
	sub->add_option("--azimuth", o->render.azimuth,
					"degrees: turns the camera about the view's up axis, towards its right (default 0)");
	sub->add_option("--elevation", o->render.elevation, "degrees: raises the camera towards the view's up axis")
		->check(CLI::Range(-90.0, 90.0));
	const std::map<std::string, render::Shading> shadings = {{"flat", render::Shading::Flat},
															 {"smooth", render::Shading::Smooth}};
	sub->add_option("--shading", o->render.shading, "flat or smooth (default)")
		->transform(CLI::CheckedTransformer(shadings, CLI::ignore_case));
	sub->add_option("--ssaa", o->render.supersampling, "supersampling: N x N samples per pixel (1-8, default 2)")
		->check(CLI::Range(1u, 8u));
	sub->add_flag("--edges", o->render.edges, "draw the mesh edges over the faces");
	sub->add_flag("--show-defects", o->render.show_defects,
				  "boundary edges in red, vertices split by the loader (non-manifold) as orange dots; hidden "
				  "ones faint. A non-manifold surface: edges without two faces in red, non-manifold vertices as "
				  "orange dots");
	sub->add_flag("--lines", o->lines, "a graph: each edge a line one pixel wide (default: tubes and balls)");
	sub->add_option("--radius", o->graph.radius,
					"a graph: the tubes' radius (default: the file's radii, else 0.5% of the bounding box's "
					"diagonal)")
		->check(CLI::PositiveNumber);
	sub->add_option("--color", o->color,
					"curvature (mean), gaussian, area, quality (triangle shape), or the name of a double/float "
					"vertex or cell attribute of the file, through viridis with a legend (default: none)");
	sub->add_option("--range", o->range,
					"MIN MAX: the values coloured from the first to the last viridis colour (default: the 2nd "
					"to 98th percentile of the drawn values; values beyond get the end colours)")
		->expected(2);
	sub->add_flag("!--no-legend", o->render.legend, "no colour bar with --color");
	sub->add_option("--background", o->background, "background colour: #rrggbb or r,g,b (default white)");
	sub->add_option("--level", o->level,
					"a multiresolution map (.cgmap): the level drawn (default: the current level saved in the file)");
	return {sub, [o] { return run_render(*o); }};
}

} // namespace cgogn::tool
