// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/conversion.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/operators/incidence_graph.h>
#include <cgogn/core/properties/incidence_graph_properties.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_incidence_graph.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/modeling/skeleton.h>

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <queue>
#include <vector>

namespace cgogn::modeling
{

namespace
{

using Triangle = std::array<uint32, 3>;
using SparseMatrix = Eigen::SparseMatrix<double>;

double triangle_area(const std::vector<Vec3>& p, const Triangle& t)
{
	return 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
}

// The cotangent Laplacian of the triangles (L_ij = cot a + cot b, L_ii =
// -sum): each cotangent bounded, so that the triangles the contraction
// flattens give large but finite weights instead of infinities.
SparseMatrix cotangent_laplacian(const std::vector<Vec3>& p, const std::vector<Triangle>& triangles)
{
	constexpr double max_cot = 1e4;
	std::vector<Eigen::Triplet<double>> t;
	t.reserve(12 * triangles.size());
	for (const Triangle& tri : triangles)
		for (uint32 k = 0; k < 3; ++k)
		{
			const uint32 a = tri[k], i = tri[(k + 1) % 3], j = tri[(k + 2) % 3];
			const Vec3 u = p[i] - p[a], v = p[j] - p[a];
			const double sin = u.cross(v).norm(), cos = u.dot(v);
			double cot = sin > 1e-300 ? cos / sin : max_cot;
			cot = std::clamp(cot, -max_cot, max_cot);
			t.emplace_back(i, j, cot);
			t.emplace_back(j, i, cot);
			t.emplace_back(i, i, -cot);
			t.emplace_back(j, j, -cot);
		}
	SparseMatrix l(Eigen::Index(p.size()), Eigen::Index(p.size()));
	l.setFromTriplets(t.begin(), t.end());
	return l;
}

std::vector<double> one_ring_areas(const std::vector<Vec3>& p, const std::vector<Triangle>& triangles)
{
	std::vector<double> area(p.size(), 0.0);
	for (const Triangle& t : triangles)
	{
		const double a = triangle_area(p, t);
		for (uint32 v : t)
			area[v] += a;
	}
	return area;
}

// Moves p by Laplacian contraction (see skeleton). Returns false when
// cancelled.
bool contract(std::vector<Vec3>& p, const std::vector<Triangle>& triangles, const SkeletonOptions& options,
			  ProgressReporter& progress)
{
	const std::size_t n = p.size();
	const std::vector<double> area0 = one_ring_areas(p, triangles);
	double total0 = 0;
	for (const Triangle& t : triangles)
		total0 += triangle_area(p, t);
	if (!(total0 > 0))
		return true;
	double wl = 1e-3 * std::sqrt(total0 / double(triangles.size()));
	std::vector<double> wh(n, 1.0);
	for (uint32 it = 0; it < options.max_iterations; ++it)
	{
		const SparseMatrix l = cotangent_laplacian(p, triangles);
		SparseMatrix a = (wl * wl) * SparseMatrix(l.transpose() * l);
		Eigen::MatrixXd rhs(Eigen::Index(n), 3);
		for (std::size_t i = 0; i < n; ++i)
		{
			a.coeffRef(Eigen::Index(i), Eigen::Index(i)) += wh[i] * wh[i];
			for (int k = 0; k < 3; ++k)
				rhs(Eigen::Index(i), k) = wh[i] * wh[i] * p[i][k];
		}
		Eigen::SimplicialLDLT<SparseMatrix> solver(a);
		if (solver.info() != Eigen::Success)
			break; // too degenerate to go on: keep the last positions
		const Eigen::MatrixXd x = solver.solve(rhs);
		if (solver.info() != Eigen::Success || !x.allFinite())
			break;
		for (std::size_t i = 0; i < n; ++i)
			p[i] = Vec3(x(Eigen::Index(i), 0), x(Eigen::Index(i), 1), x(Eigen::Index(i), 2));
		// weights: faster contraction, and more attraction where the one-ring shrank
		wl *= options.contraction_growth;
		const std::vector<double> area = one_ring_areas(p, triangles);
		for (std::size_t i = 0; i < n; ++i)
			wh[i] = std::min(std::sqrt(area0[i] / std::max(area[i], 1e-300)), 1e6);
		double total = 0;
		for (const Triangle& t : triangles)
			total += triangle_area(p, t);
		if (!progress.report(0.7 * double(it + 1) / double(options.max_iterations)))
			return false;
		if (total < options.area_ratio * total0)
			break;
	}
	return true;
}

} // namespace

Graph skeleton(const CMap2& surface, const AttributeArray<Vec3>& pos, const SkeletonOptions& options)
{
	using Vertex = CMap2::Vertex;
	if (has_boundary(surface))
		throw Error("skeleton: the surface has a boundary (a closed surface is needed)");
	// dense vertex numbers, and the faces fanned into triangles
	std::vector<uint32> number(container_of<Vertex::ORBIT>(surface).end_index(), INVALID_INDEX);
	std::vector<Vec3> p;
	foreach_cell(surface, [&](Vertex v) {
		number[index_of(surface, v)] = uint32(p.size());
		p.push_back(pos[index_of(surface, v)]);
		if (!p.back().allFinite())
			throw Error("skeleton: a vertex position is not finite");
	});
	std::vector<Triangle> triangles;
	std::vector<uint32> face;
	foreach_cell(surface, [&](CMap2::Face f) {
		face.clear();
		foreach_incident_vertex(surface, f, [&](Vertex v) { face.push_back(number[index_of(surface, v)]); });
		if (face.size() < 3)
			throw Error("skeleton: a face has fewer than 3 vertices");
		for (std::size_t i = 1; i + 1 < face.size(); ++i)
			triangles.push_back({face[0], face[i], face[i + 1]});
	});

	ProgressReporter progress(options.progress);
	contract(p, triangles, options, progress);

	// the contracted surface as an incidence graph, collapsed shortest edge
	// first until no face remains
	IncidenceGraph ig;
	auto ipos = add_attribute<Vec3, IncidenceGraph::Vertex>(ig, "position");
	std::vector<IncidenceGraph::Vertex> vertex;
	for (const Vec3& x : p)
	{
		vertex.push_back(add_vertex(ig));
		value<Vec3>(ig, ipos, vertex.back()) = x;
	}
	for (const Triangle& t : triangles)
	{
		const std::array<IncidenceGraph::Vertex, 3> tv = {vertex[t[0]], vertex[t[1]], vertex[t[2]]};
		if (tv[0] != tv[1] && tv[1] != tv[2] && tv[0] != tv[2])
			add_face_through_vertices(ig, tv);
	}
	auto length = [&](IncidenceGraph::Edge e) {
		return (value<Vec3>(ig, ipos, first_vertex(ig, e)) - value<Vec3>(ig, ipos, second_vertex(ig, e))).norm();
	};
	using Entry = std::pair<double, uint32>; // (length when queued, edge line)
	std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
	foreach_cell(ig, [&](IncidenceGraph::Edge e) { queue.emplace(length(e), e.dart.index); });
	const uint32 faces0 = nb_cells<IncidenceGraph::Face>(ig);
	// an edge refused (its collapse would pinch a face) waits in `refused`
	// until a collapse elsewhere may have changed that; when every edge with
	// faces is refused and none collapsed since, the faces left stay (their
	// edges are then in the skeleton)
	std::vector<Entry> refused;
	bool collapsed_since_refill = true;
	while (nb_cells<IncidenceGraph::Face>(ig) > 0)
	{
		if (queue.empty())
		{
			if (refused.empty() || !collapsed_since_refill)
				break;
			for (const Entry& x : refused)
				queue.push(x);
			refused.clear();
			collapsed_since_refill = false;
		}
		const auto [queued, line] = queue.top();
		queue.pop();
		const IncidenceGraph::Edge e(Dart{line});
		if (!is_valid(ig, e) || degree(ig, e) == 0)
			continue;
		const double l = length(e);
		if (l > queued * (1 + 1e-12) + 1e-300)
		{
			queue.emplace(l, line); // lengthened by an earlier collapse
			continue;
		}
		if (!can_collapse_edge(ig, e))
		{
			refused.emplace_back(l, line);
			continue;
		}
		const Vec3 mid =
			0.5 * (value<Vec3>(ig, ipos, first_vertex(ig, e)) + value<Vec3>(ig, ipos, second_vertex(ig, e)));
		const IncidenceGraph::Vertex s = collapse_edge(ig, e);
		value<Vec3>(ig, ipos, s) = mid;
		collapsed_since_refill = true;
		// the survivor's edges changed length: requeue them
		foreach_incident_edge(ig, s, [&](IncidenceGraph::Edge x) { queue.emplace(length(x), x.dart.index); });
		progress.report(0.7 + 0.3 * (1.0 - double(nb_cells<IncidenceGraph::Face>(ig)) / double(faces0)));
	}
	progress.report(1.0);
	return to_graph(ig);
}

} // namespace cgogn::modeling
