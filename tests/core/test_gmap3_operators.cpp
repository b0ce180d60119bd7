// The operators of 3-G-maps: the same counts, lines and integrity as the
// CMap3 operators at the same darts; exact results on small volumes; sewing
// with a twist; randomized sequences with check_integrity after every step.
#include <cgogn/core.h>

#include "volume_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <string>
#include <unordered_map>
#include <vector>

namespace cgogn_test_gmap3_operators
{

using namespace cgogn;

namespace
{

using test::halved;
using test::volume_counts;
using Counts = test::VolumeCounts;

template <typename MAP>
void index_everything(MAP& m)
{
	[&]<typename... C>(std::tuple<C...>*) {
		((is_indexed<C>(m) ? void() : void(index_cells<C>(m))), ...);
	}(static_cast<typename mesh_traits<MAP>::Cells*>(nullptr));
}

// The test meshes, built fresh each time (the darts are then numbered from
// 0 without holes, so to_gmap puts the darts of CMap3 dart d at 2d and 2d+1).
CMap3 mesh(int which)
{
	CMap3 m;
	switch (which)
	{
	case 0:
		build_volume(m, tet_grid_soup(2, 2, 1));
		break;
	case 1:
		build_volume(m, hex_grid_soup(2, 2, 1));
		break;
	default:
		add_hexa(m);
		add_tetra(m);
		close(m);
		break;
	}
	index_everything(m);
	return m;
}
constexpr int NB_MESHES = 3;

// The G-map dart at the origin of CMap3 dart d (its partner beta0 is at the end).
Dart A(Dart d)
{
	return Dart(2 * d.index);
}

std::vector<Dart> darts_of(const CMap3& m)
{
	std::vector<Dart> v;
	foreach_dart(m, [&](Dart d) { v.push_back(d); });
	return v;
}

// Applies one CMap3 operator and the GMap3 one at the same darts, on fresh
// copies, for every dart where the CMap3's predicate holds (or up to `limit`
// of them per mesh); the counts must agree and both maps stay valid.
template <typename OP>
void agrees_with_cmap3(const char* name, OP&& op, std::size_t limit = 150)
{
	std::size_t tried = 0;
	for (int which = 0; which < NB_MESHES; ++which)
	{
		std::size_t here = 0;
		for (Dart d : darts_of(mesh(which)))
		{
			if (here >= limit)
				break;
			CMap3 c = mesh(which);
			GMap3 g = to_gmap(c);
			index_everything(g);
			if (!op(c, g, d))
				continue;
			++here;
			ASSERT_TRUE(check_integrity(c).ok()) << name;
			ASSERT_TRUE(check_integrity(g).ok())
				<< name << " mesh " << which << " dart " << d.index << ": " << check_integrity(g).to_string();
			ASSERT_EQ(halved(volume_counts(g)), volume_counts(c)) << name << " mesh " << which << " dart " << d.index;
			ASSERT_EQ(nb_darts(g), 2 * nb_darts(c)) << name;
			ASSERT_TRUE(is_orientable(g)) << name;
			ASSERT_EQ(volume_counts(to_cmap(g)), volume_counts(c)) << name;
		}
		tried += here;
	}
	EXPECT_GT(tried, 10u) << name << " was hardly applied";
}

} // namespace

TEST(GMap3Operators, CutEdgeAgreesWithCMap3)
{
	agrees_with_cmap3("cut_edge", [](CMap3& c, GMap3& g, Dart d) {
		auto line = index_of(g, GMap3::Edge(A(d)));
		const CMap3::Vertex vc = cut_edge(c, CMap3::Edge(d));
		const GMap3::Vertex vg = cut_edge(g, GMap3::Edge(A(d)));
		EXPECT_EQ(index_of(g, GMap3::Edge(A(d))), line); // e.dart's half keeps the line
		EXPECT_EQ(degree(g, vg), degree(c, vc));
		// the new vertex's dart goes to the end of e.dart, in its face and volume
		EXPECT_TRUE(same_orbit(g, GMap3::Face2(vg.dart), GMap3::Face2(A(d))));
		return true;
	});
}

TEST(GMap3Operators, CutFaceAgreesWithCMap3)
{
	agrees_with_cmap3("cut_face", [](CMap3& c, GMap3& g, Dart d) {
		const Dart e = phi1(c, phi1(c, d));
		if (!can_cut_face(c, d, e))
			return false;
		EXPECT_TRUE(can_cut_face(g, A(d), A(e)));
		EXPECT_FALSE(can_cut_face(g, A(d), A(phi1(c, d)))); // joined by an edge
		EXPECT_FALSE(can_cut_face(g, A(d), beta0(g, A(phi_1(c, d)))));
		auto line = index_of(g, GMap3::Face(A(d)));
		cut_face(c, d, e);
		const GMap3::Edge ne = cut_face(g, A(d), A(e));
		EXPECT_EQ(index_of(g, GMap3::Face(A(d))), line);
		EXPECT_TRUE(same_orbit(g, GMap3::Vertex(ne.dart), GMap3::Vertex(A(d))));
		EXPECT_TRUE(same_orbit(g, GMap3::Vertex(beta0(g, ne.dart)), GMap3::Vertex(A(e))));
		EXPECT_EQ(codegree(g, GMap3::Face(A(d))), 3u);
		return true;
	});
}

TEST(GMap3Operators, MergeIncidentFacesAgreesWithCMap3)
{
	// on an edge made by cut_face, the only edges with two faces here
	agrees_with_cmap3("merge_incident_faces", [](CMap3& c, GMap3& g, Dart d) {
		const Dart e = phi1(c, phi1(c, d));
		if (!can_cut_face(c, d, e))
			return false;
		const CMap3::Edge ec = cut_face(c, d, e);
		const GMap3::Edge eg = cut_face(g, A(d), A(e));
		const Counts after_cut = volume_counts(g);
		EXPECT_EQ(can_merge_incident_faces(g, eg), can_merge_incident_faces(c, ec));
		if (!can_merge_incident_faces(c, ec))
			return false;
		auto line = index_of(g, GMap3::Face(eg.dart));
		merge_incident_faces(c, ec);
		const GMap3::Face f = merge_incident_faces(g, eg);
		EXPECT_EQ(index_of(g, f), line);
		EXPECT_EQ(volume_counts(g).e + 1, after_cut.e);
		return true;
	});
	// the predicates agree on every edge of the meshes (two faces meet at the
	// outer edges of a single volume)
	for (int which = 0; which < NB_MESHES; ++which)
	{
		const CMap3 c = mesh(which);
		const GMap3 g = to_gmap(c);
		uint32 can = 0;
		foreach_cell(c, [&](CMap3::Edge e) {
			EXPECT_EQ(can_merge_incident_faces(g, GMap3::Edge(A(e.dart))), can_merge_incident_faces(c, e));
			can += can_merge_incident_faces(c, e) ? 1 : 0;
			return true;
		});
		EXPECT_GT(can, 0u) << which;
	}
}

TEST(GMap3Operators, MergeIncidentVolumesAgreesWithCMap3)
{
	agrees_with_cmap3(
		"merge_incident_volumes",
		[](CMap3& c, GMap3& g, Dart d) {
			const bool can = can_merge_incident_volumes(c, CMap3::Face(d));
			EXPECT_EQ(can_merge_incident_volumes(g, GMap3::Face(A(d))), can);
			if (!can)
				return false;
			auto line = index_of(g, GMap3::Volume(A(d)));
			merge_incident_volumes(c, CMap3::Face(d));
			const GMap3::Volume w = merge_incident_volumes(g, GMap3::Face(A(d)));
			EXPECT_EQ(index_of(g, w), line);
			return true;
		},
		40);
}

TEST(GMap3Operators, UnsewVolumesAgreesWithCMap3AndSewingBackRestores)
{
	agrees_with_cmap3(
		"unsew_volumes",
		[](CMap3& c, GMap3& g, Dart d) {
			if (is_boundary(c, d) || is_boundary(c, phi3(c, d)))
				return false;
			EXPECT_TRUE(can_unsew_volumes(g, GMap3::Face(A(d))));
			const Dart other = beta3(g, A(d));
			auto line = index_of(g, GMap3::Face(A(d)));
			unsew_volumes(c, CMap3::Face(d));
			unsew_volumes(g, GMap3::Face(A(d)));
			EXPECT_EQ(index_of(g, GMap3::Face(A(d))), line);
			EXPECT_TRUE(is_boundary(g, beta3(g, A(d))));
			EXPECT_TRUE(is_boundary(g, beta3(g, other)));
			return true;
		},
		80);
	for (int which = 0; which < NB_MESHES; ++which)
	{
		const Counts original = volume_counts(to_gmap(mesh(which)));
		for (Dart d : darts_of(mesh(which)))
		{
			GMap3 g = to_gmap(mesh(which));
			index_everything(g);
			const Dart x = A(d), y = beta3(g, A(d));
			if (!can_unsew_volumes(g, GMap3::Face(x)))
				continue;
			unsew_volumes(g, GMap3::Face(x));
			ASSERT_TRUE(can_sew_volumes(g, GMap3::Face(x), GMap3::Face(y)));
			sew_volumes(g, GMap3::Face(x), GMap3::Face(y));
			ASSERT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
			ASSERT_EQ(volume_counts(g), original) << "mesh " << which << " dart " << d.index;
		}
	}
}

TEST(GMap3Operators, CutVolumeAlongAFaceAgreesWithCMap3)
{
	// the path around a face of the volume, seen from either face at its edges
	agrees_with_cmap3(
		"cut_volume",
		[](CMap3& c, GMap3& g, Dart d) {
			if (is_boundary(c, d))
				return false;
			std::vector<Dart> pc, pg;
			const bool other_side = d.index % 2 == 1;
			Dart x = d;
			do
			{
				pc.push_back(other_side ? phi2(c, phi1(c, x)) : x);
				x = phi1(c, x);
			} while (x != d);
			if (other_side) // phi2 of the next dart runs the same edge the other way: reverse the chain
				std::reverse(pc.begin(), pc.end());
			for (Dart p : pc)
				pg.push_back(A(p));
			if (!can_cut_volume(c, pc))
				return false;
			EXPECT_TRUE(can_cut_volume(g, pg));
			auto line = index_of(g, GMap3::Volume(pg[0]));
			cut_volume(c, pc);
			const GMap3::Face f = cut_volume(g, pg);
			EXPECT_EQ(index_of(g, GMap3::Volume(pg[0])), line);
			EXPECT_EQ(beta2(g, pg[0]), f.dart);
			EXPECT_EQ(codegree(g, f), uint32(pc.size()));
			return true;
		},
		60);
}

TEST(GMap3Operators, CutVolumeRejectsBrokenChains)
{
	GMap3 g = to_gmap(mesh(2));
	const Dart d = A(Dart(0)); // the hexahedron
	std::vector<Dart> face;
	for (Dart x = d; face.size() < 4; x = beta<0, 1>(g, x))
		face.push_back(x);
	EXPECT_TRUE(can_cut_volume(g, face));
	EXPECT_FALSE(can_cut_volume(g, {face[0], face[1]}));                   // too short
	EXPECT_FALSE(can_cut_volume(g, {face[0], face[2], face[1], face[3]})); // not a chain
	std::vector<Dart> twisted = face;
	twisted[2] = beta2(g, face[2]); // the same edge, from the other face: the other side
	EXPECT_FALSE(can_cut_volume(g, twisted));
	std::vector<Dart> outside;
	for (Dart x : face)
		outside.push_back(beta3(g, x));
	EXPECT_FALSE(can_cut_volume(g, outside)); // a boundary volume
}

TEST(GMap3Operators, CuttingACubeAlongItsSkewHexagon)
{
	// the six edges of a cube that avoid two opposite corners separate it
	// into two volumes of three quads and the new hexagon
	CMap3 c;
	add_hexa(c);
	close(c);
	GMap3 g = to_gmap(c);
	index_everything(g);
	// the corner a of dart d and the opposite corner; the 24 darts of the
	// volume on edges touching neither are those of the hexagon's 6 edges
	const Dart d = A(Dart(0));
	std::vector<Dart> path;
	const GMap3::Vertex a(d);
	const GMap3::Vertex opposite(beta<0, 1, 0, 1, 2, 1, 0>(g, d));
	ASSERT_FALSE(same_orbit(g, a, opposite));
	std::vector<Dart> candidates;
	foreach_dart_of_orbit(g, GMap3::Volume(d), [&](Dart y) {
		const bool touches = same_orbit(g, GMap3::Vertex(y), a) || same_orbit(g, GMap3::Vertex(beta0(g, y)), a) ||
							 same_orbit(g, GMap3::Vertex(y), opposite) ||
							 same_orbit(g, GMap3::Vertex(beta0(g, y)), opposite);
		if (!touches)
			candidates.push_back(y);
	});
	// 6 edges, 2 faces each, 2 ends: 24 darts; grow a chain from one of them
	ASSERT_EQ(candidates.size(), 24u);
	path.push_back(candidates.front());
	while (path.size() < 7)
	{
		bool grown = false;
		for (Dart y : candidates)
		{
			// y continues the chain when met after a beta1 step around the
			// end of the last dart, and is on a new edge
			Dart z = beta0(g, path.back());
			bool next = false;
			do
			{
				z = beta1(g, z);
				next = z == y;
				z = beta2(g, z);
			} while (z != beta0(g, path.back()) && !next);
			if (next && !same_orbit(g, GMap3::Edge(y), GMap3::Edge(path.back())))
			{
				path.push_back(y);
				grown = true;
				break;
			}
		}
		ASSERT_TRUE(grown);
	}
	ASSERT_EQ(path.back(), path.front()); // the chain closes after 6 darts
	path.pop_back();
	ASSERT_TRUE(can_cut_volume(g, path));
	const Counts before = volume_counts(g);
	const GMap3::Face f = cut_volume(g, path);
	ASSERT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
	const Counts after = volume_counts(g);
	EXPECT_EQ(after.v, before.v);
	EXPECT_EQ(after.e, before.e);
	EXPECT_EQ(after.f, before.f + 1);
	EXPECT_EQ(after.w, before.w + 1);
	EXPECT_EQ(codegree(g, f), 6u);
	EXPECT_EQ(nb_cells<GMap3::Face2>(g), 8u); // 3 + 1 faces in each part (boundary faces not counted)
	foreach_cell(g, [&](GMap3::Volume w) {
		if (!is_boundary(g, w.dart))
		{
			EXPECT_EQ(codegree(g, w), 4u);
		}
		return true;
	});
	EXPECT_TRUE(can_merge_incident_volumes(g, f));
	merge_incident_volumes(g, f);
	EXPECT_TRUE(check_integrity(g).ok());
	EXPECT_EQ(volume_counts(g), before);
}

TEST(GMap3Operators, SewingTheEndsOfABarWithOrWithoutATwist)
{
	// a bar of three cubes; its two end faces sewn in each of the 8 ways
	// (4 rotations, 4 reflections) make a solid torus or a solid Klein bottle
	CMap3 c;
	build_volume(c, hex_grid_soup(1, 1, 3));
	const GMap3 bar = to_gmap(c);
	ASSERT_EQ(volume_counts(bar), (Counts{256, 16, 28, 16, 3, 1, 1, 1}));
	// the end faces: boundary faces whose inner volume has one neighbour,
	// opposite to the face it shares
	std::vector<Dart> ends;
	foreach_cell(bar, [&](GMap3::Face f) {
		Dart d = f.dart;
		if (is_boundary(bar, d))
			d = beta3(bar, d);
		if (!is_boundary(bar, beta3(bar, d)))
			return true;
		const Dart opposite = beta<2, 1, 0, 1, 2>(bar, d);
		if (!is_boundary(bar, beta3(bar, opposite)))
		{
			// an end face has its opposite face shared, and is the only face
			// of its volume with all four side faces on the boundary
			uint32 boundary_sides = 0;
			Dart x = d;
			for (int i = 0; i < 4; ++i, x = beta<0, 1>(bar, x))
				boundary_sides += is_boundary(bar, beta<2, 3>(bar, x)) ? 1 : 0;
			if (boundary_sides == 4)
				ends.push_back(d);
		}
		return true;
	});
	ASSERT_EQ(ends.size(), 2u);
	uint32 orientable = 0, twisted = 0;
	std::vector<Dart> choices;
	for (Dart x = ends[1]; choices.size() < 8; x = choices.size() % 2 == 0 ? beta0(bar, x) : beta1(bar, x))
		choices.push_back(x);
	for (Dart target : choices)
	{
		GMap3 g = to_gmap(c);
		index_everything(g);
		ASSERT_TRUE(can_sew_volumes(g, GMap3::Face(ends[0]), GMap3::Face(target)));
		EXPECT_FALSE(can_sew_volumes(g, GMap3::Face(ends[0]), GMap3::Face(beta3(g, target))));
		sew_volumes(g, GMap3::Face(ends[0]), GMap3::Face(target));
		ASSERT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_EQ(volume_counts(g), (Counts{240, 12, 24, 15, 3, 1, 1, 0}));
		(is_orientable(g) ? orientable : twisted) += 1;
	}
	EXPECT_EQ(orientable, 4u);
	EXPECT_EQ(twisted, 4u);
}

TEST(GMap3Operators, SewingTwoSeparateHexahedra)
{
	CMap3 c;
	add_hexa(c);
	add_hexa(c);
	close(c);
	GMap3 g = to_gmap(c);
	index_everything(g);
	Dart d1, d2;
	foreach_cell(g, [&](GMap3::Volume w) {
		if (!is_boundary(g, w.dart))
			(d1.is_valid() ? d2 : d1) = w.dart;
		return true;
	});
	ASSERT_FALSE(same_orbit(g, GMap3::CC(d1), GMap3::CC(d2)));
	auto cc_line = index_of(g, GMap3::CC(d1));
	sew_volumes(g, GMap3::Face(d1), GMap3::Face(d2));
	ASSERT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
	EXPECT_EQ(volume_counts(g), (Counts{176, 12, 20, 11, 2, 1, 1, 1}));
	EXPECT_EQ(index_of(g, GMap3::CC(d2)), cc_line);
	EXPECT_TRUE(same_orbit(g, GMap3::Vertex(d1), GMap3::Vertex(d2)));
	EXPECT_TRUE(same_orbit(g, GMap3::Edge(d1), GMap3::Edge(d2)));
}

namespace
{
// A random dart of a random non-boundary cell, and the operators applied
// where their predicates hold. Returns the name of the operator applied, or
// nullptr.
const char* random_step(GMap3& g, std::mt19937& rng)
{
	std::vector<Dart> darts;
	foreach_dart(g, [&](Dart d) {
		if (!is_boundary(g, d))
			darts.push_back(d);
	});
	const Dart d = darts[std::uniform_int_distribution<std::size_t>(0, darts.size() - 1)(rng)];
	const Counts before = volume_counts(g);
	switch (std::uniform_int_distribution<int>(0, 6)(rng))
	{
	case 6: {
		// apart and back together, the same way round
		const Dart other = beta3(g, d);
		if (!can_unsew_volumes(g, GMap3::Face(d)))
			return nullptr;
		unsew_volumes(g, GMap3::Face(d));
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_EQ(volume_counts(g).f, before.f + 1);
		sew_volumes(g, GMap3::Face(d), GMap3::Face(other));
		EXPECT_EQ(volume_counts(g), before);
		return "unsew_volumes and sew_volumes";
	}
	case 0:
		if (nb_darts(g) > 6000)
			return nullptr;
		cut_edge(g, GMap3::Edge(d));
		EXPECT_EQ(volume_counts(g).v, before.v + 1);
		EXPECT_EQ(volume_counts(g).e, before.e + 1);
		return "cut_edge";
	case 1: {
		const Dart e = beta<0, 1, 0>(g, d);
		if (!can_cut_face(g, d, e) || nb_darts(g) > 6000)
			return nullptr;
		cut_face(g, d, e);
		EXPECT_EQ(volume_counts(g).e, before.e + 1);
		EXPECT_EQ(volume_counts(g).f, before.f + 1);
		return "cut_face";
	}
	case 2:
	case 3:
		if (!can_merge_incident_faces(g, GMap3::Edge(d)))
			return nullptr;
		merge_incident_faces(g, GMap3::Edge(d));
		EXPECT_EQ(volume_counts(g).e + 1, before.e);
		EXPECT_EQ(volume_counts(g).f + 1, before.f);
		return "merge_incident_faces";
	case 4: {
		// around the face of d, from its side or from the faces beside it
		std::vector<Dart> path;
		const bool other_side = rng() % 2 == 1;
		for (Dart x = d; path.empty() || x != d; x = beta<0, 1>(g, x))
			path.push_back(other_side ? beta2(g, x) : x);
		if (!can_cut_volume(g, path) || nb_darts(g) > 6000)
			return nullptr;
		const GMap3::Face f = cut_volume(g, path);
		const bool separated = !same_orbit(g, GMap3::Volume(f.dart), GMap3::Volume(beta3(g, f.dart)));
		EXPECT_EQ(volume_counts(g).f, before.f + 1);
		EXPECT_EQ(volume_counts(g).w, before.w + (separated ? 1 : 0));
		return "cut_volume";
	}
	default:
		if (!can_merge_incident_volumes(g, GMap3::Face(d)))
			return nullptr;
		merge_incident_volumes(g, GMap3::Face(d));
		EXPECT_EQ(volume_counts(g).f + 1, before.f);
		EXPECT_EQ(volume_counts(g).w + 1, before.w);
		return "merge_incident_volumes";
	}
}
} // namespace

TEST(GMap3Operators, RandomSequencesKeepTheMapValid)
{
	for (int which = 0; which < NB_MESHES; ++which)
	{
		std::mt19937 rng(7 + which);
		GMap3 g = to_gmap(mesh(which));
		index_everything(g);
		const int64 chi = euler_characteristic(g); // 2 for the two separate volumes
		std::map<std::string, int> used;
		int steps = 0;
		while (steps < 1000)
		{
			const char* op = random_step(g, rng);
			if (op == nullptr)
				continue;
			++steps;
			++used[op];
			ASSERT_TRUE(check_integrity(g).ok())
				<< "step " << steps << " (" << op << "): " << check_integrity(g).to_string();
			ASSERT_EQ(euler_characteristic(g), chi) << "step " << steps << " (" << op << ")";
		}
		for (const char* op : {"cut_edge", "cut_face", "merge_incident_faces", "cut_volume", "merge_incident_volumes",
							   "unsew_volumes and sew_volumes"})
			EXPECT_GT(used[op], 20) << op << " on mesh " << which;
	}
}

namespace
{
// The G-map dart at the origin of each dart of c in to_gmap(c), which numbers
// the darts of c by rank.
std::unordered_map<uint32, Dart> origins_in_gmap(const CMap3& c)
{
	std::unordered_map<uint32, Dart> a;
	uint32 k = 0;
	foreach_dart(c, [&](Dart d) { a.emplace(d.index, Dart(2 * k++)); });
	return a;
}

uint32 inner_volumes_around(const GMap3& g, GMap3::Edge e)
{
	uint32 n = 0;
	DartMarkerStore<GMap3> seen(g);
	foreach_dart_of_orbit(g, e, [&](Dart d) {
		if (!is_boundary(g, d) && !seen.is_marked(d))
		{
			++n;
			seen.mark_orbit(GMap3::Volume(d));
		}
	});
	return n;
}
} // namespace

TEST(GMap3Operators, CollapseEdgeAgreesWithCMap3AlongASequence)
{
	// collapses on a CMap3, each one also made on a fresh to_gmap of it at the
	// same dart: the predicates agree on every edge, the results on the counts
	CMap3 c;
	build_volume(c, tet_grid_soup(3, 3, 2));
	index_everything(c);
	std::mt19937 rng(11);
	int collapses = 0, refused = 0;
	for (int step = 0; step < 60; ++step)
	{
		GMap3 g = to_gmap(c);
		index_everything(g);
		const auto a = origins_in_gmap(c);
		std::vector<Dart> collapsible;
		foreach_cell(c, [&](CMap3::Edge e) {
			const bool can = can_collapse_edge(c, e);
			EXPECT_EQ(can_collapse_edge(g, GMap3::Edge(a.at(e.dart.index))), can) << "step " << step;
			(can ? collapsible.push_back(e.dart) : void(++refused));
			return true;
		});
		if (collapsible.empty())
			break;
		const Dart d = collapsible[rng() % collapsible.size()];
		const Dart gd = a.at(d.index);
		const auto survivor = index_of(g, GMap3::Vertex(beta0(g, gd)));
		collapse_edge(c, CMap3::Edge(d));
		const GMap3::Vertex v = collapse_edge(g, GMap3::Edge(gd));
		++collapses;
		ASSERT_TRUE(check_integrity(g).ok()) << "step " << step << ": " << check_integrity(g).to_string();
		ASSERT_EQ(halved(volume_counts(g)), volume_counts(c)) << "step " << step;
		EXPECT_EQ(index_of(g, v), survivor);
		EXPECT_TRUE(is_orientable(g));
	}
	EXPECT_GT(collapses, 30);
	EXPECT_GT(refused, 0);
}

TEST(GMap3Operators, CollapsingEdgesUntilNoneCan)
{
	// on the 3-G-map itself: every collapse removes one vertex, the edge and
	// one edge per triangle around it, one face per triangle and per tet
	// around it, and the tets around it
	CMap3 c;
	build_volume(c, tet_grid_soup(3, 3, 3));
	GMap3 g = to_gmap(c);
	index_everything(g);
	std::mt19937 rng(5);
	int collapses = 0;
	for (;;)
	{
		std::vector<Dart> collapsible;
		foreach_cell(g, [&](GMap3::Edge e) {
			if (can_collapse_edge(g, e))
				collapsible.push_back(e.dart);
			return true;
		});
		if (collapsible.empty())
			break;
		const GMap3::Edge e(collapsible[rng() % collapsible.size()]);
		const Counts before = volume_counts(g);
		const uint32 k = degree(g, e), t = inner_volumes_around(g, e);
		collapse_edge(g, e);
		++collapses;
		ASSERT_TRUE(check_integrity(g).ok()) << "collapse " << collapses << ": " << check_integrity(g).to_string();
		const Counts after = volume_counts(g);
		ASSERT_EQ(after.v + 1, before.v);
		ASSERT_EQ(after.e + 1 + k, before.e);
		ASSERT_EQ(after.f + k + t, before.f);
		ASSERT_EQ(after.w + t, before.w);
		ASSERT_EQ(after.chi, 1);
	}
	EXPECT_GT(collapses, 50);
}

} // namespace cgogn_test_gmap3_operators
