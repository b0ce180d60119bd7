// SPDX-License-Identifier: MIT
// Multiresolution 3-maps: regular hexahedral levels, level relations, views,
// local traversals against extracted levels, integrity.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <map>
#include <stdexcept>
#include <vector>

using namespace cgogn;

namespace
{

CMap3 one_hexahedron()
{
	CMap3 m;
	add_hexa(m);
	return m;
}

/// Two hexahedra glued along a face.
CMap3 two_hexahedra()
{
	CMap3 m;
	const CMap3::Volume a = add_hexa(m);
	const CMap3::Volume b = add_hexa(m);
	sew_volumes(m, CMap3::Face(a.dart), CMap3::Face(b.dart));
	return m;
}

/// The relations of every dart of the finest map.
std::map<uint32, std::array<uint32, 3>> relations(const CMap3& m)
{
	std::map<uint32, std::array<uint32, 3>> r;
	foreach_dart(m, [&](Dart d) { r[d.index] = {phi1(m, d).index, phi2(m, d).index, phi3(m, d).index}; });
	return r;
}

/// The hexahedral grid of a x b x c cells: (V, E, F, W).
std::vector<uint32> hex_grid_f_vector(uint32 a, uint32 b, uint32 c)
{
	return {(a + 1) * (b + 1) * (c + 1), a * (b + 1) * (c + 1) + (a + 1) * b * (c + 1) + (a + 1) * (b + 1) * c,
			a * b * (c + 1) + a * (b + 1) * c + (a + 1) * b * c, a * b * c};
}
std::vector<uint32> hex_grid_f_vector(uint32 n)
{
	return hex_grid_f_vector(n, n, n);
}

} // namespace

TEST(MRMap3, HexahedralLevelsOfOneHexahedron)
{
	MRMap3 m(one_hexahedron());
	EXPECT_EQ(max_level(m), 0u);
	for (uint32 k = 1; k <= 3; ++k)
	{
		add_level(m, Refinement::Hexahedral);
		ASSERT_EQ(max_level(m), k);
		EXPECT_EQ(current_level(m), k);
		// every level keeps its own counts after the new one is added
		for (uint32 j = 0; j <= k; ++j)
		{
			const uint32 n = 1u << j;
			const MRLevelView3 v = level_view(m, j);
			EXPECT_EQ(f_vector(v), hex_grid_f_vector(n)) << "level " << j << " of " << k;
			// 24 darts per hexahedron, 4 per boundary quad
			EXPECT_EQ(nb_darts(v), 24 * n * n * n + 24 * n * n) << "level " << j;
			EXPECT_EQ(euler_characteristic(v), 1) << "level " << j;
		}
		const IntegrityReport r = check_integrity(m);
		EXPECT_TRUE(r.ok()) << r.nb_errors << " errors";
	}
	EXPECT_EQ(f_vector(m), f_vector(finest_map(m)));
}

TEST(MRMap3, LevelsOfAGridAreFinerGridsWithTheirPoints)
{
	// a 2 x 2 x 1 grid: edges with 4 volumes around, inner vertices
	const VolumeSoup soup = hex_grid_soup(2, 2, 1);
	CMap3 base;
	ASSERT_EQ(build_volume(base, soup).nb_cells_built, 4u);
	std::array<std::shared_ptr<CellAttribute<double, Orbit::PHI21_PHI31>>, 3> xyz;
	const char* names[3] = {"x", "y", "z"};
	for (uint32 c = 0; c < 3; ++c)
	{
		xyz[c] = add_attribute<double, CMap3::Vertex>(base, names[c]);
		for (uint32 i = 0; i < soup.nb_vertices; ++i)
			(*xyz[c])[i] = soup.positions[i][c]; // soup vertex i is line i
	}
	MRMap3 m(std::move(base));
	for (uint32 c = 0; c < 3; ++c)
		xyz[c] = get_attribute<double, MRMap3::Vertex>(m, names[c]);
	add_level(m, Refinement::Hexahedral);
	add_level(m, Refinement::Hexahedral);
	const IntegrityReport r = check_integrity(m);
	ASSERT_TRUE(r.ok()) << r.nb_errors << " errors";
	for (uint32 k = 0; k <= 2; ++k)
	{
		const MRLevelView3 v = level_view(m, k);
		const uint32 n = 1u << k;
		EXPECT_EQ(f_vector(v), hex_grid_f_vector(2 * n, 2 * n, n)) << "level " << k;
		// each new vertex is the centroid of the cell it is the middle of:
		// the points of level k are those of the finer grid
		std::vector<std::array<double, 3>> points, expected;
		foreach_cell(v, [&](MRMap3::Vertex x) {
			points.push_back(
				{value<double>(v, *xyz[0], x), value<double>(v, *xyz[1], x), value<double>(v, *xyz[2], x)});
		});
		for (uint32 i = 0; i <= 2 * n; ++i)
			for (uint32 j = 0; j <= 2 * n; ++j)
				for (uint32 l = 0; l <= n; ++l)
					expected.push_back({double(i) / n, double(j) / n, double(l) / n});
		std::sort(points.begin(), points.end());
		std::sort(expected.begin(), expected.end());
		EXPECT_EQ(points, expected) << "level " << k;
	}
}

