// 2-G-maps: building from soups (orientable or not), cells, attributes,
// traversals, properties and integrity, against known surfaces and against
// the CMap2 built from the same soup.
#include <cgogn/core.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace cgogn_test_gmap2
{

using namespace cgogn;

namespace
{

struct Counts
{
	uint32 vertices, edges, faces, boundary_loops, components;
	int64 chi;
	bool operator==(const Counts&) const = default;
};

template <typename MAP>
Counts counts(const MAP& m)
{
	using T = mesh_traits<MAP>;
	return {nb_cells<typename T::Vertex>(m), nb_cells<typename T::Edge>(m), nb_cells<typename T::Face>(m),
			nb_boundary_components(m),       nb_connected_components(m),    euler_characteristic(m)};
}

// The sorted degrees of the vertices, and the sorted codegrees of the faces.
template <typename MAP>
std::pair<std::vector<uint32>, std::vector<uint32>> degrees(const MAP& m)
{
	using T = mesh_traits<MAP>;
	std::vector<uint32> dv, cf;
	foreach_cell(m, [&](typename T::Vertex v) { dv.push_back(degree(m, v)); });
	foreach_cell(m, [&](typename T::Face f) { cf.push_back(codegree(m, f)); });
	std::sort(dv.begin(), dv.end());
	std::sort(cf.begin(), cf.end());
	return {dv, cf};
}

void expect_valid(const GMap2& m)
{
	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.ok()) << r.to_string();
}

} // namespace

TEST(GMap2, OneTriangleHasSixDartsAndABoundaryFace)
{
	GMap2 m;
	const std::vector<uint32> sizes{3}, ids{0, 1, 2};
	const BuildReport r = build_surface(m, 3, sizes, ids);
	EXPECT_EQ(r.nb_cells_built, 1u);
	EXPECT_EQ(r.nb_boundary_cells, 1u);
	EXPECT_EQ(nb_darts(m), 12u); // 6 in the triangle, 6 in the hole
	EXPECT_EQ(counts(m), (Counts{3, 3, 1, 1, 1, 1}));
	EXPECT_TRUE(is_orientable(m));
	expect_valid(m);
	// a face's darts: beta0 and beta1 alternate, 3 edges
	const Dart d(0);
	EXPECT_EQ(beta0(m, beta0(m, d)), d);
	EXPECT_EQ((beta<0, 1, 0, 1, 0, 1>(m, d)), d);
	EXPECT_NE((beta<0, 1>(m, d)), d);
	EXPECT_EQ(codegree(m, GMap2::Face(d)), 3u);
	EXPECT_EQ(degree(m, GMap2::Vertex(d)), 2u);
	EXPECT_EQ(degree(m, GMap2::Edge(d)), 1u);
	EXPECT_TRUE(is_incident_to_boundary(m, GMap2::Edge(d)));
}

TEST(GMap2, MobiusStripStaysWhole)
{
	GMap2 m;
	const BuildReport r = build_surface(m, mobius_soup(24));
	EXPECT_EQ(r.nb_nonmanifold_edges, 0u);
	EXPECT_EQ(r.nb_nonmanifold_vertices, 0u);
	EXPECT_EQ(r.nb_boundary_cells, 1u);
	EXPECT_EQ(counts(m), (Counts{48, 72, 24, 1, 1, 0}));
	EXPECT_FALSE(is_orientable(m));
	EXPECT_EQ(nb_darts(m), 24u * 8 + 48 * 2);
	expect_valid(m);
}

TEST(GMap2, KleinBottleIsClosed)
{
	for (bool triangles : {false, true})
	{
		GMap2 m;
		const BuildReport r = build_surface(m, klein_bottle_soup(16, 8, triangles));
		EXPECT_EQ(r.nb_nonmanifold_edges + r.nb_nonmanifold_vertices + r.nb_boundary_cells, 0u);
		const uint32 faces = triangles ? 256 : 128;
		EXPECT_EQ(counts(m), (Counts{128, 128 + faces, faces, 0, 1, 0}));
		EXPECT_FALSE(is_orientable(m));
		EXPECT_FALSE(has_boundary(m));
		expect_valid(m);
	}
}

