// SPDX-License-Identifier: MIT
// `cgogn triangulate`: ear clipping of every polygonal face of a surface file.
#include <cgogn/modeling/triangulation.h>

#include "commands.h"

namespace cgogn::tool
{

Command add_triangulate_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("triangulate", "Cut every polygonal face into triangles (ear clipping)");
	auto files = std::make_shared<EditFiles>();
	add_edit_files(*sub, *files);
	add_origin_option(*sub, *files);
	return {sub, [files] {
				Progress progress;
				with_surface_whole(files->in, progress, [&](auto& m) {
					record_origins_if_asked(m, *files);
					progress.stage("triangulating");
					modeling::triangulate_faces(m, *positions(m));
					save_surface_file(m, files->out, files->binary, progress);
				});
				return 0;
			}};
}

} // namespace cgogn::tool
