// SPDX-License-Identifier: MIT
// Multiresolution 2-maps: regular levels, level relations, views, integrity.
#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <random>
#include <thread>
#include <vector>

using namespace cgogn;

namespace
{

CMap2 cube()
{
	CMap2 m;
	add_hexa(m);
	return m;
}

CMap2 tetrahedron()
{
	CMap2 m;
	add_tetra(m);
	return m;
}

CMap2 icosahedron()
{
	SurfaceSoup s;
	s.nb_vertices = 12;
	const uint32 f[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
							 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
							 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
	for (const auto& t : f)
	{
		s.face_sizes.push_back(3);
		s.face_vertices.insert(s.face_vertices.end(), {t[0], t[1], t[2]});
	}
	s.positions.assign(12, {0.0, 0.0, 0.0});
	CMap2 m;
	build_surface(m, s);
	return m;
}

/// A 3 x 2 grid with boundary, its first row of quads cut into triangles and
/// one face a pentagon: triangles, quads and a pentagon.
CMap2 mixed_grid()
{
	CMap2 m;
	build_surface(m, grid_soup(3, 2, false));
	uint32 cut = 0;
	foreach_cell(m, [&](CMap2::Face f) {
		if (cut++ < 2)
			cut_face(m, CMap2::Vertex(f.dart), CMap2::Vertex(phi1(m, phi1(m, f.dart))));
	});
	foreach_cell(m, [&](CMap2::Edge e) {
		if (!is_incident_to_boundary(m, e) ||
			codegree(m, CMap2::Face(is_boundary(m, e.dart) ? phi2(m, e.dart) : e.dart)) != 4)
			return true;
		cut_edge(m, e); // a boundary quad becomes a pentagon
		return false;
	});
	return m;
}

/// Number of faces of each degree.
template <typename M>
std::map<uint32, uint32> face_degrees(const M& m)
{
	std::map<uint32, uint32> d;
	foreach_cell(m, [&](MRMap2::Face f) { ++d[codegree(m, f)]; });
	return d;
}

/// Each face as its sorted darts, all faces sorted: the level's faces, whatever
/// dart represents them.
template <typename M>
std::vector<std::vector<uint32>> faces_as_darts(const M& m)
{
	std::vector<std::vector<uint32>> faces;
	foreach_cell(m, [&](MRMap2::Face f) {
		std::vector<uint32> darts;
		foreach_dart_of_orbit(m, f, [&](Dart d) { darts.push_back(d.index); });
		std::sort(darts.begin(), darts.end());
		faces.push_back(darts);
	});
	std::sort(faces.begin(), faces.end());
	return faces;
}

/// The f-vector and face degrees the next level must have: every edge cut,
/// triangles into 4 (unless Quadrangular), other k-gons into k quads.
struct Expected
{
	std::vector<uint32> f;
	std::map<uint32, uint32> degrees;
};
Expected next_level(const std::vector<uint32>& f, const std::map<uint32, uint32>& degrees, Refinement r)
{
	Expected e;
	uint32 centres = 0, inner = 0, faces = 0;
	for (auto [k, n] : degrees)
	{
		if (k == 3 && r != Refinement::Quadrangular)
		{
			inner += 3 * n;
			faces += 4 * n;
			e.degrees[3] += 4 * n;
		}
		else
		{
			centres += n;
			inner += k * n;
			faces += k * n;
			e.degrees[4] += k * n;
		}
	}
	e.f = {f[0] + f[1] + centres, 2 * f[1] + inner, faces};
	return e;
}

/// The first dart of level l of the finest map.
Dart first_dart_of_level(const MRMap2& m, uint32 l)
{
	Dart r;
	foreach_dart(finest_map(m), [&](Dart d) {
		if (dart_level(m, d) != l)
			return true;
		r = d;
		return false;
	});
	return r;
}

void expect_ok(const IntegrityReport& r)
{
	EXPECT_TRUE(r.ok()) << r.to_string();
}

} // namespace

TEST(MRMap2, CubeQuadrangularLevelsKeepEveryRow)
{
	MRMap2 m(cube());
	EXPECT_EQ(max_level(m), 0u);
	for (uint32 k = 0; k <= 4; ++k)
	{
		if (k > 0)
			add_level(m, Refinement::Quadrangular);
		ASSERT_EQ(max_level(m), k);
		EXPECT_EQ(current_level(m), k);
		expect_ok(check_integrity(m));
		for (uint32 j = 0; j <= k; ++j)
		{
			const uint32 p = 1u << (2 * j);
			const MRLevelView2 v = level_view(m, j);
			EXPECT_EQ(f_vector(v), (std::vector<uint32>{6 * p + 2, 12 * p, 6 * p})) << "level " << j << " of " << k;
			EXPECT_EQ(nb_darts(v), 24 * p);
			EXPECT_EQ(euler_characteristic(v), 2);
			EXPECT_EQ(face_degrees(v), (std::map<uint32, uint32>{{4, 6 * p}}));
		}
		uint32 sum = 0;
		for (uint32 j = 0; j <= k; ++j)
			sum += nb_darts_at_level(m, j);
		EXPECT_EQ(sum, nb_darts(finest_map(m)));
	}
	// the finest level is the flat map
	EXPECT_EQ(f_vector(m), f_vector(finest_map(m)));
}

TEST(MRMap2, TriangularLevelsOfTetrahedronAndIcosahedron)
{
	MRMap2 t(tetrahedron());
	MRMap2 ico(icosahedron());
	for (uint32 k = 0; k <= 4; ++k)
	{
		if (k > 0)
		{
			add_level(t, Refinement::Triangular);
			if (k <= 3)
				add_level(ico, Refinement::Triangular);
		}
		expect_ok(check_integrity(t));
		for (uint32 j = 0; j <= k; ++j)
		{
			const uint32 p = 1u << (2 * j);
			EXPECT_EQ(f_vector(level_view(t, j)), (std::vector<uint32>{2 * p + 2, 6 * p, 4 * p}));
			if (k <= 3)
			{
				EXPECT_EQ(f_vector(level_view(ico, j)), (std::vector<uint32>{10 * p + 2, 30 * p, 20 * p}));
			}
		}
	}
	expect_ok(check_integrity(ico));
}

TEST(MRMap2, EveryLevelIsTheFlatRefinementOfTheOneBelow)
{
	for (Refinement r : {Refinement::Quadrangular, Refinement::Mixed})
	{
		MRMap2 m(mixed_grid());
		std::vector<std::vector<uint32>> f{f_vector(m)};
		std::vector<std::map<uint32, uint32>> degrees{face_degrees(m)};
		ASSERT_EQ(degrees[0].count(5), 1u);
		ASSERT_GE(degrees[0][3], 4u);
		for (uint32 k = 1; k <= 3; ++k)
		{
			add_level(m, r);
			const Expected e = next_level(f.back(), degrees.back(), r);
			f.push_back(f_vector(m));
			degrees.push_back(face_degrees(m));
			EXPECT_EQ(f.back(), e.f) << "level " << k;
			EXPECT_EQ(degrees.back(), e.degrees) << "level " << k;
			EXPECT_EQ(euler_characteristic(m), 1);
			expect_ok(check_integrity(m));
			for (uint32 j = 0; j <= k; ++j)
			{
				set_current_level(m, j);
				EXPECT_EQ(f_vector(m), f[j]);
				EXPECT_EQ(face_degrees(m), degrees[j]);
			}
		}
	}
}

TEST(MRMap2, RemovingLevelsGivesBackTheLevelsBelow)
{
	MRMap2 m(mixed_grid());
	std::vector<std::vector<std::vector<uint32>>> faces{faces_as_darts(m)};
	std::vector<uint32> darts{nb_darts(finest_map(m))};
	for (uint32 k = 1; k <= 3; ++k)
	{
		add_level(m, Refinement::Mixed);
		faces.push_back(faces_as_darts(m));
		darts.push_back(nb_darts(finest_map(m)));
	}
	// the faces of level j, read below finer levels, are those the level had
	for (uint32 j = 0; j <= 3; ++j)
		EXPECT_EQ(faces_as_darts(level_view(m, j)), faces[j]);
	for (uint32 k = 3; k >= 1; --k)
	{
		set_current_level(m, 1);
		remove_finest_level(m);
		EXPECT_EQ(max_level(m), k - 1);
		EXPECT_EQ(current_level(m), std::min(1u, k - 1));
		EXPECT_EQ(nb_darts(finest_map(m)), darts[k - 1]);
		EXPECT_EQ(nb_darts_at_level(m, k), 0u);
		expect_ok(check_integrity(m));
		expect_ok(check_integrity(finest_map(m)));
		for (uint32 j = 0; j < k; ++j)
			EXPECT_EQ(faces_as_darts(level_view(m, j)), faces[j]);
	}
	EXPECT_THROW(remove_finest_level(m), std::invalid_argument);
	// and the levels come back the same
	add_level(m, Refinement::Mixed);
	EXPECT_EQ(f_vector(m), f_vector(level_view(m, 1)));
	EXPECT_EQ(nb_darts(finest_map(m)), darts[1]);
	expect_ok(check_integrity(m));
}

TEST(MRMap2, LevelRelations)
{
	MRMap2 m(mixed_grid());
	add_level(m, Refinement::Mixed);
	add_level(m, Refinement::Quadrangular);
	add_level(m, Refinement::Quadrangular);
	for (uint32 l = 0; l <= 3; ++l)
	{
		const MRLevelView2 v = level_view(m, l);
		uint32 seen = 0;
		foreach_dart(v, [&](Dart d) {
			++seen;
			EXPECT_LE(dart_level(m, d), l);
			EXPECT_TRUE(is_dart_valid(v, d));
			EXPECT_EQ(phi_1(v, phi1(v, d)), d);
			EXPECT_EQ(phi2(v, phi2(v, d)), d);
			EXPECT_NE(phi2(v, d), d);
			// phi2(d) leaves the vertex of the finest map where phi1(d) starts
			EXPECT_TRUE(same_orbit(finest_map(m), CMap2::Vertex(phi2(v, d)), CMap2::Vertex(phi1(v, d))));
		});
		EXPECT_EQ(seen, nb_darts(v));
		// vertices of level <= l keep their degree from their level on
		uint32 degree_sum = 0;
		foreach_cell(v, [&](MRMap2::Vertex x) { degree_sum += degree(v, x); });
		EXPECT_EQ(degree_sum, 2 * nb_cells<MRMap2::Edge>(v));
	}
	// a level-0 dart is valid everywhere, a level-3 one only at level 3
	const Dart young = first_dart_of_level(m, 3);
	EXPECT_FALSE(is_dart_valid(level_view(m, 2), young));
	EXPECT_TRUE(is_dart_valid(level_view(m, 3), young));
}

TEST(MRMap2, LocalTraversalsAtALevel)
{
	MRMap2 m(cube());
	add_level(m, Refinement::Quadrangular);
	add_level(m, Refinement::Quadrangular);
	const MRLevelView2 coarse = level_view(m, 0);
	// at level 0 every vertex is a cube corner of degree 3, its 3 neighbours corners
	foreach_cell(coarse, [&](MRMap2::Vertex v) {
		EXPECT_EQ(degree(coarse, v), 3u);
		uint32 n = 0;
		foreach_adjacent_vertex_through_edge(coarse, v, [&](MRMap2::Vertex w) {
			EXPECT_EQ(dart_level(m, w.dart), 0u);
			++n;
		});
		EXPECT_EQ(n, 3u);
		uint32 faces = 0, around = 0;
		foreach_incident_face(coarse, v, [&](MRMap2::Face) { ++faces; });
		foreach_adjacent_vertex_through_face(coarse, v, [&](MRMap2::Vertex) { ++around; });
		EXPECT_EQ(faces, 3u);
		EXPECT_EQ(around, 3u + 3u);
	});
	foreach_cell(coarse, [&](MRMap2::Face f) {
		EXPECT_EQ(codegree(coarse, f), 4u);
		uint32 n = 0;
		foreach_adjacent_face_through_edge(coarse, f, [&](MRMap2::Face) { ++n; });
		EXPECT_EQ(n, 4u);
		n = 0;
		foreach_adjacent_face_through_vertex(coarse, f, [&](MRMap2::Face) { ++n; });
		EXPECT_EQ(n, 4u);
	});
	foreach_cell(coarse, [&](MRMap2::Edge e) {
		EXPECT_EQ(degree(coarse, e), 2u);
		EXPECT_FALSE(is_incident_to_boundary(coarse, e));
		uint32 n = 0;
		foreach_adjacent_edge_through_vertex(coarse, e, [&](MRMap2::Edge) { ++n; });
		EXPECT_EQ(n, 4u);
		n = 0;
		foreach_adjacent_edge_through_face(coarse, e, [&](MRMap2::Edge) { ++n; });
		EXPECT_EQ(n, 6u);
	});
	// the component, at each level
	for (uint32 l = 0; l <= 2; ++l)
	{
		const MRLevelView2 v = level_view(m, l);
		EXPECT_EQ(nb_cells<MRMap2::Volume>(v), 1u);
		foreach_cell(v, [&](MRMap2::Volume w) {
			uint32 vertices = 0, edges = 0, faces = 0;
			foreach_incident_vertex(v, w, [&](MRMap2::Vertex) { ++vertices; });
			foreach_incident_edge(v, w, [&](MRMap2::Edge) { ++edges; });
			foreach_incident_face(v, w, [&](MRMap2::Face) { ++faces; });
			EXPECT_EQ((std::vector<uint32>{vertices, edges, faces}), f_vector(v));
		});
	}
}

TEST(MRMap2, BoundaryAtEveryLevel)
{
	MRMap2 m(mixed_grid());
	const uint32 boundary_edges0 = [&] {
		uint32 n = 0;
		foreach_cell(m, [&](MRMap2::Edge e) { n += is_incident_to_boundary(m, e); });
		return n;
	}();
	add_level(m, Refinement::Mixed);
	add_level(m, Refinement::Mixed);
	for (uint32 l = 0; l <= 2; ++l)
	{
		const MRLevelView2 v = level_view(m, l);
		uint32 n = 0, on_boundary = 0;
		foreach_cell(v, [&](MRMap2::Edge e) {
			if (is_incident_to_boundary(v, e))
			{
				++n;
				EXPECT_EQ(degree(v, e), 1u);
			}
		});
		foreach_cell(v, [&](MRMap2::Vertex x) { on_boundary += is_incident_to_boundary(v, x); });
		EXPECT_EQ(n, boundary_edges0 << l);
		EXPECT_EQ(on_boundary, n); // the boundary is one cycle
	}
}

TEST(MRMap2, ParallelAndConcurrentReadsAgree)
{
	MRMap2 m(icosahedron());
	for (int k = 0; k < 3; ++k)
		add_level(m, Refinement::Triangular);
	const uint32 workers = thread_pool()->nb_workers();
	thread_pool()->set_nb_workers(2);
	for (uint32 l = 0; l <= 3; ++l)
	{
		const MRLevelView2 v = level_view(m, l);
		std::vector<std::atomic<uint32>> hits(nb_darts(finest_map(m)) + 16);
		parallel_foreach_cell(v, [&](MRMap2::Vertex x) { hits[x.dart.index]++; });
		uint32 total = 0, sequential = 0;
		for (auto& h : hits)
		{
			EXPECT_LE(h.load(), 1u);
			total += h.load();
		}
		foreach_cell(v, [&](MRMap2::Vertex x) {
			EXPECT_EQ(hits[x.dart.index].load(), 1u);
			++sequential;
		});
		EXPECT_EQ(total, sequential);
		EXPECT_EQ(total, nb_cells<MRMap2::Vertex>(v));
	}
	thread_pool()->set_nb_workers(workers);
	// two levels read at once from two threads
	std::vector<uint32> f0, f3;
	std::thread a([&] { f0 = f_vector(level_view(m, 0)); });
	std::thread b([&] { f3 = f_vector(level_view(m, 3)); });
	a.join();
	b.join();
	EXPECT_EQ(f0, (std::vector<uint32>{12, 30, 20}));
	EXPECT_EQ(f3, (std::vector<uint32>{10 * 64 + 2, 30 * 64, 20 * 64}));
}

TEST(MRMap2, RefusalsLeaveTheMapUnchanged)
{
	MRMap2 m(cube());
	EXPECT_THROW(add_level(m, Refinement::Triangular), std::invalid_argument);
	EXPECT_THROW(add_level(m, Refinement::Hexahedral), std::invalid_argument);
	EXPECT_EQ(max_level(m), 0u);
	EXPECT_EQ(nb_darts(finest_map(m)), 24u);
	EXPECT_THROW(set_current_level(m, 1), std::out_of_range);
	EXPECT_THROW(level_view(m, 1), std::out_of_range);
	EXPECT_THROW(remove_finest_level(m), std::invalid_argument);
	add_level(m, Refinement::Quadrangular);
	EXPECT_THROW(add_level(m, Refinement::Triangular), std::invalid_argument);
	EXPECT_EQ(nb_darts(finest_map(m)), 96u);
	expect_ok(check_integrity(m));
}

TEST(MRMap2, IntegrityFindsBrokenLabels)
{
	{
		MRMap2 m(cube());
		add_level(m, Refinement::Quadrangular);
		(*detail::mr_state_of(m).edge_id)[first_dart_of_level(m, 1).index] = 3;
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::EdgeIdWrong));
	}
	{
		MRMap2 m(cube());
		add_level(m, Refinement::Quadrangular);
		(*detail::mr_state_of(m).level)[first_dart_of_level(m, 0).index] = 1;
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::LevelCountWrong));
	}
	{
		// the second piece of a cut edge given another id than the first:
		// phi1 at level 0 turns into the other side of the edge
		MRMap2 m(cube());
		add_level(m, Refinement::Quadrangular);
		detail::MRState2& s = detail::mr_state_of(m);
		const Dart back = phi2(s.map, first_dart_of_level(m, 0)); // midpoint -> origin of the edge
		Dart piece;                                               // midpoint -> end of the edge
		foreach_dart_of_orbit(s.map, CMap2::Vertex(back), [&](Dart x) {
			if (x == back || dart_level(m, phi2(s.map, x)) != 0)
				return true;
			piece = x;
			return false;
		});
		ASSERT_TRUE(piece.is_valid());
		for (Dart d : {piece, phi2(s.map, piece)})
			(*s.edge_id)[d.index] = 1;
		const IntegrityReport r = check_integrity(m);
		EXPECT_FALSE(r.ok());
		EXPECT_TRUE(check_integrity(level_view(m, 1)).ok()) << "the finest level does not read the ids";
	}
}

