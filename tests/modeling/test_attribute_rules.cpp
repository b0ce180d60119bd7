// SPDX-License-Identifier: MIT
// Attributes that follow edits: the rule of each attribute (copy,
// interpolate, none, a callback) applied by every operator that creates
// cells, and by the algorithms built on them. Exact values on small cases,
// then randomized operator sequences with check_integrity after every step:
// new vertices' colours stay in the convex hull of the input colours (their
// bounding box here), every face's region is that of the input face it came
// from (checked against record_origins), untouched cells keep their values.
#include <cgogn/cgogn.h>

#include "../core/map_test_utils.h"
#include "../io/io_test_utils.h"
#include "modeling_test_utils.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <map>
#include <random>
#include <string>
#include <vector>

namespace cgogn_test_attribute_rules
{

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;
using Corner = CMap2::HalfEdge;

namespace
{

/// The first cell of type CELL (for which pred holds).
template <typename CELL, typename MAP, typename PRED>
CELL test_first(const MAP& m, const PRED& pred)
{
	return test::find<CELL>(m, pred);
}
template <typename CELL, typename MAP>
CELL test_first(const MAP& m)
{
	return test::find<CELL>(m, [](CELL) { return true; });
}

/// Builds a surface or volume soup into m; returns its "position" attribute.
template <typename MAP, typename SOUP>
std::shared_ptr<AttributeArray<Vec3>> build_positioned(MAP& m, const SOUP& s)
{
	io_test::build_with_positions(m, s);
	return get_attribute<Vec3, typename mesh_traits<MAP>::Vertex>(m, "position");
}

/// A torus with a colour per vertex (from its position), a region per face
/// (its line modulo 5, plus one) and the origin of every face recorded.
struct Tagged
{
	CMap2 m;
	std::shared_ptr<AttributeArray<Vec3>> pos, colour;
	std::shared_ptr<AttributeArray<int32>> region;
	std::shared_ptr<AttributeArray<uint32>> origin;
	std::vector<int32> input_region; // by input face line
	Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);

	explicit Tagged(const SurfaceSoup& s)
	{
		pos = build_positioned(m, s);
		colour = add_attribute<Vec3, Vertex>(m, "colour");
		region = add_attribute<int32, Face>(m, "region");
		foreach_cell(m, [&](Vertex v) {
			const Vec3 c = (value<Vec3>(m, pos, v) + Vec3(2, 2, 2)) / 4.0;
			value<Vec3>(m, colour, v) = c;
			lo = lo.cwiseMin(c);
			hi = hi.cwiseMax(c);
		});
		foreach_cell(m, [&](Face f) { value<int32>(m, region, f) = int32(index_of(m, f) % 5) + 1; });
		origin = record_origins<Face>(m);
		input_region.assign(container_of<Face::ORBIT>(m).end_index(), 0);
		foreach_cell(m, [&](Face f) { input_region[index_of(m, f)] = value<int32>(m, region, f); });
	}

	/// Colours in the input's box, regions those of the faces' origins.
	::testing::AssertionResult follows() const
	{
		const double eps = 1e-12;
		::testing::AssertionResult r = ::testing::AssertionSuccess();
		foreach_cell(m, [&](Vertex v) {
			const Vec3& c = value<Vec3>(m, colour, v);
			if ((c.array() < lo.array() - eps).any() || (c.array() > hi.array() + eps).any())
			{
				r = ::testing::AssertionFailure() << "vertex " << index_of(m, v) << " colour out of the input's hull";
				return false;
			}
			return true;
		});
		if (!r)
			return r;
		foreach_cell(m, [&](Face f) {
			const uint32 o = value<uint32>(m, origin, f);
			if (o == INVALID_INDEX)
				return true; // a face with no input face (a filled hole)
			if (o >= input_region.size() || value<int32>(m, region, f) != input_region[o])
			{
				r = ::testing::AssertionFailure()
					<< "face " << index_of(m, f) << " region " << value<int32>(m, region, f) << " is not its origin's";
				return false;
			}
			return true;
		});
		return r;
	}
};

} // namespace

