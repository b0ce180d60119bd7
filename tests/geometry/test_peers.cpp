// SPDX-License-Identifier: MIT
// Cross-checks of the geometry layer against OpenMesh and CGAL on the same
// generated meshes (built only when the peers are found).
#include "geometry_test_meshes.h"

#ifdef CGOGN_HAS_OPENMESH
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#endif
#ifdef CGOGN_HAS_CGAL
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#endif

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

namespace cgogn_test_peers
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::build_with_positions;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

namespace
{
// noisy copies of generated meshes, closed and open, quads and triangles
std::vector<SurfaceSoup> test_soups(bool triangles_only)
{
	std::vector<SurfaceSoup> soups = {torus_soup(16, 9, true), sphere_soup(14, 8, true)};
	if (!triangles_only)
	{
		soups.push_back(torus_soup(16, 9));
		soups.push_back(grid_soup(7, 5));
		soups.push_back(cylinder_soup(9, 4, true));
	}
	for (SurfaceSoup& s : soups)
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			for (int a = 0; a < 3; ++a)
				s.positions[i][a] += 0.03 * test::noise(3 * i + uint32(a));
	return soups;
}

// The ids of the vertices of a face, rotated to start at the smallest: the
// same face gets the same key in any mesh built from the soup.
template <typename IDS>
std::vector<uint32> face_key(IDS ids)
{
	std::rotate(ids.begin(), std::min_element(ids.begin(), ids.end()), ids.end());
	return ids;
}

std::vector<uint32> face_key(const CMap2& m, Face f)
{
	std::vector<uint32> ids;
	foreach_incident_vertex(m, f, [&](Vertex v) { ids.push_back(index_of(m, v)); });
	return face_key(ids);
}
} // namespace

#ifdef CGOGN_HAS_OPENMESH

namespace
{
struct DoubleTraits : OpenMesh::DefaultTraits
{
	using Point = OpenMesh::Vec3d;
	using Normal = OpenMesh::Vec3d;
};
using OMesh = OpenMesh::PolyMesh_ArrayKernelT<DoubleTraits>;

Vec3 to_vec(const OpenMesh::Vec3d& p)
{
	return Vec3(p[0], p[1], p[2]);
}

OMesh to_openmesh(const SurfaceSoup& s)
{
	OMesh om;
	std::vector<OMesh::VertexHandle> vh;
	for (const auto& p : s.positions)
		vh.push_back(om.add_vertex(OMesh::Point(p[0], p[1], p[2])));
	uint32 k = 0;
	for (uint32 sz : s.face_sizes)
	{
		std::vector<OMesh::VertexHandle> f;
		for (uint32 j = 0; j < sz; ++j)
			f.push_back(vh[s.face_vertices[k + j]]);
		k += sz;
		om.add_face(f);
	}
	return om;
}
} // namespace

