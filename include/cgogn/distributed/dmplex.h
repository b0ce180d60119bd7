// SPDX-License-Identifier: MIT
// The bridge to PETSc: a distributed map as a DMPlex, for the solvers of
// PETSc (and the libraries built on DMPlex). Part of the optional component
// cgogn::dmplex, built when PETSc is found.
#pragma once

#include <cgogn/distributed/distributed_map.h>

#include <petscdmplex.h>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn::dist
{

/// A PETSc call failed while a DMPlex was built; what() names the call and
/// gives PETSc's message.
class DMPlexError : public std::runtime_error
{
public:
	using std::runtime_error::runtime_error;
};

/// The local map of a distributed map as an interpolated DMPlex on the
/// map's communicator: one plex point per local cell of every dimension
/// (the copies of a cell that the ghost layer's rim splits are one point),
/// the cells' positions as coordinates, and a point star forest whose root
/// for each cell is on its owner rank, so DMGlobalToLocal does what
/// exchange() does. Owns the DM (destroyed with this object, or handed over
/// by release()).
class PlexMesh
{
public:
	PlexMesh() = default;
	PlexMesh(const PlexMesh&) = delete;
	PlexMesh& operator=(const PlexMesh&) = delete;
	/// Takes other's DM; other is left empty.
	PlexMesh(PlexMesh&& other) noexcept;
	/// Destroys this DM, then takes other's.
	PlexMesh& operator=(PlexMesh&& other) noexcept;
	/// Destroys the DM (must happen before PetscFinalize).
	~PlexMesh();

	/// The DMPlex (nullptr once released).
	DM dm() const
	{
		return dm_;
	}
	/// Hands the DM to the caller, who must DMDestroy it.
	DM release();

	/// The plex point of each local line of the cells of dimension k (0 for
	/// vertices ... the map's dimension), -1 on lines that hold no cell.
	const std::vector<PetscInt>& points(uint32 k) const
	{
		return points_[k];
	}

	/// Internal to to_dmplex(): takes the DM and the points by line.
	PlexMesh(DM dm, std::vector<std::vector<PetscInt>> points) : dm_(dm), points_(std::move(points))
	{
	}

private:
	DM dm_ = nullptr;
	std::vector<std::vector<PetscInt>> points_;
};

/// The plex point of the local cell c of dm, in pm = to_dmplex(dm). O(1).
template <typename MAP, typename CELL>
PetscInt plex_point(const PlexMesh& pm, const DistributedMap<MAP>& dm, CELL c)
{
	return pm.points(DistributedMap<MAP>::template dimension_of<CELL>())[index_of(dm.map(), c)];
}

/// This rank's part of dm as a DMPlex (see PlexMesh): tetrahedra, pyramids,
/// triangular prisms and hexahedra, in any mix, with vertex coordinates from
/// the Vec3 vertex attribute `position`. Each cell's cone lists its corners
/// from a vertex chosen by global id, and each edge and face its vertices
/// from the smallest global id towards the smaller neighbour, so that the
/// copies of a cell have the same cone on every rank (DMPlexCheck's
/// interface test). The plex's overlap is one cell, and it does not
/// distribute itself again in DMSetFromOptions. The volumes must be
/// positively oriented (faces counterclockwise seen from outside, as
/// geometry::volume expects), or DMPlexCheckGeometry finds them inverted.
/// PETSc must be initialised. Collective over dm.comm().
/// Throws std::invalid_argument on every rank when a rank lacks the
/// attribute, holds another kind of cell, or holds two edges (faces) on the
/// same vertices, which DMPlex cannot tell apart (a mesh that is not
/// conforming there); std::runtime_error (DMPlexError where it can)
/// naming the PETSc call that failed; PETSc's own error printing is off
/// during the call. Cost O(size of the local map) plus PETSc's
/// interpolation, one exchange() per dimension and a few reductions.
PlexMesh to_dmplex(const DistributedCMap3& dm, const std::string& position);
PlexMesh to_dmplex(const DistributedCMap3& dm);

/// The same for a surface: triangles and quadrilaterals, in any mix,
/// counterclockwise, in a DMPlex of dimension 2 with 3-D coordinates.
PlexMesh to_dmplex(const DistributedCMap2& dm, const std::string& position);
PlexMesh to_dmplex(const DistributedCMap2& dm);

} // namespace cgogn::dist