TEST(AttributeRules, DefaultsFollowTheType)
{
	CMap2 m;
	build_surface(m, torus_soup(4, 3));
	EXPECT_EQ(attribute_rule(*add_attribute<int32, Face>(m, "a")), AttributeRule::Copy);
	EXPECT_EQ(attribute_rule(*add_attribute<bool, Face>(m, "b")), AttributeRule::Copy);
	EXPECT_EQ(attribute_rule(*add_attribute<std::string, Face>(m, "c")), AttributeRule::Copy);
	EXPECT_EQ(attribute_rule(*add_attribute<double, Vertex>(m, "d")), AttributeRule::Interpolate);
	EXPECT_EQ(attribute_rule(*add_attribute<Vec2, Corner>(m, "e")), AttributeRule::Interpolate);
	EXPECT_EQ(attribute_rule(*add_attribute<std::array<float, 4>, Vertex>(m, "f")), AttributeRule::Interpolate);
	EXPECT_EQ(attribute_rule(*add_attribute<std::vector<int>, Vertex>(m, "g")), AttributeRule::None);
}

TEST(AttributeRules, CutEdgeInterpolatesTheVertexAndCopiesTheEdge)
{
	CMap2 m;
	auto pos = build_positioned(m, torus_soup(4, 3, true));
	auto temp = add_attribute<double, Vertex>(m, "temperature");
	auto tag = add_attribute<int32, Vertex>(m, "tag");
	auto crease = add_attribute<uint8, Edge>(m, "crease");
	auto uv = add_attribute<Vec2, Corner>(m, "uv");
	auto none = add_attribute<double, Vertex>(m, "none");
	set_attribute_rule(m, none, AttributeRule::None);
	foreach_cell(m, [&](Vertex v) {
		value<double>(m, temp, v) = double(index_of(m, v));
		value<int32>(m, tag, v) = int32(index_of(m, v)) + 10;
		value<double>(m, none, v) = 7.0;
	});
	foreach_cell(m, [&](Edge e) { value<uint8>(m, crease, e) = uint8(1 + index_of(m, e) % 3); });
	foreach_dart(m, [&](Dart d) { (*uv)[d.index] = Vec2(d.index, 2.0 * d.index); });

	const Edge e = test_first<Edge>(m);
	const Dart d = e.dart, d2 = phi2(m, d), end = phi1(m, d), end2 = phi1(m, d2);
	const double ta = value<double>(m, temp, Vertex(d)), tb = value<double>(m, temp, Vertex(end));
	const int32 tag_a = value<int32>(m, tag, Vertex(d));
	const uint8 c = value<uint8>(m, crease, e);
	const Vec2 uv_d = (*uv)[d.index], uv_end = (*uv)[end.index], uv_d2 = (*uv)[d2.index], uv_end2 = (*uv)[end2.index];
	const Vertex v = cut_edge(m, e);
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_DOUBLE_EQ(value<double>(m, temp, v), 0.5 * (ta + tb));
	EXPECT_EQ(value<int32>(m, tag, v), tag_a); // copy: the first end
	EXPECT_EQ(value<double>(m, none, v), 0.0);
	EXPECT_EQ(value<uint8>(m, crease, Edge(d)), c);
	EXPECT_EQ(value<uint8>(m, crease, Edge(v.dart)), c);
	EXPECT_EQ((*uv)[phi1(m, d).index], 0.5 * (uv_d + uv_end));
	EXPECT_EQ((*uv)[phi1(m, d2).index], 0.5 * (uv_d2 + uv_end2));
}

