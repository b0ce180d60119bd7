// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/distributed/distributed_map.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <cmath>
#include <limits>

namespace cgogn::dist
{

/// The sum over the ranks of comm of an integer. Collective; O(log ranks).
uint64 global_sum(MPI_Comm comm, uint64 local);

/// The sum over the ranks of comm of a double: the ranks' values are
/// gathered and added in rank order, so every rank gets the same bits and
/// the result does not depend on message timing. Collective; O(ranks).
double global_sum(MPI_Comm comm, double local);

/// The number of cells of type CELL of the whole distributed map: each rank
/// counts the cells it owns. Collective; O(cells of the rank).
template <typename CELL, typename MAP>
uint64 global_nb_cells(const DistributedMap<MAP>& dm)
{
	uint64 n = 0;
	foreach_cell(dm.map(), [&](CELL c) { n += is_owned(dm, c); });
	return global_sum(dm.comm(), n);
}

/// V - E + F (- W for volumes) of the whole distributed map. Collective;
/// O(cells of the rank).
template <typename MAP>
int64 global_euler_characteristic(const DistributedMap<MAP>& dm)
{
	int64 chi = int64(global_nb_cells<typename MAP::Vertex>(dm)) - int64(global_nb_cells<typename MAP::Edge>(dm)) +
				int64(global_nb_cells<typename MAP::Face>(dm));
	if constexpr (MAP::dimension == 3)
		chi -= int64(global_nb_cells<CMap3::Volume>(dm));
	return chi;
}

/// The sum of f(c) over every cell of type CELL of the whole map (each
/// counted once, on its owner), compensated on each rank and added in rank
/// order (see global_sum). Collective; O(cells of the rank).
template <typename CELL, typename MAP, typename FUNC>
double global_sum_of(const DistributedMap<MAP>& dm, const FUNC& f)
{
	// Neumaier's compensated sum
	double sum = 0, compensation = 0;
	foreach_cell(dm.map(), [&](CELL c) {
		if (!is_owned(dm, c))
			return;
		const double x = f(c), t = sum + x;
		compensation += std::abs(sum) >= std::abs(x) ? (sum - t) + x : (x - t) + sum;
		sum = t;
	});
	return global_sum(dm.comm(), sum + compensation);
}

/// An axis-aligned box.
struct BoundingBox
{
	Vec3 min = Vec3::Zero(); ///< The lowest corner.
	Vec3 max = Vec3::Zero(); ///< The highest corner.
};

/// The box that holds every rank's box: componentwise minimum of the mins
/// and maximum of the maxes. Collective; two MPI_Allreduce.
BoundingBox global_union(MPI_Comm comm, const BoundingBox& local);

/// The box of the positions of all the vertices of the whole map (of no
/// vertex: min > max). Collective; O(vertices of the rank).
template <typename MAP>
BoundingBox global_bounding_box(const DistributedMap<MAP>& dm, const AttributeArray<Vec3>& pos)
{
	BoundingBox box{Vec3::Constant(std::numeric_limits<double>::infinity()),
					Vec3::Constant(-std::numeric_limits<double>::infinity())};
	foreach_cell(dm.map(), [&](typename MAP::Vertex v) {
		const Vec3& p = pos[index_of(dm.map(), v)];
		box.min = box.min.cwiseMin(p);
		box.max = box.max.cwiseMax(p);
	});
	return global_union(dm.comm(), box);
}

} // namespace cgogn::dist