TEST(MRMap2Attributes, VerticesHaveAValueAtEveryLevel)
{
	CMap2 c = cube();
	auto h0 = add_attribute<double, CMap2::Vertex>(c, "h");
	double next = 1.0;
	foreach_cell(c, [&](CMap2::Vertex v) { (*h0)[v] = next++; });
	MRMap2 m(std::move(c));
	auto h = get_attribute<double, MRMap2::Vertex>(m, "h");
	ASSERT_TRUE(h);
	std::map<uint32, double> at0; // by dart
	foreach_cell(m, [&](MRMap2::Vertex v) { at0[v.dart.index] = value<double>(m, h, v); });
	ASSERT_EQ(at0.size(), 8u);
	add_level(m, Refinement::Quadrangular);
	expect_ok(check_integrity(m));
	const MRLevelView2 v0 = level_view(m, 0), v1 = level_view(m, 1);
	// old vertices start level 1 with their value, in a line of their own
	for (auto [d, x] : at0)
	{
		EXPECT_EQ(value<double>(v1, h, MRMap2::Vertex(Dart(d))), x);
		EXPECT_NE(index_of(v0, MRMap2::Vertex(Dart(d))), index_of(v1, MRMap2::Vertex(Dart(d))));
	}
	// new vertices: the midpoint of their edge (its ends are the old
	// neighbours), the centroid of their face (the mean of its corners, which
	// is the mean of the midpoints around it)
	uint32 midpoints = 0, centres = 0;
	foreach_cell(v1, [&](MRMap2::Vertex v) {
		if (dart_level(m, v.dart) == 0)
			return;
		double old_sum = 0.0, all_sum = 0.0;
		uint32 nb_old = 0, nb = 0;
		foreach_adjacent_vertex_through_edge(v1, v, [&](MRMap2::Vertex w) {
			all_sum += value<double>(v1, h, w);
			++nb;
			if (dart_level(m, w.dart) == 0)
			{
				old_sum += value<double>(v1, h, w);
				++nb_old;
			}
		});
		if (nb_old == 2)
		{
			EXPECT_DOUBLE_EQ(value<double>(v1, h, v), old_sum / 2);
			++midpoints;
		}
		else
		{
			EXPECT_EQ(nb_old, 0u);
			EXPECT_DOUBLE_EQ(value<double>(v1, h, v), all_sum / nb);
			++centres;
		}
	});
	EXPECT_EQ(midpoints, 12u);
	EXPECT_EQ(centres, 6u);
	// writing at level 1 leaves level 0 alone
	set_current_level(m, 1);
	foreach_cell(m, [&](MRMap2::Vertex v) { value<double>(m, h, v) = -1.0; });
	for (auto [d, x] : at0)
	{
		EXPECT_EQ(value<double>(v0, h, MRMap2::Vertex(Dart(d))), x);
		EXPECT_EQ(value<double>(v1, h, MRMap2::Vertex(Dart(d))), -1.0);
		EXPECT_EQ((*h)[MRMap2::Vertex(Dart(d))], -1.0) << "operator[] reads the finest level";
	}
	// removing level 1 gives back level 0, lines and values
	remove_finest_level(m);
	expect_ok(check_integrity(m));
	for (auto [d, x] : at0)
		EXPECT_EQ(value<double>(m, h, MRMap2::Vertex(Dart(d))), x);
	uint32 lines = 0;
	const AttributeContainer& vc = *detail::state_of(finest_map(m)).cells[orbit_index(Orbit::PHI21)];
	for (uint32 i = 0; i < vc.end_index(); ++i)
		lines += vc.key()[i] != INVALID_INDEX;
	EXPECT_EQ(lines, 8u);
}

