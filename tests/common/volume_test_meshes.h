// SPDX-License-Identifier: MIT
// Shared by the volume tests of 3-maps and 3-G-maps: their cell counts, and
// a soup with every cell kind.
#pragma once

#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <ostream>

namespace cgogn::test
{

/// The darts and cells of a volume map (boundary cells excluded), its
/// boundary components and Euler characteristic.
struct VolumeCounts
{
	uint32 darts, v, e, f, w, cc, boundary;
	int64 chi;
	bool operator==(const VolumeCounts&) const = default;
};

inline std::ostream& operator<<(std::ostream& os, const VolumeCounts& c)
{
	return os << "{darts " << c.darts << ", V " << c.v << ", E " << c.e << ", F " << c.f << ", W " << c.w << ", CC "
			  << c.cc << ", boundary " << c.boundary << ", chi " << c.chi << "}";
}

template <typename MAP>
VolumeCounts volume_counts(const MAP& m)
{
	using T = mesh_traits<MAP>;
	return {nb_darts(m),
			nb_cells<typename T::Vertex>(m),
			nb_cells<typename T::Edge>(m),
			nb_cells<typename T::Face>(m),
			nb_cells<typename T::Volume>(m),
			nb_cells<typename T::CC>(m),
			nb_boundary_components(m),
			euler_characteristic(m)};
}

/// The counts of a 3-G-map with its darts halved: those of the 3-map of the
/// same mesh.
inline VolumeCounts halved(VolumeCounts c)
{
	c.darts /= 2;
	return c;
}

/// A 2x2x1 grid of unit hexahedra with a pyramid and a prism on top, all
/// positively oriented.
inline VolumeSoup mixed_volume_soup()
{
	VolumeSoup s = hex_grid_soup(2, 2, 1);
	const uint32 base = s.nb_vertices;
	auto id = [](uint32 i, uint32 j, uint32 k) { return (k * 3 + j) * 3 + i; };
	// the pyramid on top of hexahedron (0, 0)
	s.positions.push_back({0.5, 0.5, 1.7});
	s.cell_sizes.push_back(5);
	for (uint32 v : {id(0, 0, 1), id(1, 0, 1), id(1, 1, 1), id(0, 1, 1), base})
		s.cell_vertices.push_back(v);
	// the prism on top of hexahedron (1, 0): triangle (1,0,1) (2,0,1) (2,1,1) lifted
	s.positions.push_back({1.0, 0.0, 2.0});
	s.positions.push_back({2.0, 0.0, 2.0});
	s.positions.push_back({2.0, 1.0, 2.0});
	s.cell_sizes.push_back(6);
	for (uint32 v : {id(1, 0, 1), id(2, 0, 1), id(2, 1, 1), base + 1, base + 2, base + 3})
		s.cell_vertices.push_back(v);
	s.nb_vertices = base + 4;
	return s;
}

/// The hexahedral grid of a x b x c unit hexahedra (hex_grid_soup) as a
/// CMap3, with a "position" vertex attribute scaled by `scale`.
inline CMap3 hex_grid_with_positions(uint32 a, uint32 b, uint32 c, double scale = 1.0)
{
	const VolumeSoup soup = hex_grid_soup(a, b, c);
	CMap3 m;
	const BuildReport r = build_volume(m, soup);
	auto pos = add_attribute<Vec3, CMap3::Vertex>(m, "position");
	for (uint32 i = 0; i < soup.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] =
			scale * Vec3(soup.positions[i][0], soup.positions[i][1], soup.positions[i][2]); // soup vertex i
	return m;
}

} // namespace cgogn::test
