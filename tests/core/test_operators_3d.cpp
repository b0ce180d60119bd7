#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <random>

namespace cgogn_test_operators_3d
{

using namespace cgogn;
using Vertex = CMap3::Vertex;
using Edge = CMap3::Edge;
using Face = CMap3::Face;
using Volume = CMap3::Volume;

using test::Counts;
using test::counts;
using test::index_everything;

namespace
{
using test::all;
using test::find;
using test::indexed;
} // namespace

TEST(Operators3, AddVolumes)
{
	CMap3 m;
	add_tetra(m);
	add_pyramid(m, 5);
	add_prism(m, 6);
	add_hexa(m);
	index_everything(m);
	EXPECT_EQ(counts(m), (Counts{4 + 6 + 12 + 8, 6 + 10 + 18 + 12, 4 + 6 + 8 + 6, 4}));
	EXPECT_EQ(nb_boundary_components(m), 4u);
	EXPECT_INTEGRITY(m);
	CMap3 t; // indices given as they are created
	index_everything(t);
	add_hexa(t);
	EXPECT_EQ(counts(t), (Counts{8, 12, 6, 1}));
	EXPECT_INTEGRITY(t);
}

TEST(Operators3, SewVolumes)
{
	CMap3 m;
	index_everything(m);
	Volume a = add_tetra(m);
	Volume b = add_tetra(m);
	ASSERT_TRUE(can_sew_volumes(m, Face(a.dart), Face(b.dart)));
	sew_volumes(m, Face(a.dart), Face(b.dart));
	EXPECT_EQ(counts(m), (Counts{5, 9, 7, 2}));
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_EQ(nb_connected_components(m), 1u);
	EXPECT_INTEGRITY(m);
	// a third tet on a face sharing an edge with the first glue: the boundary folds
	Volume c = add_tetra(m);
	Face f = find<Face>(m, [&](Face x) {
		const Dart inside = is_boundary(m, x.dart) ? phi3(m, x.dart) : x.dart;
		return is_incident_to_boundary(m, x) && !same_orbit(m, Volume(inside), c);
	});
	ASSERT_TRUE(f.is_valid());
	if (is_boundary(m, f.dart))
		f = Face(phi3(m, f.dart)); // the dart on the volume's side
	ASSERT_TRUE(can_sew_volumes(m, f, Face(c.dart)));
	sew_volumes(m, f, Face(c.dart));
	EXPECT_EQ(nb_cells<Volume>(m), 3u);
	EXPECT_INTEGRITY(m);
}

TEST(Operators3, CloseAfterLowLevelUnsew)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(3, 3, 3));
	// a face of the centre hex: all its edges are interior, so the slit is a closed pocket
	Face inner = find<Face>(m, [&](Face f) {
		bool interior = degree(m, f) == 2;
		foreach_incident_edge(m, f, [&](Edge e) { interior = interior && !is_incident_to_boundary(m, e); });
		return interior;
	});
	ASSERT_TRUE(inner.is_valid());
	std::vector<Dart> face;
	foreach_dart_of_orbit(m, CMap3::Face2(inner.dart), [&](Dart d) { face.push_back(d); });
	for (Dart d : face)
		phi3_unsew(m, d);
	EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::PhiFixedPoint));
	EXPECT_EQ(close(m), 1u);
	EXPECT_EQ(nb_boundary_components(m), 2u);
	EXPECT_INTEGRITY(m); // only vertices are indexed: they are unchanged
}

