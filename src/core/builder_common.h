// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/marking/marker.h>

#include "cmap3_build.h"

#include <algorithm>
#include <array>
#include <span>

namespace cgogn::detail
{

/// True when the cell lists a vertex twice.
inline bool has_repeated_vertex(std::span<const uint32> vs, std::vector<uint32>& scratch)
{
	if (vs.size() <= 8)
	{
		for (std::size_t i = 0; i < vs.size(); ++i)
			for (std::size_t j = i + 1; j < vs.size(); ++j)
				if (vs[i] == vs[j])
					return true;
		return false;
	}
	scratch.assign(vs.begin(), vs.end());
	std::sort(scratch.begin(), scratch.end());
	return std::adjacent_find(scratch.begin(), scratch.end()) != scratch.end();
}

/// Calls f(face, ids) on each face of a polygon soup that the surface
/// builders build, in order: at least 3 vertices, all in [0, nb_vertices),
/// none repeated. The others are counted in `report` when given (a face
/// running past the end of `face_vertices`, or naming a vertex out of range,
/// is invalid; a short face or one with a repeated vertex is degenerate).
/// O(total size).
template <typename FUNC>
void foreach_buildable_face(uint32 nb_vertices, std::span<const uint32> face_sizes,
							std::span<const uint32> face_vertices, BuildReport* report, const FUNC& f)
{
	std::size_t first = 0;
	std::vector<uint32> scratch;
	for (uint32 face = 0; face < uint32(face_sizes.size()); ++face)
	{
		const uint32 n = face_sizes[face];
		if (first + n > face_vertices.size())
		{
			if (report)
				++report->nb_cells_invalid;
			first = face_vertices.size();
			continue;
		}
		const std::span<const uint32> fv = face_vertices.subspan(first, n);
		first += n;
		if (std::any_of(fv.begin(), fv.end(), [&](uint32 v) { return v >= nb_vertices; }))
		{
			if (report)
				++report->nb_cells_invalid;
			continue;
		}
		if (n < 3 || has_repeated_vertex(fv, scratch))
		{
			if (report)
				++report->nb_cells_degenerate;
			continue;
		}
		f(face, fv);
	}
}

/// Calls f(ids, faces) on each cell of a cell list that the volume builders
/// build, in order: a known kind (detail::cell_faces of its size, whose face
/// list is `faces`), all vertices in [0, nb_vertices), none repeated. The
/// others are counted in `report` (a cell running past the end of
/// `cell_vertices`, of an unknown kind or naming a vertex out of range is
/// invalid; one with a repeated vertex is degenerate). O(total size).
template <typename FUNC>
void foreach_buildable_cell(uint32 nb_vertices, std::span<const uint32> cell_sizes,
							std::span<const uint32> cell_vertices, BuildReport& report, const FUNC& f)
{
	std::size_t first = 0;
	std::vector<uint32> scratch;
	for (uint32 n : cell_sizes)
	{
		if (first + n > cell_vertices.size())
		{
			++report.nb_cells_invalid;
			first = cell_vertices.size();
			continue;
		}
		const std::span<const uint32> cv = cell_vertices.subspan(first, n);
		first += n;
		const FaceList* faces = cell_faces(n);
		if (faces == nullptr || std::any_of(cv.begin(), cv.end(), [&](uint32 v) { return v >= nb_vertices; }))
		{
			++report.nb_cells_invalid;
			continue;
		}
		if (has_repeated_vertex(cv, scratch))
		{
			++report.nb_cells_degenerate;
			continue;
		}
		f(cv, *faces);
	}
}

/// Whether the faces of a polyhedron (local vertex numbers) close one
/// surface, consistently oriented: every directed edge of a face is met once,
/// and its reverse once in another face; and the faces are connected through
/// their edges. `edges` is scratch. O(size x log).
inline bool is_closed_oriented_surface(const FaceList& faces, std::vector<std::array<uint32, 3>>& edges)
{
	edges.clear();
	for (uint32 f = 0; f < faces.size(); ++f)
		for (std::size_t i = 0; i < faces[f].size(); ++i)
			edges.push_back({faces[f][i], faces[f][(i + 1) % faces[f].size()], f});
	std::sort(edges.begin(), edges.end());
	std::vector<uint32> component(faces.size());
	for (uint32 f = 0; f < faces.size(); ++f)
		component[f] = f;
	const auto root = [&](uint32 f) {
		while (component[f] != f)
			f = component[f] = component[component[f]];
		return f;
	};
	for (std::size_t i = 0; i < edges.size(); ++i)
	{
		if (i + 1 < edges.size() && edges[i][0] == edges[i + 1][0] && edges[i][1] == edges[i + 1][1])
			return false; // a directed edge twice: faces of opposite orientations, or a non-manifold edge
		const std::array<uint32, 3> reverse{edges[i][1], edges[i][0], 0};
		const auto it = std::lower_bound(edges.begin(), edges.end(), reverse);
		if (it == edges.end() || (*it)[0] != reverse[0] || (*it)[1] != reverse[1])
			return false; // an open edge
		component[root(edges[i][2])] = root((*it)[2]);
	}
	for (uint32 f = 0; f < faces.size(); ++f)
		if (root(f) != root(0))
			return false;
	return true;
}

/// Calls f(labels, faces) on each polyhedron of a list that build_polyhedra
/// builds, in order: `labels` the distinct vertex ids of the cell, `faces`
/// its faces in local numbers (indices into labels). A polyhedron is built
/// when it has at least 4 faces, each of at least 3 vertices in [0,
/// nb_vertices) with none repeated, that close one consistently oriented
/// surface; the others are counted in `report` (one that runs past the end
/// of the lists, names a vertex out of range or does not close a surface is
/// invalid; one with fewer faces, a short face or a repeated vertex is
/// degenerate). O(total size x log).
template <typename FUNC>
void foreach_buildable_polyhedron(uint32 nb_vertices, std::span<const uint32> cell_nb_faces,
								  std::span<const uint32> face_sizes, std::span<const uint32> face_vertices,
								  BuildReport& report, const FUNC& f)
{
	std::size_t face = 0, first = 0;
	std::vector<uint32> labels, scratch;
	std::vector<std::pair<uint32, uint32>> local_of; // (vertex id, local number), sorted
	std::vector<std::array<uint32, 3>> edges;
	FaceList faces;
	for (uint32 nf : cell_nb_faces)
	{
		bool invalid = face + nf > face_sizes.size(), degenerate = nf < 4;
		const std::size_t nb = invalid ? face_sizes.size() - face : nf;
		labels.clear();
		local_of.clear();
		faces.assign(nb, {});
		for (std::size_t k = 0; k < nb; ++k)
		{
			const uint32 n = face_sizes[face + k];
			if (first + n > face_vertices.size())
			{
				invalid = true;
				first = face_vertices.size();
				continue;
			}
			const std::span<const uint32> fv = face_vertices.subspan(first, n);
			first += n;
			if (std::any_of(fv.begin(), fv.end(), [&](uint32 v) { return v >= nb_vertices; }))
			{
				invalid = true;
				continue;
			}
			degenerate = degenerate || n < 3 || has_repeated_vertex(fv, scratch);
			for (uint32 v : fv)
			{
				auto it = std::lower_bound(local_of.begin(), local_of.end(), std::pair<uint32, uint32>{v, 0});
				if (it == local_of.end() || it->first != v)
				{
					it = local_of.insert(it, {v, uint32(labels.size())});
					labels.push_back(v);
				}
				faces[k].push_back(it->second);
			}
		}
		face += nb;
		if (invalid)
			++report.nb_cells_invalid;
		else if (degenerate)
			++report.nb_cells_degenerate;
		else if (!is_closed_oriented_surface(faces, edges))
			++report.nb_cells_invalid;
		else
			f(std::span<const uint32>(labels), faces);
	}
}

/// The number of distinct VOLUME cells of the darts given (the boundary
/// volumes a build closed its map with). O(size of those cells).
template <typename VOLUME, typename MAP>
uint32 nb_distinct_volumes(const MAP& m, const std::vector<Dart>& darts)
{
	DartMarker<MAP> seen(m);
	uint32 n = 0;
	for (Dart d : darts)
		if (!seen.is_marked(d))
		{
			seen.mark_orbit(VOLUME(d));
			++n;
		}
	return n;
}

/// Reserves room in m's dart container for `count` more darts (boundary
/// darts, unknown in advance, grow it as needed).
inline void reserve_darts(CMapBase& m, std::size_t count)
{
	AttributeContainer& darts = *detail::state_of(m).darts;
	darts.reserve(uint32(std::min<std::size_t>(uint64(darts.end_index()) + count, INVALID_INDEX - 1)));
}

/// After a build: each vertex orbit of the new darts claims the line of its
/// soup vertex; a second orbit with the same soup vertex (a non-manifold
/// vertex) gets a new line, recorded in the report; unused lines are released.
template <typename VERTEX, typename MAP>
void assign_vertex_lines(MAP& m, const std::vector<Dart>& darts, AttributeContainer& vertices,
						 AttributeArray<uint32>& vidx, uint32 offset, uint32 nb_vertices, BuildReport& report)
{
	DartMarker<MAP> dm(m);
	std::vector<uint8> split(nb_vertices, 0);
	for (Dart d : darts)
	{
		if (dm.is_marked(d))
			continue;
		dm.mark_orbit(VERTEX(d));
		const uint32 line = vidx[d.index];
		if (vertices.key()[line] == INVALID_INDEX)
			vertices.key()[line] = d.index;
		else
		{
			const uint32 l = vertices.new_line(d.index);
			write_index(m, VERTEX(d), l);
			report.split_vertices.emplace_back(l, line - offset);
			if (!split[line - offset])
			{
				split[line - offset] = 1;
				++report.nb_nonmanifold_vertices;
			}
		}
	}
	for (uint32 v = 0; v < nb_vertices; ++v)
		if (vertices.key()[offset + v] == INVALID_INDEX)
		{
			vertices.release_unkeyed_line(offset + v);
			++report.nb_isolated_vertices;
		}
}

} // namespace cgogn::detail
