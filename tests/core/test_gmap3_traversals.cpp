// The local traversals of 3-G-maps: on tet, hex and mixed meshes, with a
// boundary or several components, each traversal of the G-map of a 3-map
// reports, from every cell, the cells the 3-map's traversal reports from the
// same cell, each once; with every orbit indexed and with none; and every
// quick incidence cache reports the dart walks and is read.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

namespace cgogn_test_gmap3_traversals
{

using namespace cgogn;

namespace
{

// The cell types of MAP by dimension: 0 vertex, 1 edge, 2 face, 3 volume.
template <typename MAP, int D>
using CellOf = std::tuple_element_t<D, std::tuple<typename mesh_traits<MAP>::Vertex, typename mesh_traits<MAP>::Edge,
												  typename mesh_traits<MAP>::Face, typename mesh_traits<MAP>::Volume>>;

constexpr const char* id_names[4] = {"vid", "eid", "fid", "wid"};

// Numbers the real cells of each dimension of m with a cell attribute
// (which indexes the orbit); to_gmap carries them to the G-map.
void number_cells(CMap3& m)
{
	uint32 k = 0;
	auto number = [&]<int D>() {
		auto a = add_attribute<uint32, CellOf<CMap3, D>>(m, id_names[D]);
		foreach_cell(m, [&](CellOf<CMap3, D> c) { value<uint32>(m, *a, c) = k++; });
	};
	number.template operator()<0>();
	number.template operator()<1>();
	number.template operator()<2>();
	number.template operator()<3>();
}

// A G-map with the darts, relations and boundary marks of g and no index at
// all (no attribute): its cells are found by walking darts. g must be compact
// (to_gmap makes it so): the copy's darts have g's numbers.
GMap3 unindexed_copy(const GMap3& g)
{
	GMap3 h;
	foreach_dart(g, [&](Dart d) {
		if (d.index % 2 == 0)
		{
			EXPECT_EQ(cgogn::detail::add_dart_pair(h).index, d.index);
		}
	});
	foreach_dart(g, [&](Dart d) {
		cgogn::detail::set_beta<1>(h, d, beta1(g, d));
		cgogn::detail::set_beta<2>(h, d, beta2(g, d));
		cgogn::detail::set_beta<3>(h, d, beta3(g, d));
		cgogn::detail::set_boundary(h, d, is_boundary(g, d));
	});
	return h;
}

// A volume mesh as a 3-map with numbered cells, its G-map (every orbit
// indexed, the numbers carried) and an unindexed copy of the G-map.
struct Mesh
{
	std::string name;
	CMap3 c;
	GMap3 g;
	GMap3 h;

	Mesh(std::string n, CMap3&& m) : name(std::move(n)), c(numbered(std::move(m))), g(to_gmap(c)), h(unindexed_copy(g))
	{
	}

	static CMap3 numbered(CMap3 m)
	{
		number_cells(m);
		return m;
	}

