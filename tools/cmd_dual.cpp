// SPDX-License-Identifier: MIT
// `cgogn dual`: the dual of a closed surface file (modeling::dual).
#include <cgogn/modeling/dual.h>

#include "commands.h"

namespace cgogn::tool
{

Command add_dual_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("dual", "Write the dual of a closed surface (a vertex per face, a face per vertex)");
	auto files = std::make_shared<EditFiles>();
	add_edit_files(*sub, *files);
	return {sub, [files] {
				Progress progress;
				CMap2 m;
				load_surface_file(m, files->in, progress);
				progress.stage("computing the dual");
				CMap2 d;
				modeling::dual(m, *positions(m), d);
				save_surface_file(d, files->out, files->binary, progress);
				return 0;
			}};
}

} // namespace cgogn::tool
