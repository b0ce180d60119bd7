// SPDX-License-Identifier: MIT
// `cgogn fill-holes`: closes the holes of a surface file (modeling::fill_holes).
#include <cgogn/modeling/hole_filling.h>

#include "commands.h"

#include <iostream>

namespace cgogn::tool
{

namespace
{

struct FillHolesOptions
{
	EditFiles files;
	bool no_refine = false;
	bool no_fair = false;
	uint32 max_size = 0;
};

int run_fill_holes(const FillHolesOptions& o)
{
	modeling::HoleFillingOptions options;
	options.refine = !o.no_refine;
	options.fair = !o.no_fair;
	if (o.max_size > 0)
		options.max_hole_size = o.max_size;
	modeling::HoleFillingResult r;
	{
		// the progress line is cleared when it goes, before the summary is written
		Progress progress;
		CMap2 m;
		load_surface_file(m, o.files.in, progress);
		record_origins_if_asked(m, o.files);
		r = modeling::fill_holes(m, *positions(m), options, progress.percent("filling holes"));
		save_surface_file(m, o.files.out, o.files.binary, progress);
	}
	std::cout << "holes: " << r.holes_found << " found, " << r.holes_filled << " filled, " << r.holes_skipped
			  << " skipped; added " << r.vertices_added << " vertices, " << r.faces_added << " faces\n";
	return 0;
}

} // namespace

Command add_fill_holes_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("fill-holes", "Fill the holes of a surface (triangulate, refine, fair)");
	auto o = std::make_shared<FillHolesOptions>();
	add_edit_files(*sub, o->files);
	add_origin_option(*sub, o->files);
	sub->add_flag("--no-refine", o->no_refine, "only triangulate the holes, no new vertex");
	sub->add_flag("--no-fair", o->no_fair, "keep the refined patches flat (no fairing)");
	sub->add_option("--max-size", o->max_size, "leave open the holes of more boundary edges than this")
		->check(CLI::Range(3u, 4000000000u));
	return {sub, [o] { return run_fill_holes(*o); }};
}

} // namespace cgogn::tool
