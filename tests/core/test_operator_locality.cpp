// SPDX-License-Identifier: MIT
// Operators are local: with every orbit indexed, the reindexing of one call
// visits the same number of darts on a small and on a large mesh, and no more
// than a small multiple of the cells it touched. The count is the reindexer's
// own dart counter (no timing). The calls are made at the first darts of
// generated grids, the same corner of the mesh whatever its size, next to the
// boundary: a walk of the boundary (of a 3-map, the boundary "volume" is the
// whole boundary surface) or of the connected component would show.
#include <cgogn/core.h>

#include "component_split.h"
#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace cgogn_test_operator_locality
{

using namespace cgogn;
using test::index_everything;

namespace
{

CMap2 grid(uint32 n)
{
	CMap2 m;
	build_surface(m, grid_soup(n, n, true));
	index_everything(m);
	return m;
}

CMap3 tet_grid(uint32 n)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(n, n, n));
	index_everything(m);
	return m;
}

// The darts the reindexing of `edit` visits on map m.
template <typename MAP>
std::uint64_t visited(MAP& m, const std::function<void(MAP&)>& edit)
{
	detail::reset_reindexed_dart_count();
	edit(m);
	EXPECT_TRUE(check_integrity(m).ok());
	return detail::reindexed_dart_count();
}

template <typename MAP>
struct Edit
{
	std::string name;
	std::function<void(MAP&)> apply;
};

// An interior face of the corner tetrahedron (dart 0's volume): its dart.
Dart inner_face_dart(const CMap3& m)
{
	Dart found;
	foreach_dart_of_orbit(m, CMap3::Volume(Dart(0)), [&](Dart d) {
		if (!is_boundary(m, phi3(m, d)))
			found = d;
		return !found.is_valid();
	});
	return found;
}

const std::vector<Edit<CMap3>>& volume_edits()
{
	static const std::vector<Edit<CMap3>> edits = {
		{"cut_edge", [](CMap3& m) { cut_edge(m, CMap3::Edge(Dart(0))); }},
		{"cut_edge(inner)", [](CMap3& m) { cut_edge(m, CMap3::Edge(inner_face_dart(m))); }},
		{"cut_face",
		 [](CMap3& m) {
			 const Dart v = phi1(m, Dart(0));
			 cut_edge(m, CMap3::Edge(Dart(0)));
			 detail::reset_reindexed_dart_count(); // the cut above is not the measured call
			 cut_face(m, v, phi1(m, phi1(m, v)));
		 }},
		{"cut_volume",
		 [](CMap3& m) {
			 const Dart d(0);
			 cut_volume(m, {d, phi1(m, d), phi_1(m, d)});
		 }},
		{"split_tetra", [](CMap3& m) { split_tetra(m, CMap3::Volume(Dart(0))); }},
		{"remove_volume", [](CMap3& m) { remove_volume(m, CMap3::Volume(Dart(0))); }},
		{"unsew_volumes", [](CMap3& m) { unsew_volumes(m, CMap3::Face(inner_face_dart(m))); }},
		{"flip_face",
		 [](CMap3& m) {
			 const CMap3::Face f(inner_face_dart(m));
			 ASSERT_TRUE(can_flip_face(m, f));
			 flip_face(m, f);
		 }},
		{"collapse_edge",
		 [](CMap3& m) {
			 // the first edge of the corner tetrahedron the predicate accepts
			 Dart e;
			 foreach_dart_of_orbit(m, CMap3::Volume(Dart(0)), [&](Dart d) {
				 if (can_collapse_edge(m, CMap3::Edge(d)))
					 e = d;
				 return !e.is_valid();
			 });
			 ASSERT_TRUE(e.is_valid());
			 collapse_edge(m, CMap3::Edge(e));
		 }},
	};
	return edits;
}