TEST(MRMap2Attributes, RefinedEdgesAndFacesKeepTheirLines)
{
	MRMap2 m(cube());
	auto tag = add_attribute<uint32, MRMap2::Edge>(m, "tag");
	auto area = add_attribute<double, MRMap2::Face>(m, "area");
	uint32 next = 1;
	foreach_cell(m, [&](MRMap2::Edge e) { value<uint32>(m, tag, e) = next++; });
	foreach_cell(m, [&](MRMap2::Face f) { value<double>(m, area, f) = double(next++); });
	std::map<uint32, std::pair<uint32, uint32>> edges0; // dart -> (line, tag)
	foreach_cell(m, [&](MRMap2::Edge e) { edges0[e.dart.index] = {index_of(m, e), value<uint32>(m, tag, e)}; });
	add_level(m, Refinement::Quadrangular);
	add_level(m, Refinement::Quadrangular);
	expect_ok(check_integrity(m));
	const MRLevelView2 v0 = level_view(m, 0), v1 = level_view(m, 1), v2 = level_view(m, 2);
	for (auto [d, lt] : edges0)
	{
		const MRMap2::Edge e{Dart(d)};
		EXPECT_EQ(index_of(v0, e), lt.first);
		EXPECT_EQ(value<uint32>(v0, tag, e), lt.second);
		// the piece of the edge at d, at the finer levels: a line of its own,
		// a copy of the value
		EXPECT_NE(index_of(v1, e), lt.first);
		EXPECT_NE(index_of(v2, e), index_of(v1, e));
		EXPECT_EQ(value<uint32>(v2, tag, e), lt.second);
	}
	// inner edges of level 1 have no parent: the default value
	uint32 inner = 0;
	foreach_cell(v1, [&](MRMap2::Edge e) {
		if (dart_level(m, e.dart) == 1 && dart_level(m, phi2(v1, e.dart)) == 1)
		{
			EXPECT_EQ(value<uint32>(v1, tag, e), 0u);
			++inner;
		}
	});
	EXPECT_EQ(inner, 24u);
	// each child face has its parent's value; the parent keeps its own
	foreach_cell(v2, [&](MRMap2::Face f) { EXPECT_GE(value<double>(v2, area, f), 13.0); });
	set_current_level(m, 2);
	foreach_cell(m, [&](MRMap2::Face f) { value<double>(m, area, f) = 0.5; });
	uint32 parents = 0;
	foreach_cell(v0, [&](MRMap2::Face f) {
		EXPECT_GE(value<double>(v0, area, f), 13.0);
		++parents;
	});
	EXPECT_EQ(parents, 6u);
	EXPECT_EQ(nb_cells<MRMap2::Face>(v2), 96u);
	remove_finest_level(m);
	remove_finest_level(m);
	expect_ok(check_integrity(m));
	for (auto [d, lt] : edges0)
	{
		EXPECT_EQ(index_of(m, MRMap2::Edge(Dart(d))), lt.first);
		EXPECT_EQ(value<uint32>(m, tag, MRMap2::Edge(Dart(d))), lt.second);
	}
}

