// The "CellFilter" section of the CGoGN API guide: traverse only the faces whose
// area is above a threshold.
#include <cgogn/cgogn.h>

#include <Eigen/Geometry>

#include <iostream>

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Face = CMap2::Face;

uint32 print_faces(const CMap2& m, const AttributeArray<double>& area, double threshold)
{
	CellFilter<CMap2> cfm(m);
	cfm.set_filter<Face>([&](Face f) -> bool { return value<double>(cfm, area, f) > threshold; });
	uint32 n = 0;
	foreach_cell(cfm, [&](Face f) -> bool {
		if (n < 5)
			std::cout << f << "\n";
		++n;
		return true;
	});
	return n;
}

int main()
{
	CMap2 m;
	SurfaceSoup soup = sphere_soup(24, 12, true);
	BuildReport report = build_surface(m, soup);
	auto position = add_attribute<Vec3, Vertex>(m, "position");
	for (uint32 i = 0; i < soup.nb_vertices; ++i)
	{
		const auto& p = soup.positions[i];
		(*position)[report.vertex_offset + i] = Vec3(p[0], p[1], p[2]);
	}
	auto area = add_attribute<double, Face>(m, "area");
	foreach_cell(m, [&](Face f) {
		const Vec3& a = value(m, position, Vertex(f.dart));
		const Vec3& b = value(m, position, Vertex(phi1(m, f.dart)));
		const Vec3& c = value(m, position, Vertex(phi<1, 1>(m, f.dart)));
		value(m, area, f) = 0.5 * (b - a).cross(c - a).norm();
	});
	double mean = 0.0;
	for (double a : *area)
		mean += a;
	mean /= nb_cells<Face>(m);

	const uint32 n = print_faces(m, *area, mean);
	uint32 expected = 0;
	for (double a : *area)
		expected += a > mean;
	std::cout << n << " of " << nb_cells<Face>(m) << " faces are larger than the mean area " << mean << "\n";
	return n == expected && n > 0 ? 0 : 1;
}
