// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/marking/marker.h>

#include <algorithm>
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