TEST(MRMap2Attributes, AnOrbitIndexedLateGetsLinesAtEveryLevel)
{
	for (Refinement r : {Refinement::Mixed, Refinement::Quadrangular})
	{
		MRMap2 m(mixed_grid());
		add_level(m, r);
		add_level(m, r);
		auto fv = add_attribute<double, MRMap2::Face>(m, "f");
		auto ev = add_attribute<double, MRMap2::Edge>(m, "e");
		auto vv = add_attribute<double, MRMap2::Vertex>(m, "v");
		auto cv = add_attribute<double, MRMap2::Volume>(m, "c");
		ASSERT_TRUE(fv && ev && vv && cv);
		EXPECT_FALSE((add_attribute<double, MRMap2::Face>(m, "f")));
		EXPECT_FALSE((add_attribute<double, MRMap2::Face>(m, "__f")));
		expect_ok(check_integrity(m));
		// the traversals of indexed orbits walk the lines: the same cells as the darts give
		for (uint32 l = 0; l <= 2; ++l)
		{
			const MRLevelView2 v = level_view(m, l);
			EXPECT_EQ(nb_cells<MRMap2::Face>(v), f_vector(v)[2]);
			std::vector<uint32> by_lines, by_darts;
			foreach_cell(v, [&](MRMap2::Edge e) { by_lines.push_back(index_of(v, e)); });
			foreach_cell(v, [&](MRMap2::HalfEdge d) {
				const Dart e = phi2(v, d.dart);
				if (d.dart.index < e.index || is_boundary(v, e))
					by_darts.push_back(index_of(v, MRMap2::Edge(d.dart)));
			});
			std::sort(by_lines.begin(), by_lines.end());
			std::sort(by_darts.begin(), by_darts.end());
			EXPECT_EQ(by_lines, by_darts);
		}
		EXPECT_TRUE(remove_attribute(m, fv));
		EXPECT_FALSE((get_attribute<double, MRMap2::Face>(m, "f")));
		remove_finest_level(m);
		expect_ok(check_integrity(m));
		add_level(m, r);
		expect_ok(check_integrity(m));
	}
}