TEST(GMap2, ProjectivePlanes)
{
	GMap2 ico;
	build_surface(ico, hemi_icosahedron_soup());
	EXPECT_EQ(counts(ico), (Counts{6, 15, 10, 0, 1, 1}));
	EXPECT_FALSE(is_orientable(ico));
	expect_valid(ico);
	foreach_cell(ico, [&](GMap2::Vertex v) { EXPECT_EQ(degree(ico, v), 5u); });

	GMap2 cube;
	build_surface(cube, hemi_cube_soup());
	EXPECT_EQ(counts(cube), (Counts{4, 6, 3, 0, 1, 1}));
	EXPECT_FALSE(is_orientable(cube));
	expect_valid(cube);
}

TEST(GMap2, OrientableSoupsGiveTheCMap2sCells)
{
	const std::vector<SurfaceSoup> soups{grid_soup(7, 5), grid_soup(4, 6, true), cylinder_soup(9, 3),
										 sphere_soup(12, 7), torus_soup(10, 6, true)};
	for (const SurfaceSoup& s : soups)
	{
		CMap2 c;
		GMap2 g;
		build_surface(c, s);
		build_surface(g, s);
		EXPECT_EQ(counts(g), counts(c));
		EXPECT_EQ(degrees(g), degrees(c));
		EXPECT_EQ(nb_darts(g), 2 * nb_darts(c));
		EXPECT_TRUE(is_orientable(g));
		expect_valid(g);
		// the same vertex lines: soup vertex i is line i in both
		std::vector<uint32> cv, gv;
		foreach_cell(c, [&](CMap2::Vertex v) { cv.push_back(index_of(c, v)); });
		foreach_cell(g, [&](GMap2::Vertex v) { gv.push_back(index_of(g, v)); });
		std::sort(cv.begin(), cv.end());
		std::sort(gv.begin(), gv.end());
		EXPECT_EQ(gv, cv);
	}
}

TEST(GMap2, AttributesOnEveryCellKind)
{
	GMap2 m;
	const SurfaceSoup s = torus_soup(6, 4);
	build_surface(m, s);
	auto pos = add_attribute<std::array<double, 3>, GMap2::Vertex>(m, "position");
	for (uint32 v = 0; v < s.nb_vertices; ++v)
		(*pos)[v] = s.positions[v];
	auto edge_id = add_attribute<uint32, GMap2::Edge>(m, "id");
	auto face_area = add_attribute<double, GMap2::Face>(m, "area");
	EXPECT_TRUE(is_indexed<GMap2::Edge>(m));
	EXPECT_TRUE(is_indexed<GMap2::Face>(m));
	uint32 k = 0;
	foreach_cell(m, [&](GMap2::Edge e) { value<uint32>(m, edge_id, e) = k++; });
	EXPECT_EQ(k, 48u);
	// every dart of an edge reads the edge's value
	foreach_cell(m, [&](GMap2::Edge e) {
		const uint32 id = value<uint32>(m, edge_id, e);
		foreach_dart_of_orbit(m, e, [&](Dart d) { EXPECT_EQ(value<uint32>(m, edge_id, GMap2::Edge(d)), id); });
	});
	foreach_cell(m, [&](GMap2::Face f) { value<double>(m, face_area, f) = 1.0; });
	double total = 0;
	foreach_cell(m, [&](GMap2::Face f) { total += value<double>(m, face_area, f); });
	EXPECT_EQ(total, 24.0);
	// the positions of a vertex's darts are the soup's
	using Vec3 = std::array<double, 3>;
	foreach_cell(m, [&](GMap2::Vertex v) {
		foreach_dart_of_orbit(m, v, [&](Dart d) {
			const Vec3& p = value<Vec3>(m, pos, GMap2::Vertex(d));
			EXPECT_EQ(p, s.positions[index_of(m, v)]);
		});
	});
	expect_valid(m);
}

TEST(GMap2, OrbitsHaveTheirSizes)
{
	GMap2 m;
	build_surface(m, grid_soup(3, 3));
	std::map<uint32, uint32> vertex_sizes;
	foreach_cell(m, [&](GMap2::Vertex v) {
		uint32 n = 0;
		foreach_dart_of_orbit(m, v, [&](Dart) { ++n; });
		++vertex_sizes[n];
	});
	// 4 corners (2 edges: 4 darts), 8 border vertices (3 edges), 4 inner (4 edges)
	EXPECT_EQ(vertex_sizes, (std::map<uint32, uint32>{{4, 4}, {6, 8}, {8, 4}}));
	foreach_cell(m, [&](GMap2::Edge e) {
		uint32 n = 0;
		foreach_dart_of_orbit(m, e, [&](Dart) { ++n; });
		EXPECT_EQ(n, 4u);
	});
	// stopping a traversal early
	uint32 seen = 0;
	foreach_dart_of_orbit(m, GMap2::Face(Dart(0)), [&](Dart) { return ++seen < 3; });
	EXPECT_EQ(seen, 3u);
}

