// SPDX-License-Identifier: MIT
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>

#include "builder_common.h"
#include "cmap3_build.h"
#include "index_lines.h"

#include <algorithm>
#include <array>

namespace cgogn
{

namespace
{

// Builds the cells that foreach_input_cell(report, f) hands to f(labels,
// faces) (each a closed surface: its local faces and the vertex id of each
// local vertex), sews them, closes the outside and indexes the vertices.
template <typename FOREACH_CELL>
BuildReport build_cells(CMap3& m, uint32 nb_vertices, uint32 nb_cells, const FOREACH_CELL& foreach_input_cell)
{
	BuildReport report;
	report.nb_cells_read = nb_cells;

	if (!is_indexed<CMap3::Vertex>(m))
		index_cells<CMap3::Vertex>(m);
	AttributeArray<uint32>& vidx = *detail::state_of(m).cell_index[orbit_index(Orbit::PHI21_PHI31)];
	AttributeContainer& vertices = *detail::state_of(m).cells[orbit_index(Orbit::PHI21_PHI31)];
	const uint32 offset = vertices.new_lines_at_end(nb_vertices);
	report.vertex_offset = offset;
	auto origin = [&](Dart d) { return vidx[d.index] - offset; };
	auto target = [&](Dart d) { return vidx[phi1(m, d).index] - offset; };

	// 1. each cell as a closed 2-map (faces sewn by phi2)
	std::vector<Dart> darts;
	std::vector<uint32> labels;
	foreach_input_cell(report, [&](std::span<const uint32> cv, const detail::FaceList& faces) {
		labels.clear();
		std::vector<Dart> cell_darts = detail::add_volume_topology(m, faces, cv, labels);
		for (std::size_t i = 0; i < cell_darts.size(); ++i)
			vidx[cell_darts[i].index] = offset + labels[i];
		darts.insert(darts.end(), cell_darts.begin(), cell_darts.end());
		++report.nb_cells_built;
	});

	// 2. sew faces of adjacent cells: same vertices, opposite orientation
	std::vector<uint32> offsets(nb_vertices + 1, 0);
	for (Dart d : darts)
		++offsets[origin(d) + 1];
	for (uint32 v = 0; v < nb_vertices; ++v)
		offsets[v + 1] += offsets[v];
	// darts leaving each vertex, sorted by the vertex they go to: a mate is
	// found by binary search (real meshes have vertices with hundreds of darts)
	std::vector<std::pair<uint32, Dart>> outgoing(darts.size());
	{
		std::vector<uint32> pos(offsets.begin(), offsets.end() - 1);
		for (Dart d : darts)
			outgoing[pos[origin(d)]++] = {target(d), d};
		for (uint32 v = 0; v < nb_vertices; ++v)
			std::sort(outgoing.begin() + offsets[v], outgoing.begin() + offsets[v + 1],
					  [](const auto& x, const auto& y) { return x.first < y.first; });
	}
	// true when the face of e is the face of d seen from the other side
	auto faces_match = [&](Dart d, Dart e) {
		Dart x = d, y = e;
		do
		{
			if (origin(x) != target(y))
				return false;
			x = phi1(m, x);
			y = phi_1(m, y);
		} while (x != d && y != e);
		return x == d && y == e;
	};
	auto find_mate = [&](Dart d, bool free_only) {
		const uint32 a = origin(d), b = target(d);
		auto first = outgoing.begin() + offsets[b], last = outgoing.begin() + offsets[b + 1];
		auto it = std::lower_bound(first, last, a, [](const auto& x, uint32 v) { return x.first < v; });
		for (; it != last && it->first == a; ++it)
		{
			const Dart e = it->second;
			if (e != d && (!free_only || phi3(m, e) == e) && faces_match(d, e))
				return e;
		}
		return Dart();
	};
	for (Dart d : darts)
	{
		if (phi3(m, d) != d)
			continue;
		const Dart e = find_mate(d, true);
		if (!e.is_valid())
			continue;
		Dart x = d, y = e;
		do
		{
			phi3_sew(m, x, y);
			x = phi1(m, x);
			y = phi_1(m, y);
		} while (x != d);
	}

	// 3. close: a boundary face on each free face, sewn into boundary volumes
	{
		// a free face whose vertices match a face already sewn: shared by a third cell
		DartMarkerStore<CMap3> counted(m);
		for (Dart d : darts)
			if (phi3(m, d) == d && !counted.is_marked(d))
			{
				counted.mark_orbit(CMap3::Face2(d));
				report.nb_nonmanifold_faces += find_mate(d, false).is_valid();
			}
	}
	std::vector<Dart> boundary_darts;
	detail::close_phi3_holes(m, darts, boundary_darts);
	report.nb_boundary_cells = detail::nb_distinct_volumes<CMap3::Volume>(m, boundary_darts);
	darts.insert(darts.end(), boundary_darts.begin(), boundary_darts.end());

	// 4. vertex lines, split of non-manifold vertices
	detail::assign_vertex_lines<CMap3::Vertex>(m, darts, vertices, vidx, offset, nb_vertices, report);

	detail::index_new_darts(m, darts);
	detail::release_idle_marks(m);
	return report;
}

} // namespace

BuildReport build_volume(CMap3& m, uint32 nb_vertices, std::span<const uint32> cell_sizes,
						 std::span<const uint32> cell_vertices)
{
	return build_cells(m, nb_vertices, uint32(cell_sizes.size()), [&](BuildReport& report, const auto& f) {
		detail::foreach_buildable_cell(nb_vertices, cell_sizes, cell_vertices, report, f);
	});
}

bool is_buildable_polyhedron(std::span<const uint32> face_sizes, std::span<const uint32> face_vertices)
{
	std::size_t size = 0;
	for (uint32 n : face_sizes)
		size += n;
	if (size != face_vertices.size())
		return false;
	detail::PolyhedronScratch scratch;
	return detail::polyhedron_status(INVALID_INDEX, face_sizes, face_vertices, scratch) ==
		   detail::CellStatus::Buildable;
}

BuildReport build_polyhedra(CMap3& m, uint32 nb_vertices, std::span<const uint32> cell_nb_faces,
							std::span<const uint32> face_sizes, std::span<const uint32> face_vertices)
{
	return build_cells(m, nb_vertices, uint32(cell_nb_faces.size()), [&](BuildReport& report, const auto& f) {
		detail::foreach_buildable_polyhedron(nb_vertices, cell_nb_faces, face_sizes, face_vertices, report, f);
	});
}

} // namespace cgogn
