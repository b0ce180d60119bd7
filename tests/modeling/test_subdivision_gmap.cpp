// SPDX-License-Identifier: MIT
// Loop, Catmull-Clark and sqrt3 on 2-G-maps: the same surface as a CMap2
// gives the same result (counts, vertex positions, degrees), and the
// non-orientable surfaces keep their topology (Euler characteristic,
// boundary, orientability) while their faces multiply.
#include <cgogn/cgogn.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace cgogn_test_subdivision_gmap
{

using namespace cgogn;
using modeling::SurfaceScheme;

namespace
{

template <typename MAP>
struct Surface
{
	MAP map;
	std::shared_ptr<AttributeArray<Vec3>> pos;

	explicit Surface(const SurfaceSoup& s)
	{
		const BuildReport r = build_surface(map, s);
		pos = add_attribute<Vec3, typename mesh_traits<MAP>::Vertex>(map, "position");
		for (uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	}
};

struct Summary
{
	uint32 v, e, f, loops;
	int64 chi;
	std::vector<uint32> degrees;
	std::vector<Vec3> positions;

	template <typename MAP>
	explicit Summary(const Surface<MAP>& s)
	{
		using T = mesh_traits<MAP>;
		const MAP& m = s.map;
		v = nb_cells<typename T::Vertex>(m);
		e = nb_cells<typename T::Edge>(m);
		f = nb_cells<typename T::Face>(m);
		loops = nb_boundary_components(m);
		chi = euler_characteristic(m);
		foreach_cell(m, [&](typename T::Vertex x) {
			degrees.push_back(degree(m, x));
			positions.push_back((*s.pos)[index_of(m, x)]);
		});
		std::sort(degrees.begin(), degrees.end());
	}
};

void expect_same(const Summary& a, const Summary& b)
{
	EXPECT_EQ(a.v, b.v);
	EXPECT_EQ(a.e, b.e);
	EXPECT_EQ(a.f, b.f);
	EXPECT_EQ(a.loops, b.loops);
	EXPECT_EQ(a.chi, b.chi);
	EXPECT_EQ(a.degrees, b.degrees);
	// the positions pair up one to one (to 1e-12: the two maps' sums may
	// differ in the last bits)
	ASSERT_EQ(a.positions.size(), b.positions.size());
	std::vector<bool> used(b.positions.size(), false);
	for (const Vec3& p : a.positions)
	{
		std::size_t j = 0;
		while (j < b.positions.size() && (used[j] || (b.positions[j] - p).norm() >= 1e-12))
			++j;
		ASSERT_LT(j, b.positions.size()) << "no vertex of the G-map at " << p.transpose();
		used[j] = true;
	}
}

// A torus with a generic twist of its positions, so that no two new points
// coincide by symmetry and the positions pair up one to one.
SurfaceSoup wobbly(SurfaceSoup s)
{
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		s.positions[i][2] += 0.01 * double((i * 7919u) % 13u);
	return s;
}

// A closed prism on an n-gon: two n-gons and n quads.
SurfaceSoup prism_soup(uint32 n)
{
	SurfaceSoup s;
	s.nb_vertices = 2 * n;
	for (uint32 k = 0; k < 2; ++k)
		for (uint32 i = 0; i < n; ++i)
		{
			const double a = 2.0 * 3.14159265358979 * double(i) / double(n);
			s.positions.push_back({std::cos(a), std::sin(a) * (1.0 + 0.1 * double(i)), double(k)});
		}
	s.face_sizes.push_back(n); // bottom, seen from below
	for (uint32 i = 0; i < n; ++i)
		s.face_vertices.push_back(n - 1 - i);
	s.face_sizes.push_back(n); // top
	for (uint32 i = 0; i < n; ++i)
		s.face_vertices.push_back(n + i);
	for (uint32 i = 0; i < n; ++i)
	{
		const uint32 j = (i + 1) % n;
		s.face_sizes.push_back(4);
		s.face_vertices.insert(s.face_vertices.end(), {i, j, n + j, n + i});
	}
	return s;
}

} // namespace

TEST(SubdivisionGMap, SameResultAsTheCMap2OnOrientableSurfaces)
{
	struct Case
	{
		SurfaceSoup soup;
		SurfaceScheme scheme;
	};
	const std::vector<Case> cases{
		{wobbly(torus_soup(6, 4, true)), SurfaceScheme::Loop},
		{wobbly(grid_soup(4, 3, true)), SurfaceScheme::Loop},
		{wobbly(torus_soup(6, 4, true)), SurfaceScheme::Sqrt3},
		{wobbly(grid_soup(4, 3, true)), SurfaceScheme::Sqrt3},
		{wobbly(torus_soup(6, 4)), SurfaceScheme::CatmullClark},
		{wobbly(grid_soup(4, 3)), SurfaceScheme::CatmullClark},
		{wobbly(sphere_soup(6, 4)), SurfaceScheme::CatmullClark},
		{prism_soup(5), SurfaceScheme::CatmullClark}, // faces of 5, 6 and 7 edges
		{prism_soup(6), SurfaceScheme::CatmullClark},
		{prism_soup(7), SurfaceScheme::CatmullClark},
	};
	for (const Case& c : cases)
	{
		SCOPED_TRACE("scheme " + std::to_string(int(c.scheme)) + ", " + std::to_string(c.soup.nb_vertices) +
					 " vertices");
		Surface<CMap2> cm(c.soup);
		Surface<GMap2> gm(c.soup);
		modeling::subdivide(cm.map, *cm.pos, c.scheme, 2);
		modeling::subdivide(gm.map, *gm.pos, c.scheme, 2);
		EXPECT_TRUE(check_integrity(gm.map).ok()) << check_integrity(gm.map).to_string();
		expect_same(Summary(cm), Summary(gm));
		// the old vertices keep their lines, hence their places, in both
		for (uint32 i = 0; i < c.soup.nb_vertices; ++i)
			EXPECT_LT(((*cm.pos)[i] - (*gm.pos)[i]).norm(), 1e-12);
	}
}

TEST(SubdivisionGMap, LoopOnAKleinBottleKeepsItsTopology)
{
	Surface<GMap2> k(klein_bottle_soup(8, 6, true));
	const Summary before(k);
	EXPECT_EQ(before.chi, 0);
	EXPECT_FALSE(is_orientable(k.map));
	ASSERT_TRUE(modeling::is_triangle_mesh(k.map));
	modeling::loop_subdivision(k.map, *k.pos);
	EXPECT_TRUE(check_integrity(k.map).ok()) << check_integrity(k.map).to_string();
	const Summary after(k);
	EXPECT_EQ(after.f, 4 * before.f);
	EXPECT_EQ(after.v, before.v + before.e);
	EXPECT_EQ(after.chi, 0);
	EXPECT_EQ(after.loops, 0u);
	EXPECT_FALSE(is_orientable(k.map));
	EXPECT_TRUE(modeling::is_triangle_mesh(k.map));
}

TEST(SubdivisionGMap, CatmullClarkAndSqrt3OnNonOrientableSurfaces)
{
	// Catmull-Clark on the quad Klein bottle and the hemi-cube: quads x 4
	for (const SurfaceSoup& s : {klein_bottle_soup(8, 6), hemi_cube_soup()})
	{
		Surface<GMap2> g(s);
		const Summary before(g);
		modeling::catmull_clark_subdivision(g.map, *g.pos);
		EXPECT_TRUE(check_integrity(g.map).ok()) << check_integrity(g.map).to_string();
		const Summary after(g);
		EXPECT_EQ(after.f, 4 * before.f);
		EXPECT_EQ(after.v, before.v + before.e + before.f);
		EXPECT_EQ(after.chi, before.chi);
		EXPECT_FALSE(is_orientable(g.map));
	}
	// sqrt3 on the triangulated Moebius strip (one boundary loop) and the
	// hemi-icosahedron: 3 triangles per triangle
	for (const SurfaceSoup& s : {mobius_soup(10, true), hemi_icosahedron_soup()})
	{
		Surface<GMap2> g(s);
		const Summary before(g);
		modeling::sqrt3_subdivision(g.map, *g.pos);
		EXPECT_TRUE(check_integrity(g.map).ok()) << check_integrity(g.map).to_string();
		const Summary after(g);
		EXPECT_EQ(after.f, 3 * before.f);
		EXPECT_EQ(after.v, before.v + before.f);
		EXPECT_EQ(after.chi, before.chi);
		EXPECT_EQ(after.loops, before.loops);
		EXPECT_FALSE(is_orientable(g.map));
	}
}

TEST(SubdivisionGMap, RejectsWhatTheSchemeCannotTake)
{
	Surface<GMap2> q(klein_bottle_soup(6, 4)); // quads
	const uint32 darts = nb_darts(q.map);
	EXPECT_FALSE(modeling::is_triangle_mesh(q.map));
	EXPECT_THROW(modeling::loop_subdivision(q.map, *q.pos), modeling::SubdivisionError);
	EXPECT_THROW(modeling::sqrt3_subdivision(q.map, *q.pos), modeling::SubdivisionError);
	EXPECT_EQ(nb_darts(q.map), darts);
}

} // namespace cgogn_test_subdivision_gmap
