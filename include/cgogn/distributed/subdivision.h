// SPDX-License-Identifier: MIT
// Uniform refinement of a distributed volume map: each rank refines its own
// volumes and its ghosts with the serial schemes' patterns, keeps one ghost
// layer, and numbers the new cells from the cells they lie in, so that every
// rank gives a new cell the same global id without a message.
#pragma once

#include <cgogn/distributed/distributed_map.h>

#include <string>

namespace cgogn::dist
{

/// One step of modeling::tet_subdivision on a distributed map: every
/// tetrahedron is cut into 8 through its edge midpoints, its inner
/// octahedron along the shortest diagonal (on a tie, the one whose ends have
/// the smallest global ids, so that every rank cuts a ghost as its owner
/// does). The map is replaced by the refined one, with the same
/// communicator and a new halo plan; attribute handles of the old map are
/// no longer attached to it.
///
/// Global ids. A new cell lies inside one old cell (an edge half inside its
/// edge, a face quarter inside its face, an inner face inside its volume).
/// Its id is the offset of its kind of old cell, plus the old cell's id
/// times the number of new cells such a cell holds, plus its rank among them
/// by their sorted vertex ids; its owner is the old cell's owner. Ids stay
/// dense (0 .. count - 1 per dimension) when the old ones are, as after
/// distribute(). New vertices: the old vertices keep their ids, an edge's
/// midpoint gets V + its edge's id. Volumes: 8 w + 0..7 for the children of
/// volume w. The result is the same to the bit for any number of ranks.
///
/// Attributes: `position` (a Vec3 vertex attribute) gets the new positions;
/// a volume attribute of a type distribute() carries is copied from each
/// volume to its children; the other attributes are named in not_carried().
///
/// Preconditions: every volume is a tetrahedron; the ghosts' positions equal
/// their owners' (as after distribute() or exchange()). Otherwise every rank
/// throws modeling::SubdivisionError (std::invalid_argument when a rank has
/// no such position attribute), the map untouched. Collective over
/// dm.comm(); O(local cells), plus the halo handshake of distribute().
void tet_subdivision(DistributedCMap3& dm, const std::string& position = "position");

/// One step of modeling::hex_subdivision on a distributed map: every
/// hexahedron is cut into 8 through its edge midpoints, face centroids and
/// vertex centroid, each centroid summed in increasing global id of its
/// vertices (the serial scheme's within rounding, the same to the bit for
/// any number of ranks). New vertices: old vertices keep their ids, then an
/// edge's midpoint is V + its edge's id, a face's centroid V + E + its face's
/// id, a volume's V + E + F + its volume's id. Everything else as
/// tet_subdivision. Precondition: every volume is a hexahedron.
void hex_subdivision(DistributedCMap3& dm, const std::string& position = "position");

} // namespace cgogn::dist
