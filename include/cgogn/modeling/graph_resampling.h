// SPDX-License-Identifier: MIT
// Resampling a graph's branches by arc length.
#pragma once

#include <cgogn/core/map/graph.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <memory>

namespace cgogn::modeling
{

/// Appends to `out` the graph g with each branch (see branches) resampled
/// at an even arc-length spacing close to `spacing`: a branch of length L
/// becomes max(1, round(L / spacing)) edges of equal length along the
/// original polyline. The branches' ends (vertices of degree other than 2)
/// and the isolated vertices keep their positions; a closed branch keeps its
/// first vertex. So the components and the cycle rank are kept. When g has
/// the double vertex attribute "radius", out gets it too, interpolated
/// linearly along the arc length. Returns the "position" attribute of out
/// (created if out has none), filled for the new vertices. Throws Error
/// (nothing appended) when spacing is not a positive finite number, when a
/// branch would need more than 2^26 edges (a spacing far too small), or
/// when out has a vertex attribute "position" (or "radius") of another type.
/// O(size of g + size of the result).
std::shared_ptr<AttributeArray<Vec3>> resample_graph(const Graph& g, const AttributeArray<Vec3>& pos, double spacing,
													 Graph& out);

/// The same into a new graph, returned, with its "position" (and "radius")
/// vertex attributes. O(size of g + size of the result).
Graph resample_graph(const Graph& g, const AttributeArray<Vec3>& pos, double spacing);

} // namespace cgogn::modeling
