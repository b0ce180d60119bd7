// SPDX-License-Identifier: MIT
#include "map_transfer.h"

#include <algorithm>
#include <array>
#include <span>
#include <vector>

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

// Turns faces of one polyhedron over so that every edge shared by two faces
// is listed in opposite directions by them (the first face of each
// connected group keeps its direction); true when a face was turned. A
// polyhedron that cannot be so oriented (an edge in more than two faces, a
// one-sided surface) is left as it is: the builder skips it.
bool make_faces_consistent(std::span<const uint32> sizes, std::span<uint32> ids)
{
	std::vector<std::size_t> first(sizes.size() + 1, 0);
	for (std::size_t f = 0; f < sizes.size(); ++f)
		first[f + 1] = first[f] + sizes[f];
	// (smaller vertex, larger vertex, face, whether the face goes smaller -> larger)
	std::vector<std::array<uint32, 4>> edges;
	for (uint32 f = 0; f < uint32(sizes.size()); ++f)
		for (std::size_t i = 0; i < sizes[f]; ++i)
		{
			const uint32 a = ids[first[f] + i], b = ids[first[f] + (i + 1) % sizes[f]];
			edges.push_back({std::min(a, b), std::max(a, b), f, a < b ? 1u : 0u});
		}
	std::sort(edges.begin(), edges.end());
	std::vector<int8> flip(sizes.size(), -1); // -1: not reached yet
	std::vector<uint32> stack;
	bool changed = false;
	for (uint32 seed = 0; seed < uint32(sizes.size()); ++seed)
	{
		if (flip[seed] >= 0)
			continue;
		flip[seed] = 0;
		stack.assign(1, seed);
		while (!stack.empty())
		{
			const uint32 f = stack.back();
			stack.pop_back();
			for (std::size_t i = 0; i < sizes[f]; ++i)
			{
				const uint32 a = ids[first[f] + i], b = ids[first[f] + (i + 1) % sizes[f]];
				const std::array<uint32, 4> key{std::min(a, b), std::max(a, b), 0, 0};
				auto lo = std::lower_bound(edges.begin(), edges.end(), key);
				auto hi = lo;
				while (hi != edges.end() && (*hi)[0] == key[0] && (*hi)[1] == key[1])
					++hi;
				if (hi - lo != 2)
					return false; // not an edge of exactly two faces: left to the builder
				const auto& other = (*lo)[2] == f ? *(lo + 1) : *lo;
				const auto& mine = (*lo)[2] == f ? *lo : *(lo + 1);
				// the other face must go the other way once both are turned as decided
				const int8 want = int8((mine[3] ^ uint32(flip[f])) == other[3] ? 1 : 0);
				if (flip[other[2]] < 0)
				{
					flip[other[2]] = want;
					stack.push_back(other[2]);
				}
				else if (flip[other[2]] != want)
					return false; // one-sided
			}
		}
	}
	for (uint32 f = 0; f < uint32(sizes.size()); ++f)
		if (flip[f] == 1)
		{
			std::reverse(ids.begin() + std::ptrdiff_t(first[f]), ids.begin() + std::ptrdiff_t(first[f + 1]));
			changed = true;
		}
	return changed;
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
	std::size_t face = 0, first = 0; // the next polyhedron's first face and its first vertex
	for (uint32 c = 0; c < d.nb_cells(); ++c)
	{
		const uint32 n = d.cell_sizes[c];
		uint32* v = d.cell_vertices.data() + k;
		k += n;
		if (d.is_polyhedron(c))
		{
			// faces listed in both directions made consistent, then the
			// signed volume, by the divergence theorem over the faces' fans:
			// every face turned over when it is negative
			const uint32 nf = d.cell_nb_faces[c];
			std::size_t size = 0;
			for (uint32 f = 0; f < nf; ++f)
				size += d.polyhedron_face_sizes[face + f];
			const bool turned = make_faces_consistent({d.polyhedron_face_sizes.data() + face, nf},
													  {d.polyhedron_face_vertices.data() + first, size});
			double volume = 0.0;
			std::size_t f_first = first;
			for (uint32 f = 0; f < nf; ++f)
			{
				const uint32 size = d.polyhedron_face_sizes[face + f];
				const uint32* fv = d.polyhedron_face_vertices.data() + f_first;
				for (uint32 i = 1; i + 1 < size; ++i)
					volume += dot(pos(fv[0]), cross(pos(fv[i]), pos(fv[i + 1])));
				f_first += size;
			}
			flipped += turned || volume < 0.0;
			if (volume < 0.0)
			{
				for (uint32 f = 0; f < nf; ++f)
				{
					const uint32 size = d.polyhedron_face_sizes[face + f];
					std::reverse(d.polyhedron_face_vertices.begin() + std::ptrdiff_t(first),
								 d.polyhedron_face_vertices.begin() + std::ptrdiff_t(first + size));
					first += size;
				}
			}
			else
				first = f_first;
			face += nf;
			continue;
		}
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
