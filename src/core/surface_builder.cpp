// SPDX-License-Identifier: MIT
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/marking/marker.h>

#include "builder_common.h"
#include "cmap2_close.h"
#include "index_lines.h"

#include <algorithm>
#include <tuple>

namespace cgogn
{

namespace
{

// Soup ids of the darts leaving each vertex, as a CSR table.
struct OutgoingDarts
{
	std::vector<uint32> offsets;
	std::vector<Dart> darts;

	OutgoingDarts(const std::vector<Dart>& all, const AttributeArray<uint32>& vidx, uint32 offset, uint32 nb_vertices)
		: offsets(nb_vertices + 1, 0), darts(all.size())
	{
		for (Dart d : all)
			++offsets[vidx[d.index] - offset + 1];
		for (uint32 v = 0; v < nb_vertices; ++v)
			offsets[v + 1] += offsets[v];
		std::vector<uint32> pos(offsets.begin(), offsets.end() - 1);
		for (Dart d : all)
			darts[pos[vidx[d.index] - offset]++] = d;
	}
	template <typename F>
	void foreach_from(uint32 v, const F& f) const
	{
		for (uint32 i = offsets[v]; i < offsets[v + 1]; ++i)
			if (!f(darts[i]))
				return;
	}
};

} // namespace

BuildReport build_surface(CMap2& m, uint32 nb_vertices, std::span<const uint32> face_sizes,
						  std::span<const uint32> face_vertices)
{
	BuildReport report;
	report.nb_cells_read = uint32(face_sizes.size());

	if (!is_indexed<CMap2::Vertex>(m))
		index_cells<CMap2::Vertex>(m);
	AttributeArray<uint32>& vidx = *detail::state_of(m).cell_index[orbit_index(Orbit::PHI21)];
	AttributeContainer& vertices = *detail::state_of(m).cells[orbit_index(Orbit::PHI21)];
	const uint32 offset = vertices.new_lines_at_end(nb_vertices);
	report.vertex_offset = offset;

	// 1. one phi1 cycle per valid face, each dart indexed by its origin vertex
	std::vector<Dart> darts;
	std::size_t total = 0;
	for (uint32 s : face_sizes)
		total += s;
	darts.reserve(std::min(total, face_vertices.size()));
	detail::reserve_darts(m, darts.capacity());
	detail::foreach_buildable_face(nb_vertices, face_sizes, face_vertices, &report,
								   [&](uint32, std::span<const uint32> fv) {
									   const uint32 n = uint32(fv.size());
									   const Dart d0 = detail::add_dart(m);
									   Dart prev = d0;
									   vidx[d0.index] = offset + fv[0];
									   darts.push_back(d0);
									   for (uint32 i = 1; i < n; ++i)
									   {
										   const Dart d = detail::add_dart(m);
										   vidx[d.index] = offset + fv[i];
										   detail::set_phi1(m, prev, d);
										   darts.push_back(d);
										   prev = d;
									   }
									   detail::set_phi1(m, prev, d0);
									   ++report.nb_cells_built;
								   });

	// 2. sew opposite half-edges: a->b with a free b->a
	OutgoingDarts out(darts, vidx, offset, nb_vertices);
	auto origin = [&](Dart d) { return vidx[d.index] - offset; };
	auto target = [&](Dart d) { return vidx[phi1(m, d).index] - offset; };
	for (Dart d : darts)
	{
		if (phi2(m, d) != d)
			continue;
		const uint32 a = origin(d), b = target(d);
		out.foreach_from(b, [&](Dart e) {
			if (phi2(m, e) == e && target(e) == a)
			{
				phi2_sew(m, d, e);
				return false;
			}
			return true;
		});
	}
	std::vector<std::pair<uint32, uint32>> detached; // the edges, each once
	for (Dart d : darts)
	{
		if (phi2(m, d) != d)
			continue;
		// a free half-edge whose edge has other half-edges: a detached face
		const uint32 a = origin(d), b = target(d);
		bool shared = false;
		out.foreach_from(b, [&](Dart e) { return !(shared = target(e) == a); });
		if (!shared)
			out.foreach_from(a, [&](Dart e) { return !(shared = e != d && target(e) == b); });
		if (shared)
			detached.emplace_back(std::min(a, b), std::max(a, b));
	}
	std::sort(detached.begin(), detached.end());
	report.nb_nonmanifold_edges = uint32(std::unique(detached.begin(), detached.end()) - detached.begin());
	// Judging the orientation sorts every edge side (it would triple the cost
	// of building): needed only when an edge was left unsewn. With none, every
	// shared edge joins two faces listing it in opposite directions: the map
	// is oriented, with no conflict.
	if (!detached.empty())
		std::tie(report.orientable, report.nb_orientation_conflicts) =
			soup_orientation(nb_vertices, face_sizes, face_vertices);

	// 3. close every hole with a boundary face
	std::vector<Dart> boundary_darts;
	for (Dart d : darts)
		if (phi2(m, d) == d)
		{
			detail::close_hole_topology(m, d, true, boundary_darts);
			++report.nb_boundary_cells;
		}
	darts.insert(darts.end(), boundary_darts.begin(), boundary_darts.end());

	// 4. one vertex line per vertex orbit: extra fans of a soup vertex are split
	detail::assign_vertex_lines<CMap2::Vertex>(m, darts, vertices, vidx, offset, nb_vertices, report);

	detail::index_new_darts(m, darts);
	detail::release_idle_marks(m);
	return report;
}

} // namespace cgogn
