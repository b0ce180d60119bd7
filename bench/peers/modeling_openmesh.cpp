// SPDX-License-Identifier: MIT
#include "modeling_peers.h"

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

namespace cgogn_bench
{

namespace
{
struct Traits : OpenMesh::DefaultTraits
{
	using Point = OpenMesh::Vec3d;
	using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::TriMesh_ArrayKernelT<Traits>;
} // namespace

double openmesh_decimate(const TriangleSoup& in, uint32_t target_faces, TriangleSoup& out)
{
	Mesh m;
	std::vector<Mesh::VertexHandle> vh;
	vh.reserve(in.points.size());
	for (const auto& p : in.points)
		vh.push_back(m.add_vertex(OpenMesh::Vec3d(p[0], p[1], p[2])));
	for (const auto& t : in.triangles)
		m.add_face(vh[t[0]], vh[t[1]], vh[t[2]]);
	m.request_face_normals();
	m.update_face_normals();

	const double t0 = modeling_thread_seconds();
	OpenMesh::Decimater::DecimaterT<Mesh> decimater(m);
	OpenMesh::Decimater::ModQuadricT<Mesh>::Handle quadric;
	OpenMesh::Decimater::ModNormalFlippingT<Mesh>::Handle flipping;
	decimater.add(quadric);
	decimater.add(flipping);
	decimater.module(flipping).set_max_normal_deviation(90.0); // fold-overs only, as cgogn's default
	decimater.initialize();
	decimater.decimate_to_faces(0, target_faces);
	m.garbage_collection();
	const double seconds = modeling_thread_seconds() - t0;

	out.points.clear();
	out.triangles.clear();
	for (auto v : m.vertices())
	{
		const auto& p = m.point(v);
		out.points.push_back({p[0], p[1], p[2]});
	}
	for (auto f : m.faces())
	{
		std::array<uint32_t, 3> t{};
		int k = 0;
		for (auto v : m.fv_range(f))
			t[std::size_t(k++)] = uint32_t(v.idx());
		out.triangles.push_back(t);
	}
	return seconds;
}

} // namespace cgogn_bench
