// SPDX-License-Identifier: MIT
// Multiresolution 3-maps refined by tetrahedral-octahedral levels: counts,
// shapes, attributes across levels, level queries, refusals.
#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <vector>

namespace cgogn_test_mrmap3_tetra_octa
{

using namespace cgogn;

namespace
{

/// The counts of the tetrahedral-octahedral levels of a mesh: vertices,
/// edges, faces, tetrahedra and octahedra; next() is one more level.
struct TetraOctaCounts
{
	uint32 v, e, f, tets, octas;
	TetraOctaCounts next() const
	{
		// every edge is cut, every triangle cut in 4; a tetrahedron adds 4
		// inner triangles, an octahedron a centre, 12 edges to it and 24
		// triangles
		return {v + e + octas, 2 * e + 3 * f + 12 * octas, 4 * f + 4 * tets + 24 * octas, 4 * tets + 8 * octas,
				tets + 6 * octas};
	}
	std::vector<uint32> f_vector() const
	{
		return {v, e, f, tets + octas};
	}
};

/// The numbers of volumes with 4 and with 8 faces at the level read.
template <typename MESH>
std::array<uint32, 2> tets_and_octas(const MESH& m)
{
	std::array<uint32, 2> n{0, 0};
	foreach_cell(m, [&](MRMap3::Volume w) {
		uint32 faces = 0;
		foreach_incident_face(m, w, [&](MRMap3::Face) { ++faces; });
		n[0] += faces == 4;
		n[1] += faces == 8;
	});
	return n;
}

/// The relations of every dart of the finest map.
std::map<uint32, std::array<uint32, 3>> relations(const CMap3& m)
{
	std::map<uint32, std::array<uint32, 3>> r;
	foreach_dart(m, [&](Dart d) { r[d.index] = {phi1(m, d).index, phi2(m, d).index, phi3(m, d).index}; });
	return r;
}

/// A regular octahedron (corners +-e_i) with a tetrahedron glued on its
/// face (e1, e2, e3), its apex at (1, 1, 1): every edge is sqrt(2) long.
/// Positions in the vertex attribute "position".
CMap3 octahedron_and_tetrahedron()
{
	PolyhedronSoup s;
	s.nb_vertices = 7;
	s.positions = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -1}, {1, 1, 1}};
	s.cell_nb_faces = {8, 4};
	for (int sx : {1, -1})
		for (int sy : {1, -1})
			for (int sz : {1, -1})
			{
				const uint32 x = sx > 0 ? 0 : 3, y = sy > 0 ? 1 : 4, z = sz > 0 ? 2 : 5;
				s.face_sizes.push_back(3);
				if (sx * sy * sz > 0)
					s.face_vertices.insert(s.face_vertices.end(), {x, y, z});
				else
					s.face_vertices.insert(s.face_vertices.end(), {x, z, y});
			}
	for (std::array<uint32, 3> f : {std::array<uint32, 3>{0, 2, 1}, {0, 1, 6}, {1, 2, 6}, {2, 0, 6}})
	{
		s.face_sizes.push_back(3);
		s.face_vertices.insert(s.face_vertices.end(), f.begin(), f.end());
	}
	CMap3 m;
	const BuildReport r = build_polyhedra(m, s);
	auto pos = add_attribute<Vec3, CMap3::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return m;
}

/// The volume of w at the level read, from its triangles (divergence).
template <typename MESH>
double volume_of(const MESH& m, const CellAttribute<Vec3, Orbit::PHI21_PHI31>& pos, MRMap3::Volume w)
{
	double sixfold = 0;
	foreach_dart_of_orbit(m, w, [&](Dart x) {
		const Vec3& a = value<Vec3>(m, pos, MRMap3::Vertex(x));
		const Vec3& b = value<Vec3>(m, pos, MRMap3::Vertex(phi1(m, x)));
		const Vec3& c = value<Vec3>(m, pos, MRMap3::Vertex(phi_1(m, x)));
		sixfold += a.dot(b.cross(c)) / 3; // each triangle is met from its 3 darts
	});
	return std::abs(sixfold) / 6;
}

} // namespace