TEST(AttributeRules, CutFaceAndTriangulateCopyTheFace)
{
	CMap2 m;
	build_positioned(m, torus_soup(4, 3));
	auto region = add_attribute<int32, Face>(m, "region");
	auto temp = add_attribute<double, Vertex>(m, "temperature");
	auto uv = add_attribute<double, Corner>(m, "u");
	foreach_cell(m, [&](Face f) { value<int32>(m, region, f) = 40 + int32(index_of(m, f)); });
	foreach_cell(m, [&](Vertex v) { value<double>(m, temp, v) = double(index_of(m, v)); });
	foreach_dart(m, [&](Dart d) { (*uv)[d.index] = double(d.index); });

	const Face f = test_first<Face>(m);
	const int32 r = value<int32>(m, region, f);
	const Dart a = f.dart, b = phi<1, 1>(m, f.dart);
	const double ua = (*uv)[a.index], ub = (*uv)[b.index];
	const Edge cut = cut_face(m, Vertex(a), Vertex(b));
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(value<int32>(m, region, Face(cut.dart)), r);
	EXPECT_EQ(value<int32>(m, region, Face(phi2(m, cut.dart))), r);
	EXPECT_EQ((*uv)[cut.dart.index], ua); // from a's origin, in the new face
	EXPECT_EQ((*uv)[phi2(m, cut.dart).index], ub);

	// a quad of the torus, triangulated: 4 triangles of its region, a centre
	// at the mean of its vertices' values, and centre corners at the mean of
	// its corners
	const Face q = test_first<Face>(m, [&](Face g) { return codegree(m, g) == 4; });
	const int32 rq = value<int32>(m, region, q);
	double mean = 0.0, corner_mean = 0.0;
	foreach_dart_of_orbit(m, q, [&](Dart x) {
		mean += value<double>(m, temp, Vertex(x)) / 4.0;
		corner_mean += (*uv)[x.index] / 4.0;
	});
	const Vertex c = triangulate_face(m, q);
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_DOUBLE_EQ(value<double>(m, temp, c), mean);
	uint32 n = 0;
	foreach_dart_of_orbit(m, c, [&](Dart x) {
		EXPECT_EQ(value<int32>(m, region, Face(x)), rq);
		EXPECT_DOUBLE_EQ((*uv)[x.index], corner_mean);
		++n;
	});
	EXPECT_EQ(n, 4u);
}

TEST(AttributeRules, CallbackGetsTheParentsAndWeights)
{
	CMap2 m;
	build_positioned(m, torus_soup(4, 3, true));
	auto level = add_attribute<int32, Vertex>(m, "level");
	foreach_cell(m, [&](Vertex v) { value<int32>(m, level, v) = int32(index_of(m, v)); });
	std::vector<double> seen;
	set_attribute_rule(m, level, [&](int32& out, std::span<const int32> parents, std::span<const double> w) {
		out = std::max(parents[0], parents[1]) + 1000;
		seen.assign(w.begin(), w.end());
	});
	const Edge e = test_first<Edge>(m);
	const int32 a = value<int32>(m, level, Vertex(e.dart)), b = value<int32>(m, level, Vertex(phi2(m, e.dart)));
	const Vertex v = cut_edge(m, e);
	EXPECT_EQ(value<int32>(m, level, v), std::max(a, b) + 1000);
	EXPECT_EQ(seen, (std::vector<double>{0.5, 0.5}));
	EXPECT_EQ(attribute_rule(*level), AttributeRule::Callback);
}

