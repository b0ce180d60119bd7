// SPDX-License-Identifier: MIT
// The `cgogn` command-line program: inspect, check, convert and edit mesh
// files. Each subcommand lives in its own cmd_*.cpp.
#include "commands.h"

#include <iostream>
#include <vector>

using namespace cgogn;

namespace
{

int serial_main(int argc, char** argv)
{
	CLI::App app{"cgogn: inspect, check, convert and process surface and volume mesh files"};
	app.require_subcommand(1);
	const std::vector<tool::Command> commands = {
		tool::add_info_command(app),      tool::add_check_command(app),       tool::add_convert_command(app),
		tool::add_smooth_command(app),    tool::add_triangulate_command(app), tool::add_decimate_command(app),
		tool::add_remesh_command(app),    tool::add_subdivide_command(app),   tool::add_fill_holes_command(app),
		tool::add_dual_command(app),      tool::add_render_command(app),      tool::add_view_command(app),
#ifdef CGOGN_TOOL_HAS_DISTRIBUTED
		tool::add_partition_command(app),
#endif
	};
	try
	{
		app.parse(argc, argv);
	}
	catch (const CLI::ParseError& e)
	{
		const int code = app.exit(e);
		return code == 0 ? 0 : tool::EXIT_ERROR;
	}
	try
	{
		for (const tool::Command& c : commands)
			if (*c.parser)
				return c.run();
		return tool::EXIT_ERROR;
	}
	catch (const std::exception& e)
	{
		std::cerr << "cgogn: " << e.what() << "\n";
		return tool::EXIT_ERROR;
	}
}

} // namespace

int main(int argc, char** argv)
{
#ifdef CGOGN_TOOL_HAS_DISTRIBUTED
	if (tool::launched_by_mpiexec())
		return tool::distributed_main(argc, argv, serial_main);
#endif
	return serial_main(argc, argv);
}