TEST(MRMap2Attributes, IntegrityFindsBrokenLines)
{
	{
		MRMap2 m(cube());
		add_attribute<double, MRMap2::Face>(m, "f");
		add_level(m, Refinement::Quadrangular);
		detail::MRState2& s = detail::mr_state_of(m);
		const Dart d = first_dart_of_level(m, 1);
		// a face of level 1 made to read another face's line
		const uint32 other = (*s.cells[2].index)[phi2(s.map, d).index];
		(*s.cells[2].index)[d.index] = other;
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::IndexNotConstant));
	}
	{
		MRMap2 m(cube());
		add_attribute<double, MRMap2::Vertex>(m, "v");
		add_level(m, Refinement::Quadrangular);
		detail::MRState2& s = detail::mr_state_of(m);
		// a level-1 vertex line refining a line of the same level
		const uint32 i = (*s.cells[0].index)[first_dart_of_level(m, 0).index];
		(*s.cells[0].down)[i] = i;
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::LevelLineWrong));
	}
	{
		MRMap2 m(cube());
		add_attribute<double, MRMap2::Edge>(m, "e");
		add_level(m, Refinement::Quadrangular);
		detail::MRState2& s = detail::mr_state_of(m);
		// a parent edge line marked as never replaced: it holds at level 1 too
		const Dart d = first_dart_of_level(m, 0);
		const uint32 parent = detail::mr_line_of(s, 0, 1, d);
		(*s.cells[1].replaced)[parent] = detail::MR_NOT_REPLACED;
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::LevelLineWrong));
	}
}

