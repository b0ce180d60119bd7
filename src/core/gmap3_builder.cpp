// SPDX-License-Identifier: MIT
// The cell-list builder of 3-G-maps: each cell as a closed 2-G-map, then
// beta3 gluing of the faces shared by two cells, then the boundary volumes
// that close the map.
#include <cgogn/core/build/map_builder.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/map/orbits.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/properties/gmap_properties.h>

#include "builder_common.h"
#include "cmap3_build.h"
#include "gmap3_close.h"
#include "gmap_darts.h"
#include "index_lines.h"

#include <algorithm>
#include <array>

namespace cgogn
{

namespace
{

// A face of a built cell: its 2k darts are darts[first .. first + 2k), the
// dart at the start of each edge side followed by the dart at its end.
// Its key, keys[key_first .. key_first + size), is its cycle of soup
// vertices from the smallest one, towards the smaller of its two
// neighbours: two faces with the same key have the same vertices in the same
// cyclic order, up to the direction; `forward` tells whether that direction
// is the face's own.
struct CellFace
{
	uint32 key_first;
	uint32 first;
	uint32 size;
	bool forward;
};

CellFace make_face(const std::vector<uint32>& fv, uint32 first, std::vector<uint32>& keys)
{
	const uint32 k = uint32(fv.size());
	const uint32 p = uint32(std::min_element(fv.begin(), fv.end()) - fv.begin());
	const bool forward = fv[(p + 1) % k] < fv[(p + k - 1) % k];
	CellFace f{uint32(keys.size()), first, k, forward};
	for (uint32 j = 0; j < k; ++j)
		keys.push_back(fv[forward ? (p + j) % k : (p + k - j) % k]);
	return f;
}

// The keys of faces, compared as sequences.
struct KeyOrder
{
	const std::vector<uint32>& keys;
	std::span<const uint32> key(const CellFace& f) const
	{
		return {keys.data() + f.key_first, f.size};
	}
	bool equal(const CellFace& f, const CellFace& g) const
	{
		return std::ranges::equal(key(f), key(g));
	}
	bool less(const CellFace& f, const CellFace& g) const
	{
		return std::ranges::lexicographical_compare(key(f), key(g));
	}
};

// An edge side of a cell: its two local vertices (smaller, larger), its
// first dart and the local vertex that dart is at.
struct EdgeSide
{
	uint32 lo, hi;
	Dart dart;
	uint32 start;
};

// One cell as a closed 2-G-map: 2n darts per face of n vertices (a pair,
// beta0, for the two ends of an edge side, beta1 between the two sides of a
// corner), beta2 between the faces of the cell along each edge, dart at a
// vertex to dart at the same vertex. The darts are appended to `darts`, with
// their soup vertex line in vidx, and the faces to `faces` (their keys to
// `keys`); fv and sides are scratch. Precondition: the cell's faces close a
// surface (each edge in exactly two faces).
void add_cell(GMap3& m, std::span<const uint32> cv, const detail::FaceList& cell, AttributeArray<uint32>& vidx,
			  uint32 offset, std::vector<Dart>& darts, std::vector<CellFace>& faces, std::vector<uint32>& keys,
			  std::vector<uint32>& fv, std::vector<EdgeSide>& sides)
{
	sides.clear();
	for (const auto& f : cell)
	{
		const uint32 k = uint32(f.size());
		const std::size_t face_start = darts.size();
		fv.clear();
		for (uint32 i = 0; i < k; ++i)
		{
			const uint32 u = f[i], w = f[(i + 1) % k];
			const Dart a = detail::add_dart_pair(m);
			const Dart b = beta0(m, a);
			vidx[a.index] = offset + cv[u];
			vidx[b.index] = offset + cv[w];
			if (i > 0)
				beta_sew<1>(m, darts.back(), a);
			darts.push_back(a);
			darts.push_back(b);
			fv.push_back(cv[u]);
			sides.push_back({std::min(u, w), std::max(u, w), a, u});
		}
		beta_sew<1>(m, darts.back(), darts[face_start]);
		faces.push_back(make_face(fv, uint32(face_start), keys));
	}
	// the two sides of each edge, sewn
	std::sort(sides.begin(), sides.end(), [](const EdgeSide& x, const EdgeSide& y) {
		return x.lo != y.lo ? x.lo < y.lo : x.hi != y.hi ? x.hi < y.hi : x.dart.index < y.dart.index;
	});
	for (std::size_t i = 0; i + 1 < sides.size(); ++i)
		if (sides[i].lo == sides[i + 1].lo && sides[i].hi == sides[i + 1].hi)
		{
			const EdgeSide& o = sides[i];
			const EdgeSide& x = sides[i + 1];
			const Dart b = beta0(m, x.dart);
			beta_sew<2>(m, x.dart, o.start == x.start ? o.dart : beta0(m, o.dart));
			beta_sew<2>(m, b, o.start == x.start ? beta0(m, o.dart) : o.dart);
			++i;
		}
}

// Builds the cells that foreach_input_cell(report, f) hands to f(labels,
// faces), glues them, closes the outside and indexes the vertices;
// `nb_darts_bound` bounds the darts of the cells (a reservation).
template <typename FOREACH_CELL>
BuildReport build_cells(GMap3& m, uint32 nb_vertices, uint32 nb_cells, std::size_t nb_darts_bound,
						const FOREACH_CELL& foreach_input_cell)
{
	BuildReport report;
	report.nb_cells_read = nb_cells;

	if (!is_indexed<GMap3::Vertex>(m))
		index_cells<GMap3::Vertex>(m);
	AttributeArray<uint32>& vidx = *detail::state_of(m).cell_index[orbit_index(GMap3::Vertex::ORBIT)];
	AttributeContainer& vertices = *detail::state_of(m).cells[orbit_index(GMap3::Vertex::ORBIT)];
	const uint32 offset = vertices.new_lines_at_end(nb_vertices);
	report.vertex_offset = offset;
	const auto soup = [&](Dart d) { return vidx[d.index] - offset; };

	// 1. each cell as a closed 2-G-map (add_cell). A cell's darts are added
	// consecutively (the io layer predicts the first dart of each cell).
	std::vector<Dart> darts;
	std::vector<CellFace> faces;
	std::vector<uint32> keys, fv;
	std::vector<EdgeSide> sides;
	detail::reserve_darts(m, nb_darts_bound);
	foreach_input_cell(report, [&](std::span<const uint32> cv, const detail::FaceList& cell) {
		add_cell(m, cv, cell, vidx, offset, darts, faces, keys, fv, sides);
		++report.nb_cells_built;
	});

	// 2. glue the faces shared by two cells: the dart at vertex a of edge
	// {a, b} of one face to the dart at vertex a of edge {a, b} of the other,
	// whatever the direction in which each cell lists the face. Among the
	// faces of the same vertices, each is glued to the first one after it
	// listing them in the other direction (a cell on the other side, as the
	// CMap3 builder sews), then the others two by two in the order of the
	// cells. A face left alone in a group of three or more is non-manifold:
	// it is closed by the boundary.
	const KeyOrder key_order{keys};
	std::vector<uint32> order(faces.size());
	for (uint32 i = 0; i < uint32(order.size()); ++i)
		order[i] = i;
	std::sort(order.begin(), order.end(), [&](uint32 x, uint32 y) {
		return !key_order.equal(faces[x], faces[y]) ? key_order.less(faces[x], faces[y]) : x < y;
	});
	bool glued_same_way = false;
	auto glue = [&](const CellFace& f, const CellFace& g) {
		glued_same_way = glued_same_way || f.forward == g.forward;
		for (uint32 i = 0; i < 2 * f.size; ++i)
		{
			const Dart x = darts[f.first + i];
			const uint32 v = soup(x), w = soup(beta0(m, x));
			for (uint32 j = 0; j < 2 * g.size; ++j)
			{
				const Dart y = darts[g.first + j];
				if (soup(y) == v && soup(beta0(m, y)) == w)
				{
					beta_sew<3>(m, x, y);
					break;
				}
			}
		}
	};
	std::vector<uint8> paired;
	for (std::size_t i = 0; i < order.size();)
	{
		std::size_t j = i + 1;
		while (j < order.size() && key_order.equal(faces[order[j]], faces[order[i]]))
			++j;
		if (j - i == 2)
			glue(faces[order[i]], faces[order[i + 1]]);
		else if (j - i > 2)
		{
			paired.assign(j - i, 0);
			for (bool opposite : {true, false})
				for (std::size_t p = 0; p < j - i; ++p)
					for (std::size_t q = p + 1; q < j - i && !paired[p]; ++q)
						if (!paired[q] && (faces[order[i + p]].forward != faces[order[i + q]].forward) == opposite)
						{
							glue(faces[order[i + p]], faces[order[i + q]]);
							paired[p] = paired[q] = 1;
						}
			report.nb_nonmanifold_faces += uint32((j - i) % 2);
		}
		i = j;
	}

	// 3. close: boundary volumes mirror the free faces
	std::vector<Dart> boundary_darts;
	detail::close_beta3_holes(m, darts, boundary_darts);
	report.nb_boundary_cells = detail::nb_distinct_volumes<GMap3::Volume>(m, boundary_darts);
	darts.insert(darts.end(), boundary_darts.begin(), boundary_darts.end());
	// the cells listed consistently (every shared face in opposite
	// directions) orient the map; otherwise a two-colouring tells
	if (glued_same_way)
	{
		DartMarker<GMap3> black(m);
		report.orientable = detail::two_colour_from(m, black, [&](const auto& f) {
			for (Dart d : darts)
				if (!f(d))
					return;
		});
	}

	// 4. vertex lines, split of non-manifold vertices
	detail::assign_vertex_lines<GMap3::Vertex>(m, darts, vertices, vidx, offset, nb_vertices, report);

	detail::index_new_darts(m, darts);
	detail::release_idle_marks(m);
	return report;
}

} // namespace

BuildReport build_volume(GMap3& m, uint32 nb_vertices, std::span<const uint32> cell_sizes,
						 std::span<const uint32> cell_vertices)
{
	std::size_t total = 0;
	for (uint32 n : cell_sizes)
		total += n;
	return build_cells(m, nb_vertices, uint32(cell_sizes.size()), 6 * std::min(total, cell_vertices.size()),
					   [&](BuildReport& report, const auto& f) {
						   detail::foreach_buildable_cell(nb_vertices, cell_sizes, cell_vertices, report, f);
					   });
}

BuildReport build_polyhedra(GMap3& m, uint32 nb_vertices, std::span<const uint32> cell_nb_faces,
							std::span<const uint32> face_sizes, std::span<const uint32> face_vertices)
{
	// a face of n vertices has 2 n darts
	return build_cells(m, nb_vertices, uint32(cell_nb_faces.size()), 2 * face_vertices.size(),
					   [&](BuildReport& report, const auto& f) {
						   detail::foreach_buildable_polyhedron(nb_vertices, cell_nb_faces, face_sizes, face_vertices,
																report, f);
					   });
}

} // namespace cgogn
