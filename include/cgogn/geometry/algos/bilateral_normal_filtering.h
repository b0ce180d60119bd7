// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_gmap2.h>
#include <cgogn/geometry/algos/normal.h>

#include <cassert>
#include <cmath>
#include <vector>

namespace cgogn::geometry
{

/// Parameters of bilateral_normal_filtering.
struct BilateralNormalFilteringParams
{
	/// Passes of the normal filter.
	uint32 normal_iterations = 20;
	/// Passes of the vertex update that fits the faces to the filtered normals.
	uint32 vertex_iterations = 10;
	/// Range (normal difference) scale sigma_r of the Gaussian weight.
	double sigma_r = 0.35;
	/// Spatial scale sigma_s; 0 means the mean distance between the centroids
	/// of edge-adjacent faces.
	double sigma_s = 0.0;
	/// Keep boundary vertices in place.
	bool fix_boundary = true;
};

/// Mesh denoising by bilateral filtering of the face normals (Zheng, Fu, Au,
/// Tai 2011): each face normal is replaced by the area-weighted average of the
/// normals of the faces sharing a vertex with it (itself included), weighted
/// by Gaussians of the centroid distance (sigma_s) and of the normal
/// difference (sigma_r), so that sharp edges survive; then the vertices are
/// moved so that the faces become orthogonal to the filtered normals
/// (x_v += mean over incident faces f of n_f (n_f . (c_f - x_v))). Any
/// polygons (Newell normals, vertex centroids). O((normal_iterations x sum of
/// the face one-ring sizes) + vertex_iterations x number of darts); scratch
/// arrays of one entry per dart and per face, allocated once. On a G-map,
/// orientable or not, each face's neighbours are oriented as the face before
/// their normals are compared, so the result is that of the 2-map of the
/// same surface. Preconditions: sigma_r > 0, sigma_s >= 0.
template <SurfaceMesh MESH>
void bilateral_normal_filtering(const MESH& m, AttributeArray<Vec3>& pos, const BilateralNormalFilteringParams& p = {})
{
	using Vertex = typename mesh_traits<MESH>::Vertex;
	using Face = typename mesh_traits<MESH>::Face;
	assert(p.sigma_r > 0.0 && p.sigma_s >= 0.0);

	// number the faces densely through their darts: no face attribute needed
	const uint32 nb_darts = container_of<Orbit::DART>(map_of(m)).end_index();
	std::vector<uint32> face_of_dart(nb_darts, INVALID_INDEX);
	// G-maps: whether a dart runs its face as the face's dart does (faces[i])
	std::vector<uint8> aligned(is_gmap_v<MESH> ? nb_darts : 0, 0);
	std::vector<Dart> faces;
	foreach_cell(m, [&](Face f) {
		foreach_dart_of_orbit(m, f, [&](Dart d) { face_of_dart[d.index] = uint32(faces.size()); });
		if constexpr (is_gmap_v<MESH>)
			for (Dart d = f.dart; !aligned[d.index]; d = oriented_phi1(m, d))
				aligned[d.index] = 1;
		faces.push_back(f.dart);
	});
	const std::size_t nf = faces.size();
	std::vector<Vec3> normal(nf), filtered(nf), center(nf);
	std::vector<double> area(nf);
	auto vertex_centroid = [&](Dart f) {
		Vec3 c = Vec3::Zero();
		uint32 k = 0;
		Dart d = f;
		do
		{
			c += origin_position(m, pos, d);
			++k;
			d = oriented_phi1(m, d);
		} while (d != f);
		return Vec3(c / k);
	};
	for (std::size_t i = 0; i < nf; ++i)
	{
		const Vec3 n = newell_vector(m, pos, faces[i]);
		area[i] = 0.5 * n.norm();
		normal[i] = area[i] > 0.0 ? Vec3(n / (2.0 * area[i])) : Vec3::Zero();
		center[i] = vertex_centroid(faces[i]);
	}
	// Calls fn(j, s) for the faces j sharing a vertex with face i, s = 1 when
	// normal[j] is oriented as face i sees it, -1 when it must be turned over
	// (G-maps: the walk around each vertex of i keeps i's orientation)
	auto foreach_neighbour = [&](std::size_t i, const auto& fn) {
		if constexpr (is_gmap_v<MESH>)
		{
			const Dart f = faces[i];
			Dart d = f;
			do
			{
				// as foreach_adjacent_face_through_vertex on a 2-map
				for (Dart it = oriented_phi1(m, oriented_phi2(m, d)); it != d;)
				{
					const Dart next = oriented_phi1(m, oriented_phi2(m, it));
					if (next == d)
						break;
					if (!is_boundary(m, it))
						fn(face_of_dart[it.index], aligned[it.index] ? 1.0 : -1.0);
					it = next;
				}
				d = oriented_phi1(m, d);
			} while (d != f);
		}
		else
			foreach_adjacent_face_through_vertex(m, Face(faces[i]),
												 [&](Face g) { fn(face_of_dart[g.dart.index], 1.0); });
	};

	double sigma_s = p.sigma_s;
	if (sigma_s <= 0.0)
	{
		double sum = 0.0;
		uint32 k = 0;
		for (std::size_t i = 0; i < nf; ++i)
			foreach_adjacent_face_through_edge(m, Face(faces[i]), [&](Face g) {
				sum += (center[i] - center[face_of_dart[g.dart.index]]).norm();
				++k;
			});
		sigma_s = k > 0 ? sum / k : 1.0;
	}
	const double ws = -0.5 / (sigma_s * sigma_s);
	const double wr = -0.5 / (p.sigma_r * p.sigma_r);

	for (uint32 it = 0; it < p.normal_iterations; ++it)
	{
		for (std::size_t i = 0; i < nf; ++i)
		{
			Vec3 s = area[i] * normal[i];
			foreach_neighbour(i, [&](uint32 j, double sign) {
				const Vec3 nj = sign * normal[j];
				const double w = area[j] * std::exp(ws * (center[i] - center[j]).squaredNorm()) *
								 std::exp(wr * (normal[i] - nj).squaredNorm());
				s += w * nj;
			});
			const double l = s.norm();
			filtered[i] = l > 0.0 ? Vec3(s / l) : normal[i];
		}
		normal.swap(filtered);
	}

	std::vector<uint8> moves(container_of<Vertex::ORBIT>(map_of(m)).end_index(), 0);
	foreach_cell(m, [&](Vertex v) { moves[index_of(m, v)] = !(p.fix_boundary && is_incident_to_boundary(m, v)); });
	std::vector<Vec3> delta(moves.size(), Vec3::Zero());
	for (uint32 it = 0; it < p.vertex_iterations; ++it)
	{
		if (it > 0) // centroids follow the vertices; the target normals stay
			for (std::size_t i = 0; i < nf; ++i)
				center[i] = vertex_centroid(faces[i]);
		foreach_cell(m, [&](Vertex v) {
			const uint32 iv = index_of(m, v);
			if (!moves[iv])
				return;
			const Vec3& x = pos[iv];
			Vec3 s = Vec3::Zero();
			uint32 k = 0;
			foreach_incident_face(m, v, [&](Face f) {
				const uint32 j = face_of_dart[f.dart.index];
				s += normal[j] * normal[j].dot(center[j] - x);
				++k;
			});
			delta[iv] = k > 0 ? Vec3(s / k) : Vec3::Zero();
		});
		foreach_cell(m, [&](Vertex v) {
			const uint32 iv = index_of(m, v);
			if (moves[iv])
				pos[iv] += delta[iv];
		});
	}
}

} // namespace cgogn::geometry