TEST(MRMap3TetraOcta, LevelsOfOneTetrahedron)
{
	CMap3 base;
	add_tetra(base);
	MRMap3 m(std::move(base));
	std::vector<TetraOctaCounts> counts{{4, 6, 4, 1, 0}};
	for (uint32 k = 1; k <= 3; ++k)
	{
		add_level(m, Refinement::TetraOcta);
		counts.push_back(counts.back().next());
		ASSERT_EQ(max_level(m), k);
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << r.nb_errors << " errors at level " << k;
		// every level still gives its own counts
		for (uint32 j = 0; j <= k; ++j)
		{
			const MRLevelView3 v = level_view(m, j);
			EXPECT_EQ(f_vector(v), counts[j].f_vector()) << "level " << j << " of " << k;
			EXPECT_EQ(tets_and_octas(v), (std::array<uint32, 2>{counts[j].tets, counts[j].octas})) << "level " << j;
			EXPECT_EQ(euler_characteristic(v), 1);
		}
	}
	// the grid points of a tetrahedron cut 8 times along each edge
	EXPECT_EQ(counts[3].v, 9u * 10u * 11u / 6u);
	EXPECT_EQ(counts[3].tets, 176u);
	EXPECT_EQ(counts[3].octas, 84u);
	// darts: both sides of every face (the boundary's included), 3 each
	EXPECT_EQ(nb_darts(finest_map(m)), 6 * counts[3].f);
}

TEST(MRMap3TetraOcta, LevelsAreRegularCellsOfHalfTheEdgeLength)
{
	MRMap3 m(octahedron_and_tetrahedron());
	const auto pos = get_attribute<Vec3, MRMap3::Vertex>(m, "position");
	ASSERT_NE(pos, nullptr);
	add_level(m, Refinement::TetraOcta);
	add_level(m, Refinement::TetraOcta);
	const IntegrityReport r = check_integrity(m);
	ASSERT_TRUE(r.ok()) << r.nb_errors << " errors";
	TetraOctaCounts c{7, 15, 11, 1, 1};
	for (uint32 k = 0; k <= 2; ++k, c = c.next())
	{
		const MRLevelView3 v = level_view(m, k);
		EXPECT_EQ(f_vector(v), c.f_vector()) << "level " << k;
		EXPECT_EQ(tets_and_octas(v), (std::array<uint32, 2>{c.tets, c.octas})) << "level " << k;
		// new vertices are the middles of edges and the centres of
		// octahedra: every cell is regular, with edges half as long
		const double length = std::sqrt(2.0) / double(1u << k);
		foreach_cell(v, [&](MRMap3::Edge e) {
			const Vec3& a = value<Vec3>(v, *pos, MRMap3::Vertex(e.dart));
			const Vec3& b = value<Vec3>(v, *pos, MRMap3::Vertex(phi1(v, e.dart)));
			EXPECT_NEAR((a - b).norm(), length, 1e-12) << "level " << k;
		});
		double total = 0;
		foreach_cell(v, [&](MRMap3::Volume w) {
			const double volume = volume_of(v, *pos, w);
			uint32 faces = 0;
			foreach_incident_face(v, w, [&](MRMap3::Face) { ++faces; });
			const double l3 = length * length * length;
			EXPECT_NEAR(volume, faces == 4 ? l3 / (6 * std::sqrt(2.0)) : l3 * std::sqrt(2.0) / 3, 1e-12);
			total += volume;
		});
		EXPECT_NEAR(total, 4.0 / 3 + 1.0 / 3, 1e-12) << "level " << k;
	}
}