TEST(MRMap3, LevelFacesAreQuadsAndVolumesHexahedra)
{
	MRMap3 m(two_hexahedra());
	add_level(m, Refinement::Hexahedral);
	add_level(m, Refinement::Hexahedral);
	for (uint32 l = 0; l <= 2; ++l)
	{
		const MRLevelView3 v = level_view(m, l);
		const uint32 n = 1u << l;
		EXPECT_EQ(f_vector(v), (std::vector<uint32>{(2 * n + 1) * (n + 1) * (n + 1),
													(2 * n) * (n + 1) * (n + 1) + 2 * (2 * n + 1) * n * (n + 1),
													(2 * n + 1) * n * n + 2 * (2 * n) * n * (n + 1), 2 * n * n * n}))
			<< "level " << l;
		uint32 nb_faces = 0;
		foreach_cell(v, [&](MRMap3::Face f) {
			++nb_faces;
			EXPECT_EQ(codegree(v, f), 4u);
		});
		foreach_cell(v, [&](MRMap3::Volume w) {
			EXPECT_EQ(codegree(v, w), 6u);
			uint32 nb_vertices = 0;
			foreach_incident_vertex(v, w, [&](MRMap3::Vertex) { ++nb_vertices; });
			EXPECT_EQ(nb_vertices, 8u);
		});
		EXPECT_GT(nb_faces, 0u);
		EXPECT_TRUE(check_integrity(v).ok());
	}
}

TEST(MRMap3, RemovingLevelsGivesBackTheSameMap)
{
	MRMap3 m(two_hexahedra());
	const auto before0 = relations(finest_map(m));
	add_level(m, Refinement::Hexahedral);
	const auto before1 = relations(finest_map(m));
	const std::vector<uint32> f1 = f_vector(m);
	add_level(m, Refinement::Hexahedral);
	remove_finest_level(m);
	EXPECT_EQ(max_level(m), 1u);
	EXPECT_EQ(current_level(m), 1u);
	EXPECT_EQ(relations(finest_map(m)), before1);
	EXPECT_EQ(f_vector(m), f1);
	EXPECT_TRUE(check_integrity(m).ok());
	remove_finest_level(m);
	EXPECT_EQ(relations(finest_map(m)), before0);
	EXPECT_EQ(nb_darts_at_level(m, 0), uint32(before0.size()));
	EXPECT_THROW(remove_finest_level(m), std::invalid_argument);
}

