#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace cgogn_test_traversals_3d
{

using namespace cgogn;
using Vertex = CMap3::Vertex;
using Edge = CMap3::Edge;
using Face = CMap3::Face;
using Volume = CMap3::Volume;

// 2x2x2 hexahedra; vertex (i, j, k) has id 9k + 3j + i; the centre is 13.
struct HexGrid : ::testing::Test
{
	CMap3 m;
	void SetUp() override
	{
		build_volume(m, hex_grid_soup(2, 2, 2));
	}
	uint32 id(Vertex v) const
	{
		return index_of(m, v);
	}
	Vertex vertex(uint32 id) const
	{
		Vertex r;
		foreach_cell(m, [&](Vertex v) {
			if (index_of(m, v) != id)
				return true;
			r = v;
			return false;
		});
		return r;
	}
	template <typename TARGET, typename CELL, typename F>
	uint32 count(CELL c, F traversal) const
	{
		uint32 n = 0;
		traversal(c, [&](TARGET) { ++n; });
		return n;
	}
};

TEST_F(HexGrid, GlobalCounts)
{
	EXPECT_EQ(nb_cells<Vertex>(m), 27u);
	EXPECT_EQ(nb_cells<Edge>(m), 54u);
	EXPECT_EQ(nb_cells<Face>(m), 36u);
	EXPECT_EQ(nb_cells<Volume>(m), 8u);
	EXPECT_EQ(nb_cells<CMap3::CC>(m), 1u);
	EXPECT_EQ(nb_cells<CMap3::Face2>(m), 48u);
	EXPECT_EQ(nb_darts(m), 8u * 24u + 24u * 4u); // cells + boundary quads
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST_F(HexGrid, AroundTheCentreVertex)
{
	const Vertex c = vertex(13);
	auto ie = [&](auto x, auto f) { foreach_incident_edge(m, x, f); };
	auto iface = [&](auto x, auto f) { foreach_incident_face(m, x, f); };
	auto ivol = [&](auto x, auto f) { foreach_incident_volume(m, x, f); };
	EXPECT_EQ(count<Edge>(c, ie), 6u);
	EXPECT_EQ(count<Face>(c, iface), 12u);
	EXPECT_EQ(count<Volume>(c, ivol), 8u);
	std::set<uint32> through_edge, through_face, through_volume;
	foreach_adjacent_vertex_through_edge(m, c, [&](Vertex v) { through_edge.insert(id(v)); });
	foreach_adjacent_vertex_through_face(m, c, [&](Vertex v) { through_face.insert(id(v)); });
	uint32 n_volume = 0;
	foreach_adjacent_vertex_through_volume(m, c, [&](Vertex v) {
		through_volume.insert(id(v));
		++n_volume;
	});
	EXPECT_EQ(through_edge, (std::set<uint32>{4, 10, 12, 14, 16, 22}));
	EXPECT_EQ(through_face.size(), 18u);
	EXPECT_EQ(through_volume.size(), 26u);
	EXPECT_EQ(n_volume, 26u); // each once
	EXPECT_FALSE(through_volume.count(13));
	EXPECT_EQ(degree(m, c), 6u);
	EXPECT_FALSE(is_incident_to_boundary(m, c));
}

TEST_F(HexGrid, CornerVertex)
{
	const Vertex c = vertex(0);
	uint32 n = 0;
	foreach_incident_volume(m, c, [&](Volume) { ++n; });
	EXPECT_EQ(n, 1u);
	n = 0;
	foreach_incident_face(m, c, [&](Face) { ++n; });
	EXPECT_EQ(n, 3u);
	n = 0;
	foreach_adjacent_vertex_through_volume(m, c, [&](Vertex) { ++n; });
	EXPECT_EQ(n, 7u);
	EXPECT_TRUE(is_incident_to_boundary(m, c));
}

TEST_F(HexGrid, EdgesFacesVolumes)
{
	// the edge from the centre up: 4 faces and 4 volumes around it, in order
	Edge up;
	foreach_incident_edge(m, vertex(13), [&](Edge e) {
		if (id(Vertex(phi1(m, e.dart))) == 22)
		{
			up = e;
			return false;
		}
		return true;
	});
	ASSERT_TRUE(up.is_valid());
	std::set<uint32> ends;
	foreach_incident_vertex(m, up, [&](Vertex v) { ends.insert(id(v)); });
	EXPECT_EQ(ends, (std::set<uint32>{13, 22}));
	uint32 nf = 0, nw = 0, adj_v = 0, adj_f = 0, adj_w = 0;
	foreach_incident_face(m, up, [&](Face) { ++nf; });
	foreach_incident_volume(m, up, [&](Volume) { ++nw; });
	foreach_adjacent_edge_through_vertex(m, up, [&](Edge) { ++adj_v; });
	foreach_adjacent_edge_through_face(m, up, [&](Edge) { ++adj_f; });
	foreach_adjacent_edge_through_volume(m, up, [&](Edge) { ++adj_w; });
	EXPECT_EQ(nf, 4u);
	EXPECT_EQ(nw, 4u);
	EXPECT_EQ(degree(m, up), 4u);
	EXPECT_EQ(adj_v, 5u + 4u); // 6 edges at the centre, 5 at the top face centre, minus itself
	EXPECT_EQ(adj_f, 4u * 3u);
	EXPECT_EQ(adj_w, 32u); // the 4 hexes above the centre form a 2x2x1 block of 33 edges
	// a volume: 8 vertices, 12 edges, 6 faces; a corner hex has 3/6/7 neighbours
	const Volume w(vertex(0).dart);
	uint32 v = 0, e = 0, f = 0, wf = 0, we = 0, wv = 0;
	foreach_incident_vertex(m, w, [&](Vertex) { ++v; });
	foreach_incident_edge(m, w, [&](Edge) { ++e; });
	foreach_incident_face(m, w, [&](Face x) {
		++f;
		uint32 k = 0;
		foreach_incident_vertex(m, x, [&](Vertex) { ++k; });
		EXPECT_EQ(k, 4u);
	});
	foreach_adjacent_volume_through_face(m, w, [&](Volume) { ++wf; });
	foreach_adjacent_volume_through_edge(m, w, [&](Volume) { ++we; });
	foreach_adjacent_volume_through_vertex(m, w, [&](Volume) { ++wv; });
	EXPECT_EQ(v, 8u);
	EXPECT_EQ(e, 12u);
	EXPECT_EQ(f, 6u);
	EXPECT_EQ(codegree(m, w), 6u);
	EXPECT_EQ(wf, 3u);
	EXPECT_EQ(we, 6u);
	EXPECT_EQ(wv, 7u);
}

TEST_F(HexGrid, FaceIncidencesAndAdjacencies)
{
	uint32 inner = 0, outer = 0;
	foreach_cell(m, [&](Face f) {
		uint32 w = 0;
		foreach_incident_volume(m, f, [&](Volume) { ++w; });
		EXPECT_EQ(w, degree(m, f));
		(w == 2 ? inner : outer)++;
		EXPECT_EQ(codegree(m, f), 4u);
		EXPECT_EQ(w == 1, is_incident_to_boundary(m, f));
	});
	EXPECT_EQ(inner, 12u);
	EXPECT_EQ(outer, 24u);
	// the face between the two bottom front hexes (x = 1 plane, y in [0,1], z in [0,1])
	Face mid;
	foreach_cell(m, [&](Face f) {
		std::set<uint32> ids;
		foreach_incident_vertex(m, f, [&](Vertex v) { ids.insert(id(v)); });
		if (ids == std::set<uint32>{1, 4, 10, 13})
		{
			mid = f;
			return false;
		}
		return true;
	});
	ASSERT_TRUE(mid.is_valid());
	uint32 through_edge = 0, through_vertex = 0, through_volume = 0;
	foreach_adjacent_face_through_edge(m, mid, [&](Face) { ++through_edge; });
	foreach_adjacent_face_through_vertex(m, mid, [&](Face) { ++through_vertex; });
	foreach_adjacent_face_through_volume(m, mid, [&](Face) { ++through_volume; });
	EXPECT_EQ(through_volume, 10u); // the other 5 faces of each of its 2 hexes
	EXPECT_GT(through_vertex, through_edge);
}

TEST(Traversals3D, TetGridIncidenceSums)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(3, 2, 2));
	const uint32 T = nb_cells<Volume>(m), E = nb_cells<Edge>(m);
	EXPECT_EQ(T, 72u);
	uint64 vt = 0, tv = 0, vv_edge = 0, et = 0, vv_vol = 0;
	foreach_cell(m, [&](Vertex v) {
		foreach_incident_volume(m, v, [&](Volume) { ++vt; });
		foreach_adjacent_vertex_through_edge(m, v, [&](Vertex) { ++vv_edge; });
		foreach_adjacent_vertex_through_volume(m, v, [&](Vertex) { ++vv_vol; });
	});
	foreach_cell(m, [&](Volume w) { foreach_incident_vertex(m, w, [&](Vertex) { ++tv; }); });
	foreach_cell(m, [&](Edge e) { foreach_incident_volume(m, e, [&](Volume) { ++et; }); });
	EXPECT_EQ(vt, 4u * T);
	EXPECT_EQ(tv, 4u * T);
	EXPECT_EQ(vv_edge, 2u * E);
	EXPECT_EQ(vv_vol, 2u * E); // in a tet mesh, vertices of a common tet share an edge
	EXPECT_EQ(et, 6u * T);
}

