// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap2.h>
#include <cgogn/geometry/algos/dart_geometry.h>

#include <cassert>
#include <vector>

namespace cgogn::geometry
{

namespace detail
{

/// Scratch of the explicit smoothing filters: one displacement and one
/// "moves" flag per vertex line, allocated once per call.
template <GeometricMesh MESH>
struct UniformSmoother
{
	using Vertex = typename mesh_traits<MESH>::Vertex;

	UniformSmoother(const MESH& m, bool fix_boundary) : m_(m), delta_(end_index()), moves_(end_index(), 0)
	{
		foreach_cell(m, [&](Vertex v) { moves_[index_of(m, v)] = !(fix_boundary && is_incident_to_boundary(m, v)); });
	}

	/// One Jacobi step x += factor (mean of the neighbours - x).
	void step(AttributeArray<Vec3>& pos, double factor)
	{
		foreach_cell(m_, [&](Vertex v) {
			const uint32 i = index_of(m_, v);
			if (!moves_[i])
				return;
			Vec3 s = Vec3::Zero();
			uint32 n = 0;
			foreach_adjacent_vertex_through_edge(m_, v, [&](Vertex w) {
				s += value<Vec3>(m_, pos, w);
				++n;
			});
			delta_[i] = n > 0 ? Vec3(factor * (s / n - pos[i])) : Vec3::Zero();
		});
		foreach_cell(m_, [&](Vertex v) {
			const uint32 i = index_of(m_, v);
			if (moves_[i])
				pos[i] += delta_[i];
		});
	}

private:
	uint32 end_index() const
	{
		return container_of<Vertex::ORBIT>(map_of(m_)).end_index();
	}

	const MESH& m_;
	std::vector<Vec3> delta_;
	std::vector<uint8> moves_;
};

} // namespace detail

/// Explicit uniform Laplacian smoothing: `iterations` Jacobi steps
/// x_i += lambda (mean of the neighbours of i - x_i). Shrinks closed shapes
/// (see taubin_smoothing). Boundary vertices (of a surface, or on the
/// boundary of a volume mesh) stay in place unless `fix_boundary` is false.
/// O(iterations x number of darts); one scratch array per vertex line.
/// Precondition: 0 < lambda <= 1.
template <GeometricMesh MESH>
void laplacian_smoothing(const MESH& m, AttributeArray<Vec3>& pos, uint32 iterations, double lambda = 0.5,
						 bool fix_boundary = true)
{
	assert(lambda > 0.0 && lambda <= 1.0);
	detail::UniformSmoother<MESH> s(m, fix_boundary);
	for (uint32 k = 0; k < iterations; ++k)
		s.step(pos, lambda);
}

/// Taubin's lambda|mu smoothing (Taubin 1995): each iteration is a uniform
/// Laplacian step with factor lambda > 0 followed by one with mu < -lambda,
/// a low-pass filter with pass-band frequency 1/lambda + 1/mu that removes
/// noise without the shrinking of plain Laplacian smoothing. Boundary as in
/// laplacian_smoothing. O(iterations x number of darts). Preconditions:
/// lambda > 0, mu < -lambda.
template <GeometricMesh MESH>
void taubin_smoothing(const MESH& m, AttributeArray<Vec3>& pos, uint32 iterations, double lambda = 0.5,
					  double mu = -0.53, bool fix_boundary = true)
{
	assert(lambda > 0.0 && mu < -lambda);
	detail::UniformSmoother<MESH> s(m, fix_boundary);
	for (uint32 k = 0; k < iterations; ++k)
	{
		s.step(pos, lambda);
		s.step(pos, mu);
	}
}

} // namespace cgogn::geometry
