// SPDX-License-Identifier: MIT
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/modeling/fairing.h>

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseLU>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace cgogn::modeling
{

namespace
{

using Vertex = CMap2::Vertex;

// a cotangent weight below this (an edge facing obtuse angles) is raised to
// it: negative weights would make the system indefinite
constexpr double MIN_COTAN_WEIGHT = 1e-3;

const Vec3& origin(const CMap2& m, const AttributeArray<Vec3>& pos, Dart d)
{
	return pos[index_of(m, Vertex(d))];
}

/// Cotangent of the angle opposite to the edge of d in d's face, 0 when that
/// face is a boundary or not a triangle.
double opposite_cotan(const CMap2& m, const AttributeArray<Vec3>& pos, Dart d)
{
	if (is_boundary(m, d) || phi1(m, phi1(m, phi1(m, d))) != d)
		return 0.0;
	const Vec3& o = origin(m, pos, phi_1(m, d));
	const Vec3 u = origin(m, pos, d) - o, v = origin(m, pos, phi1(m, d)) - o;
	const double s = u.cross(v).norm();
	return s > 0.0 ? u.dot(v) / s : 0.0;
}

/// Dense local numbering of the vertices the system touches: the free ones
/// first (0 .. nb_free - 1), then the others as they are met.
struct LocalNumbering
{
	std::unordered_map<uint32, uint32> id;
	std::vector<Vertex> vertices;

	uint32 get(const CMap2& m, Vertex v)
	{
		const auto [it, inserted] = id.emplace(index_of(m, v), uint32(vertices.size()));
		if (inserted)
			vertices.push_back(v);
		return it->second;
	}
};

} // namespace

bool fair_vertices(const CMap2& m, AttributeArray<Vec3>& pos, std::span<const CMap2::Vertex> free, FairingWeights w,
				   uint32 continuity)
{
	assert(continuity <= 2);
	if (free.empty())
		return true;
	LocalNumbering num;
	for (Vertex v : free)
		num.get(m, v);
	const uint32 nb_free = uint32(num.vertices.size());
	assert(nb_free == free.size());

	// rows of the Laplacian: the free vertices and their rings up to
	// `continuity` (what the rows of L^(continuity + 1) at the free vertices
	// read); their neighbours get numbers as columns
	std::vector<Eigen::Triplet<double>> triplets;
	uint32 rows_end = nb_free;
	uint32 row = 0;
	for (uint32 ring = 0; ring <= continuity; ++ring)
	{
		for (; row < rows_end; ++row)
		{
			const Vertex v = num.vertices[row];
			std::vector<std::pair<uint32, double>> weights;
			double total = 0.0;
			foreach_dart_of_orbit(m, v, [&](Dart d) {
				const uint32 j = num.get(m, Vertex(phi1(m, d)));
				double wj = 1.0;
				if (w == FairingWeights::Cotangent)
					wj = std::max(0.5 * (opposite_cotan(m, pos, d) + opposite_cotan(m, pos, phi2(m, d))),
								  MIN_COTAN_WEIGHT);
				weights.emplace_back(j, wj);
				total += wj;
			});
			triplets.emplace_back(row, row, -1.0);
			for (const auto& [j, wj] : weights)
				triplets.emplace_back(row, j, wj / total);
		}
		rows_end = uint32(num.vertices.size());
	}
	const uint32 n = uint32(num.vertices.size());
	Eigen::SparseMatrix<double> L(n, n);
	L.setFromTriplets(triplets.begin(), triplets.end());
	Eigen::SparseMatrix<double> power = L;
	for (uint32 k = 0; k < continuity; ++k)
		power = Eigen::SparseMatrix<double>(L * power);
	// rows of the free vertices: A x_free = -B x_fixed
	const Eigen::SparseMatrix<double> rows = power.topRows(nb_free);
	const Eigen::SparseMatrix<double> A = rows.leftCols(nb_free);
	const Eigen::SparseMatrix<double> B = rows.rightCols(n - nb_free);
	Eigen::MatrixXd fixed(n - nb_free, 3);
	for (uint32 i = nb_free; i < n; ++i)
		fixed.row(i - nb_free) = origin(m, pos, num.vertices[i].dart).transpose();
	const Eigen::MatrixXd rhs = -(B * fixed);

	Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
	solver.compute(A);
	if (solver.info() != Eigen::Success)
		return false;
	const Eigen::MatrixXd x = solver.solve(rhs);
	if (solver.info() != Eigen::Success || !x.allFinite())
		return false;
	for (uint32 i = 0; i < nb_free; ++i)
		pos[index_of(m, num.vertices[i])] = x.row(i).transpose();
	return true;
}

} // namespace cgogn::modeling
