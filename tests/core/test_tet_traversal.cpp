// The tetrahedron fast path of foreach_incident_vertex(CMap3, Volume): the
// same vertices as the flooding of the general case on tet, hex, mixed and
// edited meshes, boundary volumes included.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

namespace cgogn_test_tet_traversal
{

using namespace cgogn;
using Vertex = CMap3::Vertex;
using Face = CMap3::Face;
using Volume = CMap3::Volume;

namespace
{
struct Compared
{
	uint32 tets = 0;   // volumes the fast path takes (boundary ones included)
	uint32 others = 0; // volumes left to the flooding
};

// For every volume, boundary ones included: the vertices reported by
// foreach_incident_vertex equal (as a set, each once) those of the flooding.
Compared compare_with_flooding(CMap3& m)
{
	index_cells<Vertex>(m);
	Compared c;
	DartMarker<CMap3> seen(m);
	foreach_dart(m, [&](Dart d) {
		if (seen.is_marked(d))
			return;
		seen.mark_orbit(Volume(d));
		std::vector<uint32> fast, flooded;
		foreach_incident_vertex(m, Volume(d), [&](Vertex v) { fast.push_back(index_of(m, v)); });
		detail::foreach_cell_of_volume<Vertex>(m, d, [&](Vertex v) { flooded.push_back(index_of(m, v)); });
		std::sort(fast.begin(), fast.end());
		std::sort(flooded.begin(), flooded.end());
		EXPECT_EQ(fast, flooded) << "volume of dart " << d.index;
		std::array<Dart, 4> corners;
		if (detail::tetra_corners(m, d, corners))
		{
			++c.tets;
			EXPECT_EQ(fast.size(), 4u);
			EXPECT_EQ(corners[0], d);
			EXPECT_EQ(corners[1], phi1(m, d));
			EXPECT_EQ(corners[2], phi_1(m, d));
			EXPECT_EQ(corners[3], phi_1(m, phi2(m, d)));
		}
		else
			++c.others;
	});
	return c;
}

} // namespace

TEST(TetTraversal, SingleTetAndItsBoundary)
{
	CMap3 m;
	add_tetra(m);
	index_cells<Vertex>(m);
	const Compared c = compare_with_flooding(m);
	EXPECT_EQ(c.tets, 2u); // the tet and its boundary volume, a tet too
	EXPECT_EQ(c.others, 0u);
}

TEST(TetTraversal, TetGridEveryTetFromEveryDart)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(3, 3, 2));
	index_cells<Vertex>(m);
	const Compared c = compare_with_flooding(m);
	EXPECT_EQ(c.tets, 108u);
	EXPECT_EQ(c.others, 1u); // the boundary volume
	// any dart of a tet gives its corners
	foreach_cell(m, [&](Volume w) {
		foreach_dart_of_orbit(m, w, [&](Dart d) {
			std::array<Dart, 4> corners;
			ASSERT_TRUE(detail::tetra_corners(m, d, corners));
			std::vector<uint32> a, b;
			for (Dart x : corners)
				a.push_back(index_of(m, Vertex(x)));
			foreach_incident_vertex(m, w, [&](Vertex v) { b.push_back(index_of(m, v)); });
			std::sort(a.begin(), a.end());
			std::sort(b.begin(), b.end());
			EXPECT_EQ(a, b);
		});
	});
}

TEST(TetTraversal, StopsWhenAsked)
{
	CMap3 m;
	const Volume w = add_tetra(m);
	index_cells<Vertex>(m);
	uint32 calls = 0;
	foreach_incident_vertex(m, w, [&](Vertex) { return ++calls < 2; });
	EXPECT_EQ(calls, 2u);
}

TEST(TetTraversal, HexesUnchanged)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(3, 2, 2));
	const Compared c = compare_with_flooding(m);
	EXPECT_EQ(c.tets, 0u);
	EXPECT_EQ(c.others, 13u);
}

// Triangle-only volumes that are not tetrahedra: two tets merged into a
// triangular bipyramid (6 triangles), and split tets around them.
TEST(TetTraversal, BipyramidsAndSplitTets)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(2, 2, 2));
	uint32 merged = 0;
	std::vector<Face> inner;
	foreach_cell(m, [&](Face f) {
		if (!is_incident_to_boundary(m, f))
			inner.push_back(f);
	});
	DartMarker<CMap3> touched(m);
	for (Face f : inner)
		if (!touched.is_marked(f.dart) && !touched.is_marked(phi3(m, f.dart)) && merged < 5)
		{
			touched.mark_orbit(Volume(f.dart));
			touched.mark_orbit(Volume(phi3(m, f.dart)));
			merge_incident_volumes(m, f);
			++merged;
		}
	ASSERT_EQ(merged, 5u);
	std::vector<Volume> tets;
	foreach_cell(m, [&](Volume w) {
		std::array<Dart, 4> c;
		if (detail::tetra_corners(m, w.dart, c))
			tets.push_back(w);
	});
	ASSERT_EQ(tets.size(), 48u - 10u);
	for (std::size_t k = 0; k < tets.size(); k += 3)
		split_tetra(m, tets[k]);
	ASSERT_TRUE(check_integrity(m).ok());
	const Compared c = compare_with_flooding(m);
	EXPECT_EQ(c.tets, 38u + 3u * 13u);
	EXPECT_EQ(c.others, 5u + 1u);
}

TEST(TetTraversal, MixedRealMesh)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "volume/hex_dominant_11k.mesh");
	CMap3 m;
	io::load_volume(m, path);
	const Compared c = compare_with_flooding(m);
	uint32 tets = 0;
	foreach_cell(m, [&](Volume w) {
		std::array<Dart, 4> corners;
		tets += detail::tetra_corners(m, w.dart, corners);
	});
	EXPECT_EQ(tets, 4442u);
	EXPECT_GE(c.tets, 4442u); // boundary volumes made of 4 triangles count too
	EXPECT_GE(c.others, 5520u + 908u + 317u);
}

} // namespace cgogn_test_tet_traversal
