// SPDX-License-Identifier: MIT
#include "modeling_peers.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

namespace cgogn_bench
{

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
namespace SMS = CGAL::Surface_mesh_simplification;

Mesh build(const TriangleSoup& in)
{
	Mesh m;
	std::vector<Mesh::Vertex_index> vh;
	vh.reserve(in.points.size());
	for (const auto& p : in.points)
		vh.push_back(m.add_vertex(Point(p[0], p[1], p[2])));
	for (const auto& t : in.triangles)
		m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
	return m;
}

void extract(Mesh& m, TriangleSoup& out)
{
	m.collect_garbage();
	out.points.clear();
	out.triangles.clear();
	for (auto v : m.vertices())
	{
		const Point& p = m.point(v);
		out.points.push_back({p.x(), p.y(), p.z()});
	}
	for (auto f : m.faces())
	{
		std::array<uint32_t, 3> t{};
		std::size_t k = 0;
		for (auto v : CGAL::vertices_around_face(m.halfedge(f), m))
			t[k++] = uint32_t(v.idx());
		out.triangles.push_back(t);
	}
}
} // namespace

double cgal_decimate(const TriangleSoup& in, uint32_t target_faces, TriangleSoup& out)
{
	Mesh m = build(in);
	const double t0 = modeling_thread_seconds();
	SMS::GarlandHeckbert_plane_policies<Mesh, Kernel> policies(m);
	SMS::Count_stop_predicate<Mesh> stop(std::size_t(target_faces) * 3 / 2);
	SMS::edge_collapse(m, stop,
					   CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
	const double seconds = modeling_thread_seconds() - t0;
	extract(m, out);
	return seconds;
}

double cgal_remesh(const TriangleSoup& in, double length, uint32_t iterations, TriangleSoup& out)
{
	Mesh m = build(in);
	const double t0 = modeling_thread_seconds();
	CGAL::Polygon_mesh_processing::isotropic_remeshing(faces(m), length, m,
													   CGAL::parameters::number_of_iterations(iterations));
	const double seconds = modeling_thread_seconds() - t0;
	extract(m, out);
	return seconds;
}

} // namespace cgogn_bench
