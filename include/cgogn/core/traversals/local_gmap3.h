// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/traversals/local_cell_set.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap2.h>

namespace cgogn
{

// Local traversals of 3-G-maps, with the names, orders and boundary handling
// of the CMap3 ones (local_cmap3.h), and like them reading an IncidenceCache
// of the relation when one is built. f may return false to stop. Boundary
// volumes are never reported. Around an edge the order is the cyclic order of
// the faces and volumes around it (beta3 o beta2), along a face the order of
// its corners (beta1 o beta0); around a vertex and in a volume no order can be
// assumed (they are flooded with pooled marks: allocation-free once warm).
// Adjacencies report each cell once and never the starting cell.
//
// A 3-G-map has twice the darts of the 3-map of the same mesh, and its walks
// visit twice as many: a vertex or a volume flood costs twice the CMap3's,
// the walks around an edge and along a face visit one dart per face or
// corner, as the CMap3's do. Volumes have no tetrahedron shortcut (the CMap3
// reads a tetrahedron's corners without marks): their vertices are flooded.
//
// These overloads take `const GMap3&`: for a GMap3 they win over the GMap2
// ones (GMap3 derives from GMap2, and GMap2::Volume is GMap3::Volume, so a
// GMap2 traversal of a volume would otherwise accept it). The GMap2
// traversals still serve the cells of one volume (Vertex2, Edge2, Face2, the
// GMap2 cell types), as the CMap2 ones do for a CMap3.

namespace detail
{

/// Calls f once per cell of type CELL incident to vertex v (boundary volumes
/// skipped), marking at each new cell the darts of v in that cell: in an edge
/// the cycle of beta2 and beta3 at v, in a face its four darts at v
/// (d, beta1 d, beta3 d, beta1 beta3 d), in a volume the corner of v in it
/// (Vertex2, beta1 and beta2). O(size of the orbit of v).
template <typename CELL, typename FUNC>
void foreach_cell_around_vertex3(const GMap3& m, GMap3::Vertex v, const FUNC& f)
{
	DartMarkerStore<GMap3> seen(m);
	foreach_dart_of_orbit(m, v, [&](Dart d) {
		if (seen.is_marked(d))
			return true;
		if constexpr (std::is_same_v<CELL, GMap3::Edge>)
		{
			Dart it = d;
			do
			{
				const Dart it2 = beta2(m, it);
				seen.mark(it);
				seen.mark(it2);
				it = beta3(m, it2);
			} while (it != d);
		}
		else if constexpr (std::is_same_v<CELL, GMap3::Face>)
		{
			const Dart d1 = beta1(m, d);
			seen.mark(d);
			seen.mark(d1);
			seen.mark(beta3(m, d));
			seen.mark(beta3(m, d1));
		}
		else
		{
			static_assert(std::is_same_v<CELL, GMap3::Volume>);
			seen.mark_orbit(GMap3::Vertex2(d));
		}
		return is_boundary_cell(m, CELL(d)) || call_and_continue(f, CELL(d));
	});
}

/// Calls f once per cell of type CELL (Vertex, Edge or Face) of the volume of
/// `start`, marking at each new cell its darts in the volume (a Vertex2,
/// Edge2 or Face2 orbit). The cells of a boundary volume are real cells of the
/// mesh: none is skipped. O(darts of the volume).
template <typename CELL, typename FUNC>
void foreach_cell_of_volume3(const GMap3& m, Dart start, const FUNC& f)
{
	DartMarkerStore<GMap3> dm(m);
	foreach_dart_of_orbit(m, GMap3::Volume(start), [&](Dart d) {
		if (dm.is_marked(d))
			return true;
		if constexpr (std::is_same_v<CELL, GMap3::Vertex>)
			dm.mark_orbit(GMap3::Vertex2(d));
		else if constexpr (std::is_same_v<CELL, GMap3::Edge>)
			dm.mark_orbit(GMap3::Edge2(d));
		else
		{
			static_assert(std::is_same_v<CELL, GMap3::Face>);
			dm.mark_orbit(GMap3::Face2(d));
		}
		return is_boundary_cell(m, CELL(d)) || call_and_continue(f, CELL(d));
	});
}

} // namespace detail

// ---- incidences of a vertex

/// Edges incident to vertex v, each once (no defined order); the dart given
/// for each edge is a dart of v. O(size of the orbit of v).
template <typename FUNC>
void foreach_incident_edge(const GMap3& m, CellParam<GMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Edge, void>(m, v, f))
		return;
	detail::foreach_cell_around_vertex3<GMap3::Edge>(m, v, f);
}
/// Faces incident to vertex v, each once (no defined order). O(size of the
/// orbit of v).
template <typename FUNC>
void foreach_incident_face(const GMap3& m, CellParam<GMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Face, void>(m, v, f))
		return;
	detail::foreach_cell_around_vertex3<GMap3::Face>(m, v, f);
}
/// Volumes incident to vertex v, each once, boundary volumes skipped (no
/// defined order). O(size of the orbit of v).
template <typename FUNC>
void foreach_incident_volume(const GMap3& m, CellParam<GMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Volume, void>(m, v, f))
		return;
	detail::foreach_cell_around_vertex3<GMap3::Volume>(m, v, f);
}

