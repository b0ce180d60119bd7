// SPDX-License-Identifier: MIT
#pragma once

#include <string>
#include <vector>

namespace cgogn::io
{

/// Writes the index of a parallel VTU file (.pvtu) over pieces already
/// written: `sources` are the pieces' file names relative to the index's
/// folder, the first of which is read for the names, types and components
/// of its point and cell arrays (every piece must have the same arrays).
/// `ghost_level` is 1 when the pieces carry a ghost layer flagged in a
/// vtkGhostType cell array, else 0. ParaView and VTK's
/// vtkXMLPUnstructuredGridReader open the index; load_volume and
/// load_surface read it back as one mesh (see Format::Pvtu). Throws
/// io::Error when the first piece cannot be read or the index written.
/// O(size of the first piece's header).
void write_pvtu_index(const std::string& pvtu_path, const std::vector<std::string>& sources, int ghost_level);

} // namespace cgogn::io
