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

/// What the volume builders do with one input cell.
enum class CellStatus
{
	Buildable,
	Degenerate, ///< skipped: too few faces or vertices, a repeated vertex
	Invalid     ///< skipped: a vertex out of range, or faces that do not close a surface
};

/// Scratch of polyhedron_status, reused from cell to cell.
struct PolyhedronScratch
{
	std::vector<uint32> labels;                      ///< the distinct vertex ids of the cell
	FaceList faces;                                  ///< its faces in local numbers (indices into labels)
	std::vector<std::pair<uint32, uint32>> local_of; // (vertex id, local number), sorted
	std::vector<std::array<uint32, 3>> edges;
	std::vector<uint32> repeated;
};

/// Whether build_polyhedra builds the polyhedron of these faces (the face
/// sizes of the cell, and exactly their vertex ids): it has at least 4
/// faces, each of at least 3 vertices in [0, nb_vertices) with none
/// repeated, that close one consistently oriented surface. When it does,
/// s.labels and s.faces hold its vertices and local faces. O(size x log).
inline CellStatus polyhedron_status(uint32 nb_vertices, std::span<const uint32> face_sizes,
									std::span<const uint32> face_vertices, PolyhedronScratch& s)
{
	if (std::any_of(face_vertices.begin(), face_vertices.end(), [&](uint32 v) { return v >= nb_vertices; }))
		return CellStatus::Invalid;
	bool degenerate = face_sizes.size() < 4;
	s.labels.clear();
	s.local_of.clear();
	s.faces.assign(face_sizes.size(), {});
	std::size_t first = 0;
	for (std::size_t k = 0; k < face_sizes.size(); ++k)
	{
		const std::span<const uint32> fv = face_vertices.subspan(first, face_sizes[k]);
		first += face_sizes[k];
		degenerate = degenerate || fv.size() < 3 || has_repeated_vertex(fv, s.repeated);
		for (uint32 v : fv)
		{
			auto it = std::lower_bound(s.local_of.begin(), s.local_of.end(), std::pair<uint32, uint32>{v, 0});
			if (it == s.local_of.end() || it->first != v)
			{
				it = s.local_of.insert(it, {v, uint32(s.labels.size())});
				s.labels.push_back(v);
			}
			s.faces[k].push_back(it->second);
		}
	}
	if (degenerate)
		return CellStatus::Degenerate;
	return is_closed_oriented_surface(s.faces, s.edges) ? CellStatus::Buildable : CellStatus::Invalid;
}

/// Calls f(labels, faces) on each polyhedron of a list that build_polyhedra
/// builds (see polyhedron_status), in order: `labels` the distinct vertex
/// ids of the cell, `faces` its faces in local numbers. The others are
/// counted in `report` (a cell whose faces run past the end of the lists is
/// invalid). O(total size x log).
template <typename FUNC>
void foreach_buildable_polyhedron(uint32 nb_vertices, std::span<const uint32> cell_nb_faces,
								  std::span<const uint32> face_sizes, std::span<const uint32> face_vertices,
								  BuildReport& report, const FUNC& f)
{
	std::size_t face = 0, first = 0;
	PolyhedronScratch scratch;
	for (uint32 nf : cell_nb_faces)
	{
		const std::size_t nb = std::min<std::size_t>(nf, face_sizes.size() - face);
		std::size_t size = 0;
		for (std::size_t k = 0; k < nb; ++k)
			size += face_sizes[face + k];
		const std::span<const uint32> sizes = face_sizes.subspan(face, nb);
		face += nb;
		if (nb < nf || first + size > face_vertices.size())
		{
			++report.nb_cells_invalid;
			first = face_vertices.size();
			continue;
		}
		const std::span<const uint32> vertices = face_vertices.subspan(first, size);
		first += size;
		switch (polyhedron_status(nb_vertices, sizes, vertices, scratch))
		{
		case CellStatus::Buildable:
			f(std::span<const uint32>(scratch.labels), scratch.faces);
			break;
		case CellStatus::Degenerate:
			++report.nb_cells_degenerate;
			break;
		case CellStatus::Invalid:
			++report.nb_cells_invalid;
			break;
		}
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