TEST(Operators3, UnsewAndSewVolumesBack)
{
	CMap3 m = indexed(hex_grid_soup(3, 3, 3));
	const Counts before = counts(m);
	// an inner face with interior edges: the slit is a closed pocket
	Face f = find<Face>(m, [&](Face x) {
		bool interior = degree(m, x) == 2;
		foreach_incident_edge(m, x, [&](Edge e) { interior = interior && !is_incident_to_boundary(m, e); });
		return interior;
	});
	ASSERT_TRUE(f.is_valid());
	const Dart a = f.dart, b = phi3(m, f.dart);
	unsew_volumes(m, f);
	EXPECT_EQ(counts(m), (Counts{before.v, before.e, before.f + 1, before.w}));
	EXPECT_EQ(nb_boundary_components(m), 2u);
	EXPECT_INTEGRITY(m);
	sew_volumes(m, Face(a), Face(b));
	EXPECT_EQ(counts(m), before);
	EXPECT_EQ(nb_boundary_components(m), 1u);
	EXPECT_INTEGRITY(m);
	// two hexes sharing a face whose edges are on the boundary come apart
	CMap3 two = indexed(hex_grid_soup(2, 1, 1));
	Face mid = find<Face>(two, [&](Face x) { return degree(two, x) == 2; });
	unsew_volumes(two, mid);
	EXPECT_EQ(counts(two), (Counts{16, 24, 12, 2}));
	EXPECT_EQ(nb_connected_components(two), 2u);
	EXPECT_INTEGRITY(two);
}

TEST(Operators3, CloseOneHole)
{
	CMap3 m;
	build_volume(m, hex_grid_soup(3, 3, 3));
	Face inner = find<Face>(m, [&](Face f) {
		bool interior = degree(m, f) == 2;
		foreach_incident_edge(m, f, [&](Edge e) { interior = interior && !is_incident_to_boundary(m, e); });
		return interior;
	});
	std::vector<Dart> face;
	foreach_dart_of_orbit(m, CMap3::Face2(inner.dart), [&](Dart d) { face.push_back(d); });
	for (Dart d : face)
		phi3_unsew(m, d);
	close_hole(m, face[0]);
	EXPECT_INTEGRITY(m);
	EXPECT_EQ(nb_boundary_components(m), 2u);
}

TEST(Operators3, RemoveVolume)
{
	CMap3 m = indexed(tet_grid_soup(1, 1, 1));
	const Counts before = counts(m);
	// a tet with a face on the outside and its neighbours
	Volume w = all<Volume>(m)[0];
	remove_volume(m, w);
	EXPECT_EQ(nb_cells<Volume>(m), before.w - 1);
	EXPECT_EQ(counts(m).euler(), 1);
	EXPECT_INTEGRITY(m);
	for (Volume x : all<Volume>(m))
	{
		remove_volume(m, x);
		EXPECT_INTEGRITY(m);
	}
	EXPECT_EQ(nb_darts(m), 0u);
	EXPECT_EQ(counts(m), (Counts{0, 0, 0, 0}));
}

TEST(Operators3, CutEdgeAndFace)
{
	CMap3 m = indexed(hex_grid_soup(2, 2, 2));
	const Counts before = counts(m);
	Edge e = find<Edge>(m, [&](Edge x) { return degree(m, x) == 4; });
	Vertex v = cut_edge(m, e);
	EXPECT_EQ(degree(m, v), 2u);
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 1, before.f, before.w}));
	EXPECT_INTEGRITY(m);
	// cut an inner face along a diagonal, then merge it back
	Face f = find<Face>(m, [&](Face x) { return degree(m, x) == 2 && codegree(m, x) == 4; });
	const Dart d = f.dart, e2 = phi<1, 1>(m, f.dart);
	ASSERT_TRUE(can_cut_face(m, d, e2));
	Edge diag = cut_face(m, d, e2);
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 2, before.f + 1, before.w}));
	EXPECT_INTEGRITY(m);
	ASSERT_TRUE(can_merge_incident_faces(m, diag));
	merge_incident_faces(m, diag);
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 1, before.f, before.w}));
	EXPECT_INTEGRITY(m);
}

