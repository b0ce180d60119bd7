// SPDX-License-Identifier: MIT
// Operators of 1-G-maps: add a polygon, cut and collapse an edge.
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/operators/gmap1.h>

#include "gmap_darts.h"
#include "index_lines.h"
#include "reindex.h"

#include <cassert>
#include <vector>

namespace cgogn
{

GMap1::Face add_face(GMap1& m, uint32 n, bool set_indices)
{
	assert(n >= 1);
	std::vector<Dart> darts;
	darts.reserve(2 * n);
	for (uint32 i = 0; i < n; ++i)
	{
		const Dart d = detail::add_dart_pair(m);
		darts.insert(darts.end(), {d, beta0(m, d)});
	}
	// edge i is the pair (darts[2i], darts[2i+1]); vertex i+1 joins darts[2i+1] and darts[2i+2]
	for (uint32 i = 0; i < n; ++i)
		beta_sew<1>(m, darts[2 * i + 1], darts[(2 * i + 2) % (2 * n)]);
	if (set_indices)
		detail::index_new_darts(m, darts);
	return GMap1::Face(darts[0]);
}

GMap1::Vertex cut_edge(GMap1& m, GMap1::Edge e, bool set_indices)
{
	std::vector<Dart> region{e.dart, beta0(m, e.dart)};
	detail::RegionReindexer<GMap1> reindex;
	if (set_indices)
		reindex.record(m, region);
	const std::vector<Dart> added = detail::insert_vertex_in_edge(m, e.dart);
	region.insert(region.end(), added.begin(), added.end());
	if (set_indices)
		reindex.apply(m, region);
	return GMap1::Vertex(added[0]);
}

GMap1::Vertex collapse_edge(GMap1& m, GMap1::Edge e, bool set_indices)
{
	const Dart d = e.dart, d0 = beta0(m, e.dart);
	const Dart p = beta1(m, d), q = beta1(m, d0);
	assert(p != d0 && "the polygon has at least 2 edges");
	detail::RegionReindexer<GMap1> reindex;
	if (set_indices)
		reindex.record(m, {q, p, d, d0});
	detail::link_beta<1>(m, p, q);
	detail::remove_dart_pair(m, d);
	if (set_indices)
		reindex.apply(m, {q, p}); // q first: the vertex keeps the line of the end that survives
	return GMap1::Vertex(q);
}

} // namespace cgogn
