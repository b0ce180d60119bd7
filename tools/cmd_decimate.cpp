// SPDX-License-Identifier: MIT
// `cgogn decimate`: quadric-error edge-collapse decimation of a triangle surface.
#include <cgogn/core/traversals/global.h>
#include <cgogn/modeling/decimation.h>

#include "commands.h"

#include <cmath>

namespace cgogn::tool
{

namespace
{

struct DecimateOptions
{
	EditFiles files;
	uint32 faces = 0;
	double ratio = 0.0;
	bool keep_boundary = false;
	bool midedge = false;
};

int run_decimate(const DecimateOptions& o)
{
	Progress progress;
	CMap2 m;
	load_surface_file(m, o.files.in, progress);
	record_origins_if_asked(m, o.files);
	modeling::DecimationOptions d;
	if (o.ratio > 0.0)
	{
		uint32 nb_faces = 0;
		foreach_cell(m, [&](CMap2::Face) { ++nb_faces; });
		d.target_faces = uint32(std::llround(o.ratio * nb_faces));
	}
	else
		d.target_faces = o.faces;
	d.keep_boundary = o.keep_boundary;
	d.placement = o.midedge ? modeling::CollapsePlacement::Midpoint : modeling::CollapsePlacement::Optimal;
	modeling::decimate(m, *positions(m), d, progress.percent("decimating"));
	save_surface_file(m, o.files.out, o.files.binary, progress);
	return 0;
}

} // namespace

Command add_decimate_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("decimate", "Decimate a triangle surface by quadric-error edge collapses");
	auto o = std::make_shared<DecimateOptions>();
	add_edit_files(*sub, o->files);
	add_origin_option(*sub, o->files);
	auto* faces = sub->add_option("--faces", o->faces, "number of faces to reach");
	auto* ratio = sub->add_option("--ratio", o->ratio, "fraction of the faces to keep, in (0, 1]");
	faces->excludes(ratio);
	ratio->excludes(faces);
	sub->add_flag("--keep-boundary", o->keep_boundary, "boundary vertices neither move nor disappear");
	sub->add_flag("--midedge", o->midedge, "place each merged vertex at the edge midpoint (default: optimal)");
	return {sub, [o, faces, ratio] {
				if (faces->count() == 0 && ratio->count() == 0)
					throw std::invalid_argument("decimate: give --faces N or --ratio R");
				if (ratio->count() > 0 && !(o->ratio > 0.0 && o->ratio <= 1.0))
					throw std::invalid_argument("decimate: --ratio must be in (0, 1], got " + std::to_string(o->ratio));
				return run_decimate(*o);
			}};
}

} // namespace cgogn::tool
