// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/distributed/exchange.h>
#include <cgogn/geometry/types/vector_traits.h>

namespace cgogn::dist
{

/// The options of laplacian_smoothing().
struct SmoothingOptions
{
	double lambda = 0.5;      ///< The step: x += lambda (mean of the neighbours - x); 0 < lambda <= 1.
	bool fix_boundary = true; ///< Vertices on the boundary of the whole mesh stay in place.
	/// Add each vertex's neighbours in increasing global id: the result is
	/// then the same to the bit whatever the number of ranks (and equal to a
	/// 1-rank run). Otherwise they are added in the local map's order, which
	/// differs from rank to rank in the last bits only.
	bool deterministic = false;
	Transport transport = Transport::NeighborhoodCollective; ///< How the positions are exchanged.
};

/// Explicit uniform Laplacian smoothing of a distributed map, as
/// geometry::laplacian_smoothing of the whole map: `iterations` Jacobi steps
/// on the owned vertices, each followed by one exchange of the positions.
/// Collective over dm.comm(). O(iterations x (darts of the rank + ghost
/// layer)). Precondition: every rank's copies of the positions agree (as
/// distribute() leaves them).
void laplacian_smoothing(const DistributedCMap3& dm, CellAttribute<Vec3, CMap3::Vertex::ORBIT>& pos, uint32 iterations,
						 const SmoothingOptions& options = {});

/// The same on a distributed surface.
void laplacian_smoothing(const DistributedCMap2& dm, CellAttribute<Vec3, CMap2::Vertex::ORBIT>& pos, uint32 iterations,
						 const SmoothingOptions& options = {});

/// Taubin's lambda|mu smoothing of a distributed map, as
/// geometry::taubin_smoothing: each iteration is a Jacobi step of factor
/// options.lambda then one of factor mu, each followed by an exchange.
/// Collective; cost as laplacian_smoothing, twice. Preconditions:
/// options.lambda > 0, mu < -options.lambda.
void taubin_smoothing(const DistributedCMap3& dm, CellAttribute<Vec3, CMap3::Vertex::ORBIT>& pos, uint32 iterations,
					  double mu, const SmoothingOptions& options = {});
/// The same on a distributed surface.
void taubin_smoothing(const DistributedCMap2& dm, CellAttribute<Vec3, CMap2::Vertex::ORBIT>& pos, uint32 iterations,
					  double mu, const SmoothingOptions& options = {});

} // namespace cgogn::dist
