// SPDX-License-Identifier: MIT
// Face operators of 2-G-maps: add a polygon, triangulate a face.
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/gmap2.h>

#include "gmap_darts.h"
#include "index_lines.h"
#include "reindex.h"

#include <cassert>

namespace cgogn
{

GMap2::Face add_face(GMap2& m, uint32 n, bool set_indices)
{
	assert(n >= 1);
	const Dart f = add_face(static_cast<GMap1&>(m), n, false).dart;
	const Dart b = add_face(static_cast<GMap1&>(m), n, false).dart;
	// the boundary polygon's darts glued one to one to the face's, in the same
	// walk order (beta1 o beta0 from f and from b)
	std::vector<Dart> darts;
	darts.reserve(4 * n);
	Dart x = f, y = b;
	for (uint32 i = 0; i < n; ++i)
	{
		for (Dart z : {y, beta0(m, y)})
			detail::set_boundary(m, z, true);
		beta_sew<2>(m, x, y);
		beta_sew<2>(m, beta0(m, x), beta0(m, y));
		darts.insert(darts.end(), {x, beta0(m, x), y, beta0(m, y)});
		x = beta<0, 1>(m, x);
		y = beta<0, 1>(m, y);
	}
	if (set_indices)
		detail::index_new_darts(m, darts);
	return GMap2::Face(f);
}

GMap2::Vertex triangulate_face(GMap2& m, GMap2::Face f, bool set_indices)
{
	assert(!is_boundary(m, f.dart));
	// the edges of f in walk order: (x_i, y_i = beta0(x_i)), beta1(y_i) = x_i+1
	std::vector<Dart> xs;
	for (Dart x = f.dart;;)
	{
		xs.push_back(x);
		x = beta<0, 1>(m, x);
		if (x == f.dart)
			break;
	}
	const std::size_t n = xs.size();
	std::vector<Dart> region(xs.begin(), xs.end());
	for (Dart x : xs)
		region.push_back(beta0(m, x));
	detail::RegionReindexer<GMap2> reindex;
	if (set_indices)
		reindex.record(m, region);
	// triangle i: x_i, y_i, then s_i (at y_i's vertex), its beta0 s0_i at the
	// centre, t0_i at the centre and t_i at x_i's vertex
	std::vector<Dart> s(n), s0(n), t(n), t0(n);
	for (std::size_t i = 0; i < n; ++i)
	{
		s[i] = detail::add_dart_pair(m);
		s0[i] = beta0(m, s[i]);
		t[i] = detail::add_dart_pair(m);
		t0[i] = beta0(m, t[i]);
	}
	for (std::size_t i = 0; i < n; ++i)
	{
		const Dart x = xs[i], y = beta0(m, x);
		beta_unsew<1>(m, y); // y's old beta1 is x_i+1, which gets t_i+1
		beta_sew<1>(m, y, s[i]);
		beta_sew<1>(m, s0[i], t0[i]);
	}
	for (std::size_t i = 0; i < n; ++i)
	{
		const std::size_t j = (i + 1) % n;
		beta_sew<1>(m, xs[i], t[i]);
		beta_sew<2>(m, s[i], t[j]); // the spoke at the vertex between edges i and i + 1
		beta_sew<2>(m, s0[i], t0[j]);
	}
	for (std::size_t i = 0; i < n; ++i)
		region.insert(region.end(), {s[i], s0[i], t[i], t0[i]});
	if (set_indices)
	{
		reindex.apply(m, region);
		// rules: the centre is the mean of the face's vertices (the reindexing
		// gave each new triangle the face's values)
		if (detail::has_rules(m))
			detail::inherit_mean<GMap2::Vertex::ORBIT>(m, s0[0], xs);
	}
	return GMap2::Vertex(s0[0]);
}

} // namespace cgogn
