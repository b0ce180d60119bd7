// The geometry layer on generated meshes: positions as a Vec3 vertex
// attribute, measures, curvature, and a smoothing filter.
#include <cgogn/cgogn.h>

#include <iostream>
#include <numbers>

using namespace cgogn;
using namespace cgogn::geometry;

// Builds a soup and copies its positions into a "position" vertex attribute.
std::shared_ptr<AttributeArray<Vec3>> build(CMap2& m, const SurfaceSoup& s)
{
	const BuildReport r = build_surface(m, s);
	auto pos = add_attribute<Vec3, CMap2::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return pos;
}

int main()
{
	constexpr double pi = std::numbers::pi;

	CMap2 sphere;
	auto pos = build(sphere, sphere_soup(64, 32, true));
	std::cout << "unit sphere, " << nb_cells<CMap2::Face>(sphere) << " triangles\n"
			  << "  area   " << surface_area(sphere, *pos) << " (4 pi = " << 4 * pi << ")\n"
			  << "  volume " << signed_volume(sphere, *pos) << " (4 pi / 3 = " << 4 * pi / 3 << ")\n"
			  << "  mean edge length " << mean_edge_length(sphere, *pos) << "\n";

	// curvature at a vertex of the equator
	CMap2::Vertex v;
	foreach_cell(sphere, [&](CMap2::Vertex x) {
		if (std::abs(value<Vec3>(sphere, pos, x).z()) > 1e-9)
			return true;
		v = x;
		return false;
	});
	const PrincipalCurvatures k = principal_curvatures(sphere, v, *pos);
	std::cout << "  at the equator: H = " << mean_curvature(sphere, v, *pos)
			  << ", K = " << gaussian_curvature(sphere, v, *pos) << ", k1 = " << k.kmin << ", k2 = " << k.kmax
			  << " (all 1 on the smooth sphere)\n";

	// Gauss-Bonnet: the angle defects add up to 2 pi chi = 4 pi
	double total = 0.0;
	foreach_cell(sphere, [&](CMap2::Vertex x) { total += angle_defect(sphere, x, *pos); });
	std::cout << "  sum of angle defects " << total << " (4 pi)\n";

	// normals for rendering, one attribute each
	auto normal = add_attribute<Vec3, CMap2::Vertex>(sphere, "normal");
	compute_vertex_normals(sphere, *pos, *normal, NormalWeighting::Angle);

	// smoothing a noisy torus: Taubin keeps the volume, plain Laplacian shrinks it
	for (bool taubin : {false, true})
	{
		CMap2 torus;
		auto tpos = build(torus, torus_soup(48, 24, true));
		uint32 i = 0;
		for (Vec3& p : *tpos)
			p += 0.02 * Vec3(std::sin(12.9898 * i), std::sin(78.233 * i), std::sin(37.719 * i)), ++i;
		const double before = signed_volume(torus, *tpos);
		if (taubin)
			taubin_smoothing(torus, *tpos, 20);
		else
			laplacian_smoothing(torus, *tpos, 20);
		std::cout << (taubin ? "taubin" : "laplacian") << " smoothing of a noisy torus: volume " << before << " -> "
				  << signed_volume(torus, *tpos) << "\n";
	}

	// a volume mesh: cell volumes and the volume of the solid
	CMap3 hexes;
	const VolumeSoup hs = hex_grid_soup(3, 2, 2);
	const BuildReport r = build_volume(hexes, hs);
	auto hpos = add_attribute<Vec3, CMap3::Vertex>(hexes, "position");
	for (uint32 j = 0; j < hs.nb_vertices; ++j)
		(*hpos)[r.vertex_offset + j] = Vec3(hs.positions[j][0], hs.positions[j][1], hs.positions[j][2]);
	std::cout << "hex grid 3x2x2: solid volume " << solid_volume(hexes, *hpos) << ", boundary area "
			  << boundary_area(hexes, *hpos) << "\n";
	return 0;
}
