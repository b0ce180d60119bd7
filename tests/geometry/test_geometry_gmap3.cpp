// SPDX-License-Identifier: MIT
// The volume geometry of 3-G-maps against the 3-maps they come from: the
// same lengths, areas, centroids, volumes and centres of mass, cell by cell,
// on generated and real volume meshes; and a solid that no 3-map holds.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace cgogn_test_geometry_gmap3
{

using namespace cgogn;
using namespace cgogn::geometry;

namespace
{

// A 3-map with positions, and the volume attributes its geometry gives,
// computed before the conversion so that to_gmap carries them to the G-map.
struct Reference
{
	std::string name;
	CMap3 c;
};

std::vector<Reference> references()
{
	std::vector<Reference> out;
	const auto built = [&](const char* name, const VolumeSoup& s, bool twist) {
		Reference r{name, CMap3()};
		test::Pos pos = test::build_with_positions(r.c, s);
		if (twist)
		{
			uint32 i = 0;
			for (Vec3& p : *pos)
				p += 0.2 * Vec3(test::noise(3 * i), test::noise(3 * i + 1), test::noise(3 * i + 2)), ++i;
		}
		out.push_back(std::move(r));
	};
	built("tet grid", tet_grid_soup(2, 3, 2), false);
	built("hex grid", hex_grid_soup(3, 2, 2), false);
	built("twisted hexahedra", hex_grid_soup(3, 3, 3), true);
	for (const char* file : {"volume/liver_hex_624.mesh", "volume/armadillo_tet_4k.mesh"})
	{
		Reference r{file, CMap3()};
		io::load_volume(r.c, cgogn_test_data::path(file));
		out.push_back(std::move(r));
	}
	return out;
}

double relative(double a, double b)
{
	return std::abs(a - b) / std::max(1.0, std::abs(b));
}

} // namespace

TEST(GeometryGMap3, SameGeometryAsThe3Map)
{
	for (Reference& r : references())
	{
		SCOPED_TRACE(r.name);
		CMap3& c = r.c;
		auto pc = get_attribute<Vec3, CMap3::Vertex>(c, "position");
		ASSERT_TRUE(pc);
		auto vol = add_attribute<double, CMap3::Volume>(c, "volume");
		auto centre = add_attribute<Vec3, CMap3::Volume>(c, "mass center");
		auto middle = add_attribute<Vec3, CMap3::Volume>(c, "centroid");
		auto area = add_attribute<double, CMap3::Face>(c, "area");
		auto length = add_attribute<double, CMap3::Edge>(c, "length");
		compute_volumes(c, *pc, *vol);
		foreach_cell(c, [&](CMap3::Volume w) {
			(*centre)[w] = mass_center(c, w, *pc);
			(*middle)[w] = centroid(c, w, *pc);
		});
		compute_face_areas(c, *pc, *area);
		compute_edge_lengths(c, *pc, *length);

		GMap3 g = to_gmap(c);
		auto pg = get_attribute<Vec3, GMap3::Vertex>(g, "position");
		auto vol_c = get_attribute<double, GMap3::Volume>(g, "volume");
		auto centre_c = get_attribute<Vec3, GMap3::Volume>(g, "mass center");
		auto middle_c = get_attribute<Vec3, GMap3::Volume>(g, "centroid");
		auto area_c = get_attribute<double, GMap3::Face>(g, "area");
		auto length_c = get_attribute<double, GMap3::Edge>(g, "length");
		ASSERT_TRUE(pg && vol_c && centre_c && middle_c && area_c && length_c);

		uint32 volumes = 0;
		foreach_cell(g, [&](GMap3::Volume w) {
			++volumes;
			EXPECT_LT(relative(volume(g, w, *pg), (*vol_c)[w]), 1e-12);
			// from either orientation of the cell's darts
			EXPECT_LT(relative(volume(g, GMap3::Volume(beta0(g, w.dart)), *pg), (*vol_c)[w]), 1e-12);
			EXPECT_LT((mass_center(g, w, *pg) - (*centre_c)[w]).norm(), 1e-9);
			EXPECT_LT((centroid(g, w, *pg) - (*middle_c)[w]).norm(), 1e-12);
		});
		EXPECT_EQ(volumes, nb_cells<CMap3::Volume>(c));
		foreach_cell(g, [&](GMap3::Face f) { EXPECT_LT(relative(face_area(g, f, *pg), (*area_c)[f]), 1e-12); });
		foreach_cell(g, [&](GMap3::Edge e) { EXPECT_LT(relative(edge_length(g, e, *pg), (*length_c)[e]), 1e-12); });
		auto vol_g = add_attribute<double, GMap3::Volume>(g, "volume of the G-map");
		compute_volumes(g, *pg, *vol_g);
		foreach_cell(g, [&](GMap3::Volume w) { EXPECT_DOUBLE_EQ((*vol_g)[w], volume(g, w, *pg)); });
		EXPECT_LT(relative(solid_volume(g, *pg), solid_volume(c, *pc)), 1e-12);
		EXPECT_LT(relative(boundary_area(g, *pg), boundary_area(c, *pc)), 1e-12);
		EXPECT_LT(relative(mean_edge_length(g, *pg), mean_edge_length(c, *pc)), 1e-12);
	}
}

// A ring of 6 hexahedra closed through a reflection: no 3-map holds it. Each
// cell has the volume of the same hexahedron alone in a 3-map, and the solid
// volume is their sum.
TEST(GeometryGMap3, SolidKleinBottle)
{
	GMap3 g;
	const VolumeSoup s = solid_klein_bottle_soup(6);
	const BuildReport r = build_volume(g, s);
	ASSERT_FALSE(r.orientable);
	auto pos = add_attribute<Vec3, GMap3::Vertex>(g, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	std::vector<double> alone, in_g;
	for (std::size_t k = 0; k < s.cell_sizes.size(); ++k)
	{
		ASSERT_EQ(s.cell_sizes[k], 8u);
		VolumeSoup one;
		one.nb_vertices = 8;
		one.cell_sizes = {8};
		for (uint32 j = 0; j < 8; ++j)
		{
			one.cell_vertices.push_back(j);
			one.positions.push_back(s.positions[s.cell_vertices[8 * k + j]]);
		}
		CMap3 c;
		test::Pos pc = test::build_with_positions(c, one);
		foreach_cell(c, [&](CMap3::Volume w) { alone.push_back(std::abs(volume(c, w, *pc))); });
	}
	foreach_cell(g, [&](GMap3::Volume w) { in_g.push_back(volume(g, w, *pos)); });
	std::sort(alone.begin(), alone.end());
	std::sort(in_g.begin(), in_g.end());
	ASSERT_EQ(in_g.size(), 6u);
	ASSERT_EQ(alone.size(), 6u);
	double sum = 0.0;
	for (std::size_t k = 0; k < 6; ++k)
	{
		EXPECT_LT(relative(in_g[k], alone[k]), 1e-12);
		sum += alone[k];
	}
	EXPECT_LT(relative(solid_volume(g, *pos), sum), 1e-12);
	EXPECT_GT(sum, 0.0);
}

} // namespace cgogn_test_geometry_gmap3