// The neighbours through edges are told apart by their vertex line when the
// vertices are indexed: the same sets as the other ends of the incident
// edges, each once, located at their own line; a vertex made without a line
// (set_indices = false) falls back to the dart walk and still gets its
// neighbours, and a callable may stop early.
TEST(Traversals3D, AdjacentVerticesThroughEdgesByLineAndWithoutLines)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(3, 2, 2));
	auto by_edges = [&](Vertex v) {
		std::multiset<uint32> r;
		foreach_incident_edge(m, v, [&](Edge e) {
			foreach_incident_vertex(m, e, [&](Vertex w) {
				if (index_of(m, w) != index_of(m, v))
					r.insert(index_of(m, w));
			});
		});
		return r;
	};
	uint32 checked = 0;
	foreach_cell(m, [&](Vertex v) {
		std::multiset<uint32> adjacent;
		uint32 located = 0;
		// a generic callable is instantiated for both paths; the line path gives lines
		foreach_adjacent_vertex_through_edge(m, v, [&](auto w) {
			if constexpr (std::is_same_v<decltype(w), LocatedCell<Vertex::ORBIT>>)
			{
				EXPECT_EQ(w.line, index_of(m, Vertex(w.dart)));
				++located;
			}
			adjacent.insert(index_of(m, Vertex(w.dart)));
		});
		EXPECT_EQ(adjacent, by_edges(v));
		EXPECT_EQ(located, adjacent.size());
		++checked;
		uint32 calls = 0;
		foreach_adjacent_vertex_through_edge(m, v, [&](Vertex) { return ++calls < 2; });
		EXPECT_EQ(calls, 2u);
	});
	EXPECT_EQ(checked, nb_cells<Vertex>(m));

	// a vertex without a line in the middle of an edge: its neighbours are the
	// two ends, found through the fallback; the ends see it too
	Edge e;
	foreach_cell(m, [&](Edge x) {
		e = x;
		return false;
	});
	const uint32 a = index_of(m, Vertex(e.dart)), b = index_of(m, Vertex(phi1(m, e.dart)));
	const Vertex mid = cut_edge(m, e, false);
	ASSERT_EQ(index_of(m, mid), INVALID_INDEX);
	std::multiset<uint32> ends;
	foreach_adjacent_vertex_through_edge(m, mid, [&](Vertex w) { ends.insert(index_of(m, w)); });
	EXPECT_EQ(ends, (std::multiset<uint32>{a, b}));
	uint32 unindexed_seen = 0;
	foreach_adjacent_vertex_through_edge(m, Vertex(e.dart),
										 [&](Vertex w) { unindexed_seen += index_of(m, w) == INVALID_INDEX; });
	EXPECT_EQ(unindexed_seen, 1u);
}