// ---- incidences of an edge

/// The two vertices of edge e: that of e.dart first, then that of
/// beta0(e.dart). O(1).
template <typename FUNC>
void foreach_incident_vertex(const GMap3& m, CellParam<GMap3::Edge> e, const FUNC& f)
{
	if (call_and_continue(f, GMap3::Vertex(e.dart)))
		call_and_continue(f, GMap3::Vertex(beta0(m, e.dart)));
}
/// Faces around edge e, in cyclic order from that of e.dart (beta3 o beta2:
/// one dart per face). O(degree of e).
template <typename FUNC>
void foreach_incident_face(const GMap3& m, CellParam<GMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Face, void>(m, e, f))
		return;
	detail::foreach_step_of<2, 3>(m, e.dart, [&](Dart d) { return call_and_continue(f, GMap3::Face(d)); });
}
/// Volumes around edge e, in cyclic order from that of e.dart, boundary
/// volumes skipped. O(degree of e).
template <typename FUNC>
void foreach_incident_volume(const GMap3& m, CellParam<GMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Volume, void>(m, e, f))
		return;
	detail::foreach_step_of<2, 3>(m, e.dart,
								  [&](Dart d) { return is_boundary(m, d) || call_and_continue(f, GMap3::Volume(d)); });
}

// ---- incidences of a face

/// Vertices of face f, in the order of its corners from f.dart (beta1 o
/// beta0, on the side of f.dart). O(codegree of f).
template <typename FUNC>
void foreach_incident_vertex(const GMap3& m, CellParam<GMap3::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<GMap3::Vertex, void>(m, f, fn))
		return;
	detail::foreach_step_of<0, 1>(m, f.dart, [&](Dart d) { return call_and_continue(fn, GMap3::Vertex(d)); });
}
/// Edges of face f, in the same order: that of f.dart first. O(codegree of f).
template <typename FUNC>
void foreach_incident_edge(const GMap3& m, CellParam<GMap3::Face> f, const FUNC& fn)
{
	if (detail::foreach_cached<GMap3::Edge, void>(m, f, fn))
		return;
	detail::foreach_step_of<0, 1>(m, f.dart, [&](Dart d) { return call_and_continue(fn, GMap3::Edge(d)); });
}
/// The one or two volumes of face f: that of f.dart first (boundary volumes
/// skipped). O(1).
template <typename FUNC>
void foreach_incident_volume(const GMap3& m, CellParam<GMap3::Face> f, const FUNC& fn)
{
	if (!is_boundary(m, f.dart) && !call_and_continue(fn, GMap3::Volume(f.dart)))
		return;
	const Dart d3 = beta3(m, f.dart);
	if (!is_boundary(m, d3))
		call_and_continue(fn, GMap3::Volume(d3));
}

// ---- incidences of a volume

/// Vertices of volume w, each once (no defined order). O(darts of w).
template <typename FUNC>
void foreach_incident_vertex(const GMap3& m, CellParam<GMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Vertex, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume3<GMap3::Vertex>(m, w.dart, f);
}
/// Edges of volume w, each once (no defined order). O(darts of w).
template <typename FUNC>
void foreach_incident_edge(const GMap3& m, CellParam<GMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Edge, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume3<GMap3::Edge>(m, w.dart, f);
}
/// Faces of volume w, each once (no defined order). O(darts of w).
template <typename FUNC>
void foreach_incident_face(const GMap3& m, CellParam<GMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Face, void>(m, w, f))
		return;
	detail::foreach_cell_of_volume3<GMap3::Face>(m, w.dart, f);
}

// foreach_incident_cell3 and detail::foreach_adjacent3 (local_cmap3.h) serve
// both 3-maps and 3-G-maps.

// ---- adjacencies: X adjacent to x through a common Y, each once, x excluded