TEST(Operators3, CutVolumeAlongAFace)
{
	CMap3 m = indexed(tet_grid_soup(1, 1, 1));
	const Counts before = counts(m);
	Volume w = all<Volume>(m)[2];
	std::vector<Dart> path;
	foreach_dart_of_orbit(m, CMap3::Face2(w.dart), [&](Dart d) { path.push_back(d); });
	Face nf = cut_volume(m, path);
	EXPECT_EQ(codegree(m, nf), 3u);
	EXPECT_EQ(counts(m), (Counts{before.v, before.e, before.f + 1, before.w + 1}));
	EXPECT_INTEGRITY(m);
	// and merged back
	ASSERT_TRUE(can_merge_incident_volumes(m, nf));
	merge_incident_volumes(m, nf);
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
}

TEST(Operators3, MergeIncidentVolumes)
{
	CMap3 m = indexed(hex_grid_soup(2, 1, 1));
	Face inner = find<Face>(m, [&](Face f) { return degree(m, f) == 2; });
	const uint32 line = index_of(m, Volume(inner.dart));
	Volume w = merge_incident_volumes(m, inner);
	EXPECT_EQ(index_of(m, w), line);
	EXPECT_EQ(counts(m), (Counts{12, 20, 10, 1}));
	EXPECT_EQ(codegree(m, w), 10u);
	EXPECT_INTEGRITY(m);
}

TEST(Operators3, SplitTetra)
{
	CMap3 m = indexed(tet_grid_soup(1, 1, 1));
	const Counts before = counts(m);
	Vertex c = split_tetra(m, all<Volume>(m)[0]);
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 4, before.f + 6, before.w + 3}));
	uint32 around = 0;
	foreach_incident_volume(m, c, [&](Volume) { ++around; });
	EXPECT_EQ(around, 4u);
	EXPECT_INTEGRITY(m);
}

TEST(Operators3, SplitEveryTetThenCollapseRestores)
{
	CMap3 m = indexed(tet_grid_soup(2, 2, 1));
	const Counts before = counts(m);
	std::vector<Vertex> centres;
	for (Volume w : all<Volume>(m))
		centres.push_back(split_tetra(m, w));
	EXPECT_EQ(counts(m).v, before.v + before.w);
	EXPECT_EQ(counts(m).w, 4 * before.w);
	EXPECT_EQ(counts(m).euler(), 1);
	EXPECT_INTEGRITY(m);
	for (Vertex c : centres)
	{
		Edge e(c.dart); // leaves the centre: the centre disappears
		ASSERT_TRUE(can_collapse_edge(m, e));
		collapse_edge(m, e);
	}
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
}

TEST(Operators3, CollapseInteriorEdgeAndLinkCondition)
{
	CMap3 m = indexed(tet_grid_soup(3, 3, 3));
	const Counts before = counts(m);
	// an edge between two interior vertices
	Edge e = find<Edge>(m, [&](Edge x) {
		return !is_incident_to_boundary(m, Vertex(x.dart)) && !is_incident_to_boundary(m, Vertex(phi1(m, x.dart)));
	});
	ASSERT_TRUE(e.is_valid());
	ASSERT_TRUE(can_collapse_edge(m, e));
	const uint32 k = degree(m, e); // tets around the edge
	collapse_edge(m, e);
	EXPECT_EQ(counts(m).v, before.v - 1);
	EXPECT_EQ(counts(m).w, before.w - k);
	EXPECT_EQ(counts(m).euler(), 1);
	EXPECT_INTEGRITY(m);
	// an interior edge joining two boundary vertices would pinch the boundary
	uint32 refused = 0;
	foreach_cell(m, [&](Edge x) {
		if (!is_incident_to_boundary(m, x) && is_incident_to_boundary(m, Vertex(x.dart)) &&
			is_incident_to_boundary(m, Vertex(phi1(m, x.dart))))
		{
			EXPECT_FALSE(can_collapse_edge(m, x));
			++refused;
		}
	});
	EXPECT_GT(refused, 0u);
}

