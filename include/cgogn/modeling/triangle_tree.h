// SPDX-License-Identifier: MIT
// Closest points on a triangle set (an AABB tree), and the distance of a
// surface's vertices to another surface.
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <array>
#include <vector>

namespace cgogn::modeling
{

/// A static bounding-box tree over a snapshot of triangles, for closest-point
/// queries (projection onto a reference surface, distances between meshes).
/// Built by median splits along the longest axis, leaves of at most 4
/// triangles. Later changes of the map do not affect it.
class TriangleTree
{
public:
	using Triangle = std::array<Vec3, 3>; ///< A triangle by its three corners.

	/// The triangles of m's faces (polygons as fans from their first corner).
	/// O(n log n).
	TriangleTree(const CMap2& m, const AttributeArray<Vec3>& pos);
	/// The given triangles. O(n log n).
	explicit TriangleTree(std::vector<Triangle> triangles);

	/// The answer of closest_point().
	struct Hit
	{
		Vec3 point = Vec3::Zero(); ///< the closest point
		double squared_distance;   ///< to the query point
		uint32 triangle;           ///< index of the triangle it lies on
	};

	/// The point of the triangles nearest to p. Precondition: size() > 0.
	/// O(log n) on well-spread triangles.
	Hit closest_point(const Vec3& p) const;

	/// Number of triangles. O(1).
	std::size_t size() const
	{
		return triangles_.size();
	}
	/// Triangle i, i < size() (not checked), as Hit::triangle numbers them:
	/// the tree's own order, not the order the triangles were given in. O(1).
	const Triangle& triangle(uint32 i) const
	{
		return triangles_[i];
	}

private:
	struct Node
	{
		Vec3 lo = Vec3::Zero(), hi = Vec3::Zero(); // the box of the node's triangles
		uint32 begin = 0, end = 0;                 // triangles_[begin, end) for a leaf
		uint32 right = 0;                          // second child (the first is the next node); 0 for a leaf
	};

	void build();
	uint32 build_node(uint32 begin, uint32 end);

	std::vector<Triangle> triangles_;
	std::vector<Node> nodes_;
};

/// The closest point to p on triangle (a, b, c) (Ericson's region test). O(1).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

/// Statistics of the distances of a mesh's vertices to a reference surface,
/// in the unit of the positions.
struct SurfaceDistance
{
	double max = 0.0;  ///< largest vertex distance
	double mean = 0.0; ///< mean vertex distance
	double rms = 0.0;  ///< root mean square vertex distance
};

/// Distances of m's vertices to the reference triangles (one-sided: a
/// Hausdorff-like bound from m to the reference, sampled at the vertices).
/// O(V log n).
SurfaceDistance vertex_distance_to_surface(const CMap2& m, const AttributeArray<Vec3>& pos,
										   const TriangleTree& reference);
/// Not for 3-maps (their faces are not a surface): deleted, so that such a call does not compile.
SurfaceDistance vertex_distance_to_surface(const CMap3& m, const AttributeArray<Vec3>& pos,
										   const TriangleTree& reference) = delete;

} // namespace cgogn::modeling
