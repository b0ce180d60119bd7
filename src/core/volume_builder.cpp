// SPDX-License-Identifier: MIT
#include <cgogn/core/builder/map_builder.h>
#include <cgogn/core/functions/indexing.h>
#include <cgogn/core/operators/index_helpers.h>

#include "builder_common.h"

#include <array>

namespace cgogn
{

namespace
{

using FaceList = std::vector<std::vector<uint32>>;

// Faces of each supported cell kind, as local vertex numbers, oriented so that
// they are seen counterclockwise from outside the cell (see map_builder.h for
// the vertex conventions).
const FaceList* cell_faces(uint32 nb_vertices)
{
	static const FaceList tet = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
	static const FaceList pyramid = {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
	static const FaceList prism = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4, 3}, {1, 2, 5, 4}, {2, 0, 3, 5}};
	static const FaceList hexa = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
	switch (nb_vertices)
	{
	case 4:
		return &tet;
	case 5:
		return &pyramid;
	case 6:
		return &prism;
	case 8:
		return &hexa;
	default:
		return nullptr;
	}
}

} // namespace

BuildReport build_volume(CMap3& m, uint32 nb_vertices, std::span<const uint32> cell_sizes,
						 std::span<const uint32> cell_vertices)
{
	BuildReport report;
	report.nb_cells_read = uint32(cell_sizes.size());

	if (!is_indexed<CMap3::Vertex>(m))
		index_cells<CMap3::Vertex>(m);
	Attribute<uint32>& vidx = *m.cell_index_[orbit_index(Orbit::PHI21_PHI31)];
	AttributeContainer& vertices = *m.cells_[orbit_index(Orbit::PHI21_PHI31)];
	const uint32 offset = vertices.new_lines_at_end(nb_vertices);
	report.vertex_offset = offset;
	auto origin = [&](Dart d) { return vidx[d.index] - offset; };
	auto target = [&](Dart d) { return vidx[phi1(m, d).index] - offset; };

	// 1. each cell as a closed 2-map (faces sewn by phi2)
	std::vector<Dart> darts;
	std::vector<Dart> cell_darts;
	std::vector<uint32> scratch;
	std::size_t first = 0;
	for (uint32 n : cell_sizes)
	{
		if (first + n > cell_vertices.size())
		{
			++report.nb_cells_invalid;
			first = cell_vertices.size();
			continue;
		}
		std::span<const uint32> cv = cell_vertices.subspan(first, n);
		first += n;
		const FaceList* faces = cell_faces(n);
		if (faces == nullptr || std::any_of(cv.begin(), cv.end(), [&](uint32 v) { return v >= nb_vertices; }))
		{
			++report.nb_cells_invalid;
			continue;
		}
		if (detail::has_repeated_vertex(cv, scratch))
		{
			++report.nb_cells_degenerate;
			continue;
		}
		cell_darts.clear();
		for (const auto& f : *faces)
		{
			const std::size_t k = f.size();
			const std::size_t b = cell_darts.size();
			for (std::size_t i = 0; i < k; ++i)
			{
				const Dart d = detail::add_dart(m);
				vidx[d.index] = offset + cv[f[i]];
				cell_darts.push_back(d);
			}
			for (std::size_t i = 0; i < k; ++i)
				detail::set_phi1(m, cell_darts[b + i], cell_darts[b + (i + 1) % k]);
		}
		for (Dart d : cell_darts)
		{
			if (phi2(m, d) != d)
				continue;
			for (Dart e : cell_darts)
				if (phi2(m, e) == e && origin(e) == target(d) && target(e) == origin(d))
				{
					phi2_sew(m, d, e);
					break;
				}
		}
		darts.insert(darts.end(), cell_darts.begin(), cell_darts.end());
		++report.nb_cells_built;
	}

	// 2. sew faces of adjacent cells: same vertices, opposite orientation
	std::vector<uint32> offsets(nb_vertices + 1, 0);
	for (Dart d : darts)
		++offsets[origin(d) + 1];
	for (uint32 v = 0; v < nb_vertices; ++v)
		offsets[v + 1] += offsets[v];
	std::vector<Dart> outgoing(darts.size());
	{
		std::vector<uint32> pos(offsets.begin(), offsets.end() - 1);
		for (Dart d : darts)
			outgoing[pos[origin(d)]++] = d;
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
		for (uint32 i = offsets[b]; i < offsets[b + 1]; ++i)
		{
			const Dart e = outgoing[i];
			if (e != d && target(e) == a && (!free_only || phi3(m, e) == e) && faces_match(d, e))
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

	// 3. close: a boundary face on each free face, then sew boundary faces by phi2
	std::vector<Dart> boundary_darts;
	std::vector<Dart> face;
	for (Dart d : darts)
	{
		if (phi3(m, d) != d)
			continue;
		// (once per face: the other darts of the face are sewn below)
		if (find_mate(d, false).is_valid())
			++report.nb_nonmanifold_faces;
		face.clear();
		Dart it = d;
		do
		{
			face.push_back(it);
			it = phi1(m, it);
		} while (it != d);
		const std::size_t k = face.size();
		const std::size_t b0 = boundary_darts.size();
		for (std::size_t i = 0; i < k; ++i)
		{
			const Dart b = detail::add_dart(m);
			detail::set_boundary(m, b, true);
			vidx[b.index] = vidx[phi1(m, face[i]).index];
			boundary_darts.push_back(b);
			phi3_sew(m, face[i], b);
		}
		// face[i] goes v_i -> v_i+1; its mate b_i goes v_i+1 -> v_i, followed by b_i-1
		for (std::size_t i = 0; i < k; ++i)
			detail::set_phi1(m, boundary_darts[b0 + i], boundary_darts[b0 + (i + k - 1) % k]);
	}
	for (Dart b : boundary_darts)
	{
		if (phi2(m, b) != b)
			continue;
		// turn around the edge inside the cells until the next boundary face
		Dart it = phi2(m, phi3(m, b));
		while (!is_boundary(m, phi3(m, it)))
			it = phi2(m, phi3(m, it));
		phi2_sew(m, b, phi3(m, it));
	}
	{
		DartMarker<CMap3> dm(m);
		for (Dart b : boundary_darts)
			if (!dm.is_marked(b))
			{
				dm.mark_orbit(CMap3::Volume(b));
				++report.nb_boundary_cells;
			}
	}
	darts.insert(darts.end(), boundary_darts.begin(), boundary_darts.end());

	// 4. vertex lines, split of non-manifold vertices
	detail::assign_vertex_lines<CMap3::Vertex>(m, darts, vertices, vidx, offset, nb_vertices, report);

	detail::index_new_darts(m, darts);
	return report;
}

} // namespace cgogn
