// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/distributed/distribute.h>
#include <cgogn/io/options.h>

#include <string>

namespace cgogn::io
{

/// Writes a distributed map as parallel VTU: each rank writes its local map
/// (owned cells and ghosts) to `<stem>_<rank>.vtu` beside `path`, with its
/// attributes and four arrays more: GlobalNodeIds (UInt64) and vtkGhostType
/// (UInt8, 1 on the vertices this rank does not own) on the points,
/// GlobalCellIds and vtkGhostType (1 on ghost cells, VTK's DUPLICATECELL)
/// on the cells. Rank 0 then writes the `.pvtu` index (GhostLevel 1).
/// ParaView and VTK open it and drop the ghosts; load_volume/load_surface
/// and dist::load_volume/load_surface read it back with any number of
/// ranks. The four arrays are the map's attributes of those names while it
/// writes (an attribute of one of those names and another type is an
/// error). Collective over dm.comm(); throws io::Error on every rank when a
/// rank fails. O(size of the rank's map).
void save_pvtu(dist::DistributedCMap3& dm, const std::string& path, const SaveOptions& options);
void save_pvtu(dist::DistributedCMap2& dm, const std::string& path, const SaveOptions& options);
/// The same with the default options (binary).
void save_pvtu(dist::DistributedCMap3& dm, const std::string& path);
void save_pvtu(dist::DistributedCMap2& dm, const std::string& path);

} // namespace cgogn::io

namespace cgogn::dist
{

/// Reads a volume mesh file of any format io::load_volume reads (a .pvtu
/// written with any number of ranks included) on the root and distributes
/// it over comm (see distribute()). Collective; throws io::Error on every
/// rank when the root cannot read the file. O(size of the file) on the root.
DistributedCMap3 load_volume(MPI_Comm comm, const std::string& path, const DistributeOptions& options, int root = 0);
/// The same for a surface (io::load_surface).
DistributedCMap2 load_surface(MPI_Comm comm, const std::string& path, const DistributeOptions& options, int root = 0);
DistributedCMap3 load_volume(MPI_Comm comm, const std::string& path);
DistributedCMap2 load_surface(MPI_Comm comm, const std::string& path);

} // namespace cgogn::dist