TEST(MRMap3TetraOcta, AttributesCellQueriesAndRemoval)
{
	MRMap3 m(octahedron_and_tetrahedron());
	auto ft = add_attribute<uint32, MRMap3::Face>(m, "f");
	auto wt = add_attribute<uint32, MRMap3::Volume>(m, "w");
	uint32 next = 1;
	foreach_cell(m, [&](MRMap3::Face f) { value<uint32>(m, ft, f) = next++; });
	foreach_cell(m, [&](MRMap3::Volume w) { value<uint32>(m, wt, w) = next++; });
	const auto before = relations(finest_map(m));
	add_level(m, Refinement::TetraOcta);
	ASSERT_TRUE(check_integrity(m).ok());
	// every piece of a face (its middle triangle too) copies the face's
	// value, inner faces have none; every child volume (the middle
	// octahedron and the face tetrahedra too) copies its parent's
	const MRLevelView3 v1 = level_view(m, 1);
	std::map<uint32, uint32> faces, volumes;
	foreach_cell(v1, [&](MRMap3::Face f) { ++faces[value<uint32>(v1, ft, f)]; });
	foreach_cell(v1, [&](MRMap3::Volume w) { ++volumes[value<uint32>(v1, wt, w)]; });
	EXPECT_EQ(faces.size(), 12u);
	EXPECT_EQ(faces[0], 4u + 24u);
	for (uint32 x = 1; x <= 11; ++x)
		EXPECT_EQ(faces[x], 4u) << "face " << x;
	ASSERT_EQ(volumes.size(), 2u);
	EXPECT_EQ(volumes.begin()->second + volumes.rbegin()->second, 19u);
	EXPECT_EQ(std::min(volumes.begin()->second, volumes.rbegin()->second), 5u);
	EXPECT_EQ(volumes.count(0), 0u);

	// the level queries
	add_level(m, Refinement::TetraOcta);
	for (uint32 k = 0; k <= 2; ++k)
	{
		const MRLevelView3 v = level_view(m, k);
		foreach_cell(v, [&](MRMap3::Volume w) {
			EXPECT_EQ(volume_level(v, w), k);
			EXPECT_EQ(volume_is_subdivided(v, w), k < 2);
		});
		foreach_cell(v, [&](MRMap3::Face f) {
			EXPECT_EQ(face_level(v, f), k);
			EXPECT_EQ(face_is_subdivided(v, f), k < 2);
		});
		foreach_cell(v, [&](MRMap3::Edge e) { EXPECT_EQ(edge_is_subdivided(v, e), k < 2); });
		const CMap3 flat = extract_level(m, k);
		EXPECT_EQ(f_vector(flat), f_vector(v));
		EXPECT_TRUE(check_integrity(flat).ok());
	}
	// hexahedral refinement and adaptive subdivision need hexahedra
	set_current_level(m, 2);
	EXPECT_THROW(add_level(m, Refinement::Hexahedral), std::invalid_argument);
	Dart inside;
	foreach_cell(m, [&](MRMap3::Volume w) {
		inside = w.dart;
		return false;
	});
	EXPECT_THROW(subdivide_volume(m, MRMap3::Volume(inside)), std::invalid_argument);

	remove_finest_level(m);
	remove_finest_level(m);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(relations(finest_map(m)), before);
	foreach_cell(m, [&](MRMap3::Volume w) { EXPECT_GT(value<uint32>(m, wt, w), 11u); });
}

TEST(MRMap3TetraOcta, RefusalsLeaveTheMapUnchanged)
{
	for (uint32 kind = 0; kind < 3; ++kind)
	{
		CMap3 base;
		add_tetra(base);
		if (kind == 0)
			add_hexa(base);
		else if (kind == 1)
			add_pyramid(base, 4);
		else
			add_prism(base, 3);
		MRMap3 m(std::move(base));
		const auto before = relations(finest_map(m));
		EXPECT_THROW(add_level(m, Refinement::TetraOcta), std::invalid_argument) << "kind " << kind;
		EXPECT_EQ(relations(finest_map(m)), before);
		EXPECT_EQ(max_level(m), 0u);
		EXPECT_TRUE(check_integrity(m).ok());
	}
	CMap3 base;
	add_tetra(base);
	MRMap3 m(std::move(base));
	EXPECT_THROW(add_level(m, Refinement::Quadrangular), std::invalid_argument);
}

} // namespace cgogn_test_mrmap3_tetra_octa