	// The number of a cell of c, or of g or h through g (h has g's darts);
	// INVALID_INDEX for a cell without one (a boundary volume).
	template <int D>
	uint32 id(const CMap3& m, CellOf<CMap3, D> x) const
	{
		const uint32 i = index_of(m, x);
		return i == INVALID_INDEX ? INVALID_INDEX : (*get_attribute<uint32, CellOf<CMap3, D>>(m, id_names[D]))[i];
	}
	template <int D>
	uint32 id(const GMap3&, CellOf<GMap3, D> x) const
	{
		const uint32 i = index_of(g, CellOf<GMap3, D>(x.dart));
		return i == INVALID_INDEX ? INVALID_INDEX : (*get_attribute<uint32, CellOf<GMap3, D>>(g, id_names[D]))[i];
	}
};

CMap3 built(const VolumeSoup& s)
{
	CMap3 m;
	build_volume(m, s);
	return m;
}

CMap3 loaded(const std::string& rel)
{
	CMap3 m;
	io::load_volume(m, cgogn_test_data::path(rel));
	return m;
}

// A free face of w with n edges: one whose other side is a boundary volume.
CMap3::Face free_face(const CMap3& m, CMap3::Volume w, uint32 n, uint32 skip = 0)
{
	CMap3::Face r;
	foreach_incident_face(m, w, [&](CMap3::Face f) {
		const Dart d = is_boundary(m, f.dart) ? phi3(m, f.dart) : f.dart;
		if (!is_boundary(m, phi3(m, d)) || codegree(m, CMap3::Face(d)) != n)
			return true;
		if (skip > 0)
		{
			--skip;
			return true;
		}
		r = CMap3::Face(d);
		return false;
	});
	return r;
}

// A hexahedron with a pyramid on one face, a tetrahedron on a face of the
// pyramid, a triangular prism on another face of the hexahedron and a
// tetrahedron on the prism: every kind of cell, glued, with a boundary.
CMap3 mixed()
{
	CMap3 m;
	const CMap3::Volume hexa = add_hexa(m);
	const CMap3::Volume pyramid = add_pyramid(m, 4);
	const CMap3::Volume tetra = add_tetra(m);
	const CMap3::Volume prism = add_prism(m, 3);
	const CMap3::Volume tetra2 = add_tetra(m);
	sew_volumes(m, free_face(m, hexa, 4), free_face(m, pyramid, 4));
	sew_volumes(m, free_face(m, pyramid, 3), free_face(m, tetra, 3));
	bool sewn = false;
	for (uint32 k = 0; !sewn; ++k)
	{
		const CMap3::Face f = free_face(m, hexa, 4, k);
		if (!f.is_valid())
			break;
		const CMap3::Face q = free_face(m, prism, 4);
		if (can_sew_volumes(m, f, q))
		{
			sew_volumes(m, f, q);
			sewn = true;
		}
	}
	EXPECT_TRUE(sewn) << "no free face of the hexahedron takes the prism";
	sew_volumes(m, free_face(m, prism, 3), free_face(m, tetra2, 3));
	return m;
}

// Two hexahedra glued and a third apart: two components.
CMap3 two_components()
{
	CMap3 m;
	const CMap3::Volume a = add_hexa(m);
	const CMap3::Volume b = add_hexa(m);
	add_hexa(m);
	sew_volumes(m, free_face(m, a, 4), free_face(m, b, 4));
	return m;
}

std::vector<Mesh> meshes()
{
	std::vector<Mesh> out;
	out.emplace_back("tet grid", built(tet_grid_soup(3, 2, 2)));
	out.emplace_back("hex grid", built(hex_grid_soup(2, 3, 2)));
	out.emplace_back("mixed", mixed());
	out.emplace_back("two components", two_components());
	out.emplace_back("liver_hex_624", loaded("volume/liver_hex_624.mesh"));
	out.emplace_back("armadillo_tet_4k", loaded("volume/armadillo_tet_4k.mesh"));
	out.emplace_back("hex_dominant_11k", loaded("volume/hex_dominant_11k.mesh"));
	return out;
}

// What trav reports from each FROM cell of m, as sorted numbers, by the
// number of the FROM cell; a reported cell met twice is counted in `repeats`.
// Of more than 1000 FROM cells, about 1000 spread over the mesh (the same in
// every map: chosen by their numbers), to keep the test quick.
template <int FROM, int TO, typename MAP, typename TRAV>
std::unordered_map<uint32, std::vector<uint32>> reports(const Mesh& s, const MAP& m, const TRAV& trav, uint32& repeats)
{
	std::unordered_map<uint32, std::vector<uint32>> r;
	const uint32 stride = std::max(1u, nb_cells<CellOf<CMap3, FROM>>(s.c) / 1000);
	foreach_cell(m, [&](CellOf<MAP, FROM> x) {
		const uint32 id = s.template id<FROM>(m, x);
		if (id % stride != 0)
			return;
		std::vector<uint32>& row = r[id];
		trav(m, x, [&](CellOf<MAP, TO> y) { row.push_back(s.template id<TO>(m, y)); });
		std::sort(row.begin(), row.end());
		if (std::adjacent_find(row.begin(), row.end()) != row.end())
			++repeats;
		// f returning false stops the traversal at once
		uint32 calls = 0;
		trav(m, x, [&](CellOf<MAP, TO>) {
			++calls;
			return false;
		});
		EXPECT_EQ(calls, row.empty() ? 0u : 1u);
	});
	return r;
}

// trav on the G-map, indexed (g) and not (h), reports from every cell the
// cells it reports on the 3-map, each once.
template <int FROM, int TO, typename TRAV>
void expect_same_cells(const Mesh& s, const char* what, const TRAV& trav)
{
	uint32 repeats_c = 0, repeats_g = 0, repeats_h = 0;
	const auto rc = reports<FROM, TO>(s, s.c, trav, repeats_c);
	const auto rg = reports<FROM, TO>(s, s.g, trav, repeats_g);
	const auto rh = reports<FROM, TO>(s, s.h, trav, repeats_h);
	EXPECT_EQ(repeats_c, 0u) << s.name << ": " << what << " (CMap3)";
	EXPECT_EQ(repeats_g, 0u) << s.name << ": " << what << " (GMap3, indexed)";
	EXPECT_EQ(repeats_h, 0u) << s.name << ": " << what << " (GMap3, unindexed)";
	EXPECT_EQ(rg.size(), rc.size()) << s.name << ": " << what;
	EXPECT_EQ(rh.size(), rc.size()) << s.name << ": " << what;
	uint32 differ_g = 0, differ_h = 0;
	for (const auto& [id, cells] : rc)
	{
		const auto ig = rg.find(id), ih = rh.find(id);
		differ_g += ig == rg.end() || ig->second != cells;
		differ_h += ih == rh.end() || ih->second != cells;
	}
	EXPECT_EQ(differ_g, 0u) << s.name << ": " << what << " (GMap3, indexed): cells whose neighbours differ";
	EXPECT_EQ(differ_h, 0u) << s.name << ": " << what << " (GMap3, unindexed): cells whose neighbours differ";
}

#define CGOGN_TRAV(NAME) [](const auto& m, auto c, const auto& f) { NAME(m, c, f); }

void expect_all_traversals_agree(const Mesh& s)
{
	// incidences
	expect_same_cells<0, 1>(s, "vertex -> edges", CGOGN_TRAV(foreach_incident_edge));
	expect_same_cells<0, 2>(s, "vertex -> faces", CGOGN_TRAV(foreach_incident_face));
	expect_same_cells<0, 3>(s, "vertex -> volumes", CGOGN_TRAV(foreach_incident_volume));
	expect_same_cells<1, 0>(s, "edge -> vertices", CGOGN_TRAV(foreach_incident_vertex));
	expect_same_cells<1, 2>(s, "edge -> faces", CGOGN_TRAV(foreach_incident_face));
	expect_same_cells<1, 3>(s, "edge -> volumes", CGOGN_TRAV(foreach_incident_volume));
	expect_same_cells<2, 0>(s, "face -> vertices", CGOGN_TRAV(foreach_incident_vertex));
	expect_same_cells<2, 1>(s, "face -> edges", CGOGN_TRAV(foreach_incident_edge));
	expect_same_cells<2, 3>(s, "face -> volumes", CGOGN_TRAV(foreach_incident_volume));
	expect_same_cells<3, 0>(s, "volume -> vertices", CGOGN_TRAV(foreach_incident_vertex));
	expect_same_cells<3, 1>(s, "volume -> edges", CGOGN_TRAV(foreach_incident_edge));
	expect_same_cells<3, 2>(s, "volume -> faces", CGOGN_TRAV(foreach_incident_face));
	// adjacencies
	expect_same_cells<0, 0>(s, "vertex through edge", CGOGN_TRAV(foreach_adjacent_vertex_through_edge));
	expect_same_cells<0, 0>(s, "vertex through face", CGOGN_TRAV(foreach_adjacent_vertex_through_face));
	expect_same_cells<0, 0>(s, "vertex through volume", CGOGN_TRAV(foreach_adjacent_vertex_through_volume));
	expect_same_cells<1, 1>(s, "edge through vertex", CGOGN_TRAV(foreach_adjacent_edge_through_vertex));
	expect_same_cells<1, 1>(s, "edge through face", CGOGN_TRAV(foreach_adjacent_edge_through_face));
	expect_same_cells<1, 1>(s, "edge through volume", CGOGN_TRAV(foreach_adjacent_edge_through_volume));
	expect_same_cells<2, 2>(s, "face through vertex", CGOGN_TRAV(foreach_adjacent_face_through_vertex));
	expect_same_cells<2, 2>(s, "face through edge", CGOGN_TRAV(foreach_adjacent_face_through_edge));
	expect_same_cells<2, 2>(s, "face through volume", CGOGN_TRAV(foreach_adjacent_face_through_volume));
	expect_same_cells<3, 3>(s, "volume through vertex", CGOGN_TRAV(foreach_adjacent_volume_through_vertex));
	expect_same_cells<3, 3>(s, "volume through edge", CGOGN_TRAV(foreach_adjacent_volume_through_edge));
	expect_same_cells<3, 3>(s, "volume through face", CGOGN_TRAV(foreach_adjacent_volume_through_face));
}

// Every neighbour reported by trav from every FROM cell of m, in order (the
// darts), rows separated.
template <typename FROM, typename TO, typename TRAV>
std::vector<uint32> walk(const GMap3& m, const TRAV& trav)
{
	std::vector<uint32> r;
	foreach_cell(m, [&](FROM c) {
		r.push_back(INVALID_INDEX); // row separator
		trav(m, c, [&](TO x) { r.push_back(x.dart.index); });
	});
	return r;
}

// Builds the cache of FROM -> TO (through THROUGH), checks that the traversal
// reports the same neighbours in the same order through it, that
// check_integrity accepts it and that the table is read (a corrupted row
// shows).
template <typename FROM, typename TO, typename THROUGH, typename TRAV>
void expect_cached_equal(GMap3& m, const TRAV& trav)
{
	using Cache = IncidenceCache<GMap3, FROM, TO, THROUGH>;
	const std::vector<uint32> walked = walk<FROM, TO>(m, trav);
	Cache::build(m);
	ASSERT_TRUE(Cache::is_built(m));
	EXPECT_EQ((walk<FROM, TO>(m, trav)), walked);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	auto& t = **cgogn::detail::state_of(m).incidence_tables.begin();
	ASSERT_GT(t.targets.size(), 1u);
	std::swap(t.targets[0], t.targets[t.targets.size() - 1]);
	if (t.targets[0] != t.targets[t.targets.size() - 1])
	{
		EXPECT_NE((walk<FROM, TO>(m, trav)), walked) << "the table is read";
		EXPECT_TRUE(check_integrity(m).has(IntegrityError::Kind::IncidenceCacheStale));
	}
	Cache::remove(m);
	EXPECT_EQ((walk<FROM, TO>(m, trav)), walked);
}

} // namespace

TEST(GMap3Traversals, TheGMapReportsThe3MapsCells)
{
	for (const Mesh& s : meshes())
	{
		ASSERT_TRUE(check_integrity(s.c).ok()) << s.name << ": " << check_integrity(s.c).to_string();
		ASSERT_TRUE(check_integrity(s.h).ok()) << s.name << ": " << check_integrity(s.h).to_string();
		// the numbers identify the G-map's cells; the copy has no index
		EXPECT_EQ(nb_cells<GMap3::Volume>(s.h), nb_cells<CMap3::Volume>(s.c)) << s.name;
		EXPECT_FALSE(is_indexed<GMap3::Vertex>(s.h));
		EXPECT_FALSE(is_indexed<GMap3::Volume>(s.h));
		EXPECT_TRUE(is_indexed<GMap3::Edge>(s.g));
		expect_all_traversals_agree(s);
	}
}

// Without vertex lines a 3-map finds the neighbours of a vertex through its
// edges. Two edges may join the same two vertices (hex_dominant_11k has
// such): the neighbour is still reported once, as the walk by lines does.
TEST(GMap3Traversals, UnindexedAdjacentVerticesAreReportedOnce)
{
	for (const Mesh& s : meshes())
	{
		const CMap3 u = to_cmap(s.h);
		ASSERT_FALSE(is_indexed<CMap3::Vertex>(u));
		// each dart's vertex number, from a walk of the vertices
		std::vector<uint32> vertex_of(container_of<Orbit::DART>(u).end_index(), INVALID_INDEX);
		uint32 n = 0;
		foreach_cell(u, [&](CMap3::Vertex v) {
			foreach_dart_of_orbit(u, v, [&](Dart d) { vertex_of[d.index] = n; });
			++n;
		});
		uint64 total_u = 0, total_c = 0;
		uint32 repeats = 0, selves = 0;
		foreach_cell(u, [&](CMap3::Vertex v) {
			std::vector<uint32> row;
			foreach_adjacent_vertex_through_edge(u, v,
												 [&](CMap3::Vertex w) { row.push_back(vertex_of[w.dart.index]); });
			selves += uint32(std::count(row.begin(), row.end(), vertex_of[v.dart.index]));
			std::sort(row.begin(), row.end());
			repeats += std::adjacent_find(row.begin(), row.end()) != row.end();
			total_u += row.size();
		});
		foreach_cell(s.c, [&](CMap3::Vertex v) {
			foreach_adjacent_vertex_through_edge(s.c, v, [&](CMap3::Vertex) { ++total_c; });
		});
		EXPECT_EQ(repeats, 0u) << s.name << ": vertices with a neighbour reported twice";
		EXPECT_EQ(selves, 0u) << s.name;
		EXPECT_EQ(total_u, total_c) << s.name;
	}
}

TEST(GMap3Traversals, IncidenceCachesReportTheWalks)
{
	using V = GMap3::Vertex;
	using E = GMap3::Edge;
	using F = GMap3::Face;
	using W = GMap3::Volume;
	std::vector<CMap3> sources;
	sources.push_back(built(tet_grid_soup(3, 2, 2)));
	sources.push_back(built(hex_grid_soup(2, 2, 3)));
	sources.push_back(mixed());
	for (const CMap3& c : sources)
	{
		GMap3 m = to_gmap(c);
		expect_cached_equal<V, E, void>(m, CGOGN_TRAV(foreach_incident_edge));
		expect_cached_equal<V, F, void>(m, CGOGN_TRAV(foreach_incident_face));
		expect_cached_equal<V, W, void>(m, CGOGN_TRAV(foreach_incident_volume));
		expect_cached_equal<E, F, void>(m, CGOGN_TRAV(foreach_incident_face));
		expect_cached_equal<E, W, void>(m, CGOGN_TRAV(foreach_incident_volume));
		expect_cached_equal<F, V, void>(m, CGOGN_TRAV(foreach_incident_vertex));
		expect_cached_equal<F, E, void>(m, CGOGN_TRAV(foreach_incident_edge));
		expect_cached_equal<W, V, void>(m, CGOGN_TRAV(foreach_incident_vertex));
		expect_cached_equal<W, E, void>(m, CGOGN_TRAV(foreach_incident_edge));
		expect_cached_equal<W, F, void>(m, CGOGN_TRAV(foreach_incident_face));
		expect_cached_equal<V, V, E>(m, CGOGN_TRAV(foreach_adjacent_vertex_through_edge));
		expect_cached_equal<V, V, F>(m, CGOGN_TRAV(foreach_adjacent_vertex_through_face));
		expect_cached_equal<V, V, W>(m, CGOGN_TRAV(foreach_adjacent_vertex_through_volume));
		expect_cached_equal<E, E, V>(m, CGOGN_TRAV(foreach_adjacent_edge_through_vertex));
		expect_cached_equal<E, E, F>(m, CGOGN_TRAV(foreach_adjacent_edge_through_face));
		expect_cached_equal<E, E, W>(m, CGOGN_TRAV(foreach_adjacent_edge_through_volume));
		expect_cached_equal<F, F, V>(m, CGOGN_TRAV(foreach_adjacent_face_through_vertex));
		expect_cached_equal<F, F, E>(m, CGOGN_TRAV(foreach_adjacent_face_through_edge));
		expect_cached_equal<F, F, W>(m, CGOGN_TRAV(foreach_adjacent_face_through_volume));
		expect_cached_equal<W, W, V>(m, CGOGN_TRAV(foreach_adjacent_volume_through_vertex));
		expect_cached_equal<W, W, E>(m, CGOGN_TRAV(foreach_adjacent_volume_through_edge));
		expect_cached_equal<W, W, F>(m, CGOGN_TRAV(foreach_adjacent_volume_through_face));
		// a topological change drops the tables
		IncidenceCache<GMap3, V, E>::build(m);
		EXPECT_TRUE((IncidenceCache<GMap3, V, E>::is_built(m)));
		beta_unsew<3>(m, Dart(0));
		EXPECT_FALSE((IncidenceCache<GMap3, V, E>::is_built(m)));
	}
}

TEST(GMap3Traversals, OrdersAroundEdgesAndAlongFaces)
{
	// around an edge, consecutive faces share a volume (boundary volumes
	// included); along a face, edge i joins vertices i and i + 1
	const CMap3 c = built(hex_grid_soup(2, 2, 2));
	const GMap3 g = to_gmap(c);
	auto share_a_volume = [&](Dart a, Dart b) {
		for (Dart x : {a, beta3(g, a)})
			for (Dart y : {b, beta3(g, b)})
				if (same_orbit(g, GMap3::Volume(x), GMap3::Volume(y)))
					return true;
		return false;
	};
	foreach_cell(g, [&](GMap3::Edge e) {
		std::vector<Dart> faces;
		foreach_incident_face(g, e, [&](GMap3::Face f) { faces.push_back(f.dart); });
		EXPECT_GE(faces.size(), 2u);
		for (std::size_t i = 0; i < faces.size(); ++i)
			EXPECT_TRUE(share_a_volume(faces[i], faces[(i + 1) % faces.size()]));
	});
	foreach_cell(g, [&](GMap3::Face f) {
		std::vector<GMap3::Edge> edges;
		foreach_incident_edge(g, f, [&](GMap3::Edge e) { edges.push_back(e); });
		std::vector<GMap3::Vertex> vertices;
		foreach_incident_vertex(g, f, [&](GMap3::Vertex v) { vertices.push_back(v); });
		ASSERT_EQ(edges.size(), vertices.size());
		for (std::size_t i = 0; i < edges.size(); ++i)
		{
			// edge i runs from vertex i to vertex i + 1
			EXPECT_TRUE(same_orbit(g, GMap3::Vertex(edges[i].dart), vertices[i]));
			EXPECT_TRUE(same_orbit(g, GMap3::Vertex(beta0(g, edges[i].dart)), vertices[(i + 1) % vertices.size()]));
		}
	});
}

TEST(GMap3Traversals, TheSurfaceTraversalsServeTheCellsOfOneVolume)
{
	// the GMap2 traversals, given the cells of one volume (GMap2's cell types)
	const GMap3 g = to_gmap(built(hex_grid_soup(2, 2, 2)));
	uint32 volumes = 0;
	foreach_cell(g, [&](GMap3::Volume w) {
		++volumes;
		uint32 edges = 0, faces = 0, vertices = 0, in_volume = 0;
		foreach_incident_edge(g, GMap3::Vertex2(w.dart), [&](GMap3::Edge2) { ++edges; });
		foreach_incident_face(g, GMap3::Vertex2(w.dart), [&](GMap3::Face2) { ++faces; });
		foreach_incident_vertex(g, GMap3::Face2(w.dart), [&](GMap3::Vertex2) { ++vertices; });
		foreach_incident_volume(g, GMap3::Face2(w.dart), [&](GMap3::Volume x) { in_volume += same_orbit(g, x, w); });
		EXPECT_EQ(edges, 3u);
		EXPECT_EQ(faces, 3u);
		EXPECT_EQ(vertices, 4u);
		EXPECT_EQ(in_volume, 1u);
	});
	EXPECT_EQ(volumes, 8u);
}

} // namespace cgogn_test_gmap3_traversals
