// SPDX-License-Identifier: MIT
#pragma once

// --reorder: cgogn's maps (plain and quick) are reordered after building by
// the core's reorder() with Morton keys of the vertex positions (geometry
// layer), so that the "after reorder" rows measure what a user gets by calling
// it on a badly ordered input (--permute). Untimed, as the build.

#include <cgogn/core.h>
#include <cgogn/geometry/algos/morton.h>

#include <vector>

namespace cgogn_bench
{

/// Reorders m by the Morton keys of `pos`; returns the new vertex line of each
/// soup vertex i (whose line was vertex_offset + i before).
template <typename MAP>
std::vector<cgogn::uint32> reorder_by_morton(MAP& m, const cgogn::AttributeArray<cgogn::Vec3>& pos,
											 cgogn::uint32 vertex_offset, cgogn::uint32 nb_vertices)
{
	using Vertex = typename MAP::Vertex;
	auto key = cgogn::add_attribute<cgogn::uint64, Vertex>(m, "bench_morton");
	auto soup_id = cgogn::add_attribute<cgogn::uint32, Vertex>(m, "bench_soup_id");
	for (cgogn::uint32 i = 0; i < nb_vertices; ++i)
		(*soup_id)[vertex_offset + i] = i;
	cgogn::geometry::compute_morton_keys<Vertex>(m, pos, *key);
	cgogn::reorder(m, [&](Vertex v) { return cgogn::value<cgogn::uint64>(m, *key, v); });
	std::vector<cgogn::uint32> line(nb_vertices, cgogn::INVALID_INDEX);
	cgogn::foreach_cell(m,
						[&](Vertex v) { line[cgogn::value<cgogn::uint32>(m, *soup_id, v)] = cgogn::index_of(m, v); });
	cgogn::remove_attribute(m, key);
	cgogn::remove_attribute(m, soup_id);
	return line;
}

} // namespace cgogn_bench