TEST(AttributeRules, SplitsAndMergesOfVolumes)
{
	CMap3 m;
	const BuildReport r = build_volume(m, hex_grid_soup(2, 1, 1));
	(void)r;
	auto temp = add_attribute<double, CMap3::Vertex>(m, "temperature");
	auto material = add_attribute<int32, CMap3::Volume>(m, "material");
	auto bc = add_attribute<int32, CMap3::Face>(m, "bc");
	foreach_cell(m, [&](CMap3::Vertex v) { value<double>(m, temp, v) = double(index_of(m, v)); });
	foreach_cell(m, [&](CMap3::Volume w) { value<int32>(m, material, w) = 3 + int32(index_of(m, w)); });
	foreach_cell(m, [&](CMap3::Face f) { value<int32>(m, bc, f) = 20 + int32(index_of(m, f)); });

	const CMap3::Edge e = test_first<CMap3::Edge>(m);
	const double ta = value<double>(m, temp, CMap3::Vertex(e.dart));
	const double tb = value<double>(m, temp, CMap3::Vertex(phi1(m, e.dart)));
	const CMap3::Vertex v = cut_edge(m, e);
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_DOUBLE_EQ(value<double>(m, temp, v), 0.5 * (ta + tb));

	// a face of 5 vertices now: cut it between v and a vertex two steps on
	const Dart d = v.dart;
	const int32 face_bc = value<int32>(m, bc, CMap3::Face(d));
	const CMap3::Edge cut = cut_face(m, d, phi<1, 1>(m, d));
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(value<int32>(m, bc, CMap3::Face(cut.dart)), face_bc);
	EXPECT_EQ(value<int32>(m, bc, CMap3::Face(phi2(m, cut.dart))), face_bc);

	// hexahedral subdivision: every child keeps its parent's material, new
	// vertices stay in the range of the old values
	CMap3 h;
	auto pos = build_positioned(h, hex_grid_soup(2, 1, 1));
	auto ht = add_attribute<double, CMap3::Vertex>(h, "temperature");
	auto hm = add_attribute<int32, CMap3::Volume>(h, "material");
	foreach_cell(h, [&](CMap3::Vertex x) { value<double>(h, ht, x) = value<Vec3>(h, pos, x).x(); });
	foreach_cell(h, [&](CMap3::Volume w) {
		Vec3 c = Vec3::Zero();
		foreach_incident_vertex(h, w, [&](CMap3::Vertex x) { c += value<Vec3>(h, pos, x) / 8.0; });
		value<int32>(h, hm, w) = c.x() < 1.0 ? 1 : 2;
	});
	modeling::hex_subdivision(h, *pos);
	ASSERT_TRUE(check_integrity(h).ok());
	EXPECT_EQ(nb_cells<CMap3::Volume>(h), 16u);
	foreach_cell(h, [&](CMap3::Vertex x) { EXPECT_DOUBLE_EQ(value<double>(h, ht, x), value<Vec3>(h, pos, x).x()); });
	foreach_cell(h, [&](CMap3::Volume w) {
		Vec3 c = Vec3::Zero();
		foreach_incident_vertex(h, w, [&](CMap3::Vertex x) { c += value<Vec3>(h, pos, x) / 8.0; });
		EXPECT_EQ(value<int32>(h, hm, w), c.x() < 1.0 ? 1 : 2);
	});

	// tetrahedra: split_tetra and tet subdivision
	CMap3 t;
	auto tpos = build_positioned(t, tet_grid_soup(1, 1, 1));
	auto tt = add_attribute<double, CMap3::Vertex>(t, "temperature");
	auto tm = add_attribute<int32, CMap3::Volume>(t, "material");
	foreach_cell(t, [&](CMap3::Vertex x) { value<double>(t, tt, x) = value<Vec3>(t, tpos, x).sum(); });
	foreach_cell(t, [&](CMap3::Volume w) { value<int32>(t, tm, w) = 100 + int32(index_of(t, w)); });
	const CMap3::Volume w0 = test_first<CMap3::Volume>(t);
	const int32 m0 = value<int32>(t, tm, w0);
	double mean = 0.0;
	foreach_incident_vertex(t, w0, [&](CMap3::Vertex x) { mean += value<double>(t, tt, x) / 4.0; });
	const CMap3::Vertex centre = split_tetra(t, w0);
	ASSERT_TRUE(check_integrity(t).ok());
	EXPECT_DOUBLE_EQ(value<double>(t, tt, centre), mean);
	foreach_incident_volume(t, centre, [&](CMap3::Volume w) { EXPECT_EQ(value<int32>(t, tm, w), m0); });
	// the positions interpolate too (their rule, outside an algorithm): the
	// field is still the sum of the coordinates at the centre
	EXPECT_NEAR(value<double>(t, tt, centre), value<Vec3>(t, tpos, centre).sum(), 1e-12);

	// tet subdivision of the split mesh: the 8 children of each tetrahedron
	// keep its material, the linear field stays linear (new vertices at edge
	// midpoints)
	std::map<int32, uint32> parents, children; // by material
	foreach_cell(t, [&](CMap3::Volume w) { ++parents[value<int32>(t, tm, w)]; });
	modeling::tet_subdivision(t, *tpos);
	ASSERT_TRUE(check_integrity(t).ok());
	foreach_cell(t,
				 [&](CMap3::Vertex x) { EXPECT_NEAR(value<double>(t, tt, x), value<Vec3>(t, tpos, x).sum(), 1e-12); });
	foreach_cell(t, [&](CMap3::Volume w) { ++children[value<int32>(t, tm, w)]; });
	EXPECT_EQ(children.size(), parents.size());
	for (const auto& [material, n] : parents)
		EXPECT_EQ(children[material], 8 * n) << "material " << material;
}

