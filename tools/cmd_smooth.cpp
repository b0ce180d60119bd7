// SPDX-License-Identifier: MIT
// `cgogn smooth`: the geometry layer's smoothing filters on a surface file.
#include <cgogn/geometry.h>

#include "commands.h"

#include <map>

namespace cgogn::tool
{

namespace
{

enum class Method
{
	Laplacian,
	Taubin,
	Bilateral,
	Implicit
};

struct SmoothOptions
{
	EditFiles files;
	Method method = Method::Taubin;
	/// 0: the method's default (10 passes of the explicit filters, 1 implicit step)
	uint32 iterations = 0;
	double lambda = 0.5;
	double mu = -0.53;
	double time_step = 1.0;
	bool move_boundary = false;
};

int run_smooth(const SmoothOptions& o)
{
	Progress progress;
	const uint32 iterations = o.iterations > 0 ? o.iterations : (o.method == Method::Implicit ? 1 : 10);
	with_surface_whole(o.files.in, progress, [&](auto& m) {
		auto pos = positions(m);
		progress.stage("smoothing");
		switch (o.method)
		{
		case Method::Laplacian:
			geometry::laplacian_smoothing(m, *pos, iterations, o.lambda, !o.move_boundary);
			break;
		case Method::Taubin:
			geometry::taubin_smoothing(m, *pos, iterations, o.lambda, o.mu, !o.move_boundary);
			break;
		case Method::Bilateral: {
			geometry::BilateralNormalFilteringParams p;
			p.normal_iterations = iterations;
			p.fix_boundary = !o.move_boundary;
			geometry::bilateral_normal_filtering(m, *pos, p);
			break;
		}
		case Method::Implicit: {
			const double l = geometry::mean_edge_length(m, *pos);
			geometry::implicit_smoothing(m, *pos, o.time_step * l * l, iterations, false, !o.move_boundary);
			break;
		}
		}
		save_surface_file(m, o.files.out, o.files.binary, progress);
	});
	return 0;
}

} // namespace

Command add_smooth_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("smooth", "Smooth a surface (Laplacian, Taubin, bilateral normal, implicit)");
	auto o = std::make_shared<SmoothOptions>();
	add_edit_files(*sub, o->files);
	const std::map<std::string, Method> methods = {{"laplacian", Method::Laplacian},
												   {"taubin", Method::Taubin},
												   {"bilateral", Method::Bilateral},
												   {"implicit", Method::Implicit}};
	sub->add_option("--method", o->method, "filter (default taubin)")
		->transform(CLI::CheckedTransformer(methods, CLI::ignore_case));
	sub->add_option("--iterations,-n", o->iterations,
					"passes of the filter (default 10; implicit: 1 step, each shrinks the shape further)")
		->check(CLI::Range(1u, 1000000u));
	sub->add_option("--lambda", o->lambda, "laplacian/taubin step in (0, 1] (default 0.5)")
		->check(CLI::Range(1e-9, 1.0));
	sub->add_option("--mu", o->mu, "taubin's negative step, mu < -lambda (default -0.53)");
	sub->add_option("--time-step", o->time_step, "implicit: t in units of the squared mean edge length (default 1)")
		->check(CLI::PositiveNumber);
	sub->add_flag("--move-boundary", o->move_boundary, "let boundary vertices move too");
	return {sub, [o] {
				if (o->method == Method::Taubin && !(o->mu < -o->lambda))
					throw std::invalid_argument("--mu must be smaller than -lambda");
				return run_smooth(*o);
			}};
}

} // namespace cgogn::tool