TEST(MRMap3, ExtractedLevelsAgreeWithTheViews)
{
	MRMap3 m(two_hexahedra());
	add_level(m, Refinement::Hexahedral);
	add_level(m, Refinement::Hexahedral);
	for (uint32 l = 0; l <= 2; ++l)
	{
		const MRLevelView3 v = level_view(m, l);
		const CMap3 flat = extract_level(m, l);
		ASSERT_TRUE(check_integrity(flat).ok()) << "level " << l;
		EXPECT_EQ(f_vector(flat), f_vector(v));
		// flat dart i is the i-th dart of the level in the finest map's order
		std::vector<Dart> source;
		foreach_dart(v, [&](Dart d) { source.push_back(d); });
		ASSERT_EQ(source.size(), std::size_t(nb_darts(flat)));
		std::map<uint32, uint32> flat_of;
		for (uint32 i = 0; i < source.size(); ++i)
			flat_of[source[i].index] = i;
		for (uint32 i = 0; i < source.size(); ++i)
		{
			const Dart d = source[i];
			ASSERT_EQ(flat_of[phi1(v, d).index], phi1(flat, Dart(i)).index);
			ASSERT_EQ(flat_of[phi_1(v, d).index], phi_1(flat, Dart(i)).index);
			ASSERT_EQ(flat_of[phi2(v, d).index], phi2(flat, Dart(i)).index);
			ASSERT_EQ(flat_of[phi3(v, d).index], phi3(flat, Dart(i)).index);
		}
		// the local traversals of the level meet the cells the flat map's meet
		const auto count_around = [](const auto& mesh, auto cell) {
			std::vector<uint32> n(4, 0);
			if constexpr (requires { foreach_incident_vertex(mesh, cell, [](MRMap3::Vertex) {}); })
				foreach_incident_vertex(mesh, cell, [&](MRMap3::Vertex) { ++n[0]; });
			if constexpr (requires { foreach_incident_edge(mesh, cell, [](MRMap3::Edge) {}); })
				foreach_incident_edge(mesh, cell, [&](MRMap3::Edge) { ++n[1]; });
			if constexpr (requires { foreach_incident_face(mesh, cell, [](MRMap3::Face) {}); })
				foreach_incident_face(mesh, cell, [&](MRMap3::Face) { ++n[2]; });
			if constexpr (requires { foreach_incident_volume(mesh, cell, [](MRMap3::Volume) {}); })
				foreach_incident_volume(mesh, cell, [&](MRMap3::Volume) { ++n[3]; });
			return n;
		};
		for (uint32 i = 0; i < source.size(); ++i)
		{
			if (is_boundary(flat, Dart(i)))
				continue;
			const Dart d = source[i];
			const Dart e(i);
			EXPECT_EQ(count_around(v, MRMap3::Vertex(d)), count_around(flat, CMap3::Vertex(e)));
			EXPECT_EQ(count_around(v, MRMap3::Edge(d)), count_around(flat, CMap3::Edge(e)));
			EXPECT_EQ(count_around(v, MRMap3::Face(d)), count_around(flat, CMap3::Face(e)));
			EXPECT_EQ(count_around(v, MRMap3::Volume(d)), count_around(flat, CMap3::Volume(e)));
			uint32 a = 0, b = 0;
			foreach_adjacent_vertex_through_edge(v, MRMap3::Vertex(d), [&](MRMap3::Vertex) { ++a; });
			foreach_adjacent_vertex_through_edge(flat, CMap3::Vertex(e), [&](CMap3::Vertex) { ++b; });
			EXPECT_EQ(a, b);
			a = b = 0;
			foreach_adjacent_volume_through_face(v, MRMap3::Volume(d), [&](MRMap3::Volume) { ++a; });
			foreach_adjacent_volume_through_face(flat, CMap3::Volume(e), [&](CMap3::Volume) { ++b; });
			EXPECT_EQ(a, b);
			EXPECT_EQ(degree(v, MRMap3::Edge(d)), degree(flat, CMap3::Edge(e)));
		}
	}
	EXPECT_THROW(extract_level(m, 3), std::out_of_range);
}

TEST(MRMap3, ParallelTraversalReportsEachCellOnce)
{
	MRMap3 m(two_hexahedra());
	add_level(m, Refinement::Hexahedral);
	add_level(m, Refinement::Hexahedral);
	for (uint32 l = 0; l <= 2; ++l)
	{
		const MRLevelView3 v = level_view(m, l);
		std::atomic<uint32> n{0};
		parallel_foreach_cell(v, [&](MRMap3::Vertex) { ++n; });
		EXPECT_EQ(n.load(), nb_cells<MRMap3::Vertex>(v));
		n = 0;
		parallel_foreach_cell(v, [&](MRMap3::Volume) { ++n; });
		EXPECT_EQ(n.load(), 2u << (3 * l));
	}
}