TEST(MRMap2Attributes, MarkersAtALevel)
{
	MRMap2 m(cube());
	add_level(m, Refinement::Quadrangular);
	const MRLevelView2 v0 = level_view(m, 0);
	CellMarker<MRLevelView2, MRMap2::Face> marked(v0);
	uint32 n = 0;
	foreach_cell(v0, [&](MRMap2::Face f) {
		if (n++ % 2 == 0)
			marked.mark(f);
	});
	uint32 seen = 0;
	foreach_cell(v0, [&](MRMap2::Face f) {
		foreach_dart_of_orbit(v0, f,
							  [&](Dart d) { EXPECT_EQ(marked.is_marked(MRMap2::Face(d)), marked.is_marked(f)); });
		seen += marked.is_marked(f);
	});
	EXPECT_EQ(seen, 3u);
	CellMarker<MRMap2, MRMap2::Vertex> vm(m);
	foreach_cell(m, [&](MRMap2::Vertex x) { vm.mark(x); });
	foreach_cell(m, [&](MRMap2::Vertex x) { EXPECT_TRUE(vm.is_marked(x)); });
}

TEST(MRMap2Attributes, ExtractLevelGivesTheLevelAsAFlatMap)
{
	MRMap2 m(mixed_grid());
	auto h = add_attribute<double, MRMap2::Vertex>(m, "h");
	auto tag = add_attribute<uint32, MRMap2::Face>(m, "tag");
	auto side = add_attribute<uint32, MRMap2::HalfEdge>(m, "side");
	double x = 0.0;
	foreach_cell(m, [&](MRMap2::Vertex v) { value<double>(m, h, v) = x += 1.0; });
	uint32 t = 0;
	foreach_cell(m, [&](MRMap2::Face f) { value<uint32>(m, tag, f) = ++t; });
	add_level(m, Refinement::Mixed);
	add_level(m, Refinement::Mixed);
	foreach_dart(finest_map(m), [&](Dart d) { (*side)[d.index] = d.index; });
	set_current_level(m, 2);
	foreach_cell(m, [&](MRMap2::Vertex v) { value<double>(m, h, v) += 100.0; });
	for (uint32 l = 0; l <= 2; ++l)
	{
		const MRLevelView2 v = level_view(m, l);
		const CMap2 flat = extract_level(m, l);
		expect_ok(check_integrity(flat));
		EXPECT_EQ(f_vector(flat), f_vector(v));
		EXPECT_EQ(nb_darts(flat), nb_darts(v));
		auto fh = get_attribute<double, CMap2::Vertex>(flat, "h");
		auto ftag = get_attribute<uint32, CMap2::Face>(flat, "tag");
		auto fside = get_attribute<uint32, CMap2::HalfEdge>(flat, "side");
		ASSERT_TRUE(fh && ftag && fside);
		// flat dart i is the i-th dart of the level in the finest map
		std::vector<Dart> source;
		foreach_dart(v, [&](Dart d) { source.push_back(d); });
		foreach_dart(flat, [&](Dart d) {
			const Dart s = source[d.index];
			EXPECT_EQ((*fside)[d.index], s.index);
			EXPECT_EQ(value<double>(flat, fh, CMap2::Vertex(d)), value<double>(v, h, MRMap2::Vertex(s)));
			if (!is_boundary(flat, d))
			{
				EXPECT_EQ(value<uint32>(flat, ftag, CMap2::Face(d)), value<uint32>(v, tag, MRMap2::Face(s)));
			}
			EXPECT_EQ(source[phi1(flat, d).index], phi1(v, s));
			EXPECT_EQ(source[phi2(flat, d).index], phi2(v, s));
		});
	}
	EXPECT_THROW(extract_level(m, 3), std::out_of_range);
}

