// SPDX-License-Identifier: MIT
// The refinement of one face of a multiresolution 2-map (add_level and
// subdivide_face).
#pragma once

#include <cgogn/core/map/mrmap2.h>

#include <vector>

namespace cgogn::detail
{

/// Labels the darts created by one refinement with their level and edge id,
/// counts them, and keeps them when asked (for the local indexing of
/// subdivide_face).
class MRNewDarts
{
public:
	MRNewDarts(MRState2& s, uint8 level, bool keep = false) : s_(s), level_(level), keep_(keep)
	{
	}
	/// Labels the two darts of edge d (a new edge, or a new piece of a cut one).
	void label_edge(Dart d, uint8 edge_id)
	{
		label(d, edge_id);
		label(phi2(s_.map, d), edge_id);
	}
	/// Labels dart d.
	void label(Dart d, uint8 edge_id)
	{
		(*s_.level)[d.index] = level_;
		(*s_.edge_id)[d.index] = edge_id;
		++count_;
		if (keep_)
			darts_.push_back(d);
	}
	/// The number of darts labelled.
	uint32 count() const
	{
		return count_;
	}
	/// The darts labelled (when kept).
	const std::vector<Dart>& darts() const
	{
		return darts_;
	}

private:
	MRState2& s_;
	uint8 level_;
	bool keep_;
	uint32 count_ = 0;
	std::vector<Dart> darts_;
};

/// The smallest edge id in {0, 1, 2} different from a and b: a new inner edge
/// differs from the edges whose midpoints it joins, so that phi1 at a coarser
/// level, turning around those midpoints, does not take it.
uint8 mr_new_edge_id(uint8 a, uint8 b);

/// Joins the edge midpoints of a triangle whose edges are cut: c[i] is the
/// dart leaving the midpoint of the i-th edge (in phi1 order). Runs the
/// finest map's operators without indices. O(1).
void mr_refine_triangle(MRState2& s, MRNewDarts& labels, const Dart (&c)[3]);

/// Joins the k edge midpoints of a face whose edges are cut to a new centre:
/// c[i] is the dart leaving the midpoint of the i-th edge (in phi1 order).
/// O(k).
void mr_refine_quadrangular(MRState2& s, MRNewDarts& labels, const std::vector<Dart>& c);

} // namespace cgogn::detail
