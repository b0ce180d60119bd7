// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap3.h>

#include <vector>

namespace cgogn
{

// A CMap3 is a CMap2 is a CMap1 (public inheritance: the 3-map reuses the
// lower maps' relations and traversals). So an operator of a lower dimension
// would accept a higher map through the derived-to-base conversion, and
// would leave the map broken: add_face(CMap3&, n) creates darts without
// phi3, cut_edge(CMap2&, HalfEdge) inserts a dart without its phi2 partner.
// The overloads below take the higher map exactly, so they win that
// overload resolution, and are deleted: such a call does not compile
// ("use of deleted function"). Operators meant for a higher map have their
// own overloads (cut_edge(CMap3&, CMap3::Edge), add_pyramid(CMap3&, n), ...).

// ---- 1-map operators on 2- and 3-maps

CMap1::Vertex cut_edge(CMap2& m, CMap1::Edge e, bool set_indices = true) = delete;
CMap1::Vertex cut_edge(CMap3& m, CMap1::Edge e, bool set_indices = true) = delete;
CMap1::Vertex collapse_edge(CMap2& m, CMap1::Edge e, bool set_indices = true) = delete;
CMap1::Vertex collapse_edge(CMap3& m, CMap1::Edge e, bool set_indices = true) = delete;

// ---- 1- and 2-map operators on 3-maps

CMap2::Face add_face(CMap3& m, uint32 n, bool set_indices = true) = delete;
void remove_face(CMap3& m, CMap2::Face f, bool set_indices = true) = delete;
CMap2::Vertex cut_edge(CMap3& m, CMap2::Edge e, bool set_indices = true) = delete;
bool can_collapse_edge(const CMap3& m, CMap2::Edge e) = delete;
CMap2::Vertex collapse_edge(CMap3& m, CMap2::Edge e, bool set_indices = true) = delete;
bool can_flip_edge(const CMap3& m, CMap2::Edge e) = delete;
void flip_edge(CMap3& m, CMap2::Edge e, bool set_indices = true) = delete;
void flip_back_edge(CMap3& m, CMap2::Edge e, bool set_indices = true) = delete;
bool can_flip_back_edge(const CMap3& m, CMap2::Edge e) = delete;
bool can_cut_face(const CMap3& m, CMap2::Vertex v1, CMap2::Vertex v2) = delete;
CMap2::Edge cut_face(CMap3& m, CMap2::Vertex v1, CMap2::Vertex v2, bool set_indices = true) = delete;
bool can_merge_incident_faces(const CMap3& m, CMap2::Edge e) = delete;
CMap2::Face merge_incident_faces(CMap3& m, CMap2::Edge e, bool set_indices = true) = delete;
bool can_merge_incident_faces(const CMap3& m, CMap2::Vertex v) = delete;
CMap2::Face merge_incident_faces(CMap3& m, CMap2::Vertex v, bool set_indices = true) = delete;
bool can_merge_incident_edges(const CMap3& m, CMap2::Vertex v) = delete;
CMap2::Edge merge_incident_edges(CMap3& m, CMap2::Vertex v, bool set_indices = true) = delete;
CMap2::Edge split_vertex(CMap3& m, Dart d1, Dart d2, bool set_indices = true) = delete;
CMap2::Vertex triangulate_face(CMap3& m, CMap2::Face f, bool set_indices = true) = delete;
CMap2::Face close_hole(CMap3& m, Dart d, bool mark_boundary, bool set_indices) = delete;
bool can_fill_hole_with_face(const CMap3& m, Dart d) = delete;
CMap2::Face fill_hole_with_face(CMap3& m, Dart d, bool set_indices = true) = delete;
// the former names of the predicates and of fill_hole_with_face
bool edge_can_collapse(const CMap3& m, CMap2::Edge e) = delete;
bool edge_can_flip(const CMap3& m, CMap2::Edge e) = delete;
bool edge_can_flip_back(const CMap3& m, CMap2::Edge e) = delete;
bool can_fill_hole(const CMap3& m, Dart d) = delete;
CMap2::Face fill_hole(CMap3& m, Dart d, bool set_indices = true) = delete;
bool can_sew_faces(const CMap3& m, CMap2::Edge e1, CMap2::Edge e2) = delete;
void sew_faces(CMap3& m, CMap2::Edge e1, CMap2::Edge e2, bool set_indices = true) = delete;
void unsew_faces(CMap3& m, CMap2::Edge e, bool set_indices = true) = delete;
void reverse_orientation(CMap3& m) = delete;
std::vector<Dart> merge(CMap3& m, const CMap2& other) = delete;
std::vector<Dart> merge(CMap2& m, const CMap3& other) = delete;
std::vector<Dart> merge(CMap3& m, const CMap3& other) = delete;

// ---- 1-G-map operators on 2-G-maps (GMap2 derives from GMap1 in the same
// way): an edge of a polygon is not an edge of a surface
GMap1::Vertex cut_edge(GMap2& m, GMap1::Edge e, bool set_indices = true) = delete;
GMap1::Vertex collapse_edge(GMap2& m, GMap1::Edge e, bool set_indices = true) = delete;

// ---- 1- and 2-G-map operators on 3-G-maps (GMap3 derives from GMap2): they
// would leave beta3 unlinked
GMap1::Vertex cut_edge(GMap3& m, GMap1::Edge e, bool set_indices = true) = delete;
GMap1::Vertex collapse_edge(GMap3& m, GMap1::Edge e, bool set_indices = true) = delete;
GMap2::Face add_face(GMap3& m, uint32 n, bool set_indices = true) = delete;
GMap2::Vertex cut_edge(GMap3& m, GMap2::Edge e, bool set_indices = true) = delete;
bool can_collapse_edge(const GMap3& m, GMap2::Edge e) = delete;
GMap2::Vertex collapse_edge(GMap3& m, GMap2::Edge e, bool set_indices = true) = delete;
bool can_flip_edge(const GMap3& m, GMap2::Edge e) = delete;
void flip_edge(GMap3& m, GMap2::Edge e, bool set_indices = true) = delete;
bool can_flip_back_edge(const GMap3& m, GMap2::Edge e) = delete;
void flip_back_edge(GMap3& m, GMap2::Edge e, bool set_indices = true) = delete;
bool can_cut_face(const GMap3& m, GMap2::Vertex v1, GMap2::Vertex v2) = delete;
GMap2::Edge cut_face(GMap3& m, GMap2::Vertex v1, GMap2::Vertex v2, bool set_indices = true) = delete;
bool can_merge_incident_faces(const GMap3& m, GMap2::Edge e) = delete;
GMap2::Face merge_incident_faces(GMap3& m, GMap2::Edge e, bool set_indices = true) = delete;
GMap2::Vertex triangulate_face(GMap3& m, GMap2::Face f, bool set_indices = true) = delete;
GMap2::Face close_hole(GMap3& m, Dart d, bool mark_boundary = true, bool set_indices = true) = delete;
uint32 close(GMap3& m, bool set_indices = true) = delete;
bool can_fill_hole_with_face(const GMap3& m, Dart d) = delete;
GMap2::Face fill_hole_with_face(GMap3& m, Dart d, bool set_indices = true) = delete;
bool can_sew_faces(const GMap3& m, GMap2::Edge e1, GMap2::Edge e2) = delete;
void sew_faces(GMap3& m, GMap2::Edge e1, GMap2::Edge e2, bool set_indices = true) = delete;
bool can_unsew_faces(const GMap3& m, GMap2::Edge e) = delete;
void unsew_faces(GMap3& m, GMap2::Edge e, bool set_indices = true) = delete;

} // namespace cgogn