/// Vertices joined to v by an edge, each once (no defined order): at beta0
/// of the darts of v. With indexed vertices they are told apart by a mark on
/// their lines (one flood of v, see detail::foreach_adjacent_vertex_by_line):
/// O(size of the orbit of v). Without (or when a vertex has no line), by
/// marking the darts of each neighbour found, since two edges may join the
/// same two vertices (two faces not glued, as a non-conforming mesh has):
/// O(size of the orbit of v + sum of the sizes of the neighbours' orbits).
template <typename FUNC>
void foreach_adjacent_vertex_through_edge(const GMap3& m, CellParam<GMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Vertex, GMap3::Edge>(m, v, f))
		return;
	if (is_indexed<GMap3::Vertex>(m) && detail::foreach_adjacent_vertex_by_line(m, v, f))
		return;
	// two edges may join v to the same vertex (and a loop edge to v itself):
	// each neighbour is reported once, v never. Darts are marked, not lines:
	// this walk also serves vertices left without a line by an operator.
	DartMarkerStore<GMap3> seen(m);
	seen.mark_orbit(v);
	foreach_incident_edge(m, v, [&](GMap3::Edge e) {
		// e.dart is a dart of v (see foreach_cell_around_vertex3): beta0 is at the other end
		const GMap3::Vertex w(beta0(m, e.dart));
		if (seen.is_marked(w.dart))
			return true;
		seen.mark_orbit(w);
		return call_and_continue(f, w);
	});
}
/// Vertices sharing a face with v, each once, v excluded. O(sum of the sizes
/// of the faces of v and of their vertices).
template <typename FUNC>
void foreach_adjacent_vertex_through_face(const GMap3& m, CellParam<GMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Vertex, GMap3::Face>(m, v, f))
		return;
	detail::foreach_adjacent3<GMap3::Vertex, GMap3::Face>(m, v, f);
}
/// Vertices sharing a (non-boundary) volume with v, each once, v excluded.
/// O(sum of the sizes of the volumes of v and of their vertices).
template <typename FUNC>
void foreach_adjacent_vertex_through_volume(const GMap3& m, CellParam<GMap3::Vertex> v, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Vertex, GMap3::Volume>(m, v, f))
		return;
	detail::foreach_adjacent3<GMap3::Vertex, GMap3::Volume>(m, v, f);
}
/// Edges sharing a vertex with e, each once, e excluded. O(sum of the sizes
/// of its two vertices and of their edges).
template <typename FUNC>
void foreach_adjacent_edge_through_vertex(const GMap3& m, CellParam<GMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Edge, GMap3::Vertex>(m, e, f))
		return;
	detail::foreach_adjacent3<GMap3::Edge, GMap3::Vertex>(m, e, f);
}
/// Edges sharing a face with e, each once, e excluded. O(sum of the sizes of
/// the faces around e and of their edges).
template <typename FUNC>
void foreach_adjacent_edge_through_face(const GMap3& m, CellParam<GMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Edge, GMap3::Face>(m, e, f))
		return;
	detail::foreach_adjacent3<GMap3::Edge, GMap3::Face>(m, e, f);
}
/// Edges sharing a (non-boundary) volume with e, each once, e excluded.
/// O(sum of the darts of the volumes around e).
template <typename FUNC>
void foreach_adjacent_edge_through_volume(const GMap3& m, CellParam<GMap3::Edge> e, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Edge, GMap3::Volume>(m, e, f))
		return;
	detail::foreach_adjacent3<GMap3::Edge, GMap3::Volume>(m, e, f);
}
/// Faces sharing a vertex with fc, each once, fc excluded. O(sum of the
/// sizes of its vertices and of their faces).
template <typename FUNC>
void foreach_adjacent_face_through_vertex(const GMap3& m, CellParam<GMap3::Face> fc, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Face, GMap3::Vertex>(m, fc, f))
		return;
	detail::foreach_adjacent3<GMap3::Face, GMap3::Vertex>(m, fc, f);
}
/// Faces sharing an edge with fc, each once, fc excluded. O(sum of the
/// degrees of its edges and of the sizes of their faces).
template <typename FUNC>
void foreach_adjacent_face_through_edge(const GMap3& m, CellParam<GMap3::Face> fc, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Face, GMap3::Edge>(m, fc, f))
		return;
	detail::foreach_adjacent3<GMap3::Face, GMap3::Edge>(m, fc, f);
}
/// Faces sharing a (non-boundary) volume with fc, each once, fc excluded.
/// O(darts of its one or two volumes).
template <typename FUNC>
void foreach_adjacent_face_through_volume(const GMap3& m, CellParam<GMap3::Face> fc, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Face, GMap3::Volume>(m, fc, f))
		return;
	detail::foreach_adjacent3<GMap3::Face, GMap3::Volume>(m, fc, f);
}
/// Non-boundary volumes sharing a vertex with w, each once, w excluded.
/// O(darts of w + sum of the sizes of its vertices).
template <typename FUNC>
void foreach_adjacent_volume_through_vertex(const GMap3& m, CellParam<GMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Volume, GMap3::Vertex>(m, w, f))
		return;
	detail::foreach_adjacent3<GMap3::Volume, GMap3::Vertex>(m, w, f);
}
/// Non-boundary volumes sharing an edge with w, each once, w excluded.
/// O(darts of w + sum of the degrees of its edges).
template <typename FUNC>
void foreach_adjacent_volume_through_edge(const GMap3& m, CellParam<GMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Volume, GMap3::Edge>(m, w, f))
		return;
	detail::foreach_adjacent3<GMap3::Volume, GMap3::Edge>(m, w, f);
}
/// Non-boundary volumes sharing a face with w, each once, w excluded.
/// O(darts of w).
template <typename FUNC>
void foreach_adjacent_volume_through_face(const GMap3& m, CellParam<GMap3::Volume> w, const FUNC& f)
{
	if (detail::foreach_cached<GMap3::Volume, GMap3::Face>(m, w, f))
		return;
	detail::foreach_adjacent3<GMap3::Volume, GMap3::Face>(m, w, f);
}

} // namespace cgogn
