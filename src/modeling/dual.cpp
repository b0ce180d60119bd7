// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/geometry/algos/centroid.h>
#include <cgogn/modeling/dual.h>

#include <algorithm>
#include <string>
#include <vector>

namespace cgogn::modeling
{

std::shared_ptr<AttributeArray<Vec3>> dual(const CMap2& m, const AttributeArray<Vec3>& pos, CMap2& out)
{
	if (container_of<CMap2::Vertex::ORBIT>(out).find("position") != nullptr &&
		get_attribute<Vec3, CMap2::Vertex>(out, "position") == nullptr)
		throw Error("modeling::dual: the output map has a vertex attribute 'position' that is not a Vec3");
	if (const uint32 holes = nb_boundary_components(m); holes > 0)
		throw TopologyError("modeling::dual: the surface has " + std::to_string(holes) +
							" boundary loop(s); the dual is defined for closed surfaces (fill the holes first)");

	// dual vertex of each face, by dart
	std::vector<uint32> face_of_dart(container_of<Orbit::DART>(m).end_index(), INVALID_INDEX);
	std::vector<Vec3> centers;
	foreach_cell(m, [&](CMap2::Face f) {
		const uint32 id = uint32(centers.size());
		foreach_dart_of_orbit(m, f, [&](Dart d) { face_of_dart[d.index] = id; });
		centers.push_back(geometry::centroid(m, f, pos));
	});

	// dual face of each vertex: the faces of its darts, in the reverse of the
	// vertex orbit's order (phi1 o phi2 turns clockwise around the vertex seen
	// from the side the faces face, so reversing keeps the dual oriented like m)
	std::vector<uint32> sizes, ids, sorted;
	foreach_cell(m, [&](CMap2::Vertex v) {
		const std::size_t first = ids.size();
		foreach_dart_of_orbit(m, v, [&](Dart d) { ids.push_back(face_of_dart[d.index]); });
		std::reverse(ids.begin() + std::ptrdiff_t(first), ids.end());
		const uint32 n = uint32(ids.size() - first);
		sorted.assign(ids.begin() + std::ptrdiff_t(first), ids.end());
		std::sort(sorted.begin(), sorted.end());
		if (n < 3 || std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
			throw TopologyError("modeling::dual: a vertex of degree " + std::to_string(n) +
								(n < 3 ? "" : " meets a face twice") + ": its dual face would be degenerate");
		sizes.push_back(n);
	});

	const BuildReport r = build_surface(out, uint32(centers.size()), sizes, ids);
	auto out_pos = get_attribute<Vec3, CMap2::Vertex>(out, "position");
	if (!out_pos)
		out_pos = add_attribute<Vec3, CMap2::Vertex>(out, "position");
	for (uint32 i = 0; i < centers.size(); ++i)
		(*out_pos)[r.vertex_offset + i] = centers[i];
	return out_pos;
}

} // namespace cgogn::modeling
