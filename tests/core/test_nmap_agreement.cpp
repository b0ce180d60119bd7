// SPDX-License-Identifier: MIT
// The maps of any dimension against the tuned maps of dimension 2 and 3 on
// real meshes: the same cells, incidences, adjacencies and properties, and
// the generic functions on the tuned maps themselves.
#include <cgogn/core.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cgogn_test_data.h>
#include <map>
#include <nmap_test_support.h>
#include <string>
#include <vector>

namespace cgogn_test_nmap_agreement
{

using namespace cgogn;
using cgogn::test::key_of;
using cgogn::test::relation;

namespace
{

// Incidence I -> J and adjacency of I-cells through K-cells, by the generic
// functions, on any map, each cell once or (given each_incidence) once per
// incidence.
template <uint32 I, uint32 J, typename MAP, typename... EACH>
std::map<uint32, std::vector<uint32>> incidence(const MAP& m, EACH... each)
{
	return relation<cell_of_dimension_t<MAP, I>>(m, [&](auto c, const auto& put) {
		foreach_incident_cell<J>(
			m, c, [&](auto x) { put(x); }, each...);
	});
}
template <uint32 I, uint32 K, typename MAP, typename... EACH>
std::map<uint32, std::vector<uint32>> adjacency(const MAP& m, EACH... each)
{
	return relation<cell_of_dimension_t<MAP, I>>(m, [&](auto c, const auto& put) {
		foreach_adjacent_cell<K>(
			m, c, [&](auto x) { put(x); }, each...);
	});
}

template <typename MAP>
void expect_compact(const MAP& m)
{
	ASSERT_EQ(nb_darts(m), container_of<Orbit::DART>(m).end_index()) << "the darts keep their indices only if compact";
}

} // namespace

TEST(NMapAgreement, SurfacesGiveTheCellsAndNeighboursOfTheCMap2)
{
	for (const char* file : {"surface/elephant-with-holes.off", "surface/fandisk_quads.off", "surface/torus_quad.off",
							 "surface/spot_control_mesh.obj"})
	{
		SCOPED_TRACE(file);
		CMap2 m;
		io::load_surface(m, cgogn_test_data::path(file));
		expect_compact(m);
		const CMapN<2> n = to_nmap(m);
		EXPECT_TRUE(check_integrity(n).ok()) << check_integrity(n).to_string();
		EXPECT_EQ(f_vector(n), f_vector(m));
		EXPECT_EQ(f_vector(n), (std::vector<uint32>{nb_cells<CMap2::Vertex>(m), nb_cells<CMap2::Edge>(m),
													nb_cells<CMap2::Face>(m)}));
		EXPECT_EQ(euler_characteristic(n), euler_characteristic(m));
		EXPECT_EQ(nb_connected_components(n), nb_connected_components(m));
		EXPECT_EQ(has_boundary(n), has_boundary(m));
		// the tuned circulators of the CMap2, the generic ones of the CMapN
		const auto faces_of_vertices = relation<CMap2::Vertex>(
			m, [&](CMap2::Vertex v, const auto& put) { foreach_incident_face(m, v, [&](CMap2::Face f) { put(f); }); });
		EXPECT_EQ((incidence<0, 2>(n)), faces_of_vertices);
		EXPECT_EQ((incidence<0, 2>(m)), faces_of_vertices);
		const auto vertex_neighbours = relation<CMap2::Vertex>(m, [&](CMap2::Vertex v, const auto& put) {
			foreach_adjacent_vertex_through_edge(m, v, [&](CMap2::Vertex w) { put(w); });
		});
		EXPECT_EQ((adjacency<0, 1>(n)), vertex_neighbours);
		EXPECT_EQ((adjacency<0, 1>(m)), vertex_neighbours);
		const auto face_neighbours = relation<CMap2::Face>(m, [&](CMap2::Face f, const auto& put) {
			foreach_adjacent_face_through_edge(m, f, [&](CMap2::Face g) { put(g); });
		});
		EXPECT_EQ((adjacency<2, 1>(n)), face_neighbours);
		EXPECT_EQ((incidence<1, 0>(n)), (incidence<1, 0>(m)));
		EXPECT_EQ((incidence<2, 1>(n)), (incidence<2, 1>(m)));
		// once per incidence: the contract of the tuned circulators
		EXPECT_EQ((incidence<0, 2>(n, each_incidence)), faces_of_vertices);
		EXPECT_EQ((incidence<0, 2>(m, each_incidence)), faces_of_vertices);
		EXPECT_EQ((incidence<2, 0>(n, each_incidence)), relation<CMap2::Face>(m, [&](CMap2::Face f, const auto& put) {
					  foreach_incident_vertex(m, f, [&](CMap2::Vertex v) { put(v); });
				  }));
		EXPECT_EQ((incidence<0, 1>(n, each_incidence)),
				  relation<CMap2::Vertex>(m, [&](CMap2::Vertex v, const auto& put) {
					  foreach_incident_edge(m, v, [&](CMap2::Edge e) { put(e); });
				  }));
		EXPECT_EQ((adjacency<0, 1>(n, each_incidence)), vertex_neighbours);
		EXPECT_EQ((adjacency<2, 1>(n, each_incidence)), face_neighbours);
		EXPECT_EQ((adjacency<0, 2>(n, each_incidence)), (adjacency<0, 2>(m, each_incidence)));
		// and back: the same map
		const CMap2 back = to_fixed_map(n);
		EXPECT_TRUE(check_integrity(back).ok());
		EXPECT_EQ(f_vector(back), f_vector(m));
	}
}

TEST(NMapAgreement, VolumesGiveTheCellsAndNeighboursOfTheCMap3)
{
	for (const char* file : {"volume/armadillo_tet_4k.mesh", "volume/liver_hex_624.mesh"})
	{
		SCOPED_TRACE(file);
		CMap3 m;
		io::load_volume(m, cgogn_test_data::path(file));
		expect_compact(m);
		const CMapN<3> n = to_nmap(m);
		EXPECT_TRUE(check_integrity(n).ok()) << check_integrity(n).to_string();
		EXPECT_EQ(f_vector(n), f_vector(m));
		EXPECT_EQ(euler_characteristic(n), euler_characteristic(m));
		EXPECT_EQ(nb_connected_components(n), nb_connected_components(m));
		const auto volumes_of_vertices = relation<CMap3::Vertex>(m, [&](CMap3::Vertex v, const auto& put) {
			foreach_incident_volume(m, v, [&](CMap3::Volume w) { put(w); });
		});
		EXPECT_EQ((incidence<0, 3>(n)), volumes_of_vertices);
		EXPECT_EQ((incidence<0, 3>(m)), volumes_of_vertices);
		const auto faces_of_edges = relation<CMap3::Edge>(
			m, [&](CMap3::Edge e, const auto& put) { foreach_incident_face(m, e, [&](CMap3::Face f) { put(f); }); });
		EXPECT_EQ((incidence<1, 2>(n)), faces_of_edges);
		const auto volume_neighbours = relation<CMap3::Volume>(m, [&](CMap3::Volume w, const auto& put) {
			foreach_adjacent_volume_through_face(m, w, [&](CMap3::Volume x) { put(x); });
		});
		EXPECT_EQ((adjacency<3, 2>(n)), volume_neighbours);
		EXPECT_EQ((adjacency<3, 2>(m)), volume_neighbours);
		const auto vertex_neighbours = relation<CMap3::Vertex>(m, [&](CMap3::Vertex v, const auto& put) {
			foreach_adjacent_vertex_through_edge(m, v, [&](CMap3::Vertex w) { put(w); });
		});
		EXPECT_EQ((adjacency<0, 1>(n)), vertex_neighbours);
		// once per incidence: the contract of the tuned circulators
		EXPECT_EQ((incidence<0, 3>(n, each_incidence)), volumes_of_vertices);
		EXPECT_EQ((incidence<0, 3>(m, each_incidence)), volumes_of_vertices);
		EXPECT_EQ((incidence<1, 2>(n, each_incidence)), faces_of_edges);
		EXPECT_EQ((incidence<0, 2>(n, each_incidence)),
				  relation<CMap3::Vertex>(m, [&](CMap3::Vertex v, const auto& put) {
					  foreach_incident_face(m, v, [&](CMap3::Face f) { put(f); });
				  }));
		EXPECT_EQ((incidence<0, 1>(n, each_incidence)),
				  relation<CMap3::Vertex>(m, [&](CMap3::Vertex v, const auto& put) {
					  foreach_incident_edge(m, v, [&](CMap3::Edge e) { put(e); });
				  }));
		EXPECT_EQ((incidence<3, 0>(n, each_incidence)),
				  relation<CMap3::Volume>(m, [&](CMap3::Volume w, const auto& put) {
					  foreach_incident_vertex(m, w, [&](CMap3::Vertex v) { put(v); });
				  }));
		EXPECT_EQ((adjacency<3, 2>(n, each_incidence)), volume_neighbours);
		EXPECT_EQ((adjacency<0, 1>(n, each_incidence)), vertex_neighbours);
		// the boundary surface, extracted, is the CMap2 of the boundary
		const CMapN<2> b = extract_boundary(n);
		EXPECT_TRUE(check_integrity(b).ok()) << check_integrity(b).to_string();
		uint32 boundary_faces = 0;
		foreach_cell(m, [&](CMap3::Face f) { boundary_faces += is_incident_to_boundary(m, f); });
		EXPECT_EQ(f_vector(b).back(), boundary_faces);
	}
}

TEST(NMapAgreement, NonOrientableSurfacesGiveTheCellsOfTheGMap2)
{
	for (const char* file : {"surface/mobius_strip.off", "surface/klein_bottle.off"})
	{
		SCOPED_TRACE(file);
		GMap2 m;
		io::load_surface(m, cgogn_test_data::path(file));
		expect_compact(m);
		const GMapN<2> n = to_nmap(m);
		EXPECT_TRUE(check_integrity(n).ok()) << check_integrity(n).to_string();
		EXPECT_EQ(f_vector(n), f_vector(m));
		EXPECT_EQ(euler_characteristic(n), euler_characteristic(m));
		EXPECT_FALSE(is_orientable(n));
		EXPECT_EQ((incidence<0, 2>(n)), (incidence<0, 2>(m)));
		EXPECT_EQ((adjacency<0, 1>(n)), (adjacency<0, 1>(m)));
		EXPECT_EQ((incidence<0, 2>(n, each_incidence)),
				  relation<GMap2::Vertex>(m, [&](GMap2::Vertex v, const auto& put) {
					  foreach_incident_face(m, v, [&](GMap2::Face f) { put(f); });
				  }));
		EXPECT_EQ((adjacency<0, 1>(n, each_incidence)),
				  relation<GMap2::Vertex>(m, [&](GMap2::Vertex v, const auto& put) {
					  foreach_adjacent_vertex_through_edge(m, v, [&](GMap2::Vertex w) { put(w); });
				  }));
		EXPECT_EQ((incidence<2, 0>(n, each_incidence)), (incidence<2, 0>(m, each_incidence)));
	}
}

} // namespace cgogn_test_nmap_agreement
