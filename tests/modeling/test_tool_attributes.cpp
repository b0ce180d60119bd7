// SPDX-License-Identifier: MIT
// Attributes through the tool's edits: a PLY with a colour and a
// temperature per vertex and an int region per face goes through every
// subdivision scheme, decimation, remeshing and hole filling. Afterwards
// every vertex's values lie in the range of the input's, and every face's
// region is that of the input face it came from (--origin).
#include <cgogn/cgogn.h>

#include "../io/io_test_utils.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace cgogn_test_tool_attributes
{

using namespace cgogn;
using namespace cgogn::io_test;

namespace
{

struct Input
{
	std::vector<int32> region; // by input face index
	double t_lo = 1e300, t_hi = -1e300;
	Vec3 c_lo = Vec3::Constant(1e300), c_hi = Vec3::Constant(-1e300);
};

/// A triangulated sphere with two holes (for fill-holes), saved as PLY with
/// its data; returns the values to compare with.
Input write_input(const std::string& path, bool with_holes)
{
	CMap2 m;
	build_with_positions(m, sphere_soup(16, 10, true));
	auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	if (with_holes)
	{
		std::vector<CMap2::Face> faces;
		uint32 k = 0;
		foreach_cell(m, [&](CMap2::Face f) {
			if (k == 40 || k == 200)
				faces.push_back(f);
			++k;
		});
		for (CMap2::Face f : faces)
			remove_face(m, f);
		compact(m);
	}
	auto temperature = add_attribute<double, CMap2::Vertex>(m, "temperature");
	auto colour = add_attribute<Vec3, CMap2::Vertex>(m, "colour");
	auto region = add_attribute<int32, CMap2::Face>(m, "region");
	Input in;
	foreach_cell(m, [&](CMap2::Vertex v) {
		const Vec3& p = value<Vec3>(m, pos, v);
		const double t = 20.0 + 10.0 * p.z();
		const Vec3 c = (p + Vec3(1, 1, 1)) / 2.0;
		value<double>(m, temperature, v) = t;
		value<Vec3>(m, colour, v) = c;
		in.t_lo = std::min(in.t_lo, t);
		in.t_hi = std::max(in.t_hi, t);
		in.c_lo = in.c_lo.cwiseMin(c);
		in.c_hi = in.c_hi.cwiseMax(c);
	});
	foreach_cell(m, [&](CMap2::Face f) {
		const int32 r = 1 + int32(index_of(m, f) % 4);
		value<int32>(m, region, f) = r;
		in.region.push_back(r);
	});
	io::save_surface(m, path);
	return in;
}

void check_output(const std::string& path, const Input& in, const std::string& what)
{
	CMap2 m;
	io::load_surface(m, path);
	ASSERT_TRUE(check_integrity(m).ok()) << what;
	auto temperature = get_attribute<double, CMap2::Vertex>(m, "temperature");
	auto colour = get_attribute<Vec3, CMap2::Vertex>(m, "colour");
	auto region = get_attribute<int32, CMap2::Face>(m, "region");
	auto origin = get_attribute<uint32, CMap2::Face>(m, "origin");
	ASSERT_TRUE(temperature && colour && region && origin) << what << ": an attribute is missing or retyped";
	const double eps = 1e-9;
	foreach_cell(m, [&](CMap2::Vertex v) {
		const double t = value<double>(m, temperature, v);
		EXPECT_TRUE(t >= in.t_lo - eps && t <= in.t_hi + eps) << what << ": temperature " << t;
		const Vec3& c = value<Vec3>(m, colour, v);
		EXPECT_TRUE((c.array() >= in.c_lo.array() - eps).all() && (c.array() <= in.c_hi.array() + eps).all())
			<< what << ": colour out of the input's hull";
	});
	uint32 from_input = 0;
	foreach_cell(m, [&](CMap2::Face f) {
		const uint32 o = value<uint32>(m, origin, f);
		if (o == INVALID_INDEX)
			return; // a face filling a hole
		++from_input;
		ASSERT_LT(o, in.region.size()) << what;
		EXPECT_EQ(value<int32>(m, region, f), in.region[o]) << what << ": face from input face " << o;
	});
	EXPECT_GT(from_input, 0u) << what;
}

} // namespace

TEST(ToolAttributes, EveryEditKeepsColoursAndRegions)
{
	TempDir dir;
	const std::string closed = dir.file("sphere.ply"), open = dir.file("open.ply");
	const Input in = write_input(closed, false);
	const Input in_open = write_input(open, true);
	const std::vector<std::pair<std::string, std::string>> runs = {
		{"subdivide --scheme loop -n 2", closed},
		{"subdivide --scheme catmull-clark", closed},
		{"subdivide --scheme sqrt3 -n 2", closed},
		{"decimate --ratio 0.3", closed},
		{"remesh -n 3", closed},
		{"fill-holes", open},
	};
	for (const auto& [command, input] : runs)
	{
		const std::string out = dir.file("out.ply");
		const ToolRun r =
			run_tool(command + " " + quoted(input) + " " + quoted(out) + " --origin origin --binary", dir);
		ASSERT_EQ(r.status, 0) << command << ": " << r.err;
		check_output(out, input == open ? in_open : in, command);
	}
}

TEST(ToolAttributes, OriginNameTakenIsAClearError)
{
	TempDir dir;
	write_input(dir.file("sphere.ply"), false);
	const ToolRun r = run_tool("subdivide --scheme loop " + quoted(dir.file("sphere.ply")) + " " +
								   quoted(dir.file("out.ply")) + " --origin region",
							   dir);
	EXPECT_EQ(r.status, 2) << r.err;
	EXPECT_NE(r.err.find("region"), std::string::npos) << r.err;
}

} // namespace cgogn_test_tool_attributes