// Volume subdivision of a grid with a tag on every face and edge: each
// new face (edge) on an old one has its tag, and lies inside its box;
// faces and edges inside old faces or volumes have none (0).
template <typename SUBDIVIDE>
void expect_faces_and_edges_copied(CMap3& m, std::shared_ptr<AttributeArray<Vec3>> pos, const SUBDIVIDE& subdivide,
								   uint32 faces_inside_per_volume)
{
	using Box = Eigen::AlignedBox<double, 3>;
	auto bc = add_attribute<int32, CMap3::Face>(m, "bc");
	auto crease = add_attribute<int32, CMap3::Edge>(m, "crease");
	std::map<int32, Box> face_box, edge_box;
	foreach_cell(m, [&](CMap3::Face f) {
		const int32 tag = 1 + int32(index_of(m, f));
		value<int32>(m, bc, f) = tag;
		foreach_incident_vertex(m, f, [&](CMap3::Vertex v) { face_box[tag].extend(value<Vec3>(m, pos, v)); });
	});
	foreach_cell(m, [&](CMap3::Edge e) {
		const int32 tag = 1 + int32(index_of(m, e));
		value<int32>(m, crease, e) = tag;
		foreach_incident_vertex(m, e, [&](CMap3::Vertex v) { edge_box[tag].extend(value<Vec3>(m, pos, v)); });
	});
	const uint32 nb_volumes = nb_cells<CMap3::Volume>(m);
	subdivide(m, *pos);
	ASSERT_TRUE(check_integrity(m).ok());
	auto check = [&](auto cell, const std::shared_ptr<AttributeArray<int32>>& tag, std::map<int32, Box>& boxes,
					 uint32 children) {
		using CELL = decltype(cell);
		std::map<int32, uint32> count;
		uint32 outside = 0;
		foreach_cell(m, [&](CELL c) {
			const int32 t = value<int32>(m, tag, c);
			++count[t];
			if (t != 0)
				foreach_incident_vertex(m, c, [&](CMap3::Vertex v) {
					outside += boxes[t].exteriorDistance(value<Vec3>(m, pos, v)) > 1e-12;
				});
		});
		EXPECT_EQ(outside, 0u);
		for (const auto& [t, box] : boxes)
			EXPECT_EQ(count[t], children) << "tag " << t;
		return count[0];
	};
	EXPECT_EQ(check(CMap3::Face(), bc, face_box, 4), faces_inside_per_volume * nb_volumes);
	const uint32 edges_inside = check(CMap3::Edge(), crease, edge_box, 2);
	EXPECT_EQ(edges_inside + 2 * edge_box.size(), nb_cells<CMap3::Edge>(m));
}

TEST(AttributeRules, VolumeSubdivisionsCopyFacesAndEdgesOnOldOnes)
{
	{
		SCOPED_TRACE("hexahedra");
		CMap3 h;
		auto pos = build_positioned(h, hex_grid_soup(2, 2, 1));
		expect_faces_and_edges_copied(
			h, pos, [](CMap3& m, AttributeArray<Vec3>& p) { modeling::hex_subdivision(m, p); }, 12);
	}
	{
		SCOPED_TRACE("tetrahedra");
		CMap3 t;
		auto pos = build_positioned(t, tet_grid_soup(2, 1, 1));
		expect_faces_and_edges_copied(
			t, pos, [](CMap3& m, AttributeArray<Vec3>& p) { modeling::tet_subdivision(m, p); }, 8);
	}
}

TEST(AttributeRules, SubdivisionSchemesKeepRegionsAndColours)
{
	for (const modeling::SurfaceScheme scheme :
		 {modeling::SurfaceScheme::Loop, modeling::SurfaceScheme::CatmullClark, modeling::SurfaceScheme::Sqrt3})
	{
		Tagged t(torus_soup(6, 4, scheme != modeling::SurfaceScheme::CatmullClark));
		const uint32 before = nb_cells<Face>(t.m);
		modeling::subdivide(t.m, *t.pos, scheme, 2);
		ASSERT_TRUE(check_integrity(t.m).ok());
		EXPECT_GT(nb_cells<Face>(t.m), before);
		EXPECT_TRUE(t.follows()) << int(scheme);
		EXPECT_EQ(attribute_rule(*t.pos), AttributeRule::Interpolate); // given back after the algorithm
	}
}

