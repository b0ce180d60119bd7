// SPDX-License-Identifier: MIT
#include <cgogn/core/build/generators.h>

#include "cmap3_build.h"

#include <cmath>
#include <numbers>

namespace cgogn
{

namespace
{

void add_quad(SurfaceSoup& s, uint32 a, uint32 b, uint32 c, uint32 d, bool triangles)
{
	if (triangles)
	{
		s.face_sizes.insert(s.face_sizes.end(), {3, 3});
		s.face_vertices.insert(s.face_vertices.end(), {a, b, c, a, c, d});
	}
	else
	{
		s.face_sizes.push_back(4);
		s.face_vertices.insert(s.face_vertices.end(), {a, b, c, d});
	}
}

void add_triangle(SurfaceSoup& s, uint32 a, uint32 b, uint32 c)
{
	s.face_sizes.push_back(3);
	s.face_vertices.insert(s.face_vertices.end(), {a, b, c});
}

double det3(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
			const std::array<double, 3>& d)
{
	const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
	const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
	const double w[3] = {d[0] - a[0], d[1] - a[1], d[2] - a[2]};
	return u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
}

std::vector<std::array<double, 3>> grid_points(uint32 nx, uint32 ny, uint32 nz)
{
	std::vector<std::array<double, 3>> p;
	p.reserve(std::size_t(nx + 1) * (ny + 1) * (nz + 1));
	for (uint32 k = 0; k <= nz; ++k)
		for (uint32 j = 0; j <= ny; ++j)
			for (uint32 i = 0; i <= nx; ++i)
				p.push_back({double(i), double(j), double(k)});
	return p;
}

} // namespace

SurfaceSoup grid_soup(uint32 nx, uint32 ny, bool triangles)
{
	SurfaceSoup s;
	s.nb_vertices = (nx + 1) * (ny + 1);
	for (uint32 j = 0; j <= ny; ++j)
		for (uint32 i = 0; i <= nx; ++i)
			s.positions.push_back({double(i), double(j), 0.0});
	auto v = [&](uint32 i, uint32 j) { return j * (nx + 1) + i; };
	for (uint32 j = 0; j < ny; ++j)
		for (uint32 i = 0; i < nx; ++i)
			add_quad(s, v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1), triangles);
	return s;
}

SurfaceSoup cylinder_soup(uint32 nu, uint32 nv, bool triangles)
{
	SurfaceSoup s;
	s.nb_vertices = nu * (nv + 1);
	for (uint32 j = 0; j <= nv; ++j)
		for (uint32 i = 0; i < nu; ++i)
		{
			const double t = 2.0 * std::numbers::pi * i / nu;
			s.positions.push_back({std::cos(t), std::sin(t), double(j) / nv});
		}
	auto v = [&](uint32 i, uint32 j) { return j * nu + (i % nu); };
	for (uint32 j = 0; j < nv; ++j)
		for (uint32 i = 0; i < nu; ++i)
			add_quad(s, v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1), triangles);
	return s;
}

SurfaceSoup sphere_soup(uint32 nu, uint32 nv, bool triangles)
{
	SurfaceSoup s;
	const uint32 rings = nv - 1;
	s.nb_vertices = 2 + nu * rings;
	s.positions.push_back({0.0, 0.0, -1.0});
	s.positions.push_back({0.0, 0.0, 1.0});
	for (uint32 k = 1; k <= rings; ++k)
	{
		const double phi = -std::numbers::pi / 2 + std::numbers::pi * k / nv;
		for (uint32 i = 0; i < nu; ++i)
		{
			const double t = 2.0 * std::numbers::pi * i / nu;
			s.positions.push_back({std::cos(phi) * std::cos(t), std::cos(phi) * std::sin(t), std::sin(phi)});
		}
	}
	auto v = [&](uint32 i, uint32 k) { return 2 + (k - 1) * nu + (i % nu); };
	for (uint32 i = 0; i < nu; ++i)
		add_triangle(s, 0, v(i + 1, 1), v(i, 1));
	for (uint32 k = 1; k < rings; ++k)
		for (uint32 i = 0; i < nu; ++i)
			add_quad(s, v(i, k), v(i + 1, k), v(i + 1, k + 1), v(i, k + 1), triangles);
	for (uint32 i = 0; i < nu; ++i)
		add_triangle(s, v(i, rings), v(i + 1, rings), 1);
	return s;
}

SurfaceSoup torus_soup(uint32 nu, uint32 nv, bool triangles)
{
	SurfaceSoup s;
	s.nb_vertices = nu * nv;
	for (uint32 i = 0; i < nu; ++i)
		for (uint32 j = 0; j < nv; ++j)
		{
			const double t = 2.0 * std::numbers::pi * i / nu;
			const double p = 2.0 * std::numbers::pi * j / nv;
			const double r = 1.0 + 0.5 * std::cos(p);
			s.positions.push_back({r * std::cos(t), r * std::sin(t), 0.5 * std::sin(p)});
		}
	auto v = [&](uint32 i, uint32 j) { return (i % nu) * nv + (j % nv); };
	for (uint32 i = 0; i < nu; ++i)
		for (uint32 j = 0; j < nv; ++j)
			add_quad(s, v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1), triangles);
	return s;
}