namespace
{
/// Whether every two leaves adjacent at the finest level differ by one level at most.
bool balanced(const MRMap2& m)
{
	const MRLevelView2 v = level_view(m, max_level(m));
	bool ok = true;
	foreach_cell(v, [&](MRMap2::Face f) {
		const uint32 lf = face_level(v, f);
		foreach_dart_of_orbit(v, f, [&](Dart d) {
			const Dart e = phi2(v, d);
			if (is_boundary(v, e))
				return true;
			const uint32 lg = face_level(v, MRMap2::Face(e));
			ok = ok && (lf > lg ? lf - lg : lg - lf) <= 1;
			return ok;
		});
		return ok;
	});
	return ok;
}

/// The labels of every dart, by dart.
std::map<uint32, std::pair<uint32, uint32>> labels_of(const MRMap2& m)
{
	std::map<uint32, std::pair<uint32, uint32>> r;
	foreach_dart(finest_map(m), [&](Dart d) {
		r[d.index] = {dart_level(m, d), (*detail::mr_state_of(m).edge_id)[d.index]};
	});
	return r;
}
} // namespace

TEST(MRMap2Adaptive, SubdivideAndCoarsenOneFace)
{
	for (Refinement r : {Refinement::Quadrangular, Refinement::Mixed})
	{
		MRMap2 m(cube());
		auto h = add_attribute<double, MRMap2::Vertex>(m, "h");
		auto tag = add_attribute<uint32, MRMap2::Face>(m, "tag");
		auto etag = add_attribute<uint32, MRMap2::Edge>(m, "etag");
		uint32 t = 0;
		foreach_cell(m, [&](MRMap2::Face f) { value<uint32>(m, tag, f) = ++t; });
		foreach_cell(m, [&](MRMap2::Edge e) { value<uint32>(m, etag, e) = ++t; });
		foreach_cell(m, [&](MRMap2::Vertex v) { value<double>(m, h, v) = double(++t); });
		const auto labels = labels_of(m);
		const MRMap2::Face f = test::all<MRMap2::Face>(m)[0];
		const uint32 f_tag = value<uint32>(m, tag, f);
		subdivide_face(m, f, r);
		expect_ok(check_integrity(m));
		EXPECT_EQ(max_level(m), 1u);
		EXPECT_EQ(current_level(m), 0u);
		EXPECT_TRUE(face_is_subdivided(m, f));
		EXPECT_THROW(subdivide_face(m, f, r), std::invalid_argument);
		foreach_dart_of_orbit(m, f, [&](Dart d) { EXPECT_TRUE(edge_is_subdivided(m, MRMap2::Edge(d))); });
		const MRLevelView2 v1 = level_view(m, 1);
		EXPECT_EQ(f_vector(v1), (std::vector<uint32>{13, 20, 9}));
		uint32 children = 0;
		foreach_cell(v1, [&](MRMap2::Face c) {
			if (face_level(v1, c) == 1)
			{
				++children;
				EXPECT_EQ(value<uint32>(v1, tag, c), f_tag); // a copy of the parent's value
				EXPECT_NE(index_of(v1, c), index_of(m, f));
			}
		});
		EXPECT_EQ(children, 4u);
		EXPECT_EQ(value<uint32>(m, tag, f), f_tag);
		// the new vertices: the midpoints and the centre of their edges and face
		foreach_cell(v1, [&](MRMap2::Vertex x) {
			if (dart_level(m, x.dart) == 0)
				return;
			double sum = 0.0;
			uint32 n = 0, old = 0;
			foreach_adjacent_vertex_through_edge(v1, x, [&](MRMap2::Vertex w) {
				old += dart_level(m, w.dart) == 0;
				if (dart_level(m, w.dart) == 0 || degree(v1, x) == 4)
				{
					sum += value<double>(v1, h, w);
					++n;
				}
			});
			EXPECT_DOUBLE_EQ(value<double>(v1, h, x), sum / n);
		});
		EXPECT_TRUE(can_coarsen_face(m, f));
		coarsen_face(m, f);
		expect_ok(check_integrity(m));
		EXPECT_EQ(max_level(m), 0u);
		EXPECT_EQ(labels_of(m), labels);
		EXPECT_EQ(f_vector(m), (std::vector<uint32>{8, 12, 6}));
		EXPECT_EQ(value<uint32>(m, tag, f), f_tag);
		EXPECT_FALSE(can_coarsen_face(m, f));
	}
}

