// SPDX-License-Identifier: MIT
// The refinement of one face of a multiresolution 2-map (add_level and
// subdivide_face).
#include "mrmap2_refine.h"

#include <cgogn/core/operators/cmap2.h>

namespace cgogn::detail
{

uint8 mr_new_edge_id(uint8 a, uint8 b)
{
	uint8 id = 0;
	while (id == a || id == b)
		++id;
	return id;
}

/// Joins the edge midpoints of a triangle whose edges are cut: c[i] is the
/// dart leaving the midpoint of the i-th edge (in phi1 order).
void mr_refine_triangle(MRState2& s, MRNewDarts& labels, const Dart (&c)[3])
{
	const auto id = [&](Dart d) { return (*s.edge_id)[d.index]; };
	// cut off the corners at the ends of c[0], c[1] and c[2] in turn
	const CMap2::Edge e0 = cut_face(s.map, CMap2::Vertex(c[0]), CMap2::Vertex(c[1]), false);
	labels.label_edge(e0.dart, mr_new_edge_id(id(c[0]), id(c[1])));
	const CMap2::Edge e1 = cut_face(s.map, CMap2::Vertex(c[1]), CMap2::Vertex(c[2]), false);
	labels.label_edge(e1.dart, mr_new_edge_id(id(c[1]), id(c[2])));
	const CMap2::Edge e2 = cut_face(s.map, CMap2::Vertex(c[2]), CMap2::Vertex(e0.dart), false);
	labels.label_edge(e2.dart, mr_new_edge_id(id(c[2]), id(c[0])));
}

/// Joins the k edge midpoints of a face whose edges are cut to a new centre:
/// c[i] is the dart leaving the midpoint of the i-th edge (in phi1 order).
void mr_refine_quadrangular(MRState2& s, MRNewDarts& labels, const std::vector<Dart>& c)
{
	const auto id = [&](Dart d) { return (*s.edge_id)[d.index]; };
	// an inner edge differs from the edge whose midpoint it leaves
	const auto inner_id = [&](Dart mid) { return mr_new_edge_id(id(mid), id(mid)); };
	const CMap2::Edge across = cut_face(s.map, CMap2::Vertex(c[0]), CMap2::Vertex(c[2]), false);
	const Dart a = across.dart; // midpoint 0 -> midpoint 2
	const CMap2::Vertex centre = cut_edge(s.map, across, false);
	labels.label_edge(a, inner_id(c[0]));
	labels.label_edge(centre.dart, inner_id(c[2])); // centre -> midpoint 2
	// the centre's dart in the face of midpoint 1
	const CMap2::Edge e1 = cut_face(s.map, CMap2::Vertex(phi2(s.map, a)), CMap2::Vertex(c[1]), false);
	labels.label_edge(e1.dart, inner_id(c[1]));
	// midpoints 3 ... k - 1 lie in the face of centre.dart, each cut leaving the next in the new part
	Dart from_centre = centre.dart;
	for (std::size_t i = 3; i < c.size(); ++i)
	{
		const CMap2::Edge e = cut_face(s.map, CMap2::Vertex(from_centre), CMap2::Vertex(c[i]), false);
		labels.label_edge(e.dart, inner_id(c[i]));
		from_centre = e.dart;
	}
}

} // namespace cgogn::detail