const std::vector<Edit<CMap2>>& surface_edits()
{
	static const std::vector<Edit<CMap2>> edits = {
		{"cut_edge", [](CMap2& m) { cut_edge(m, CMap2::Edge(Dart(0))); }},
		{"remove_face", [](CMap2& m) { remove_face(m, CMap2::Face(Dart(0))); }},
		{"fill_hole_with_face",
		 [](CMap2& m) {
			 // the first face away from the border, in container order
			 Dart d;
			 foreach_dart(m, [&](Dart x) {
				 if (!d.is_valid() && !is_boundary(m, x) && !is_incident_to_boundary(m, CMap2::Face(x)))
					 d = x;
			 });
			 remove_face(m, CMap2::Face(d));
			 ASSERT_TRUE(can_fill_hole_with_face(m, d));
			 detail::reset_reindexed_dart_count();
			 fill_hole_with_face(m, d);
		 }},
		{"unsew_faces",
		 [](CMap2& m) {
			 Dart d(0);
			 while (!can_unsew_faces(m, CMap2::Edge(d)))
				 d = phi1(m, d);
			 unsew_faces(m, CMap2::Edge(d));
		 }},
		{"sew_faces",
		 [](CMap2& m) {
			 Dart d(0);
			 while (!can_unsew_faces(m, CMap2::Edge(d)))
				 d = phi1(m, d);
			 const Dart d2 = phi2(m, d);
			 unsew_faces(m, CMap2::Edge(d));
			 detail::reset_reindexed_dart_count();
			 sew_faces(m, CMap2::Edge(d), CMap2::Edge(d2));
		 }},
		{"collapse_edge",
		 [](CMap2& m) {
			 Dart d(0);
			 for (uint32 i = 0; i < 3 && !can_collapse_edge(m, CMap2::Edge(d)); ++i)
				 d = phi1(m, d);
			 ASSERT_TRUE(can_collapse_edge(m, CMap2::Edge(d)));
			 collapse_edge(m, CMap2::Edge(d));
		 }},
	};
	return edits;
}

// Each edit on a map made by make(small) and one made by make(large): the
// reindexing visits as many darts on both, and at most `bound`.
template <typename MAP>
void expect_local(const std::vector<Edit<MAP>>& edits, MAP (*make)(uint32), uint32 small, uint32 large,
				  std::uint64_t bound)
{
	for (const auto& [name, edit] : edits)
	{
		MAP on_small = make(small), on_large = make(large);
		const std::uint64_t n_small = visited(on_small, edit), n_large = visited(on_large, edit);
		EXPECT_EQ(n_small, n_large) << name;
		EXPECT_LE(n_large, bound) << name;
	}
}

} // namespace

// The boundary of the large grid has 6 x 2 x 24^2 triangles (20,736 darts),
// its component more than 1,000,000 darts: a bound of 4,000 darts leaves room
// for the cells an edit touches (the reindexing walks each touched cell of
// each of the 8 indexed orbits twice) and fails when either is walked.
// split_tetra indexes its new cells directly (it visits no dart).
TEST(OperatorLocality, VolumeEditsVisitTheSameDartsOnSmallAndLargeMeshes)
{
	expect_local(volume_edits(), tet_grid, 4, 24, 4000);
}

// 2-maps index the cells of an edit directly; the count covers the walks of
// components (remove_face, fill_hole_with_face, sew and unsew).
TEST(OperatorLocality, SurfaceEditsVisitTheSameDartsOnSmallAndLargeMeshes)
{
	expect_local(surface_edits(), grid, 8, 300, 500);
}

// A component that an edit really cuts in two is walked, but only its smaller
// part: unsewing the only edge between a grid and a triangle glued to its
// border leaves the triangle alone, with a new line; the grid keeps its line.
TEST(OperatorLocality, ASplitComponentWalksOnlyItsSmallerPart)
{
	SurfaceSoup s = grid_soup(20, 20, true); // vertex (i, j) is j * 21 + i
	const uint32 apex = s.nb_vertices++;
	s.face_sizes.push_back(3);
	s.face_vertices.insert(s.face_vertices.end(), {1, 0, apex}); // across the border edge 0 -> 1
	CMap2 m;
	build_surface(m, s);
	index_everything(m);
	ASSERT_EQ(nb_cells<CMap2::Volume>(m), 1u);
	const Dart d = Dart(0), t = phi2(m, d); // 0 -> 1 in the grid, 1 -> 0 in the triangle
	ASSERT_FALSE(is_boundary(m, t));
	const uint32 line = index_of(m, CMap2::Volume(d));
	ASSERT_TRUE(can_unsew_faces(m, CMap2::Edge(d)));
	detail::reset_reindexed_dart_count();
	unsew_faces(m, CMap2::Edge(d));
	EXPECT_LE(detail::reindexed_dart_count(), 100u); // the grid has 2,400 darts
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_cells<CMap2::Volume>(m), 2u);
	EXPECT_EQ(index_of(m, CMap2::Volume(d)), line);
	EXPECT_NE(index_of(m, CMap2::Volume(t)), line);
}

} // namespace cgogn_test_operator_locality
