// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/cotan_stiffness.h>
#include <cgogn/geometry/algos/vertex_numbering.h>
#include <cgogn/geometry/algos/voronoi_area.h>

#include <Eigen/Sparse>

#include <vector>

namespace cgogn::geometry
{

/// Sparse matrix type of the geometry layer (column-major, double).
using SparseMatrix = Eigen::SparseMatrix<double>;

/// Cotangent Laplacian L of a surface, indexed by the dense numbering `num`:
/// L(i, j) = (cot a_ij + cot b_ij) / 2 for the edge (i, j) of two triangles,
/// L(i, i) = -sum_j L(i, j). Symmetric, zero row sums, negative semi-definite
/// (minus the stiffness matrix of linear finite elements; off-diagonal
/// entries turn negative across obtuse angles); (L x)_i is the integrated
/// Laplace-Beltrami of x at vertex i (divide by the vertex area for the
/// pointwise value).
/// Polygons use the virtual refinement of detail::FaceStiffness (vertices of a
/// polygon that share no edge get weights too). Boundary edges have a
/// single cotangent (natural Neumann condition). O(sum of squared face degrees).
template <SurfaceMesh MESH>
SparseMatrix cotan_laplacian(const MESH& m, const AttributeArray<Vec3>& pos, const VertexNumbering& num)
{
	using Face = typename mesh_traits<MESH>::Face;
	using Vertex = typename mesh_traits<MESH>::Vertex;
	std::vector<Eigen::Triplet<double>> triplets;
	triplets.reserve(9 * std::size_t(nb_cells<Face>(m)));
	detail::FaceStiffness k;
	foreach_cell(m, [&](Face f) {
		const uint32 n = k.compute(m, pos, f.dart);
		for (uint32 i = 0; i < n; ++i)
		{
			const uint32 r = num[index_of(m, Vertex(k.dart(i)))];
			for (uint32 j = 0; j < n; ++j)
				triplets.emplace_back(r, num[index_of(m, Vertex(k.dart(j)))], k(i, j));
		}
	});
	SparseMatrix L(num.size(), num.size());
	L.setFromTriplets(triplets.begin(), triplets.end());
	return L;
}

/// Uniform (graph) Laplacian of a mesh, indexed by `num`: L(i, j) = 1 for
/// each edge (i, j), L(i, i) = -degree(i). Symmetric, zero row sums; the
/// averaging operator of uniform smoothing is D^-1 L with D = -diag(L).
/// O(number of edges).
template <GeometricMesh MESH>
SparseMatrix uniform_laplacian(const MESH& m, const VertexNumbering& num)
{
	using Edge = typename mesh_traits<MESH>::Edge;
	using Vertex = typename mesh_traits<MESH>::Vertex;
	std::vector<Eigen::Triplet<double>> triplets;
	triplets.reserve(4 * std::size_t(nb_cells<Edge>(m)));
	foreach_cell(m, [&](Edge e) {
		const uint32 a = num[index_of(m, Vertex(e.dart))];
		const uint32 b = num[index_of(m, Vertex(oriented_phi1(m, e.dart)))];
		triplets.emplace_back(a, b, 1.0);
		triplets.emplace_back(b, a, 1.0);
		triplets.emplace_back(a, a, -1.0);
		triplets.emplace_back(b, b, -1.0);
	});
	SparseMatrix L(num.size(), num.size());
	L.setFromTriplets(triplets.begin(), triplets.end());
	return L;
}

/// Diagonal mass matrix of a surface, indexed by `num`: the voronoi_area of
/// each vertex (mixed Voronoi on triangles). Its trace is the surface area.
/// O(number of darts).
template <SurfaceMesh MESH>
SparseMatrix mass_matrix(const MESH& m, const AttributeArray<Vec3>& pos, const VertexNumbering& num)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	std::vector<Eigen::Triplet<double>> triplets;
	triplets.reserve(num.size());
	foreach_cell(m, [&](Vertex v) {
		const uint32 i = num[index_of(m, v)];
		triplets.emplace_back(i, i, voronoi_area(m, v, pos));
	});
	SparseMatrix M(num.size(), num.size());
	M.setFromTriplets(triplets.begin(), triplets.end());
	return M;
}

} // namespace cgogn::geometry