SurfaceSoup mobius_soup(uint32 n, bool triangles)
{
	SurfaceSoup s;
	s.nb_vertices = 2 * n;
	// vertex (i, side): at angle t = 2 pi i / n, the segment across the strip
	// turned by t / 2 around the circle's tangent, so it has turned half a
	// turn after a full loop: side 0 of the last ring meets side 1 of the first
	for (uint32 i = 0; i < n; ++i)
	{
		const double t = 2.0 * std::numbers::pi * i / n;
		for (double w : {-0.25, 0.25})
		{
			const double r = 1.0 + w * std::cos(t / 2);
			s.positions.push_back({r * std::cos(t), r * std::sin(t), w * std::sin(t / 2)});
		}
	}
	auto v = [&](uint32 i, uint32 side) { return 2 * i + side; };
	for (uint32 i = 0; i + 1 < n; ++i)
		add_quad(s, v(i, 0), v(i + 1, 0), v(i + 1, 1), v(i, 1), triangles);
	add_quad(s, v(n - 1, 0), v(0, 1), v(0, 0), v(n - 1, 1), triangles);
	return s;
}

SurfaceSoup klein_bottle_soup(uint32 nu, uint32 nv, bool triangles)
{
	SurfaceSoup s = torus_soup(nu, nv, triangles);
	// the ring i = nu is ring 0 reversed: rewrite the last row of faces
	s.face_sizes.clear();
	s.face_vertices.clear();
	auto v = [&](uint32 i, uint32 j) { return i == nu ? (nv - j % nv) % nv : i * nv + (j % nv); };
	for (uint32 i = 0; i < nu; ++i)
		for (uint32 j = 0; j < nv; ++j)
			add_quad(s, v(i, j), v(i + 1, j), v(i + 1, j + 1), v(i, j + 1), triangles);
	return s;
}

VolumeSoup solid_klein_bottle_soup(uint32 n)
{
	VolumeSoup s;
	s.nb_vertices = 4 * n;
	// the corners of the section, in cycle order; `mirrored` reflects it
	// across the plane through the ring's axis circle (a <-> -a)
	constexpr double a[4] = {-0.5, 0.5, 0.5, -0.5}, b[4] = {-0.5, -0.5, 0.5, 0.5};
	constexpr uint32 mirrored[4] = {1, 0, 3, 2};
	for (uint32 i = 0; i < n; ++i)
	{
		const double t = 2.0 * std::numbers::pi * i / n;
		for (uint32 k = 0; k < 4; ++k)
			s.positions.push_back({(2.0 + a[k]) * std::cos(t), (2.0 + a[k]) * std::sin(t), b[k]});
	}
	for (uint32 i = 0; i < n; ++i)
	{
		s.cell_sizes.push_back(8);
		for (uint32 k = 0; k < 4; ++k)
			s.cell_vertices.push_back(4 * i + k);
		for (uint32 k = 0; k < 4; ++k)
			s.cell_vertices.push_back(i + 1 < n ? 4 * (i + 1) + k : mirrored[k]);
	}
	return s;
}

SurfaceSoup hemi_icosahedron_soup()
{
	SurfaceSoup s;
	s.nb_vertices = 6;
	// the north pole and the upper ring of 5 of the unit icosahedron
	s.positions.push_back({0.0, 0.0, 1.0});
	const double z = 1.0 / std::sqrt(5.0), r = 2.0 / std::sqrt(5.0);
	for (uint32 k = 0; k < 5; ++k)
	{
		const double t = 2.0 * std::numbers::pi * k / 5;
		s.positions.push_back({r * std::cos(t), r * std::sin(t), z});
	}
	// the 5 triangles around the pole, and the 5 of the antipodal band, whose
	// lower ring vertex k + 5/2 is upper vertex k + 2 or k + 3 identified
	constexpr uint32 faces[10][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}, {0, 5, 1},
									 {1, 2, 4}, {2, 3, 5}, {3, 4, 1}, {4, 5, 2}, {5, 1, 3}};
	for (const auto& f : faces)
	{
		s.face_sizes.push_back(3);
		s.face_vertices.insert(s.face_vertices.end(), {f[0], f[1], f[2]});
	}
	return s;
}

