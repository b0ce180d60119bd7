// SPDX-License-Identifier: MIT
// Catmull-Clark and Loop against CGAL's Subdivision_method_3 on the same
// closed meshes: same counts, same positions (matched by position) to 1e-9.
#include "peer_compare.h"

#include <gtest/gtest.h>

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/subdivision_method_3.h>

namespace cgogn_test_peers_subdivision_cgal
{

using namespace cgogn;
using namespace cgogn::peer_test;

namespace
{

using Kernel = CGAL::Simple_cartesian<double>;
using CgalMesh = CGAL::Surface_mesh<Kernel::Point_3>;

CgalMesh cgal_of(const Soup& s)
{
	CgalMesh sm;
	std::vector<CgalMesh::Vertex_index> vh;
	for (const Vec3& p : s.points)
		vh.push_back(sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
	for (const auto& f : s.faces)
	{
		std::vector<CgalMesh::Vertex_index> fv;
		for (uint32 i : f)
			fv.push_back(vh[i]);
		sm.add_face(fv);
	}
	return sm;
}

std::vector<Vec3> positions_of(const CgalMesh& sm)
{
	std::vector<Vec3> p;
	for (auto v : sm.vertices())
		p.emplace_back(sm.point(v).x(), sm.point(v).y(), sm.point(v).z());
	return p;
}

void expect_same_counts_and_positions(const CMap2& m, const AttributeArray<Vec3>& pos, const CgalMesh& sm)
{
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), sm.number_of_vertices());
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), sm.number_of_edges());
	EXPECT_EQ(nb_cells<CMap2::Face>(m), sm.number_of_faces());
	EXPECT_LT(max_mismatch(peer_test::positions_of(m, pos), positions_of(sm)), 1e-9);
	EXPECT_TRUE(check_integrity(m).ok());
}

} // namespace

TEST(CgalPeer, CatmullClarkOnClosedMeshes)
{
	for (const char* name : {"spot_quadrangulated.obj", "spot_control_mesh.obj", "cube_quad.off"})
	{
		CMap2 m;
		if (!load(m, name))
			GTEST_SKIP() << cgogn_test_data::missing_large(std::string("surface/") + name);
		auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
		CgalMesh sm = cgal_of(soup_of(m, *pos));
		CGAL::Subdivision_method_3::CatmullClark_subdivision(sm, CGAL::parameters::number_of_iterations(2));
		modeling::subdivide(m, *pos, modeling::SurfaceScheme::CatmullClark, 2);
		expect_same_counts_and_positions(m, *pos, sm);
	}
}

TEST(CgalPeer, CatmullClarkWithBoundaryOnFandisk)
{
	CMap2 m;
	if (!load(m, "fandisk_quads.off"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/fandisk_quads.off");
	auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	CgalMesh sm = cgal_of(soup_of(m, *pos));
	CGAL::Subdivision_method_3::CatmullClark_subdivision(sm, CGAL::parameters::number_of_iterations(1));
	modeling::catmull_clark_subdivision(m, *pos);
	expect_same_counts_and_positions(m, *pos, sm);
}

TEST(CgalPeer, LoopOnClosedMeshes)
{
	CMap2 m;
	if (!load(m, "nefertiti.obj"))
		GTEST_SKIP() << cgogn_test_data::missing_large("surface/nefertiti.obj");
	auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	CgalMesh sm = cgal_of(soup_of(m, *pos));
	CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
	modeling::loop_subdivision(m, *pos);
	expect_same_counts_and_positions(m, *pos, sm);
}

} // namespace cgogn_test_peers_subdivision_cgal