TEST(GMap2, IntegrityFindsBrokenInvolutions)
{
	GMap2 m;
	build_surface(m, sphere_soup(6, 4));
	expect_valid(m);
	// beta2 made one-sided: no longer an involution
	const Dart d(0), e = beta2(m, d);
	detail::set_beta<2>(m, d, beta0(m, e));
	IntegrityReport r = check_integrity(m);
	EXPECT_FALSE(r.ok());
	EXPECT_TRUE(r.has(IntegrityError::Kind::PhiNotInvolution)) << r.to_string();
	detail::set_beta<2>(m, d, e);
	expect_valid(m);
	// beta2 o beta0 not an involution: the far ends of two edges exchanged,
	// so that d's edge is glued to one face at d and to another at beta0(d)
	const Dart d0 = beta0(m, d), e0 = beta0(m, e);
	const Dart f0 = beta0(m, beta1(m, d)), g0 = beta2(m, f0);
	beta_unsew<2>(m, d0);
	beta_unsew<2>(m, f0);
	beta_sew<2>(m, d0, g0);
	beta_sew<2>(m, e0, f0);
	r = check_integrity(m);
	EXPECT_TRUE(r.has(IntegrityError::Kind::BetaCompositionNotInvolution)) << r.to_string();
}

TEST(GMap2, ParallelTraversalVisitsEveryCell)
{
	GMap2 m;
	build_surface(m, klein_bottle_soup(40, 30, true));
	std::atomic<uint32> n = 0;
	parallel_foreach_cell(m, [&](GMap2::Face) { ++n; });
	EXPECT_EQ(n.load(), 2400u);
	n = 0;
	parallel_foreach_cell(m, [&](GMap2::Vertex) { ++n; });
	EXPECT_EQ(n.load(), 1200u);
}

namespace
{

// (position, degree) of every vertex, sorted: the same multiset in two maps
// of the same surface whatever their dart and line numbers.
template <typename MAP>
std::vector<std::pair<std::array<double, 3>, uint32>> vertex_signature(const MAP& m)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	auto pos = get_attribute<std::array<double, 3>, Vertex>(m, "position");
	std::vector<std::pair<std::array<double, 3>, uint32>> out;
	foreach_cell(m, [&](Vertex v) { out.emplace_back(value(m, pos, v), degree(m, v)); });
	std::sort(out.begin(), out.end());
	return out;
}

template <typename MAP>
std::vector<double> face_values(const MAP& m, const std::string& name)
{
	using Face = typename mesh_traits<MAP>::Face;
	auto a = get_attribute<double, Face>(m, name);
	std::vector<double> out;
	foreach_cell(m, [&](Face f) { out.push_back(value(m, a, f)); });
	std::sort(out.begin(), out.end());
	return out;
}

template <typename MAP>
void add_data(MAP& m, const SurfaceSoup& s)
{
	using T = mesh_traits<MAP>;
	auto pos = add_attribute<std::array<double, 3>, typename T::Vertex>(m, "position");
	for (uint32 v = 0; v < s.nb_vertices; ++v)
		(*pos)[v] = s.positions[v];
	auto degree_of = add_attribute<double, typename T::Face>(m, "degree");
	foreach_cell(m, [&](typename T::Face f) { value(m, degree_of, f) = double(codegree(m, f)); });
	add_attribute<uint32, typename T::Edge>(m, "edge_data");
}

} // namespace

