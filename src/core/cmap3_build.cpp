// SPDX-License-Identifier: MIT
#include "cmap3_build.h"

#include <cgogn/core/map/darts.h>
#include <cgogn/core/marking/dart_marker.h>

#include "index_lines.h"

#include <map>
#include <unordered_map>

namespace cgogn::detail
{

const FaceList* cell_faces(uint32 nb_vertices)
{
	static const FaceList tet = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
	static const FaceList pyramid = pyramid_faces(4);
	static const FaceList prism = prism_faces(3);
	static const FaceList hexa = prism_faces(4);
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

FaceList pyramid_faces(uint32 n)
{
	// base 0..n-1 seen from the apex side counterclockwise; apex n
	FaceList f;
	std::vector<uint32> base;
	for (uint32 i = n; i-- > 0;)
		base.push_back(i);
	f.push_back(base);
	for (uint32 i = 0; i < n; ++i)
		f.push_back({i, (i + 1) % n, n});
	return f;
}

FaceList prism_faces(uint32 n)
{
	// bottom 0..n-1, top n..2n-1 above it
	FaceList f;
	std::vector<uint32> bottom, top;
	for (uint32 i = n; i-- > 0;)
		bottom.push_back(i);
	for (uint32 i = 0; i < n; ++i)
		top.push_back(n + i);
	f.push_back(bottom);
	f.push_back(top);
	for (uint32 i = 0; i < n; ++i)
		f.push_back({i, (i + 1) % n, n + (i + 1) % n, n + i});
	return f;
}

std::vector<Dart> add_volume_topology(CMap3& m, const FaceList& faces, std::span<const uint32> labels,
									  std::vector<uint32>& dart_labels)
{
	std::vector<Dart> darts;
	const std::size_t first_label = dart_labels.size();
	for (const auto& f : faces)
	{
		const std::size_t b = darts.size();
		for (uint32 v : f)
		{
			darts.push_back(add_dart(m));
			dart_labels.push_back(labels[v]);
		}
		for (std::size_t i = 0; i < f.size(); ++i)
			set_phi1(m, darts[b + i], darts[b + (i + 1) % f.size()]);
	}
	// sew each half-edge a -> b with the free b -> a
	std::map<std::pair<uint32, uint32>, std::vector<Dart>> free_half_edges;
	std::unordered_map<uint32, uint32> label_of_dart;
	for (std::size_t i = 0; i < darts.size(); ++i)
		label_of_dart[darts[i].index] = dart_labels[first_label + i];
	for (Dart d : darts)
	{
		const uint32 a = label_of_dart[d.index], b = label_of_dart[phi1(m, d).index];
		auto it = free_half_edges.find({b, a});
		if (it != free_half_edges.end() && !it->second.empty())
		{
			phi2_sew(m, d, it->second.back());
			it->second.pop_back();
		}
		else
			free_half_edges[{a, b}].push_back(d);
	}
	return darts;
}

namespace
{
// From boundary dart b, the boundary dart met by turning around its edge
// through the volumes (phi3 into the volume, then phi2 and phi3 until a
// boundary volume). The walk back from the result gives b.
Dart turn_to_boundary(const CMap3& m, Dart b)
{
	Dart it = phi2(m, phi3(m, b));
	while (!is_boundary(m, phi3(m, it)))
		it = phi2(m, phi3(m, it));
	return phi3(m, it);
}
} // namespace

void close_phi3_holes(CMap3& m, const std::vector<Dart>& darts, std::vector<Dart>& created,
					  std::span<const std::pair<Dart, Dart>> cut, std::vector<Dart>* repaired)
{
	const std::size_t first = created.size();
	std::vector<Dart> face;
	for (Dart d : darts)
	{
		if (phi3(m, d) != d)
			continue;
		face.clear();
		Dart it = d;
		do
		{
			face.push_back(it);
			it = phi1(m, it);
		} while (it != d);
		const std::size_t k = face.size(), b0 = created.size();
		for (std::size_t i = 0; i < k; ++i)
		{
			const Dart b = add_dart(m);
			set_boundary(m, b, true);
			copy_dart_index<Orbit::PHI21_PHI31>(m, b, phi1(m, face[i]));
			created.push_back(b);
			phi3_sew(m, face[i], b);
		}
		// face[i] goes v_i -> v_i+1; its mate b_i goes v_i+1 -> v_i, followed by b_i-1
		for (std::size_t i = 0; i < k; ++i)
			set_phi1(m, created[b0 + i], created[b0 + (i + k - 1) % k]);
	}
	const std::span<const Dart> fresh(created.begin() + std::ptrdiff_t(first), created.end());
	// Each new boundary dart b takes the boundary dart z met by turning around
	// its edge: the fan of volumes between them becomes an edge of its own,
	// closed by the boundary. When z was paired with an older boundary dart p
	// (the edge had a boundary already), p is left free.
	std::vector<std::pair<Dart, Dart>> taken; // (z, its former partner p)
	for (Dart b : fresh)
	{
		if (phi2(m, b) != b)
			continue;
		const Dart z = turn_to_boundary(m, b);
		if (phi2(m, z) != z)
		{
			taken.emplace_back(z, phi2(m, z));
			phi2_unsew(m, z);
		}
		phi2_sew(m, b, z);
	}
	if (taken.empty())
		return;
	// A freed p is paired with the dart the edge led to before the change,
	// through the fan that left: from p's former partner, turn through the
	// volumes, across each cut face to the other side (`cut`), until an old
	// boundary dart z', whose former partner closes the gap. The rest of a
	// pinched edge (fans joined by boundary faces) thus stays one edge. Where
	// the walk meets a new face with no other side (closing low-level sewing),
	// p turns around its own edge like a new dart.
	auto former_partner = [&](Dart z) {
		for (const auto& [zz, p] : taken)
			if (zz == z)
				return p;
		return Dart();
	};
	auto other_side = [&](Dart b) {
		const Dart x = phi3(m, b);
		for (const auto& [c1, c2] : cut)
			if (c1 == x || c2 == x)
				return phi3(m, c1 == x ? c2 : c1);
		return Dart();
	};
	DartMarkerStore<CMap3> fresh_mark(m);
	for (Dart b : fresh)
		fresh_mark.mark(b);
	for (std::size_t i = 0; i < taken.size(); ++i)
	{
		const auto [z, p] = taken[i];
		if (repaired != nullptr) // both ends of both: the vertices may come apart too
			repaired->insert(repaired->end(), {z, phi1(m, z), p, phi1(m, p)});
		if (phi2(m, p) != p)
			continue;
		Dart c = z, mate;
		for (std::size_t guard = 0; guard <= fresh.size() && !mate.is_valid(); ++guard)
		{
			const Dart end = turn_to_boundary(m, c);
			if (!fresh_mark.is_marked(end))
				mate = phi2(m, end) == end ? end : former_partner(end);
			else if (!(c = other_side(end)).is_valid())
				break;
		}
		if (!mate.is_valid() || phi2(m, mate) != mate)
			mate = turn_to_boundary(m, p);
		if (phi2(m, mate) != mate)
			continue; // paired meanwhile: p's own walk meets a dart already taken
		phi2_sew(m, p, mate);
	}
}

} // namespace cgogn::detail