TEST(MRMap2Adaptive, BalanceKeepsNeighboursWithinOneLevel)
{
	MRMap2 m(cube());
	add_attribute<double, MRMap2::Vertex>(m, "h");
	add_attribute<uint32, MRMap2::Face>(m, "tag");
	// the same corner refined 4 times: its neighbours follow
	Dart d = test::all<MRMap2::Face>(m)[0].dart;
	for (uint32 k = 0; k < 4; ++k)
	{
		set_current_level(m, max_level(m));
		subdivide_face(m, MRMap2::Face(d), Refinement::Quadrangular);
		expect_ok(check_integrity(m));
		EXPECT_TRUE(balanced(m)) << "after " << k + 1;
	}
	EXPECT_EQ(max_level(m), 4u);
	// without balance the jump is allowed
	MRMap2 n(cube());
	d = test::all<MRMap2::Face>(n)[0].dart;
	for (uint32 k = 0; k < 3; ++k)
	{
		set_current_level(n, max_level(n));
		subdivide_face(n, MRMap2::Face(d), Refinement::Quadrangular, false);
	}
	expect_ok(check_integrity(n));
	EXPECT_FALSE(balanced(n));
}

TEST(MRMap2Adaptive, RandomRefinementAndCoarsening)
{
	for (Refinement r : {Refinement::Quadrangular, Refinement::Triangular})
	{
		MRMap2 m(r == Refinement::Triangular ? icosahedron() : cube());
		auto h = add_attribute<double, MRMap2::Vertex>(m, "h");
		add_attribute<uint32, MRMap2::Edge>(m, "e");
		add_attribute<uint32, MRMap2::Face>(m, "f");
		std::mt19937 rng(r == Refinement::Triangular ? 7u : 11u);
		uint32 subdivisions = 0, coarsenings = 0;
		for (uint32 step = 0; step < 1000; ++step)
		{
			const bool refine = std::uniform_int_distribution<int>(0, 9)(rng) < 6 || max_level(m) == 0;
			if (refine)
			{
				set_current_level(m, max_level(m));
				std::vector<MRMap2::Face> leaves;
				foreach_cell(m, [&](MRMap2::Face f) {
					if (face_level(m, f) < 4)
						leaves.push_back(f);
				});
				if (leaves.empty())
					continue;
				subdivide_face(m, leaves[std::uniform_int_distribution<std::size_t>(0, leaves.size() - 1)(rng)], r);
				++subdivisions;
			}
			else
			{
				std::vector<std::pair<uint32, MRMap2::Face>> parents;
				for (uint32 k = 0; k < max_level(m); ++k)
				{
					set_current_level(m, k);
					foreach_cell(m, [&](MRMap2::Face f) {
						if (can_coarsen_face(m, f))
							parents.emplace_back(k, f);
					});
				}
				if (parents.empty())
					continue;
				const auto [k, f] = parents[std::uniform_int_distribution<std::size_t>(0, parents.size() - 1)(rng)];
				set_current_level(m, k);
				coarsen_face(m, f);
				++coarsenings;
			}
			const IntegrityReport report = check_integrity(m);
			ASSERT_TRUE(report.ok()) << "step " << step << ": " << report.to_string();
			ASSERT_TRUE(balanced(m)) << "step " << step;
			uint32 sum = 0;
			for (uint32 l = 0; l <= max_level(m); ++l)
				sum += nb_darts_at_level(m, l);
			ASSERT_EQ(sum, nb_darts(finest_map(m)));
			ASSERT_GT(nb_darts_at_level(m, max_level(m)), 0u);
			ASSERT_EQ(euler_characteristic(level_view(m, max_level(m))), 2);
		}
		EXPECT_GT(subdivisions, 300u);
		EXPECT_GT(coarsenings, 100u);
		(void)h;
	}
}

TEST(MRMap2Adaptive, AddLevelRefusesAnAdaptiveHierarchy)
{
	MRMap2 m(cube());
	subdivide_face(m, test::all<MRMap2::Face>(m)[0], Refinement::Quadrangular);
	const uint32 darts = nb_darts(finest_map(m));
	// the other faces of level 0 have midpoints of level 1 but no children
	EXPECT_THROW(add_level(m, Refinement::Quadrangular), std::invalid_argument);
	EXPECT_EQ(nb_darts(finest_map(m)), darts);
	EXPECT_EQ(max_level(m), 1u);
	expect_ok(check_integrity(m));
	// and remove_finest_level takes an adaptive level away
	remove_finest_level(m);
	EXPECT_EQ(f_vector(m), (std::vector<uint32>{8, 12, 6}));
	expect_ok(check_integrity(m));
}
