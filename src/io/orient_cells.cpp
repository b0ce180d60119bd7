// SPDX-License-Identifier: MIT
#include "map_transfer.h"

#include <array>

namespace cgogn::io::detail
{

namespace
{

using P = std::array<double, 3>;

P sub(const P& a, const P& b)
{
	return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
P cross(const P& a, const P& b)
{
	return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const P& a, const P& b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

} // namespace

uint32 orient_cells(MeshData& d)
{
	auto pos = [&](uint32 v) {
		return P{d.positions[3 * std::size_t(v)], d.positions[3 * std::size_t(v) + 1],
				 d.positions[3 * std::size_t(v) + 2]};
	};
	uint32 flipped = 0;
	std::size_t k = 0;
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		const uint32 n = d.cell_sizes[c];
		uint32* v = d.cell_vertices.data() + k;
		k += n;
		if (n != 4 && n != 5 && n != 6 && n != 8)
			continue;
		// the bottom face (its first `b` vertices) and the rest
		const uint32 b = n == 4 || n == 6 ? 3 : 4;
		// bottom normal (Newell) and centroids
		P normal{0, 0, 0}, cb{0, 0, 0}, ct{0, 0, 0};
		for (uint32 i = 0; i < b; ++i)
		{
			const P p = pos(v[i]), q = pos(v[(i + 1) % b]);
			normal = {normal[0] + (p[1] - q[1]) * (p[2] + q[2]), normal[1] + (p[2] - q[2]) * (p[0] + q[0]),
					  normal[2] + (p[0] - q[0]) * (p[1] + q[1])};
			for (int j = 0; j < 3; ++j)
				cb[std::size_t(j)] += p[std::size_t(j)] / b;
		}
		for (uint32 i = b; i < n; ++i)
		{
			const P p = pos(v[i]);
			for (int j = 0; j < 3; ++j)
				ct[std::size_t(j)] += p[std::size_t(j)] / (n - b);
		}
		double s = dot(normal, sub(ct, cb));
		if (n == 4)
			s = dot(cross(sub(pos(v[1]), pos(v[0])), sub(pos(v[2]), pos(v[0]))), sub(pos(v[3]), pos(v[0])));
		if (!(s < 0.0))
			continue;
		++flipped;
		// reverse the bottom (and the top) keeping vertex 0 first
		auto reverse_from_1 = [](uint32* a, uint32 len) {
			for (uint32 i = 1, j = len - 1; i < j; ++i, --j)
				std::swap(a[i], a[j]);
		};
		reverse_from_1(v, b);
		if (n == 6 || n == 8)
			reverse_from_1(v + b, b);
	}
	return flipped;
}

} // namespace cgogn::io::detail