TEST(GMap2, ConversionsCarryCellsAndAttributes)
{
	for (const SurfaceSoup& s : {grid_soup(5, 4), sphere_soup(8, 5, true), torus_soup(6, 5), cylinder_soup(7, 3)})
	{
		CMap2 c;
		build_surface(c, s);
		add_data(c, s);
		const GMap2 g = to_gmap(c);
		expect_valid(g);
		EXPECT_EQ(nb_darts(g), 2 * nb_darts(c));
		EXPECT_EQ(counts(g), counts(c));
		EXPECT_EQ(degrees(g), degrees(c));
		EXPECT_EQ(vertex_signature(g), vertex_signature(c));
		EXPECT_EQ(face_values(g, "degree"), face_values(c, "degree"));
		EXPECT_TRUE((get_attribute<uint32, GMap2::Edge>(g, "edge_data")));
		EXPECT_TRUE(is_orientable(g));

		const CMap2 back = to_cmap(g);
		EXPECT_TRUE(check_integrity(back).ok()) << check_integrity(back).to_string();
		EXPECT_EQ(nb_darts(back), nb_darts(c));
		EXPECT_EQ(counts(back), counts(c));
		EXPECT_EQ(degrees(back), degrees(c));
		EXPECT_EQ(vertex_signature(back), vertex_signature(c));
		EXPECT_EQ(face_values(back, "degree"), face_values(c, "degree"));
	}
	// from a G-map built directly, too
	GMap2 g;
	const SurfaceSoup s = sphere_soup(9, 4);
	build_surface(g, s);
	add_data(g, s);
	const CMap2 c = to_cmap(g);
	EXPECT_TRUE(check_integrity(c).ok());
	EXPECT_EQ(counts(c), counts(g));
	EXPECT_EQ(vertex_signature(c), vertex_signature(g));
}

TEST(GMap2, ANonOrientableGMapHasNoCMap)
{
	GMap2 g;
	build_surface(g, klein_bottle_soup(5, 4));
	EXPECT_THROW(to_cmap(g), TopologyError);
}

TEST(GMap2, SoupOrientationIsTheGMapsOrientability)
{
	// a Möbius strip: one edge glues two faces listing it the same way
	{
		const SurfaceSoup s = mobius_soup(5);
		const auto [orientable, conflicts] = soup_orientation(s.nb_vertices, s.face_sizes, s.face_vertices);
		EXPECT_FALSE(orientable);
		EXPECT_EQ(conflicts, 1u);
	}
	// a grid with one face turned over: conflicts, yet orientable
	{
		SurfaceSoup s = grid_soup(3, 3);
		std::reverse(s.face_vertices.begin() + 4 * 4, s.face_vertices.begin() + 4 * 5); // the middle quad
		const auto [orientable, conflicts] = soup_orientation(s.nb_vertices, s.face_sizes, s.face_vertices);
		EXPECT_TRUE(orientable);
		EXPECT_EQ(conflicts, 4u);
		GMap2 g;
		const BuildReport r = build_surface(g, s);
		EXPECT_TRUE(r.orientable);
		EXPECT_TRUE(is_orientable(g));
		EXPECT_EQ(counts(g), (Counts{16, 24, 9, 1, 1, 1}));
		CMap2 c;
		const BuildReport rc = build_surface(c, s);
		EXPECT_EQ(rc.nb_orientation_conflicts, 4u);
		EXPECT_EQ(rc.nb_nonmanifold_edges, 4u); // the CMap2 detaches the turned face there
	}
	// non-manifold edges, glued two by two: the report agrees with the G-map
	for (uint32 turned = 0; turned < 16; ++turned)
	{
		// four triangles on the edge (0, 1), each listing it one way or the other,
		// and two more joining the first and the third through vertex 2's edges
		std::vector<std::vector<uint32>> faces{{0, 1, 2}, {0, 1, 3}, {0, 1, 4}, {0, 1, 5}, {1, 2, 4}, {0, 2, 4}};
		for (uint32 k = 0; k < 4; ++k)
			if (turned & (1u << k))
				std::swap(faces[k][0], faces[k][1]);
		std::vector<uint32> sizes, ids;
		for (const auto& f : faces)
		{
			sizes.push_back(3);
			ids.insert(ids.end(), f.begin(), f.end());
		}
		GMap2 g;
		const BuildReport r = build_surface(g, 6, sizes, ids);
		EXPECT_EQ(r.orientable, is_orientable(g)) << turned;
		expect_valid(g);
	}
}

