// SPDX-License-Identifier: MIT
// Every surface format: write a map, read it back, compare counts, positions
// (within the format's precision) and attribute values.
#include <cgogn/cgogn.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace cgogn_test_surface_roundtrip
{

using namespace cgogn;
using namespace cgogn::io_test;
using Vertex = CMap2::Vertex;
using Face = CMap2::Face;

struct SurfaceCase
{
	const char* name;
	const char* file;
	bool binary;
	double tolerance; // on positions
	bool attributes;  // the format keeps our test attributes
	bool same_order;  // vertices come back in the same order
};

std::string case_name(const testing::TestParamInfo<SurfaceCase>& i)
{
	return i.param.name;
}

class SurfaceRoundTrip : public testing::TestWithParam<SurfaceCase>
{
};

// A closed triangulated torus with a scalar and a Vec3 on vertices, a scalar on faces.
void make_mesh(CMap2& m)
{
	SurfaceSoup s = torus_soup(12, 7, true);
	// irregular coordinates: exercise the shortest round-trip float printing
	for (auto& p : s.positions)
		for (double& x : p)
			x = x * 1.2345678901234567 + 1e-9;
	build_with_positions(m, s);
	auto q = add_attribute<double, Vertex>(m, "quality");
	auto n = add_attribute<Vec3, Vertex>(m, "normal");
	auto label = add_attribute<double, Face>(m, "label");
	uint32 i = 0;
	foreach_cell(m, [&](Vertex v) {
		value<double>(m, q, v) = 0.25 * i;
		value<Vec3>(m, n, v) = Vec3(i % 3, 1.0 / (i + 1), -double(i));
		++i;
	});
	i = 0;
	foreach_cell(m, [&](Face f) { value<double>(m, label, f) = double(i++ % 5); });
}

std::vector<Vec3> positions(const CMap2& m)
{
	std::vector<Vec3> out;
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	foreach_cell(m, [&](Vertex v) { out.push_back(value<Vec3>(m, *pos, v)); });
	return out;
}

TEST_P(SurfaceRoundTrip, SameCountsPositionsAndAttributes)
{
	const SurfaceCase& c = GetParam();
	TempDir dir;
	CMap2 a;
	make_mesh(a);
	io::SaveOptions options;
	options.binary = c.binary;
	io::save_surface(a, dir.file(c.file), options);

	CMap2 b;
	const io::LoadReport r = io::load_surface(b, dir.file(c.file));
	EXPECT_EQ(r.nb_cells_read, nb_cells<Face>(a));
	EXPECT_EQ(r.nb_cells_skipped, 0u);
	EXPECT_TRUE(r.manifold());
	EXPECT_EQ(nb_cells<Vertex>(b), nb_cells<Vertex>(a));
	EXPECT_EQ(nb_cells<CMap2::Edge>(b), nb_cells<CMap2::Edge>(a));
	EXPECT_EQ(nb_cells<Face>(b), nb_cells<Face>(a));
	EXPECT_EQ(nb_boundary_components(b), 0u);
	EXPECT_TRUE(check_integrity(b).ok()) << check_integrity(b).to_string();

	std::vector<Vec3> pa = positions(a), pb = positions(b);
	ASSERT_EQ(pa.size(), pb.size());
	if (!c.same_order)
	{
		auto less = [](const Vec3& x, const Vec3& y) {
			return std::lexicographical_compare(x.data(), x.data() + 3, y.data(), y.data() + 3);
		};
		if (c.binary) // binary STL holds floats
			for (auto& p : pa)
				p = p.cast<float>().cast<double>();
		std::sort(pa.begin(), pa.end(), less);
		std::sort(pb.begin(), pb.end(), less);
	}
	for (std::size_t i = 0; i < pa.size(); ++i)
		EXPECT_LE((pa[i] - pb[i]).norm(), c.tolerance * (1.0 + pa[i].norm())) << "vertex " << i;

	if (c.attributes)
	{
		auto qa = get_attribute<double, Vertex>(a, "quality");
		auto qb = get_attribute<double, Vertex>(b, "quality");
		auto na = get_attribute<Vec3, Vertex>(a, "normal");
		auto nb = get_attribute<Vec3, Vertex>(b, "normal");
		auto la = get_attribute<double, Face>(a, "label");
		auto lb = get_attribute<double, Face>(b, "label");
		ASSERT_TRUE(qb && nb && lb);
		std::vector<double> va, vb;
		for (double x : *qa)
			va.push_back(x);
		for (double x : *qb)
			vb.push_back(x);
		EXPECT_EQ(va, vb);
		std::vector<Vec3> wa, wb;
		for (const Vec3& x : *na)
			wa.push_back(x);
		for (const Vec3& x : *nb)
			wb.push_back(x);
		EXPECT_EQ(wa, wb);
		va.clear();
		vb.clear();
		for (double x : *la)
			va.push_back(x);
		for (double x : *lb)
			vb.push_back(x);
		EXPECT_EQ(va, vb);
	}
}

INSTANTIATE_TEST_SUITE_P(Formats, SurfaceRoundTrip,
						 testing::Values(SurfaceCase{"off", "m.off", false, 0.0, false, true},
										 SurfaceCase{"obj", "m.obj", false, 0.0, false, true},
										 SurfaceCase{"ply_ascii", "m.ply", false, 0.0, true, true},
										 SurfaceCase{"ply_binary", "m.ply", true, 0.0, true, true},
										 SurfaceCase{"stl_ascii", "m.stl", false, 0.0, false, false},
										 SurfaceCase{"stl_binary", "m.stl", true, 1e-7, false, false}),
						 case_name);

TEST(SurfaceRoundTrip, OffAndObjKeepNormalsColorsAndTexCoords)
{
	TempDir dir;
	CMap2 a;
	build_with_positions(a, grid_soup(3, 2));
	auto n = add_attribute<Vec3, Vertex>(a, "normal");
	auto t = add_attribute<Vec2, Vertex>(a, "tex_coord");
	auto col = add_attribute<Vec3, Face>(a, "color");
	uint32 i = 0;
	foreach_cell(a, [&](Vertex v) {
		value<Vec3>(a, n, v) = Vec3(0, 0, 1);
		value<Vec2>(a, t, v) = Vec2(0.5 * i, 0.25 * i);
		++i;
	});
	foreach_cell(a, [&](Face f) { value<Vec3>(a, col, f) = Vec3(255, 128, i++); });
	for (const char* file : {"g.off", "g.obj"})
	{
		SCOPED_TRACE(file);
		io::save_surface(a, dir.file(file));
		CMap2 b;
		io::load_surface(b, dir.file(file));
		auto nb = get_attribute<Vec3, Vertex>(b, "normal");
		auto tb = get_attribute<Vec2, Vertex>(b, "tex_coord");
		ASSERT_TRUE(nb && tb);
		std::vector<Vec2> ta_v, tb_v;
		for (const Vec2& x : *t)
			ta_v.push_back(x);
		for (const Vec2& x : *tb)
			tb_v.push_back(x);
		EXPECT_EQ(ta_v, tb_v);
		if (std::string(file) == "g.off")
		{
			auto cb = get_attribute<Vec3, Face>(b, "color");
			ASSERT_TRUE(cb);
			std::vector<Vec3> ca_v, cb_v;
			for (const Vec3& x : *col)
				ca_v.push_back(x);
			for (const Vec3& x : *cb)
				cb_v.push_back(x);
			EXPECT_EQ(ca_v, cb_v);
		}
	}
}

TEST(SurfaceRoundTrip, PolygonsAndBoundariesSurvive)
{
	TempDir dir;
	CMap2 a;
	build_with_positions(a, cylinder_soup(7, 3));
	for (const char* file : {"c.off", "c.obj", "c.ply"})
	{
		SCOPED_TRACE(file);
		io::save_surface(a, dir.file(file));
		CMap2 b;
		const io::LoadReport r = io::load_surface(b, dir.file(file));
		EXPECT_EQ(r.nb_holes_closed, 2u);
		EXPECT_EQ(nb_boundary_components(b), 2u);
		EXPECT_EQ(nb_cells<Face>(b), 21u);
		EXPECT_EQ(nb_cells<Vertex>(b), 28u);
	}
	// STL triangulates polygons as fans
	io::save_surface(a, dir.file("c.stl"));
	CMap2 b;
	io::load_surface(b, dir.file("c.stl"));
	EXPECT_EQ(nb_cells<Face>(b), 42u);
	EXPECT_EQ(nb_cells<Vertex>(b), 28u);
}

} // namespace cgogn_test_surface_roundtrip