TEST(MRMap3, RefusalsLeaveTheMapUnchanged)
{
	CMap3 tet;
	add_tetra(tet);
	MRMap3 m(std::move(tet));
	const auto before = relations(finest_map(m));
	EXPECT_THROW(add_level(m, Refinement::Hexahedral), std::invalid_argument);
	EXPECT_THROW(add_level(m, Refinement::Triangular), std::invalid_argument);
	EXPECT_EQ(relations(finest_map(m)), before);
	EXPECT_EQ(max_level(m), 0u);
	EXPECT_THROW(set_current_level(m, 1), std::out_of_range);
	EXPECT_THROW(level_view(m, 1), std::out_of_range);

	// the cells of one volume cannot be indexed: refused, the map given back untouched
	CMap3 with_corners = one_hexahedron();
	add_attribute<double, CMap3::Vertex2>(with_corners, "weight");
	EXPECT_THROW(MRMap3{std::move(with_corners)}, std::invalid_argument);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(with_corners), 8u);
	EXPECT_NE((get_attribute<double, CMap3::Vertex2>(with_corners, "weight")), nullptr);
}

TEST(MRMap3, PerDartAttributesAreExtracted)
{
	CMap3 base = one_hexahedron();
	auto tag = add_attribute<uint32, CMap3::HalfEdge>(base, "tag");
	foreach_dart(base, [&](Dart d) { (*tag)[d.index] = d.index + 7; });
	MRMap3 m(std::move(base));
	add_level(m, Refinement::Hexahedral);
	const CMap3 flat = extract_level(m, 0);
	const auto t = get_attribute<uint32, CMap3::HalfEdge>(flat, "tag");
	ASSERT_NE(t, nullptr);
	uint32 i = 0;
	foreach_dart(level_view(m, 0), [&](Dart d) { EXPECT_EQ((*t)[i++], d.index + 7); });
}

TEST(MRMap3, IntegrityFindsBrokenLabels)
{
	const auto refined = [] {
		MRMap3 m(one_hexahedron());
		add_level(m, Refinement::Hexahedral);
		return m;
	};
	{
		// one dart of a face with another face id
		MRMap3 m = refined();
		auto& s = detail::mr_state_of(m);
		(*s.face_id)[0] = 9;
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::FaceIdWrong));
	}
	{
		// a wrong level count
		MRMap3 m = refined();
		detail::mr_state_of(m).darts_per_level[1] += 1;
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::LevelCountWrong));
	}
	{
		// an inner face given the face id of the faces it lies between: phi1
		// at level 0 turns into it
		MRMap3 m = refined();
		auto& s = detail::mr_state_of(m);
		Dart inner;
		foreach_dart(s.map, [&](Dart d) {
			if ((*s.face_id)[d.index] != 0)
			{
				inner = d;
				return false;
			}
			return true;
		});
		ASSERT_TRUE(inner.is_valid());
		foreach_dart_of_orbit(s.map, CMap3::Face(inner), [&](Dart d) { (*s.face_id)[d.index] = 0; });
		const IntegrityReport r = check_integrity(m);
		EXPECT_FALSE(r.ok());
		EXPECT_FALSE(r.has(IntegrityError::Kind::FaceIdWrong)); // the labels agree, the levels do not
	}
	{
		// the pieces of an edge with different edge ids: phi1 at level 0 does not find the second half
		MRMap3 m = refined();
		auto& s = detail::mr_state_of(m);
		Dart second_half;
		foreach_dart(s.map, [&](Dart d) {
			if ((*s.level)[d.index] == 1 && (*s.level)[phi2(s.map, d).index] == 0)
			{
				second_half = d;
				return false;
			}
			return true;
		});
		ASSERT_TRUE(second_half.is_valid());
		foreach_dart_of_orbit(s.map, CMap3::Edge(second_half), [&](Dart d) { (*s.edge_id)[d.index] += 1; });
		EXPECT_FALSE(check_integrity(m).ok());
	}
}