namespace
{

// The cells around each vertex and face of a surface, named by vertex lines
// (the builders give soup vertex i line i in both models): vertices by their
// line, edges by their two ends, faces by their sorted vertices.
template <typename MAP>
std::map<std::string, std::vector<std::vector<uint32>>> neighbourhoods(const MAP& m)
{
	using T = mesh_traits<MAP>;
	using Vertex = typename T::Vertex;
	using Edge = typename T::Edge;
	using Face = typename T::Face;
	const auto vertex_name = [&](Vertex v) { return std::vector<uint32>{index_of(m, v)}; };
	const auto edge_name = [&](Edge e) {
		std::vector<uint32> n;
		foreach_incident_vertex(m, e, [&](Vertex v) { n.push_back(index_of(m, v)); });
		std::sort(n.begin(), n.end());
		return n;
	};
	const auto face_name = [&](Face f) {
		std::vector<uint32> n;
		foreach_incident_vertex(m, f, [&](Vertex v) { n.push_back(index_of(m, v)); });
		std::sort(n.begin(), n.end());
		return n;
	};
	std::map<std::string, std::vector<std::vector<uint32>>> out;
	auto add = [&](const std::string& key, std::vector<std::vector<uint32>> names, std::vector<uint32> of) {
		std::sort(names.begin(), names.end());
		std::vector<uint32> row = of;
		row.push_back(INVALID_INDEX);
		for (const auto& n : names)
		{
			row.insert(row.end(), n.begin(), n.end());
			row.push_back(INVALID_INDEX);
		}
		out[key].push_back(row);
	};
	foreach_cell(m, [&](Vertex v) {
		std::vector<std::vector<uint32>> e, f, av, avf;
		foreach_incident_edge(m, v, [&](Edge x) { e.push_back(edge_name(x)); });
		foreach_incident_face(m, v, [&](Face x) { f.push_back(face_name(x)); });
		foreach_adjacent_vertex_through_edge(m, v, [&](Vertex x) { av.push_back(vertex_name(x)); });
		foreach_adjacent_vertex_through_face(m, v, [&](Vertex x) { avf.push_back(vertex_name(x)); });
		add("vertex-edges", e, vertex_name(v));
		add("vertex-faces", f, vertex_name(v));
		add("vertex-vertices-by-edge", av, vertex_name(v));
		add("vertex-vertices-by-face", avf, vertex_name(v));
	});
	foreach_cell(m, [&](Edge x) {
		std::vector<std::vector<uint32>> f, aev, aef;
		foreach_incident_face(m, x, [&](Face y) { f.push_back(face_name(y)); });
		foreach_adjacent_edge_through_vertex(m, x, [&](Edge y) { aev.push_back(edge_name(y)); });
		foreach_adjacent_edge_through_face(m, x, [&](Edge y) { aef.push_back(edge_name(y)); });
		add("edge-faces", f, edge_name(x));
		add("edge-edges-by-vertex", aev, edge_name(x));
		add("edge-edges-by-face", aef, edge_name(x));
	});
	foreach_cell(m, [&](Face x) {
		std::vector<std::vector<uint32>> e, af, afv;
		foreach_incident_edge(m, x, [&](Edge y) { e.push_back(edge_name(y)); });
		foreach_adjacent_face_through_edge(m, x, [&](Face y) { af.push_back(face_name(y)); });
		foreach_adjacent_face_through_vertex(m, x, [&](Face y) { afv.push_back(face_name(y)); });
		add("face-edges", e, face_name(x));
		add("face-faces-by-edge", af, face_name(x));
		add("face-faces-by-vertex", afv, face_name(x));
	});
	for (auto& [k, rows] : out)
		std::sort(rows.begin(), rows.end());
	return out;
}

} // namespace

TEST(GMap2, LocalTraversalsGiveTheCMap2sNeighbours)
{
	for (const SurfaceSoup& s :
		 {grid_soup(4, 3), grid_soup(3, 3, true), sphere_soup(7, 5), torus_soup(6, 5, true), cylinder_soup(5, 2)})
	{
		CMap2 c;
		GMap2 g;
		build_surface(c, s);
		build_surface(g, s);
		const auto nc = neighbourhoods(c), ng = neighbourhoods(g);
		ASSERT_EQ(nc.size(), ng.size());
		for (const auto& [key, rows] : nc)
			EXPECT_EQ(ng.at(key), rows) << key;
	}
	// on a Möbius strip: every face has its 4 vertices and 2 or 3 neighbours
	GMap2 g;
	build_surface(g, mobius_soup(8));
	foreach_cell(g, [&](GMap2::Face f) {
		uint32 nv = 0, nf = 0;
		foreach_incident_vertex(g, f, [&](GMap2::Vertex) { ++nv; });
		foreach_adjacent_face_through_edge(g, f, [&](GMap2::Face) { ++nf; });
		EXPECT_EQ(nv, 4u);
		EXPECT_EQ(nf, 2u);
	});
	uint32 n = 0;
	foreach_incident_face(g, GMap2::Volume(Dart(0)), [&](GMap2::Face) { ++n; });
	EXPECT_EQ(n, 8u);
}

} // namespace cgogn_test_gmap2
