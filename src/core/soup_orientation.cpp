// SPDX-License-Identifier: MIT
// Orientability of a polygon soup, judged on its faces alone (no map).
#include <cgogn/core/build/map_builder.h>

#include "builder_common.h"

#include <algorithm>
#include <tuple>

namespace cgogn
{

std::pair<bool, uint32> soup_orientation(uint32 nb_vertices, std::span<const uint32> face_sizes,
										 std::span<const uint32> face_vertices)
{
	// every edge side: (low end, high end, face, listed from low to high)
	struct Side
	{
		uint32 lo, hi, face;
		bool forward;
	};
	std::vector<Side> sides;
	sides.reserve(face_vertices.size());
	const uint32 nb_faces = uint32(face_sizes.size());
	// the faces the builders skip are left out
	detail::foreach_buildable_face(nb_vertices, face_sizes, face_vertices, nullptr,
								   [&](uint32 f, std::span<const uint32> fv) {
									   for (std::size_t i = 0; i < fv.size(); ++i)
									   {
										   const uint32 a = fv[i], b = fv[(i + 1) % fv.size()];
										   sides.push_back({std::min(a, b), std::max(a, b), f, a < b});
									   }
								   });
	std::sort(sides.begin(), sides.end(),
			  [](const Side& x, const Side& y) { return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face); });

	// the faces glued two by two: (other face, same direction) per face, CSR
	std::vector<uint32> offsets(nb_faces + 1, 0);
	std::vector<std::tuple<uint32, uint32, bool>> pairs;
	uint32 conflicts = 0;
	for (std::size_t i = 0; i < sides.size();)
	{
		std::size_t j = i;
		while (j < sides.size() && sides[j].lo == sides[i].lo && sides[j].hi == sides[i].hi)
			++j;
		// glued two by two in face order, as the GMap2 builder glues them
		for (std::size_t k = i; k + 1 < j; k += 2)
		{
			const bool same = sides[k].forward == sides[k + 1].forward;
			conflicts += same && j - i == 2;
			pairs.emplace_back(sides[k].face, sides[k + 1].face, same);
			++offsets[sides[k].face + 1];
			++offsets[sides[k + 1].face + 1];
		}
		i = j;
	}
	for (uint32 f = 0; f < nb_faces; ++f)
		offsets[f + 1] += offsets[f];
	std::vector<std::pair<uint32, bool>> glued(offsets[nb_faces]);
	{
		std::vector<uint32> pos(offsets.begin(), offsets.end() - 1);
		for (const auto& [f, g, same] : pairs)
		{
			glued[pos[f]++] = {g, same};
			glued[pos[g]++] = {f, same};
		}
	}

	// two-colour the faces: across an edge listed the same way, one of the two
	// faces must be turned over
	std::vector<uint8> colour(nb_faces, 2); // 2: not reached yet
	std::vector<uint32> work;
	for (uint32 start = 0; start < nb_faces; ++start)
	{
		if (colour[start] != 2)
			continue;
		colour[start] = 0;
		work.assign(1, start);
		while (!work.empty())
		{
			const uint32 f = work.back();
			work.pop_back();
			for (uint32 k = offsets[f]; k < offsets[f + 1]; ++k)
			{
				const auto [g, same] = glued[k];
				const uint8 want = uint8(colour[f] ^ uint8(same));
				if (colour[g] == 2)
				{
					colour[g] = want;
					work.push_back(g);
				}
				else if (colour[g] != want)
					return {false, conflicts};
			}
		}
	}
	return {true, conflicts};
}

} // namespace cgogn
