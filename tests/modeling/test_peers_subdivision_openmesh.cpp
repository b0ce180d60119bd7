// SPDX-License-Identifier: MIT
// Loop, sqrt3 and Catmull-Clark against OpenMesh's uniform subdividers on the
// same meshes: same counts, same positions (matched by position) to 1e-9.
#include "../geometry/geometry_test_meshes.h"
#include "peer_compare.h"

#include <gtest/gtest.h>

#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/CatmullClarkT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/Sqrt3T.hh>

namespace cgogn_test_peers_subdivision_openmesh
{

using namespace cgogn;
using namespace cgogn::peer_test;

namespace
{

struct DoubleTraits : OpenMesh::DefaultTraits
{
	using Point = OpenMesh::Vec3d;
	using Normal = OpenMesh::Vec3d;
};
using TriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;
using PolyMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

template <typename MESH>
MESH openmesh_of(const Soup& s)
{
	MESH om;
	std::vector<typename MESH::VertexHandle> vh;
	for (const Vec3& p : s.points)
		vh.push_back(om.add_vertex(typename MESH::Point(p.x(), p.y(), p.z())));
	for (const auto& f : s.faces)
	{
		std::vector<typename MESH::VertexHandle> fv;
		for (uint32 i : f)
			fv.push_back(vh[i]);
		om.add_face(fv);
	}
	return om;
}

template <typename MESH>
std::vector<Vec3> positions_of(const MESH& om)
{
	std::vector<Vec3> p;
	for (auto v : om.vertices())
		p.emplace_back(om.point(v)[0], om.point(v)[1], om.point(v)[2]);
	return p;
}

template <typename SUBDIVIDER, typename MESH>
void expect_same_as_openmesh(CMap2& m, AttributeArray<Vec3>& pos, modeling::SurfaceScheme scheme, uint32 steps)
{
	MESH om = openmesh_of<MESH>(soup_of(m, pos));
	SUBDIVIDER sub;
	sub.attach(om);
	sub(steps);
	sub.detach();
	modeling::subdivide(m, pos, scheme, steps);
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), om.n_vertices());
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), om.n_edges());
	EXPECT_EQ(nb_cells<CMap2::Face>(m), om.n_faces());
	EXPECT_LT(max_mismatch(peer_test::positions_of(m, pos), positions_of(om)), 1e-9);
	EXPECT_TRUE(check_integrity(m).ok());
}

using Loop = OpenMesh::Subdivider::Uniform::LoopT<TriMesh, double>;
using Sqrt3 = OpenMesh::Subdivider::Uniform::Sqrt3T<TriMesh, double>;
using CatmullClark = OpenMesh::Subdivider::Uniform::CatmullClarkT<PolyMesh, double>;

} // namespace

TEST(OpenMeshPeer, LoopOnTetrahedronSphereAndNefertiti)
{
	{
		CMap2 m;
		auto pos = test::build_with_positions(m, sphere_soup(20, 12, true));
		expect_same_as_openmesh<Loop, TriMesh>(m, *pos, modeling::SurfaceScheme::Loop, 2);
	}
	for (const char* name : {"tetrahedron.off", "nefertiti.obj"})
	{
		CMap2 m;
		if (!load(m, name))
			GTEST_SKIP() << cgogn_test_data::missing_large(std::string("surface/") + name);
		expect_same_as_openmesh<Loop, TriMesh>(m, *get_attribute<Vec3, CMap2::Vertex>(m, "position"),
											   modeling::SurfaceScheme::Loop, 1);
	}
}

TEST(OpenMeshPeer, LoopBoundaryRulesAgreeOnHemisphere)
{
	CMap2 m;
	if (!load(m, "hemisphere.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/hemisphere.off");
	expect_same_as_openmesh<Loop, TriMesh>(m, *get_attribute<Vec3, CMap2::Vertex>(m, "position"),
										   modeling::SurfaceScheme::Loop, 2);
}

TEST(OpenMeshPeer, Sqrt3OnClosedMeshes)
{
	{
		CMap2 m;
		auto pos = test::build_with_positions(m, sphere_soup(20, 12, true));
		expect_same_as_openmesh<Sqrt3, TriMesh>(m, *pos, modeling::SurfaceScheme::Sqrt3, 2);
	}
	CMap2 m;
	if (!load(m, "nefertiti.obj"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/nefertiti.obj");
	expect_same_as_openmesh<Sqrt3, TriMesh>(m, *get_attribute<Vec3, CMap2::Vertex>(m, "position"),
											modeling::SurfaceScheme::Sqrt3, 1);
}

TEST(OpenMeshPeer, Sqrt3FirstStepWithBoundaryAgrees)
{
	// OpenMesh's generation 0 keeps the boundary as cgogn's every step does
	CMap2 m;
	if (!load(m, "hemisphere.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/hemisphere.off");
	expect_same_as_openmesh<Sqrt3, TriMesh>(m, *get_attribute<Vec3, CMap2::Vertex>(m, "position"),
											modeling::SurfaceScheme::Sqrt3, 1);
}

TEST(OpenMeshPeer, CatmullClarkOnClosedPolygonMeshes)
{
	for (const char* name : {"spot_control_mesh.obj", "spot_quadrangulated.obj"})
	{
		CMap2 m;
		if (!load(m, name))
			GTEST_SKIP() << cgogn_test_data::missing_large(std::string("surface/") + name);
		expect_same_as_openmesh<CatmullClark, PolyMesh>(m, *get_attribute<Vec3, CMap2::Vertex>(m, "position"),
														modeling::SurfaceScheme::CatmullClark, 2);
	}
}

} // namespace cgogn_test_peers_subdivision_openmesh
