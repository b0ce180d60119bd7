// SPDX-License-Identifier: MIT
// `cgogn remesh`: isotropic remeshing of a triangle surface.
#include <cgogn/modeling/remeshing.h>

#include "commands.h"

#include <cmath>

namespace cgogn::tool
{

namespace
{

struct RemeshOptions
{
	EditFiles files;
	double edge_length = 0.0;
	uint32 iterations = 10;
	double feature_angle = 0.0;
};

int run_remesh(const RemeshOptions& o)
{
	Progress progress;
	CMap2 m;
	load_surface_file(m, o.files.in, progress);
	record_origins_if_asked(m, o.files);
	modeling::RemeshingOptions r;
	r.target_edge_length = o.edge_length;
	r.iterations = o.iterations;
	r.feature_angle = o.feature_angle;
	modeling::isotropic_remeshing(m, *positions(m), r, progress.percent("remeshing"));
	save_surface_file(m, o.files.out, o.files.binary, progress);
	return 0;
}

} // namespace

Command add_remesh_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("remesh", "Isotropic remeshing of a triangle surface (Botsch-Kobbelt)");
	auto o = std::make_shared<RemeshOptions>();
	add_edit_files(*sub, o->files);
	add_origin_option(*sub, o->files);
	sub->add_option("--edge-length,-l", o->edge_length, "target edge length (default: the input's mean edge length)")
		->check(CLI::PositiveNumber);
	sub->add_option("--iterations,-n", o->iterations, "iterations (default 10)")->check(CLI::Range(1u, 1000000u));
	sub->add_option("--feature-angle", o->feature_angle,
					"keep edges whose dihedral angle exceeds this many degrees (default: none)")
		->check(CLI::Range(0.0, 180.0));
	return {sub, [o] { return run_remesh(*o); }};
}

} // namespace cgogn::tool