// The darts of a 3-D vertex (foreach_dart_of_orbit on PHI21_PHI31, a flood
// with prefetches) on real tet and hex-dominant meshes in file order: from
// any of its darts, exactly the darts holding the vertex's line, each once;
// the vertices' orbits cover every dart; a walk stopped early leaves no mark
// behind (the next full walk from the same dart sees the whole orbit).
TEST(Traversals3D, VertexDartsOnRealMeshes)
{
	for (const char* name : {"volume/armadillo_tet_4k.mesh", "volume/hex_dominant_11k.mesh"})
	{
		const std::string path = cgogn_test_data::path(name);
		SCOPED_TRACE(name);
		CMap3 m;
		io::load_volume(m, path);
		std::map<uint32, uint32> darts_of_line;
		foreach_dart(m, [&](Dart d) { ++darts_of_line[index_of(m, Vertex(d))]; });
		EXPECT_EQ(darts_of_line.size(), nb_cells<Vertex>(m));
		uint64 covered = 0;
		uint32 bad = 0;
		foreach_cell(m, [&](Vertex v) {
			const uint32 line = index_of(m, v);
			std::vector<uint32> orbit;
			foreach_dart_of_orbit(m, v, [&](Dart d) {
				orbit.push_back(d.index);
				bad += index_of(m, Vertex(d)) != line;
			});
			std::sort(orbit.begin(), orbit.end());
			bad += std::adjacent_find(orbit.begin(), orbit.end()) != orbit.end();
			bad += orbit.size() != darts_of_line[line];
			covered += orbit.size();
			// from another dart of the orbit, stopped after half of it, then in full
			const Dart other(orbit[orbit.size() / 2]);
			const uint32 half = uint32(orbit.size() / 2) + 1;
			uint32 calls = 0;
			foreach_dart_of_orbit(m, Vertex(other), [&](Dart) { return ++calls < half; });
			bad += calls != half;
			std::vector<uint32> again;
			foreach_dart_of_orbit(m, Vertex(other), [&](Dart d) { again.push_back(d.index); });
			std::sort(again.begin(), again.end());
			bad += again != orbit;
		});
		EXPECT_EQ(bad, 0u);
		EXPECT_EQ(covered, nb_darts(m));
	}
}

