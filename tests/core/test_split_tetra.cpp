// The direct 1-to-4 split of a tetrahedron: exact counts, integrity after
// every split, indices of every orbit, volumes conserved, and the same mesh as
// the generic cavity re-tetrahedralization it replaced.
#include <cgogn/cgogn.h>

#include "../../src/core/cmap3_cavity.h"
#include "cgogn_test_data.h"
#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <numeric>
#include <random>

namespace cgogn_test_split_tetra
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
// a map of the soup with its positions
CMap3 build(const VolumeSoup& s)
{
	CMap3 m;
	const BuildReport r = build_volume(m, s);
	auto pos = add_attribute<Vec3, Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return m;
}

// the four corner positions of tet w, sorted: a tet's identity in a mesh
using Corners = std::array<std::array<double, 3>, 4>;
Corners corners(const CMap3& m, const AttributeArray<Vec3>& pos, Volume w)
{
	Corners c;
	uint32 k = 0;
	foreach_incident_vertex(m, w, [&](Vertex v) {
		const Vec3& p = value<Vec3>(m, pos, v);
		c[k++] = {p[0], p[1], p[2]};
	});
	EXPECT_EQ(k, 4u);
	std::sort(c.begin(), c.end());
	return c;
}

// the barycenter, summed in sorted corner order so that two maps of the same
// mesh get bit-identical centres whatever their dart order
Vec3 barycenter(const CMap3& m, const AttributeArray<Vec3>& pos, Volume w)
{
	Vec3 b = Vec3::Zero();
	for (const auto& p : corners(m, pos, w))
		b += Vec3(p[0], p[1], p[2]);
	return b / 4.0;
}

std::vector<Corners> all_tets(const CMap3& m, const AttributeArray<Vec3>& pos)
{
	std::vector<Corners> t;
	foreach_cell(m, [&](Volume w) { t.push_back(corners(m, pos, w)); });
	std::sort(t.begin(), t.end());
	return t;
}

// the split as it was done before the direct operator: the cavity of one tet
// re-filled by four tets around a new vertex
Vertex split_by_cavity(CMap3& m, Volume w)
{
	detail::Cavity cavity(m, {w.dart});
	const auto [p, q, r, s] = cavity.tetra_labels(w.dart);
	const uint32 c = cavity.new_vertex();
	cavity.fill({{c, q, r, s}, {p, c, r, s}, {p, q, c, s}, {p, q, r, c}}, true);
	return Vertex(cavity.vertex_dart(c));
}

// Splits tet w at its barycenter and checks everything local to the split:
// counts, integrity, the returned vertex, the lines kept by the old cells,
// the four volumes adding up to the old one.
Vertex split_and_check(CMap3& m, AttributeArray<Vec3>& pos, Volume w)
{
	const Counts before = counts(m);
	const Vec3 centre = barycenter(m, pos, w);
	const double volume = geometry::volume(m, w, pos);
	const Dart d = w.dart;
	const uint32 origin_line = index_of(m, Vertex(d));
	const bool volumes_indexed = is_indexed<Volume>(m), faces_indexed = is_indexed<Face>(m);
	const uint32 volume_line = volumes_indexed ? index_of(m, w) : INVALID_INDEX;
	const uint32 face_line = faces_indexed ? index_of(m, Face(d)) : INVALID_INDEX;

	const Vertex c = split_tetra(m, w);
	value<Vec3>(m, pos, c) = centre;

	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.ok()) << r.to_string();
	EXPECT_EQ(counts(m), (Counts{before.v + 1, before.e + 4, before.f + 6, before.w + 3}));
	// the returned dart leaves the centre towards the origin of w, in the tet of w
	EXPECT_EQ(index_of(m, Vertex(phi1(m, c.dart))), origin_line);
	EXPECT_EQ(index_of(m, Vertex(d)), origin_line);
	EXPECT_EQ(phi1(m, phi1(m, phi1(m, c.dart))), c.dart);
	bool in_tet_of_w = false;
	foreach_dart_of_orbit(m, Volume(d), [&](Dart x) { return !(in_tet_of_w = x == c.dart); });
	EXPECT_TRUE(in_tet_of_w);
	if (volumes_indexed)
	{
		EXPECT_EQ(index_of(m, Volume(d)), volume_line);
	}
	if (faces_indexed)
	{
		EXPECT_EQ(index_of(m, Face(d)), face_line); // an outer face of the split tet
	}
	uint32 around = 0;
	double sum = 0.0;
	foreach_incident_volume(m, c, [&](Volume x) {
		++around;
		const double v = geometry::volume(m, x, pos);
		EXPECT_GT(v, 0.0);
		sum += v;
	});
	EXPECT_EQ(around, 4u);
	EXPECT_NEAR(sum, volume, 1e-12 * std::abs(volume));
	return c;
}

} // namespace

