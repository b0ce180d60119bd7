// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/geometry/algos/dart_geometry.h>

#include <Eigen/Core>

#include <vector>

namespace cgogn::geometry::detail
{

/// The cotangent stiffness matrix of one face: K(i, j) = w_ij for i != j and
/// K(i, i) = -sum_j w_ij, so that sum_j K(i, j) x_j is the face's share of the
/// Laplacian of x at its i-th vertex. Triangles: w_ij = cot(angle opposite
/// (i, j)) / 2. Other polygons: the virtual refinement of Bunge et al. 2020
/// with a uniform virtual vertex: the polygon is fanned around its vertex
/// centroid, the cotangent matrix K' of the fan is computed, and the centroid
/// is eliminated (K = P^T K' P, P the n x (n+1) prolongation whose last row is
/// 1/n). K stays symmetric with zero row sums and reproduces linear functions on
/// planar polygons. Keeps its buffers: no allocation once warm.
class FaceStiffness
{
public:
	/// Fills the matrix for the face cycle of dart f (on a G-map, walked in
	/// the orientation of f: see oriented_phi1; K does not depend on it).
	/// Returns its degree n; dart(i) is the dart of the i-th vertex, K(i, j)
	/// the matrix.
	template <GeometricMesh MESH>
	uint32 compute(const MESH& m, const AttributeArray<Vec3>& pos, Dart f)
	{
		darts_.clear();
		p_.clear();
		Dart it = f;
		do
		{
			darts_.push_back(it);
			p_.push_back(origin_position(m, pos, it));
			it = oriented_phi1(m, it);
		} while (it != f);
		const uint32 n = uint32(darts_.size());
		if (n == 3)
		{
			if (k_.rows() < 3)
				k_.resize(3, 3);
			k_.topLeftCorner(3, 3).setZero();
			triangle(0, 1, 2, p_[0], p_[1], p_[2]);
			return 3;
		}
		// fan around the centroid c (node n), then eliminate c
		Vec3 c = Vec3::Zero();
		for (const Vec3& q : p_)
			c += q;
		c /= n;
		if (k_.rows() < n + 1)
			k_.resize(n + 1, n + 1);
		k_.topLeftCorner(n + 1, n + 1).setZero();
		for (uint32 i = 0; i < n; ++i)
		{
			const uint32 j = (i + 1) % n;
			triangle(i, j, n, p_[i], p_[j], c);
		}
		const double s = 1.0 / n;
		const double kcc = k_(n, n);
		for (uint32 i = 0; i < n; ++i)
			for (uint32 j = 0; j < n; ++j)
				k_(i, j) += s * (k_(i, n) + k_(n, j)) + s * s * kcc;
		return n;
	}

	Dart dart(uint32 i) const
	{
		return darts_[i];
	}
	double operator()(uint32 i, uint32 j) const
	{
		return k_(i, j);
	}
	const Vec3& position(uint32 i) const
	{
		return p_[i];
	}

private:
	void add(uint32 a, uint32 b, double w)
	{
		k_(a, b) += w;
		k_(b, a) += w;
		k_(a, a) -= w;
		k_(b, b) -= w;
	}
	void triangle(uint32 a, uint32 b, uint32 c, const Vec3& pa, const Vec3& pb, const Vec3& pc)
	{
		add(b, c, 0.5 * cotan(pb - pa, pc - pa));
		add(c, a, 0.5 * cotan(pc - pb, pa - pb));
		add(a, b, 0.5 * cotan(pa - pc, pb - pc));
	}

	std::vector<Dart> darts_;
	std::vector<Vec3> p_;
	Eigen::MatrixXd k_;
};

/// A per-thread FaceStiffness for functions that work on one vertex at a
/// time, so that calling them in a loop does not allocate.
inline FaceStiffness& face_stiffness_scratch()
{
	thread_local FaceStiffness s;
	return s;
}

} // namespace cgogn::geometry::detail
