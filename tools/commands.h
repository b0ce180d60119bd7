// SPDX-License-Identifier: MIT
// The subcommands of the `cgogn` program, one file each (cmd_*.cpp).
#pragma once

#include "tool_common.h"

namespace cgogn::tool
{

Command add_info_command(CLI::App& app);
Command add_check_command(CLI::App& app);
Command add_convert_command(CLI::App& app);
Command add_smooth_command(CLI::App& app);
Command add_triangulate_command(CLI::App& app);
Command add_decimate_command(CLI::App& app);
Command add_remesh_command(CLI::App& app);
Command add_subdivide_command(CLI::App& app);
Command add_fill_holes_command(CLI::App& app);
Command add_dual_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_view_command(CLI::App& app);
#ifdef CGOGN_TOOL_HAS_DISTRIBUTED
Command add_partition_command(CLI::App& app); // with the distributed layer only

/// Whether the process was started by mpiexec (Open MPI's, or a PMI one).
bool launched_by_mpiexec();
/// The program under mpiexec: with one rank, serial_main; with more,
/// info, smooth and convert on the distributed map. Initializes and
/// finalizes MPI.
int distributed_main(int argc, char** argv, int (*serial_main)(int, char**));
#endif

} // namespace cgogn::tool
