// SPDX-License-Identifier: MIT
// Error quadrics of Garland and Heckbert (1997): sums of squared distances to planes.
#pragma once

#include <cgogn/geometry/types/vector_traits.h>

#include <Eigen/Core>

#include <array>
#include <cmath>

namespace cgogn::modeling
{

/// A symmetric 4x4 quadric Q = sum of w (n, d)(n, d)^T over planes n.x + d = 0
/// (n unit), stored as its 10 distinct coefficients. Q(x) is the weighted sum
/// of the squared distances of x to the planes.
class Quadric
{
public:
	Quadric() = default;

	/// The quadric of the plane through p with unit normal n, weighted by w.
	static Quadric plane(const Vec3& n, const Vec3& p, double w = 1.0)
	{
		const double d = -n.dot(p);
		Quadric q;
		q.c_ = {w * n.x() * n.x(), w * n.x() * n.y(), w * n.x() * n.z(), w * n.x() * d, w * n.y() * n.y(),
				w * n.y() * n.z(), w * n.y() * d,     w * n.z() * n.z(), w * n.z() * d, w * d * d};
		return q;
	}

	/// Adds the planes of o: Q(x) becomes Q(x) + o(x). O(1).
	Quadric& operator+=(const Quadric& o)
	{
		for (std::size_t i = 0; i < c_.size(); ++i)
			c_[i] += o.c_[i];
		return *this;
	}
	/// The quadric of the planes of a and b: (a + b)(x) = a(x) + b(x). O(1).
	friend Quadric operator+(Quadric a, const Quadric& b)
	{
		return a += b;
	}

	/// Q(x) = x^T A x + 2 b.x + c, clamped at 0 against rounding.
	double operator()(const Vec3& x) const
	{
		const double e = x.x() * (c_[0] * x.x() + 2.0 * (c_[1] * x.y() + c_[2] * x.z() + c_[3])) +
						 x.y() * (c_[4] * x.y() + 2.0 * (c_[5] * x.z() + c_[6])) +
						 x.z() * (c_[7] * x.z() + 2.0 * c_[8]) + c_[9];
		return e > 0.0 ? e : 0.0;
	}

	/// The minimizer of Q when the 3x3 part A is well conditioned (its
	/// determinant is not negligible against the cube of its trace, so nearly
	/// flat or cylindrical neighbourhoods count as singular); false otherwise.
	bool minimizer(Vec3& x) const
	{
		const double a = c_[0], b = c_[1], c = c_[2], d = c_[4], e = c_[5], f = c_[7];
		// cofactors of the symmetric matrix [a b c; b d e; c e f]
		const double c00 = d * f - e * e, c01 = c * e - b * f, c02 = b * e - c * d;
		const double det = a * c00 + b * c01 + c * c02;
		const double tr = a + d + f;
		if (!(std::abs(det) > 1e-10 * tr * tr * tr))
			return false;
		const double c11 = a * f - c * c, c12 = b * c - a * e, c22 = a * d - b * b;
		const Vec3 r(-c_[3], -c_[6], -c_[8]);
		x = Vec3(c00 * r.x() + c01 * r.y() + c02 * r.z(), c01 * r.x() + c11 * r.y() + c12 * r.z(),
				 c02 * r.x() + c12 * r.y() + c22 * r.z()) /
			det;
		return true;
	}

private:
	std::array<double, 10> c_{};
};

} // namespace cgogn::modeling
