#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

namespace cgogn_test_maintenance
{

using namespace cgogn;
using P = std::array<double, 3>;

namespace
{
// every vertex with its sorted neighbour positions: invariant under renumbering
template <typename MAP>
std::vector<std::vector<P>> neighbourhoods(const MAP& m, const AttributeArray<P>& pos)
{
	using Vertex = typename MAP::Vertex;
	std::vector<std::vector<P>> all;
	foreach_cell(m, [&](Vertex v) {
		std::vector<P> n{value<P>(m, pos, v)};
		std::vector<P> ring;
		foreach_adjacent_vertex_through_edge(m, v, [&](Vertex w) { ring.push_back(value<P>(m, pos, w)); });
		std::sort(ring.begin(), ring.end());
		n.insert(n.end(), ring.begin(), ring.end());
		all.push_back(n);
	});
	std::sort(all.begin(), all.end());
	return all;
}
} // namespace

TEST(Maintenance, CompactAfterEditingKeepsCellsAndValues)
{
	CMap2 m;
	SurfaceSoup s = torus_soup(12, 10, true);
	BuildReport r = build_surface(m, s);
	auto pos = add_attribute<P, CMap2::Vertex>(m, "position");
	add_attribute<int, CMap2::Face>(m, "f");
	add_attribute<int, CMap2::Edge>(m, "e");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = s.positions[i];
	std::mt19937 rng(3);
	for (int k = 0; k < 60; ++k)
	{
		std::vector<CMap2::Edge> edges;
		foreach_cell(m, [&](CMap2::Edge e) { edges.push_back(e); });
		CMap2::Edge e = edges[rng() % edges.size()];
		if (can_collapse_edge(m, e))
			collapse_edge(m, e);
	}
	const auto before = neighbourhoods(m, *pos);
	const uint32 darts = nb_darts(m), faces = nb_cells<CMap2::Face>(m);
	ASSERT_LT(darts, cgogn::detail::state_of(m).darts->end_index()); // there are holes
	CompactMaps maps = compact(m);
	EXPECT_EQ(cgogn::detail::state_of(m).darts->end_index(), darts);
	EXPECT_EQ(nb_darts(m), darts);
	EXPECT_EQ(container_of<Orbit::PHI1>(m).end_index(), faces);
	EXPECT_EQ(container_of<Orbit::PHI21>(m).end_index(), nb_cells<CMap2::Vertex>(m));
	EXPECT_EQ(uint32(std::count_if(maps.darts.begin(), maps.darts.end(), [](uint32 x) { return x != INVALID_INDEX; })),
			  darts);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(neighbourhoods(m, *pos), before);
}

TEST(Maintenance, ReorderFollowsTheKey)
{
	CMap2 m;
	SurfaceSoup s = torus_soup(16, 9, true);
	BuildReport r = build_surface(m, s);
	auto pos = add_attribute<P, CMap2::Vertex>(m, "position");
	add_attribute<int, CMap2::Face>(m, "f");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = s.positions[i];
	const auto before = neighbourhoods(m, *pos);
	// a key that scrambles the soup order
	auto key = [&](CMap2::Vertex v) { return uint64((index_of(m, v) * 7919u) % 1009u); };
	reorder(m, [&](CMap2::Vertex v) { return key(v); });
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(neighbourhoods(m, *pos), before);
	// the darts of the first vertex come first
	const uint32 first_vertex = index_of(m, CMap2::Vertex(Dart(0)));
	EXPECT_EQ(first_vertex, 0u);
	uint32 d = 0;
	foreach_dart_of_orbit(m, CMap2::Vertex(Dart(0)), [&](Dart x) { EXPECT_EQ(x.index, d++); });
}

TEST(Maintenance, CompactAndReorderAVolumeMesh)
{
	CMap3 m;
	VolumeSoup s = tet_grid_soup(2, 2, 2);
	BuildReport r = build_volume(m, s);
	auto pos = add_attribute<P, CMap3::Vertex>(m, "position");
	add_attribute<int, CMap3::Volume>(m, "w");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = s.positions[i];
	std::vector<CMap3::Volume> tets;
	foreach_cell(m, [&](CMap3::Volume w) { tets.push_back(w); });
	std::vector<CMap3::Vertex> centres;
	for (std::size_t k = 0; k < tets.size(); k += 3)
		centres.push_back(split_tetra(m, tets[k]));
	for (CMap3::Vertex c : centres)
		collapse_edge(m, CMap3::Edge(c.dart));
	const auto before = neighbourhoods(m, *pos);
	compact(m);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(neighbourhoods(m, *pos), before);
	reorder(m, [&](CMap3::Vertex v) { return uint64(1000 - value<P>(m, pos, v)[0] * 10 - value<P>(m, pos, v)[1]); });
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(neighbourhoods(m, *pos), before);
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 48u);
}

} // namespace cgogn_test_maintenance