TEST(AttributeRules, DecimationInterpolatesAtTheNewPosition)
{
	Tagged t(torus_soup(24, 16, true));
	modeling::DecimationOptions o;
	o.target_faces = 120;
	modeling::decimate(t.m, *t.pos, o);
	ASSERT_TRUE(check_integrity(t.m).ok());
	EXPECT_TRUE(t.follows());
	// the colour was a linear function of the position; the collapse puts
	// the kept vertex between the ends, so it stays one near the edge
	uint32 close = 0, n = 0;
	foreach_cell(t.m, [&](Vertex v) {
		const Vec3 expected = (value<Vec3>(t.m, t.pos, v) + Vec3(2, 2, 2)) / 4.0;
		close += (value<Vec3>(t.m, t.colour, v) - expected).norm() < 0.1;
		++n;
	});
	EXPECT_GT(close, n / 2);
}

TEST(AttributeRules, RemeshingAndHoleFillingKeepRegionsAndColours)
{
	Tagged t(torus_soup(16, 10, true));
	modeling::RemeshingOptions o;
	o.iterations = 3;
	modeling::isotropic_remeshing(t.m, *t.pos, o);
	ASSERT_TRUE(check_integrity(t.m).ok());
	EXPECT_TRUE(t.follows());

	Tagged h(torus_soup(16, 10, true));
	// open two holes, then fill them
	std::vector<Face> removed;
	foreach_cell(h.m, [&](Face f) {
		if (index_of(h.m, f) == 10 || index_of(h.m, f) == 90)
			removed.push_back(f);
	});
	for (Face f : removed)
		remove_face(h.m, f);
	modeling::fill_holes(h.m, *h.pos);
	ASSERT_TRUE(check_integrity(h.m).ok());
	EXPECT_TRUE(h.follows());
	uint32 unknown = 0;
	foreach_cell(h.m, [&](Face f) { unknown += value<uint32>(h.m, h.origin, f) == INVALID_INDEX; });
	EXPECT_GT(unknown, 0u); // the faces filling the holes come from no input face
}

TEST(AttributeRules, RandomizedOperatorsFollowTheRules)
{
	Tagged t(torus_soup(12, 8, true));
	auto crease = add_attribute<int32, Edge>(t.m, "crease");
	auto uv = add_attribute<Vec2, Corner>(t.m, "uv");
	foreach_cell(t.m, [&](Edge e) { value<int32>(t.m, crease, e) = 1; });
	Vec2 uv_lo(1e300, 1e300), uv_hi(-1e300, -1e300);
	foreach_dart(t.m, [&](Dart d) {
		(*uv)[d.index] = Vec2(value<Vec3>(t.m, t.pos, Vertex(d)).x(), double(d.index % 7));
		uv_lo = uv_lo.cwiseMin((*uv)[d.index]);
		uv_hi = uv_hi.cwiseMax((*uv)[d.index]);
	});
	std::mt19937 rng(5);
	uint32 applied = 0;
	for (uint32 step = 0; step < 3000; ++step)
	{
		const std::vector<Dart> darts = [&] {
			std::vector<Dart> v;
			foreach_dart(t.m, [&](Dart d) { v.push_back(d); });
			return v;
		}();
		const Dart d = darts[rng() % darts.size()];
		// lines alive before, with their values: untouched ones must keep them
		std::vector<std::pair<uint32, int32>> regions;
		foreach_cell(t.m, [&](Face f) { regions.emplace_back(index_of(t.m, f), value<int32>(t.m, t.region, f)); });
		switch (rng() % 7)
		{
		case 0:
			cut_edge(t.m, Edge(d));
			break;
		case 1: {
			const Dart e = phi<1, 1>(t.m, d);
			if (!can_cut_face(t.m, Vertex(d), Vertex(e)))
				continue;
			cut_face(t.m, Vertex(d), Vertex(e));
			break;
		}
		case 2:
			if (is_boundary(t.m, d))
				continue;
			triangulate_face(t.m, Face(d));
			break;
		case 3:
			if (!can_flip_edge(t.m, Edge(d)))
				continue;
			flip_edge(t.m, Edge(d));
			break;
		case 4:
			if (!can_collapse_edge(t.m, Edge(d)) || nb_cells<Vertex>(t.m) < 60)
				continue;
			collapse_edge(t.m, Edge(d));
			break;
		case 5:
			if (!can_merge_incident_faces(t.m, Edge(d)))
				continue;
			merge_incident_faces(t.m, Edge(d));
			break;
		default: {
			const Dart d2 = phi<2, 1>(t.m, phi<2, 1>(t.m, d));
			if (!can_split_vertex(t.m, d, d2))
				continue;
			split_vertex(t.m, d, d2);
			break;
		}
		}
		++applied;
		const IntegrityReport report = check_integrity(t.m);
		ASSERT_TRUE(report.ok()) << "step " << step << "\n" << report.to_string();
		ASSERT_TRUE(t.follows()) << "step " << step;
		foreach_cell(t.m, [&](Edge e) {
			// every edge is an input edge, a part of one, or new inside a face
			const int32 c = value<int32>(t.m, crease, e);
			EXPECT_TRUE(c == 0 || c == 1);
		});
		bool uv_ok = true;
		foreach_dart(t.m, [&](Dart x) {
			if (!is_boundary(t.m, x))
				uv_ok = uv_ok && ((*uv)[x.index].array() >= uv_lo.array() - 1e-12).all() &&
						((*uv)[x.index].array() <= uv_hi.array() + 1e-12).all();
		});
		ASSERT_TRUE(uv_ok) << "step " << step;
		// a face that kept its line and its region: merges keep the surviving
		// face's value
		const AttributeContainer& fc = container_of<Face::ORBIT>(t.m);
		for (const auto& [line, r] : regions)
		{
			if (fc.is_live(line))
			{
				ASSERT_EQ((*t.region)[line], r) << "step " << step;
			}
		}
	}
	EXPECT_GT(applied, 1500u);
}