TEST(PeerOpenMesh, FacesEdgesAnglesAndNormalsAgree)
{
	for (const SurfaceSoup& s : test_soups(false))
	{
		CMap2 m;
		auto pos = build_with_positions(m, s);
		OMesh om = to_openmesh(s);
		ASSERT_EQ(om.n_faces(), nb_cells<Face>(m));
		om.request_face_normals();
		om.update_face_normals();

		std::map<std::vector<uint32>, OMesh::FaceHandle> faces;
		for (OMesh::FaceHandle fh : om.faces())
		{
			std::vector<uint32> ids;
			for (OMesh::VertexHandle v : om.fv_range(fh))
				ids.push_back(uint32(v.idx()));
			faces[face_key(ids)] = fh;
		}
		foreach_cell(m, [&](Face f) {
			const OMesh::FaceHandle fh = faces.at(face_key(m, f));
			EXPECT_NEAR((face_normal(m, f, *pos) - to_vec(om.calc_face_normal(fh))).norm(), 0.0, 1e-12);
			EXPECT_NEAR((centroid(m, f, *pos) - to_vec(om.calc_face_centroid(fh))).norm(), 0.0, 1e-12);
		});

		const bool triangles = std::all_of(s.face_sizes.begin(), s.face_sizes.end(), [](uint32 n) { return n == 3; });
		// half-edges by (origin, target): lengths, corner angles, dihedral angles
		std::map<std::pair<uint32, uint32>, OMesh::HalfedgeHandle> halfedges;
		for (OMesh::HalfedgeHandle h : om.halfedges())
			halfedges[{uint32(om.from_vertex_handle(h).idx()), uint32(om.to_vertex_handle(h).idx())}] = h;
		foreach_dart(m, [&](Dart d) {
			if (is_boundary(m, d))
				return;
			const uint32 a = index_of(m, Vertex(d)), b = index_of(m, Vertex(phi1(m, d)));
			const OMesh::HalfedgeHandle h = halfedges.at({a, b});
			EXPECT_NEAR(edge_length(m, Edge(d), *pos), om.calc_edge_length(h), 1e-12);
			// OpenMesh's sector of h is the corner at its target, between h and next(h)
			EXPECT_NEAR(corner_angle(m, phi1(m, d), *pos), om.calc_sector_angle(h), 1e-12);
			// OpenMesh measures the dihedral angle between the corner normals at h,
			// not the face normals: the same on triangles only
			if (triangles)
			{
				EXPECT_NEAR(dihedral_angle(m, Edge(d), *pos), om.calc_dihedral_angle(h), 1e-10);
			}
		});

		// vertex normals: OpenMesh's default (sum of unit face normals) is our
		// uniform weighting; its "correct" one (sum of sector normals) is our
		// area weighting on triangles
		foreach_cell(m, [&](Vertex v) {
			const OMesh::VertexHandle vh(int(index_of(m, v)));
			EXPECT_NEAR(
				(vertex_normal(m, v, *pos, NormalWeighting::Uniform) - to_vec(om.calc_vertex_normal(vh))).norm(), 0.0,
				1e-12);
			if (triangles)
			{
				EXPECT_NEAR((vertex_normal(m, v, *pos, NormalWeighting::Area) - to_vec(om.calc_normal(vh))).norm(), 0.0,
							1e-12);
			}
		});
	}
}

#endif

#ifdef CGOGN_HAS_CGAL

TEST(PeerCGAL, AreasAndVolumesAgree)
{
	using K = CGAL::Exact_predicates_inexact_constructions_kernel;
	using SM = CGAL::Surface_mesh<K::Point_3>;
	namespace PMP = CGAL::Polygon_mesh_processing;
	for (const SurfaceSoup& s : test_soups(true))
	{
		CMap2 m;
		auto pos = build_with_positions(m, s);
		SM sm;
		std::vector<SM::Vertex_index> vi;
		for (const auto& p : s.positions)
			vi.push_back(sm.add_vertex(K::Point_3(p[0], p[1], p[2])));
		for (std::size_t f = 0; f < s.face_sizes.size(); ++f)
			sm.add_face(vi[s.face_vertices[3 * f]], vi[s.face_vertices[3 * f + 1]], vi[s.face_vertices[3 * f + 2]]);
		EXPECT_NEAR(surface_area(m, *pos), PMP::area(sm), 1e-12 * PMP::area(sm));
		EXPECT_NEAR(signed_volume(m, *pos), PMP::volume(sm), 1e-12 * PMP::volume(sm));

		std::map<std::vector<uint32>, double> areas;
		for (SM::Face_index f : sm.faces())
		{
			std::vector<uint32> ids;
			for (SM::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm))
				ids.push_back(uint32(v));
			areas[face_key(ids)] = PMP::face_area(f, sm);
		}
		foreach_cell(m, [&](Face f) { EXPECT_NEAR(face_area(m, f, *pos), areas.at(face_key(m, f)), 1e-14); });
	}
}

#endif

} // namespace cgogn_test_peers
