// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/properties.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/geometry/algos/laplacian.h>

#include <Eigen/SparseCholesky>

#include <cassert>
#include <vector>

namespace cgogn::geometry
{

/// Implicit Laplacian smoothing (Desbrun, Meyer, Schroeder, Barr 1999): each
/// iteration solves (M - t L) x' = M x with a sparse Cholesky factorization
/// (Eigen's SimplicialLDLT). With the cotangent Laplacian (default) M is the
/// mixed Voronoi mass matrix and t a diffusion time in squared length units
/// (t = (mean edge length)^2 smooths at the scale of the edges); with the
/// uniform Laplacian M is the identity and t counts explicit steps. L is
/// rebuilt from the current positions at each iteration. Boundary vertices
/// are fixed unless `fix_boundary` is false (they enter the right-hand side).
/// Stable for any t > 0 (precondition, asserted). O(iterations x
/// factorization cost, about n^1.5 for a surface of n vertices). Throws
/// cgogn::Error when the system cannot be factorized (e.g. a singular system
/// from a mesh collapsed to a point).
template <SurfaceMesh MESH>
void implicit_smoothing(const MESH& m, AttributeArray<Vec3>& pos, double t, uint32 iterations = 1,
						bool use_uniform_laplacian = false, bool fix_boundary = true)
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	assert(t > 0.0 && "implicit_smoothing: the time step must be positive");
	const VertexNumbering num = vertex_numbering(m);
	const uint32 n = num.size();
	// row_of[i]: row of dense vertex i in the system, INVALID_INDEX when fixed
	std::vector<uint32> row_of(n, INVALID_INDEX);
	uint32 nb_free = 0;
	foreach_cell(m, [&](Vertex v) {
		if (!(fix_boundary && is_incident_to_boundary(m, v)))
			row_of[num[index_of(m, v)]] = 0;
	});
	for (uint32 i = 0; i < n; ++i)
		if (row_of[i] == 0)
			row_of[i] = nb_free++;
	if (nb_free == 0)
		return;

	std::vector<Eigen::Triplet<double>> triplets;
	Eigen::MatrixXd b(nb_free, 3);
	Eigen::SimplicialLDLT<SparseMatrix> solver;
	for (uint32 it = 0; it < iterations; ++it)
	{
		const SparseMatrix L = use_uniform_laplacian ? uniform_laplacian(m, num) : cotan_laplacian(m, pos, num);
		Eigen::VectorXd mass = Eigen::VectorXd::Ones(n);
		if (!use_uniform_laplacian)
			foreach_cell(m, [&](Vertex v) { mass(num[index_of(m, v)]) = voronoi_area(m, v, pos); });

		triplets.clear();
		for (uint32 i = 0; i < n; ++i)
			if (row_of[i] != INVALID_INDEX)
			{
				triplets.emplace_back(row_of[i], row_of[i], mass(i));
				b.row(row_of[i]) = mass(i) * pos[num.line_of_dense_[i]].transpose();
			}
		for (int c = 0; c < L.outerSize(); ++c)
			for (SparseMatrix::InnerIterator e(L, c); e; ++e)
			{
				const uint32 r = row_of[e.row()];
				if (r == INVALID_INDEX)
					continue;
				const uint32 fc = row_of[e.col()];
				if (fc != INVALID_INDEX)
					triplets.emplace_back(r, fc, -t * e.value());
				else // a fixed neighbour: known, moves to the right-hand side
					b.row(r) += t * e.value() * pos[num.line_of_dense_[e.col()]].transpose();
			}
		SparseMatrix A(nb_free, nb_free);
		A.setFromTriplets(triplets.begin(), triplets.end());
		solver.compute(A);
		if (solver.info() != Eigen::Success)
			throw Error("implicit_smoothing: the system (M - t L) could not be factorized");
		const Eigen::MatrixXd x = solver.solve(b);
		if (solver.info() != Eigen::Success)
			throw Error("implicit_smoothing: the sparse solve failed");
		for (uint32 i = 0; i < n; ++i)
			if (row_of[i] != INVALID_INDEX)
				pos[num.line_of_dense_[i]] = x.row(row_of[i]).transpose();
	}
}

} // namespace cgogn::geometry
