// SPDX-License-Identifier: MIT
// `cgogn view`: a self-contained HTML page drawing a surface, or a volume
// mesh with a clipping plane, in the browser (cgogn::render::viewer_html).
#include <cgogn/render/render.h>

#include "commands.h"
#include "map_files.h"

#include <filesystem>
#include <map>

namespace cgogn::tool
{

namespace
{

struct ViewCommandOptions
{
	std::string in, out;
	std::string color = "none";
	bool only_color = false;
	render::ViewerOptions view;
	std::optional<uint32> level; // a multiresolution map's level (.cgmap)
};

int run_view(ViewCommandOptions o)
{
	const std::map<std::string, render::ColorSource> sources = {{"none", render::ColorSource::Uniform},
																{"curvature", render::ColorSource::MeanCurvature},
																{"gaussian", render::ColorSource::GaussianCurvature},
																{"area", render::ColorSource::Area},
																{"quality", render::ColorSource::Quality}};
	if (auto it = sources.find(o.color); it != sources.end())
		o.view.color = it->second;
	else
	{
		o.view.color = render::ColorSource::Attribute;
		o.view.attribute = o.color;
	}
	o.view.all_quantities = !o.only_color;
	if (o.view.title.empty())
		o.view.title = std::filesystem::path(o.in).filename().string();
	Progress progress;
	const auto write = [&](const auto& m) {
		using Vertex = typename mesh_traits<std::decay_t<decltype(m)>>::Vertex;
		auto pos = get_attribute<Vec3, Vertex>(m, "position");
		if (!pos)
			throw std::runtime_error(o.in + ": the mesh has no vertex positions");
		progress.stage("writing " + o.out);
		std::string html;
		try
		{
			html = render::viewer_html(m, *pos, o.view);
		}
		catch (const render::RenderError& e)
		{
			throw render::RenderError(o.in + ": " + e.what());
		}
		render::write_file(html, o.out);
	};
	if (is_map_file(o.in))
		with_drawable_map_file(o.in, o.level, progress, write);
	else if (o.level.has_value())
		throw std::invalid_argument("--level: " + o.in +
									" is not a .cgmap file (levels are those of a "
									"multiresolution map)");
	else
		with_loaded(o.in, progress, [&](const auto& m, const io::LoadReport&) { write(m); });
	return 0;
}

} // namespace

Command add_view_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("view", "Write a self-contained HTML page that draws a surface, or a volume mesh "
										   "with a clipping plane, in a browser (WebGL; no network needed)");
	auto o = std::make_shared<ViewCommandOptions>();
	sub->add_option(
		   "IN", o->in,
		   "input mesh file (surface or volume format), or .cgmap (a CMap2, CMap3 or multiresolution MRMap2, MRMap3)")
		->required();
	sub->add_option("OUT", o->out, "output HTML file")->required();
	sub->add_option("--color", o->color,
					"colouring selected when the page opens: none (default), curvature, gaussian, area, quality, "
					"or a double/float vertex or cell attribute of the file");
	sub->add_flag("--only-color", o->only_color,
				  "embed only the --color quantity (smaller page) instead of every quantity");
	sub->add_flag("--edges", o->view.edges, "edges shown when the page opens");
	sub->add_flag("--show-defects", o->view.show_defects,
				  "boundary edges and split vertices shown when the page opens");
	sub->add_option("--title", o->view.title, "title of the page (default: the input's file name)");
	sub->add_option("--level", o->level,
					"a multiresolution map (.cgmap): the level drawn (default: the current level saved in the file)");
	return {sub, [o] { return run_view(*o); }};
}

} // namespace cgogn::tool