TEST(MRMap3Attributes, VerticesHaveAValueAtEveryLevel)
{
	CMap3 c = one_hexahedron();
	auto h0 = add_attribute<double, CMap3::Vertex>(c, "h");
	double next = 1.0;
	foreach_cell(c, [&](CMap3::Vertex v) {
		(*h0)[v] = next * next;
		next += 1.0;
	});
	MRMap3 m(std::move(c));
	auto h = get_attribute<double, MRMap3::Vertex>(m, "h");
	ASSERT_TRUE(h);
	std::map<uint32, double> at0; // by dart
	foreach_cell(m, [&](MRMap3::Vertex v) { at0[v.dart.index] = value<double>(m, h, v); });
	ASSERT_EQ(at0.size(), 8u);
	add_level(m, Refinement::Hexahedral);
	add_level(m, Refinement::Hexahedral);
	ASSERT_TRUE(check_integrity(m).ok());
	const MRLevelView3 v0 = level_view(m, 0), v1 = level_view(m, 1);
	for (auto [d, x] : at0)
	{
		EXPECT_EQ(value<double>(v1, h, MRMap3::Vertex(Dart(d))), x);
		EXPECT_NE(index_of(v0, MRMap3::Vertex(Dart(d))), index_of(v1, MRMap3::Vertex(Dart(d))));
	}
	// at each level, a new vertex is the mean of the corners of the cell it
	// is the middle of: an edge midpoint of its 2 old neighbours, a face
	// centre of the 4 midpoints around it (whose mean is that of the
	// corners), a volume centre of the 6 face centres around it
	for (uint32 l = 1; l <= 2; ++l)
	{
		const MRLevelView3 v = level_view(m, l);
		const auto is_old = [&](MRMap3::Vertex w) {
			bool old = false;
			foreach_dart_of_orbit(v, w, [&](Dart d) { return !(old = dart_level(m, d) < l); });
			return old;
		};
		const auto neighbours = [&](MRMap3::Vertex x) {
			std::vector<MRMap3::Vertex> n;
			foreach_adjacent_vertex_through_edge(v, x, [&](MRMap3::Vertex w) { n.push_back(w); });
			return n;
		};
		const auto mean = [&](const std::vector<MRMap3::Vertex>& ws) {
			double sum = 0.0;
			for (MRMap3::Vertex w : ws)
				sum += value<double>(v, h, w);
			return sum / double(ws.size());
		};
		std::vector<MRMap3::Vertex> midpoints, others;
		std::vector<uint32> midpoint_darts;
		foreach_cell(v, [&](MRMap3::Vertex x) {
			if (is_old(x))
				return;
			std::vector<MRMap3::Vertex> old;
			for (MRMap3::Vertex w : neighbours(x))
				if (is_old(w))
					old.push_back(w);
			if (old.size() == 2)
			{
				EXPECT_NEAR(value<double>(v, h, x), mean(old), 1e-12);
				midpoints.push_back(x);
				foreach_dart_of_orbit(v, x, [&](Dart d) { midpoint_darts.push_back(d.index); });
			}
			else
			{
				EXPECT_TRUE(old.empty());
				others.push_back(x);
			}
		});
		std::sort(midpoint_darts.begin(), midpoint_darts.end());
		uint32 face_centres = 0, volume_centres = 0;
		for (MRMap3::Vertex x : others)
		{
			std::vector<MRMap3::Vertex> mids, all = neighbours(x);
			for (MRMap3::Vertex w : all)
				if (std::binary_search(midpoint_darts.begin(), midpoint_darts.end(), w.dart.index))
					mids.push_back(w);
			if (mids.empty())
			{
				EXPECT_EQ(all.size(), 6u);
				EXPECT_NEAR(value<double>(v, h, x), mean(all), 1e-12);
				++volume_centres;
			}
			else
			{
				EXPECT_EQ(mids.size(), 4u);
				EXPECT_NEAR(value<double>(v, h, x), mean(mids), 1e-12);
				++face_centres;
			}
		}
		const uint32 n = 1u << (l - 1); // the level below is an n x n x n grid
		EXPECT_EQ(midpoints.size(), 3 * n * (n + 1) * (n + 1)) << "level " << l;
		EXPECT_EQ(face_centres, 3 * n * n * (n + 1)) << "level " << l;
		EXPECT_EQ(volume_centres, n * n * n) << "level " << l;
	}
	// writing at level 1 leaves level 0 alone
	set_current_level(m, 1);
	foreach_cell(m, [&](MRMap3::Vertex v) { value<double>(m, h, v) = -1.0; });
	for (auto [d, x] : at0)
	{
		EXPECT_EQ(value<double>(v0, h, MRMap3::Vertex(Dart(d))), x);
		EXPECT_EQ(value<double>(v1, h, MRMap3::Vertex(Dart(d))), -1.0);
	}
	// removing the levels gives back level 0, lines and values
	remove_finest_level(m);
	remove_finest_level(m);
	EXPECT_TRUE(check_integrity(m).ok());
	for (auto [d, x] : at0)
		EXPECT_EQ(value<double>(m, h, MRMap3::Vertex(Dart(d))), x);
	uint32 lines = 0;
	const AttributeContainer& vc = *detail::state_of(finest_map(m)).cells[orbit_index(Orbit::PHI21_PHI31)];
	for (uint32 i = 0; i < vc.end_index(); ++i)
		lines += vc.key()[i] != INVALID_INDEX;
	EXPECT_EQ(lines, 8u);
}