TEST(Operators3, Flips)
{
	CMap3 m = indexed(tet_grid_soup(2, 2, 2));
	const Counts before = counts(m);
	Face f = find<Face>(m, [&](Face x) { return can_flip_face(m, x); });
	ASSERT_TRUE(f.is_valid());
	Edge e = flip_face(m, f);
	EXPECT_EQ(degree(m, e), 3u);
	EXPECT_EQ(counts(m), (Counts{before.v, before.e + 1, before.f + 2, before.w + 1}));
	EXPECT_INTEGRITY(m);
	ASSERT_TRUE(can_flip_edge(m, e));
	flip_edge(m, e); // 3-2 back
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
	// a 4-4 flip
	Edge e4 = find<Edge>(m, [&](Edge x) { return degree(m, x) == 4 && can_flip_edge(m, x); });
	ASSERT_TRUE(e4.is_valid());
	flip_edge(m, e4);
	EXPECT_EQ(counts(m), before);
	EXPECT_INTEGRITY(m);
}

TEST(Operators3, PureTopology)
{
	CMap3 m;
	Volume a = add_tetra(m, false);
	Volume b = add_tetra(m, false);
	sew_volumes(m, Face(a.dart), Face(b.dart), false);
	ASSERT_TRUE(can_flip_face(m, Face(a.dart)));
	Edge e = flip_face(m, Face(a.dart), false);
	split_tetra(m, Volume(e.dart), false);
	cut_edge(m, e, false);
	EXPECT_TRUE(check_integrity(m).ok()); // nothing indexed: relations only
	EXPECT_EQ(nb_cells<Volume>(m), 6u);
}

TEST(Operators3Random, TetrahedralEditing)
{
	CMap3 m = indexed(tet_grid_soup(2, 2, 1));
	auto tag = get_attribute<uint32, Vertex>(m, "vtag");
	uint32 next_tag = 1;
	foreach_cell(m, [&](Vertex v) { value<uint32>(m, tag, v) = next_tag++; });
	std::mt19937 rng(7);
	auto pick = [&](const auto& v) { return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)]; };
	uint32 applied = 0;
	for (uint32 step = 0; step < 400; ++step)
	{
		std::vector<std::pair<uint32, uint32>> values;
		foreach_cell(m, [&](Vertex v) { values.emplace_back(index_of(m, v), value<uint32>(m, tag, v)); });
		const int op = std::uniform_int_distribution<int>(0, 3)(rng);
		bool done = false;
		if (op == 0 && nb_cells<Volume>(m) < 400)
		{
			split_tetra(m, pick(all<Volume>(m)));
			done = true;
		}
		else if (op == 1)
		{
			Edge e = pick(all<Edge>(m));
			if ((done = can_collapse_edge(m, e)))
				collapse_edge(m, e);
		}
		else if (op == 2)
		{
			Face f = pick(all<Face>(m));
			if ((done = can_flip_face(m, f)))
				flip_face(m, f);
		}
		else if (op == 3)
		{
			Edge e = pick(all<Edge>(m));
			if ((done = can_flip_edge(m, e)))
				flip_edge(m, e);
		}
		applied += done;
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << "step " << step << " op " << op << "\n" << r.to_string();
		ASSERT_EQ(counts(m).euler(), 1) << "step " << step << " op " << op;
		const AttributeContainer& vc = container_of<Orbit::PHI21_PHI31>(m);
		for (auto [line, val] : values)
		{
			if (vc.is_live(line))
			{
				ASSERT_TRUE((*tag)[line] == val || (*tag)[line] == 0) << "step " << step;
			}
		}
		foreach_cell(m, [&](Vertex v) {
			uint32& t = value<uint32>(m, tag, v);
			if (t == 0)
				t = next_tag++;
		});
	}
	EXPECT_GT(applied, 100u);
}

} // namespace cgogn_test_operators_3d