TEST(SplitTetra, SingleTet)
{
	VolumeSoup s{4, {4}, {0, 1, 2, 3}, {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
	CMap3 m = build(s);
	index_everything(m);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	Volume w;
	foreach_cell(m, [&](Volume x) { w = x; });
	split_and_check(m, *pos, w);
	EXPECT_EQ(counts(m), (Counts{5, 10, 10, 4}));
	EXPECT_EQ(nb_cells<CMap3::Face2>(m), 16u);
	EXPECT_EQ(nb_cells<CMap3::Edge2>(m), 4u * 6u); // the boundary volume's cells have no index
	EXPECT_EQ(nb_cells<CMap3::Vertex2>(m), 4u * 4u);
	EXPECT_EQ(nb_cells<CMap3::CC>(m), 1u);
	EXPECT_NEAR(geometry::solid_volume(m, *pos), 1.0 / 6.0, 1e-15);
}

TEST(SplitTetra, PureTopology)
{
	CMap3 m;
	const Volume w = add_tetra(m, false);
	const Vertex c = split_tetra(m, w, false);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(counts(m), (Counts{5, 10, 10, 4}));
	uint32 around = 0;
	foreach_incident_volume(m, c, [&](Volume) { ++around; });
	EXPECT_EQ(around, 4u);
	// indexing afterwards gives the same counts
	index_everything(m);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(counts(m), (Counts{5, 10, 10, 4}));
}

TEST(SplitTetra, RefusesOtherVolumes)
{
	CMap3 m = build(hex_grid_soup(1, 1, 1));
	Volume hex;
	foreach_cell(m, [&](Volume w) { hex = w; });
	const uint32 darts = nb_darts(m);
	EXPECT_THROW(split_tetra(m, hex), TopologyError);
	// the boundary volume of a single tet is made of four triangles too
	CMap3 t;
	const Volume w = add_tetra(t);
	const Volume outside(phi3(t, w.dart));
	EXPECT_THROW(split_tetra(t, outside), TopologyError);
	// a triangular bipyramid: six triangles
	CMap3 b = build(tet_grid_soup(1, 1, 1));
	Face inner;
	foreach_cell(b, [&](Face f) {
		if (!is_boundary(b, phi3(b, f.dart)) && !is_boundary(b, f.dart))
			inner = f;
	});
	const Volume bipyramid = merge_incident_volumes(b, inner);
	EXPECT_THROW(split_tetra(b, bipyramid), TopologyError);
	EXPECT_EQ(nb_darts(m), darts);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_darts(t), 24u);
	EXPECT_TRUE(check_integrity(t).ok());
	EXPECT_TRUE(check_integrity(b).ok());
}

TEST(SplitTetra, EveryTetOfAGridSameAsCavity)
{
	const VolumeSoup s = tet_grid_soup(3, 2, 2);
	CMap3 m = build(s), ref = build(s);
	index_everything(m);
	index_everything(ref);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	auto ref_pos = get_attribute<Vec3, Vertex>(ref, "position");
	const Counts before = counts(m);
	std::vector<Volume> tets, ref_tets;
	foreach_cell(m, [&](Volume w) { tets.push_back(w); });
	foreach_cell(ref, [&](Volume w) { ref_tets.push_back(w); });
	ASSERT_EQ(tets.size(), 72u);
	for (std::size_t k = 0; k < tets.size(); ++k)
	{
		split_and_check(m, *pos, tets[k]);
		const Vec3 b = barycenter(ref, *ref_pos, ref_tets[k]);
		value<Vec3>(ref, ref_pos, split_by_cavity(ref, ref_tets[k])) = b;
		ASSERT_FALSE(HasFatalFailure()) << "tet " << k;
	}
	const uint32 t = before.w;
	const Counts after = counts(m);
	EXPECT_EQ(after, (Counts{before.v + t, before.e + 4 * t, before.f + 6 * t, 4 * t}));
	EXPECT_EQ(after.euler(), 1);
	EXPECT_EQ(after, counts(ref));
	EXPECT_TRUE(check_integrity(ref).ok());
	EXPECT_EQ(all_tets(m, *pos), all_tets(ref, *ref_pos));
	EXPECT_NEAR(geometry::solid_volume(m, *pos), 12.0, 1e-12);
}

// Splits of tets made by earlier splits: their lines and representatives come
// from the operator itself.
TEST(SplitTetra, RepeatedSplitsOfRandomTets)
{
	CMap3 m = build(tet_grid_soup(2, 2, 1));
	index_everything(m);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	std::mt19937 rng(2024);
	Vertex last;
	for (uint32 step = 0; step < 150; ++step)
	{
		std::vector<Volume> tets;
		foreach_cell(m, [&](Volume w) { tets.push_back(w); });
		// every other step a tet of the last split (around its centre)
		const Volume w = step % 2 == 1 ? Volume(phi<2, 3>(m, last.dart))
									   : tets[std::uniform_int_distribution<std::size_t>(0, tets.size() - 1)(rng)];
		last = split_and_check(m, *pos, w);
		ASSERT_FALSE(HasFatalFailure()) << "step " << step;
	}
	EXPECT_EQ(counts(m).w, 24u + 3u * 150u);
	EXPECT_EQ(counts(m).euler(), 1);
	EXPECT_NEAR(geometry::solid_volume(m, *pos), 4.0, 1e-12);
}

TEST(SplitTetra, RealMeshRandomSubsetSameAsCavity)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "volume/elephant_tet_8k.mesh");
	CMap3 m, ref;
	io::load_volume(m, path);
	io::load_volume(ref, path);
	add_attribute<uint32, Volume>(m, "wtag"); // vertices (positions) and volumes indexed
	add_attribute<uint32, Volume>(ref, "wtag");
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	auto ref_pos = get_attribute<Vec3, Vertex>(ref, "position");
	const Counts before = counts(m);
	const int64 chi = before.euler();
	const double solid = geometry::solid_volume(m, *pos);
	std::vector<Volume> tets, ref_tets;
	foreach_cell(m, [&](Volume w) { tets.push_back(w); });
	foreach_cell(ref, [&](Volume w) { ref_tets.push_back(w); });
	ASSERT_EQ(tets.size(), 8284u);
	std::vector<std::size_t> order(tets.size());
	std::iota(order.begin(), order.end(), 0);
	std::shuffle(order.begin(), order.end(), std::mt19937(11));
	const uint32 n = 300;
	for (uint32 k = 0; k < n; ++k)
	{
		split_and_check(m, *pos, tets[order[k]]);
		const Vec3 b = barycenter(ref, *ref_pos, ref_tets[order[k]]);
		value<Vec3>(ref, ref_pos, split_by_cavity(ref, ref_tets[order[k]])) = b;
		ASSERT_FALSE(HasFatalFailure()) << "split " << k;
	}
	EXPECT_EQ(counts(m), (Counts{before.v + n, before.e + 4 * n, before.f + 6 * n, before.w + 3 * n}));
	EXPECT_EQ(counts(m).euler(), chi);
	EXPECT_EQ(counts(m), counts(ref));
	EXPECT_TRUE(check_integrity(ref).ok());
	EXPECT_EQ(all_tets(m, *pos), all_tets(ref, *ref_pos));
	EXPECT_NEAR(geometry::solid_volume(m, *pos), solid, 1e-9 * solid);
}

// Every tet of a real mesh, vertices indexed only (as in the benchmark).
TEST(SplitTetra, RealMeshEveryTet)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "volume/armadillo_tet_4k.mesh");
	CMap3 m;
	io::load_volume(m, path);
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	const Counts before = counts(m);
	const double solid = geometry::solid_volume(m, *pos);
	std::vector<Volume> tets;
	foreach_cell(m, [&](Volume w) { tets.push_back(w); });
	for (Volume w : tets)
	{
		const Vec3 b = barycenter(m, *pos, w);
		value<Vec3>(m, pos, split_tetra(m, w)) = b;
	}
	const uint32 t = before.w;
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(counts(m), (Counts{before.v + t, before.e + 4 * t, before.f + 6 * t, 4 * t}));
	EXPECT_EQ(counts(m).euler(), before.euler());
	double sum = 0.0;
	foreach_cell(m, [&](Volume w) { sum += geometry::volume(m, w, *pos); });
	EXPECT_NEAR(sum, solid, 1e-9 * solid);
	EXPECT_NEAR(geometry::solid_volume(m, *pos), solid, 1e-9 * solid);
}

} // namespace cgogn_test_split_tetra