TEST(MRMap3Attributes, RefinedCellsKeepTheirLinesAndChildrenCopyThem)
{
	MRMap3 m(two_hexahedra());
	auto et = add_attribute<uint32, MRMap3::Edge>(m, "e");
	auto ft = add_attribute<uint32, MRMap3::Face>(m, "f");
	auto wt = add_attribute<uint32, MRMap3::Volume>(m, "w");
	uint32 next = 1;
	foreach_cell(m, [&](MRMap3::Edge e) { value<uint32>(m, et, e) = next++; });
	foreach_cell(m, [&](MRMap3::Face f) { value<uint32>(m, ft, f) = next++; });
	foreach_cell(m, [&](MRMap3::Volume w) { value<uint32>(m, wt, w) = next++; });
	std::map<uint32, uint32> faces0, volumes0; // dart -> value
	foreach_cell(m, [&](MRMap3::Face f) { faces0[f.dart.index] = value<uint32>(m, ft, f); });
	foreach_cell(m, [&](MRMap3::Volume w) { volumes0[w.dart.index] = value<uint32>(m, wt, w); });
	add_level(m, Refinement::Hexahedral);
	ASSERT_TRUE(check_integrity(m).ok());
	const MRLevelView3 v0 = level_view(m, 0), v1 = level_view(m, 1);
	for (auto [d, x] : faces0)
	{
		EXPECT_EQ(value<uint32>(v0, ft, MRMap3::Face(Dart(d))), x);
		EXPECT_EQ(value<uint32>(v1, ft, MRMap3::Face(Dart(d))), x) << "a child copies its parent";
		EXPECT_NE(index_of(v1, MRMap3::Face(Dart(d))), index_of(v0, MRMap3::Face(Dart(d))));
	}
	for (auto [d, x] : volumes0)
		EXPECT_EQ(value<uint32>(v1, wt, MRMap3::Volume(Dart(d))), x);
	// children with a parent's value, inner cells with none: 11 faces of level
	// 0 give 44 children, each hexahedron 12 inner faces; 2 x 8 child volumes
	std::map<uint32, uint32> face_values, volume_values;
	foreach_cell(v1, [&](MRMap3::Face f) { ++face_values[value<uint32>(v1, ft, f)]; });
	foreach_cell(v1, [&](MRMap3::Volume w) { ++volume_values[value<uint32>(v1, wt, w)]; });
	EXPECT_EQ(face_values[0], 24u);
	EXPECT_EQ(face_values.size(), 12u);
	for (auto [x, n] : face_values)
	{
		if (x != 0)
		{
			EXPECT_EQ(n, 4u);
		}
	}
	EXPECT_EQ(volume_values.size(), 2u);
	for (auto [x, n] : volume_values)
		EXPECT_EQ(n, 8u);
	uint32 inner_edges = 0;
	foreach_cell(v1, [&](MRMap3::Edge e) { inner_edges += value<uint32>(v1, et, e) == 0; });
	EXPECT_EQ(inner_edges, f_vector(v1)[1] - 2 * f_vector(v0)[1]);
	// writing the children leaves the parents
	set_current_level(m, 1);
	foreach_cell(m, [&](MRMap3::Face f) { value<uint32>(m, ft, f) = 0; });
	for (auto [d, x] : faces0)
		EXPECT_EQ(value<uint32>(v0, ft, MRMap3::Face(Dart(d))), x);
	remove_finest_level(m);
	EXPECT_TRUE(check_integrity(m).ok());
	for (auto [d, x] : faces0)
		EXPECT_EQ(value<uint32>(m, ft, MRMap3::Face(Dart(d))), x);
}

