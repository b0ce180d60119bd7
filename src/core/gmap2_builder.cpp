// SPDX-License-Identifier: MIT
// The polygon-soup builder of 2-G-maps: faces, then beta2 sewing per
// undirected edge, then the boundary faces that close the holes.
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/marking/marker.h>

#include "builder_common.h"
#include "index_lines.h"

#include <algorithm>
#include <tuple>

namespace cgogn
{

namespace
{

// The edge sides (the dart at the start of each edge of each face) by the
// smaller soup id of their two ends, as a CSR table: the candidates for
// sewing a side are the sides listed under the same smaller end.
struct SidesByVertex
{
	std::vector<uint32> offsets;
	std::vector<Dart> sides;

	template <typename KEY>
	SidesByVertex(const std::vector<Dart>& all, uint32 nb_vertices, const KEY& key)
		: offsets(nb_vertices + 1, 0), sides(all.size())
	{
		for (Dart d : all)
			++offsets[key(d) + 1];
		for (uint32 v = 0; v < nb_vertices; ++v)
			offsets[v + 1] += offsets[v];
		std::vector<uint32> pos(offsets.begin(), offsets.end() - 1);
		for (Dart d : all)
			sides[pos[key(d)]++] = d;
	}
	template <typename F>
	void foreach_at(uint32 v, const F& f) const
	{
		for (uint32 i = offsets[v]; i < offsets[v + 1]; ++i)
			if (!f(sides[i]))
				return;
	}
};

// Closes the holes: every beta2 fixed point d gets a boundary dart d' =
// beta2(d) at the same vertex; beta0 of d' is the boundary dart of beta0(d),
// and beta1 of d' the boundary dart of the free dart met first turning
// around the vertex from beta1(d) (beta2 then beta1, inside the surface).
// Returns the boundary darts, in the order of the free darts.
std::vector<Dart> close_holes(GMap2& m, const std::vector<Dart>& darts, AttributeArray<uint32>& vidx)
{
	std::vector<Dart> created;
	for (Dart d : darts)
		if (beta2(m, d) == d)
		{
			// the pair of a free dart is free (beta0 o beta2 is an involution)
			const Dart p = detail::add_dart_pair(m);
			for (const auto& [x, b] : {std::pair{d, p}, std::pair{beta0(m, d), beta0(m, p)}})
			{
				detail::set_boundary(m, b, true);
				vidx[b.index] = vidx[x.index];
				beta_sew<2>(m, x, b);
				created.push_back(b);
			}
		}
	for (Dart b : created)
	{
		const Dart d = beta2(m, b);
		if (beta1(m, b) == b)
		{
			Dart e = beta1(m, d);
			while (!is_boundary(m, beta2(m, e)))
				e = beta1(m, beta2(m, e));
			beta_sew<1>(m, b, beta2(m, e));
		}
	}
	return created;
}

} // namespace

BuildReport build_surface(GMap2& m, uint32 nb_vertices, std::span<const uint32> face_sizes,
						  std::span<const uint32> face_vertices)
{
	BuildReport report;
	report.nb_cells_read = uint32(face_sizes.size());

	if (!is_indexed<GMap2::Vertex>(m))
		index_cells<GMap2::Vertex>(m);
	AttributeArray<uint32>& vidx = *detail::state_of(m).cell_index[orbit_index(GMap2::Vertex::ORBIT)];
	AttributeContainer& vertices = *detail::state_of(m).cells[orbit_index(GMap2::Vertex::ORBIT)];
	const uint32 offset = vertices.new_lines_at_end(nb_vertices);
	report.vertex_offset = offset;

	// 1. two darts per edge of each valid face: a at the start of the edge,
	// b = beta0(a) at its end, and beta1 from b to the next edge's a
	std::vector<Dart> darts, sides;
	std::size_t total = 0;
	for (uint32 s : face_sizes)
		total += s;
	total = std::min(total, face_vertices.size());
	darts.reserve(2 * total);
	sides.reserve(total);
	detail::reserve_darts(m, darts.capacity());
	detail::foreach_buildable_face(nb_vertices, face_sizes, face_vertices, &report,
								   [&](uint32, std::span<const uint32> fv) {
									   const uint32 n = uint32(fv.size());
									   const std::size_t face_start = darts.size();
									   for (uint32 i = 0; i < n; ++i)
									   {
										   const Dart a = detail::add_dart_pair(m);
										   const Dart b = beta0(m, a);
										   vidx[a.index] = offset + fv[i];
										   vidx[b.index] = offset + fv[(i + 1) % n];
										   if (i > 0)
											   beta_sew<1>(m, darts.back(), a);
										   darts.push_back(a);
										   darts.push_back(b);
										   sides.push_back(a);
									   }
									   beta_sew<1>(m, darts.back(), darts[face_start]);
									   ++report.nb_cells_built;
								   });

	// 2. glue the sides of each undirected edge two by two, end to end: the
	// darts of both sides at the same vertex are exchanged by beta2, whatever
	// the direction in which each face lists the edge
	const auto soup = [&](Dart d) { return vidx[d.index] - offset; };
	const auto low_end = [&](Dart a) { return std::min(soup(a), soup(beta0(m, a))); };
	const auto high_end = [&](Dart a) { return std::max(soup(a), soup(beta0(m, a))); };
	SidesByVertex by_low(sides, nb_vertices, low_end);
	bool glued_same_way = false;
	for (Dart a : sides)
	{
		if (beta2(m, a) != a)
			continue;
		const uint32 lo = low_end(a), hi = high_end(a);
		by_low.foreach_at(lo, [&](Dart e) {
			if (e == a || beta2(m, e) != e || high_end(e) != hi)
				return true;
			const bool same_start = soup(e) == soup(a);
			glued_same_way = glued_same_way || same_start;
			beta_sew<2>(m, a, same_start ? e : beta0(m, e));
			beta_sew<2>(m, beta0(m, a), same_start ? beta0(m, e) : e);
			return false;
		});
	}
	std::vector<std::pair<uint32, uint32>> detached; // the edges, each once
	for (Dart a : sides)
	{
		if (beta2(m, a) != a)
			continue;
		// a free side whose edge has other sides: a face detached there
		const uint32 lo = low_end(a), hi = high_end(a);
		bool shared = false;
		by_low.foreach_at(lo, [&](Dart e) { return !(shared = e != a && high_end(e) == hi); });
		if (shared)
			detached.emplace_back(lo, hi);
	}
	std::sort(detached.begin(), detached.end());
	report.nb_nonmanifold_edges = uint32(std::unique(detached.begin(), detached.end()) - detached.begin());
	// Judging the orientation sorts every edge side: needed only when two
	// faces were glued along an edge they list in the same direction. With
	// none, keeping every face as listed orients the map, with no conflict.
	if (glued_same_way)
		std::tie(report.orientable, report.nb_orientation_conflicts) =
			soup_orientation(nb_vertices, face_sizes, face_vertices);

	// 3. close every hole with a boundary face
	const std::vector<Dart> boundary_darts = close_holes(m, darts, vidx);
	{
		DartMarker<GMap2> seen(m);
		for (Dart b : boundary_darts)
			if (!seen.is_marked(b))
			{
				seen.mark_orbit(GMap2::Face(b));
				++report.nb_boundary_cells;
			}
	}
	darts.insert(darts.end(), boundary_darts.begin(), boundary_darts.end());

	// 4. one vertex line per vertex orbit: extra fans of a soup vertex are split
	detail::assign_vertex_lines<GMap2::Vertex>(m, darts, vertices, vidx, offset, nb_vertices, report);

	detail::index_new_darts(m, darts);
	detail::release_idle_marks(m);
	return report;
}

} // namespace cgogn