SurfaceSoup hemi_cube_soup()
{
	SurfaceSoup s;
	s.nb_vertices = 4;
	// one vertex of each antipodal pair of the cube
	s.positions = {{1.0, 1.0, 1.0}, {-1.0, 1.0, 1.0}, {-1.0, -1.0, 1.0}, {1.0, -1.0, 1.0}};
	// the three 4-cycles of K4: each edge in two of them
	constexpr uint32 faces[3][4] = {{0, 1, 2, 3}, {0, 1, 3, 2}, {0, 2, 1, 3}};
	for (const auto& f : faces)
	{
		s.face_sizes.push_back(4);
		s.face_vertices.insert(s.face_vertices.end(), {f[0], f[1], f[2], f[3]});
	}
	return s;
}

VolumeSoup tet_grid_soup(uint32 nx, uint32 ny, uint32 nz)
{
	VolumeSoup s;
	s.positions = grid_points(nx, ny, nz);
	s.nb_vertices = uint32(s.positions.size());
	auto v = [&](uint32 i, uint32 j, uint32 k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
	// Kuhn split of each cube into 6 tets along its main diagonal: conforming
	constexpr uint32 perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
	for (uint32 k = 0; k < nz; ++k)
		for (uint32 j = 0; j < ny; ++j)
			for (uint32 i = 0; i < nx; ++i)
			{
				auto corner = [&](uint32 bits) {
					return v(i + (bits & 1), j + ((bits >> 1) & 1), k + ((bits >> 2) & 1));
				};
				for (const auto& p : perms)
				{
					const uint32 b1 = 1u << p[0];
					const uint32 b2 = b1 | (1u << p[1]);
					std::array<uint32, 4> t = {corner(0), corner(b1), corner(b2), corner(7)};
					if (det3(s.positions[t[0]], s.positions[t[1]], s.positions[t[2]], s.positions[t[3]]) < 0)
						std::swap(t[2], t[3]);
					s.cell_sizes.push_back(4);
					s.cell_vertices.insert(s.cell_vertices.end(), t.begin(), t.end());
				}
			}
	return s;
}

VolumeSoup hex_grid_soup(uint32 nx, uint32 ny, uint32 nz)
{
	VolumeSoup s;
	s.positions = grid_points(nx, ny, nz);
	s.nb_vertices = uint32(s.positions.size());
	auto v = [&](uint32 i, uint32 j, uint32 k) { return (k * (ny + 1) + j) * (nx + 1) + i; };
	for (uint32 k = 0; k < nz; ++k)
		for (uint32 j = 0; j < ny; ++j)
			for (uint32 i = 0; i < nx; ++i)
			{
				s.cell_sizes.push_back(8);
				s.cell_vertices.insert(s.cell_vertices.end(),
									   {v(i, j, k), v(i + 1, j, k), v(i + 1, j + 1, k), v(i, j + 1, k), v(i, j, k + 1),
										v(i + 1, j, k + 1), v(i + 1, j + 1, k + 1), v(i, j + 1, k + 1)});
			}
	return s;
}

PolyhedronSoup polyhedra_of(const VolumeSoup& s)
{
	PolyhedronSoup p;
	p.nb_vertices = s.nb_vertices;
	p.positions = s.positions;
	std::size_t first = 0;
	for (uint32 n : s.cell_sizes)
	{
		const detail::FaceList* faces = detail::cell_faces(n);
		if (faces != nullptr && first + n <= s.cell_vertices.size())
		{
			p.cell_nb_faces.push_back(uint32(faces->size()));
			for (const auto& f : *faces)
			{
				p.face_sizes.push_back(uint32(f.size()));
				for (uint32 local : f)
					p.face_vertices.push_back(s.cell_vertices[first + local]);
			}
		}
		first += n;
	}
	return p;
}

PolyhedronSoup prism_column_soup(uint32 n, uint32 layers)
{
	PolyhedronSoup s;
	s.nb_vertices = n * (layers + 1);
	for (uint32 l = 0; l <= layers; ++l)
		for (uint32 i = 0; i < n; ++i)
		{
			const double a = 2 * std::numbers::pi * i / n;
			s.positions.push_back({std::cos(a), std::sin(a), double(l)});
		}
	for (uint32 l = 0; l < layers; ++l)
	{
		const uint32 b = l * n, t = (l + 1) * n;
		s.cell_nb_faces.push_back(n + 2);
		s.face_sizes.push_back(n); // the bottom, seen from below
		s.face_vertices.push_back(b);
		for (uint32 i = n - 1; i >= 1; --i)
			s.face_vertices.push_back(b + i);
		s.face_sizes.push_back(n); // the top
		for (uint32 i = 0; i < n; ++i)
			s.face_vertices.push_back(t + i);
		for (uint32 i = 0; i < n; ++i) // the sides
		{
			s.face_sizes.push_back(4);
			s.face_vertices.insert(s.face_vertices.end(), {b + i, b + (i + 1) % n, t + (i + 1) % n, t + i});
		}
	}
	return s;
}

} // namespace cgogn