// A callable may throw out of a flooded walk (a 3-D vertex, a volume): the
// walk's marks are cleared and given back, so later walks see whole orbits.
TEST(Traversals3D, ThrowingCallableLeavesNoMark)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(3, 2, 2));
	Vertex centre;
	uint32 most = 0;
	foreach_cell(m, [&](Vertex v) {
		uint32 n = 0;
		foreach_dart_of_orbit(m, v, [&](Dart) { ++n; });
		if (n > most)
		{
			most = n;
			centre = v;
		}
	});
	const uint32 volume_darts = [&] {
		uint32 n = 0;
		foreach_dart_of_orbit(m, Volume(centre.dart), [&](Dart) { ++n; });
		return n;
	}();
	auto first_free_mark = [&] {
		MarkAttribute* mark = cgogn::detail::state_of(m).darts->acquire_mark();
		cgogn::detail::state_of(m).darts->release_mark(mark);
		return mark;
	};
	MarkAttribute* const free_before = first_free_mark();
	for (int round = 0; round < 100; ++round)
	{
		uint32 calls = 0;
		EXPECT_THROW(foreach_dart_of_orbit(m, centre,
										   [&](Dart) {
											   if (++calls == most / 2)
												   throw std::runtime_error("stop");
										   }),
					 std::runtime_error);
		calls = 0;
		EXPECT_THROW(foreach_dart_of_orbit(m, Volume(centre.dart),
										   [&](Dart) {
											   if (++calls == volume_darts / 2)
												   throw std::runtime_error("stop");
										   }),
					 std::runtime_error);
	}
	// every mark given back (the same first free one) and cleared
	EXPECT_EQ(first_free_mark(), free_before);
	EXPECT_TRUE(free_before->all_clear());
	uint32 n = 0, w = 0;
	foreach_dart_of_orbit(m, centre, [&](Dart) { ++n; });
	foreach_dart_of_orbit(m, Volume(centre.dart), [&](Dart) { ++w; });
	EXPECT_EQ(n, most);
	EXPECT_EQ(w, volume_darts);
	EXPECT_GT(most, 12u);
}

} // namespace cgogn_test_traversals_3d
