// SPDX-License-Identifier: MIT
// Misuse that must not compile. Each case is built on its own (CGOGN_CASE);
// the ctest case expects the build to fail with the message named in
// CMakeLists.txt. Case "control" must build: it proves the setup is sound.
#include <cgogn/cgogn.h>

using namespace cgogn;

#define CASE(name) (CGOGN_CASE == CGOGN_CASE_##name)

void misuse()
{
	CMap1 m1;
	CMap2 m2;
	CMap3 m3;
	GMap3 g3;
	const CMap2& c2 = m2;
	auto pos2 = add_attribute<Vec3, CMap2::Vertex>(m2, "position");
	auto pos3 = add_attribute<Vec3, CMap3::Vertex>(m3, "position");
	auto area = add_attribute<double, CMap2::Face>(m2, "area");
	(void)m1;
	(void)g3;
	(void)c2;
	(void)pos3;
	(void)area;
	MRMap2 mr{CMap2()};
	auto level_value = add_attribute<double, MRMap2::Vertex>(mr, "h");
	const MRLevelView2 level0 = level_view(mr, 0);
	(void)level0;
#if CASE(control)
	// the legitimate forms of every call below
	add_face(m2, 4);
	add_pyramid(m3, 4);
	cut_edge(m2, CMap2::Edge(Dart(0)));
	cut_edge(m3, CMap3::Edge(Dart(0)));
	cut_edge(m1, CMap1::Edge(Dart(0)));
	flip_edge(m2, CMap2::Edge(Dart(0)));
	modeling::triangulate_faces(m2, *pos2);
	const Vec3& p = value(c2, pos2, CMap2::Vertex(Dart(0)));
	(*pos2)[CMap2::Vertex(Dart(0))] = p;
	(*area)[CMap2::Face(Dart(0))] = 1.0;
	(void)io::load_volume(g3, "volume.mesh");
	add_level(mr, Refinement::Quadrangular);
	value(mr, level_value, MRMap2::Vertex(Dart(0))) = value(level0, level_value, MRMap2::Vertex(Dart(0)));
#elif CASE(add_face_on_3map)
	add_face(m3, 4); // would create darts without phi3
#elif CASE(cut_edge_2d_on_3map)
	cut_edge(m3, CMap2::Edge(Dart(0)));
#elif CASE(flip_edge_2d_on_3map)
	flip_edge(m3, CMap2::Edge(Dart(0)));
#elif CASE(cut_edge_1d_on_2map)
	cut_edge(m2, CMap2::HalfEdge(Dart(0))); // CMap1's operator: phi2 left unset
#elif CASE(collapse_edge_1d_on_3map)
	collapse_edge(m3, CMap3::HalfEdge(Dart(0)));
#elif CASE(decimate_on_3map)
	modeling::decimate(m3, *pos3, modeling::DecimationOptions{});
#elif CASE(triangulate_faces_on_3map)
	modeling::triangulate_faces(m3, *pos3);
#elif CASE(subdivision_on_3map)
	modeling::loop_subdivision(m3, *pos3);
#elif CASE(load_surface_on_gmap3)
	io::load_surface(g3, "surface.off"); // a GMap3 is a GMap2: it would be read as a surface
#elif CASE(value_on_const_map_is_read_only)
	value(c2, area, CMap2::Face(Dart(0))) = 1.0;
#elif CASE(attribute_indexed_by_other_orbit)
	(*area)[CMap2::Vertex(Dart(0))] = 1.0;
#elif CASE(flip_edge_on_mrmap2)
	flip_edge(mr, MRMap2::Edge(Dart(0))); // the labels of the hierarchy would break
#elif CASE(value_on_level_view_is_read_only)
	value(level0, level_value, MRMap2::Vertex(Dart(0))) = 1.0;
#elif CASE(map_members_are_private)
	(void)m2.darts_; // the maps' containers are reached through the free functions
#else
#error "unknown CGOGN_CASE"
#endif
}

int main()
{
	misuse();
	return 0;
}