TEST(AttributeRules, GMapOperatorsFollowTheRules)
{
	GMap2 m;
	const SurfaceSoup s = torus_soup(5, 4);
	const BuildReport r = build_surface(m, s);
	auto temp = add_attribute<double, GMap2::Vertex>(m, "temperature");
	auto region = add_attribute<int32, GMap2::Face>(m, "region");
	auto crease = add_attribute<int32, GMap2::Edge>(m, "crease");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*temp)[r.vertex_offset + i] = s.positions[i][0];
	foreach_cell(m, [&](GMap2::Face f) { value<int32>(m, region, f) = 7 + int32(index_of(m, f)); });
	foreach_cell(m, [&](GMap2::Edge e) { value<int32>(m, crease, e) = 3; });
	const GMap2::Edge e = test_first<GMap2::Edge>(m);
	const double ta = value<double>(m, temp, GMap2::Vertex(e.dart));
	const double tb = value<double>(m, temp, GMap2::Vertex(beta0(m, e.dart)));
	const GMap2::Vertex v = cut_edge(m, e);
	ASSERT_TRUE(check_integrity(m).ok());
	EXPECT_DOUBLE_EQ(value<double>(m, temp, v), 0.5 * (ta + tb));
	foreach_dart_of_orbit(m, v, [&](Dart d) { EXPECT_EQ(value<int32>(m, crease, GMap2::Edge(d)), 3); });

	const GMap2::Face f = test_first<GMap2::Face>(m, [&](GMap2::Face g) { return codegree(m, g) == 4; });
	const int32 rf = value<int32>(m, region, f);
	const GMap2::Vertex c = triangulate_face(m, f);
	ASSERT_TRUE(check_integrity(m).ok());
	foreach_dart_of_orbit(m, c, [&](Dart d) { EXPECT_EQ(value<int32>(m, region, GMap2::Face(d)), rf); });

	{
		GMap2 g;
		auto pos = build_positioned(g, torus_soup(6, 4, true));
		auto gr = add_attribute<int32, GMap2::Face>(g, "region");
		foreach_cell(g, [&](GMap2::Face x) { value<int32>(g, gr, x) = 1 + int32(index_of(g, x) % 3); });
		auto origin = record_origins<GMap2::Face>(g);
		std::vector<int32> input(container_of<GMap2::Face::ORBIT>(g).end_index());
		foreach_cell(g, [&](GMap2::Face x) { input[index_of(g, x)] = value<int32>(g, gr, x); });
		modeling::subdivide(g, *pos, modeling::SurfaceScheme::Loop, 1);
		ASSERT_TRUE(check_integrity(g).ok());
		foreach_cell(g, [&](GMap2::Face x) { EXPECT_EQ(value<int32>(g, gr, x), input[value<uint32>(g, origin, x)]); });
	}
}

} // namespace cgogn_test_attribute_rules