TEST(MRMap3Attributes, OrbitsIndexedLateAndExtractedLevels)
{
	MRMap3 m(two_hexahedra());
	add_level(m, Refinement::Hexahedral);
	add_level(m, Refinement::Hexahedral);
	auto vv = add_attribute<double, MRMap3::Vertex>(m, "v");
	auto ev = add_attribute<double, MRMap3::Edge>(m, "e");
	auto fv = add_attribute<double, MRMap3::Face>(m, "f");
	auto wv = add_attribute<double, MRMap3::Volume>(m, "w");
	auto cv = add_attribute<double, MRMap3::CC>(m, "c");
	ASSERT_TRUE(vv && ev && fv && wv && cv);
	EXPECT_FALSE((add_attribute<double, MRMap3::Face>(m, "f")));
	EXPECT_FALSE((add_attribute<double, MRMap3::Face>(m, "__f")));
	ASSERT_TRUE(check_integrity(m).ok());
	double next = 0.5;
	for (uint32 l = 0; l <= 2; ++l)
	{
		set_current_level(m, l);
		foreach_cell(m, [&](MRMap3::Vertex v) { value<double>(m, vv, v) = next++; });
		foreach_cell(m, [&](MRMap3::Face f) { value<double>(m, fv, f) = next++; });
		foreach_cell(m, [&](MRMap3::Volume w) { value<double>(m, wv, w) = next++; });
	}
	for (uint32 l = 0; l <= 2; ++l)
	{
		const MRLevelView3 v = level_view(m, l);
		const CMap3 flat = extract_level(m, l);
		ASSERT_TRUE(check_integrity(flat).ok());
		std::vector<Dart> source;
		foreach_dart(v, [&](Dart d) { source.push_back(d); });
		const auto fvv = get_attribute<double, CMap3::Vertex>(flat, "v");
		const auto ffv = get_attribute<double, CMap3::Face>(flat, "f");
		const auto fwv = get_attribute<double, CMap3::Volume>(flat, "w");
		ASSERT_TRUE(fvv && ffv && fwv);
		foreach_cell(flat, [&](CMap3::Vertex x) {
			EXPECT_EQ((*fvv)[x], value<double>(v, vv, MRMap3::Vertex(source[x.dart.index])));
		});
		foreach_cell(flat, [&](CMap3::Face x) {
			EXPECT_EQ((*ffv)[x], value<double>(v, fv, MRMap3::Face(source[x.dart.index])));
		});
		foreach_cell(flat, [&](CMap3::Volume x) {
			EXPECT_EQ((*fwv)[x], value<double>(v, wv, MRMap3::Volume(source[x.dart.index])));
		});
	}
	EXPECT_TRUE(remove_attribute(m, fv));
	EXPECT_FALSE((get_attribute<double, MRMap3::Face>(m, "f")));
	remove_finest_level(m);
	EXPECT_TRUE(check_integrity(m).ok());
	add_level(m, Refinement::Hexahedral);
	EXPECT_TRUE(check_integrity(m).ok());
	// a marker of one level
	CellMarker<MRLevelView3, MRMap3::Volume> marked(level_view(m, 1));
	uint32 nb = 0;
	foreach_cell(level_view(m, 1), [&](MRMap3::Volume w) {
		if (nb++ % 2 == 0)
			marked.mark(w);
	});
	uint32 nb_marked = 0;
	foreach_cell(level_view(m, 1), [&](MRMap3::Volume w) {
		nb_marked += marked.is_marked(w);
		foreach_dart_of_orbit(level_view(m, 1), w,
							  [&](Dart d) { EXPECT_EQ(marked.is_marked(MRMap3::Volume(d)), marked.is_marked(w)); });
	});
	EXPECT_EQ(nb_marked, 8u);
}
