// SPDX-License-Identifier: MIT
// The modeling subcommands of the `cgogn` program (smooth, triangulate,
// fill-holes, dual), run as a user would: exit codes, the output file's
// counts, errors on stderr, no progress output when not on a terminal.
#include "../io/io_test_utils.h"
#include "modeling_test_utils.h"

#include <cstdlib>
#include <sys/wait.h>

namespace cgogn_test_tool_edit
{

using namespace cgogn;
using namespace cgogn::io_test;
using namespace cgogn::modeling_test;

namespace
{

std::string spot_path()
{
	// appended, not `std::string(DIR) + "..."`: g++ 12 at -O1 sees a false
	// out-of-bounds copy in that temporary (-Warray-bounds)
	std::string path = CGOGN_EXAMPLE_DATA_DIR;
	path += "/spot_control_mesh.obj";
	return path;
}

std::string spot()
{
	return quoted(spot_path());
}

struct Loaded
{
	CMap2 m;
	uint32 v = 0, e = 0, f = 0;
	explicit Loaded(const std::string& path)
	{
		io::load_surface(m, path);
		v = nb_cells<CMap2::Vertex>(m);
		e = nb_cells<CMap2::Edge>(m);
		f = nb_cells<CMap2::Face>(m);
	}
};

/// An L-shaped hexagon (area 3) with its boundary: one hole of 6 edges.
std::string write_l_shape(const TempDir& dir)
{
	write_text(dir.file("L.off"), "OFF\n6 1 0\n0 0 0\n2 0 0\n2 2 0\n1 2 0\n1 1 0\n0 1 0\n6 0 1 2 3 4 5\n");
	return dir.file("L.off");
}

std::string write_volume(const TempDir& dir)
{
	CMap3 m;
	build_with_positions(m, tet_grid_soup(2, 2, 2));
	io::save_volume(m, dir.file("g.mesh"));
	return dir.file("g.mesh");
}

} // namespace

TEST(ToolModeling, SmoothEveryMethodKeepsTheConnectivity)
{
	TempDir dir;
	const Loaded in(spot_path());
	const auto in_pos = positions(in.m);
	for (const char* method : {"laplacian", "taubin", "bilateral", "implicit"})
	{
		// each method's default number of passes (10 implicit steps at the
		// default time step would collapse this coarse cage until (M - t L)
		// is singular: a clean exit 2, hence 1 implicit step by default)
		const ToolRun r =
			run_tool(std::string("smooth ") + spot() + " " + quoted(dir.file("s.off")) + " --method " + method, dir);
		ASSERT_EQ(r.status, 0) << method << ": " << r.err;
		EXPECT_EQ(r.err, "") << "no progress output when stderr is not a terminal";
		const Loaded out(dir.file("s.off"));
		EXPECT_EQ(out.v, 188u) << method;
		EXPECT_EQ(out.e, 366u) << method;
		EXPECT_EQ(out.f, 180u) << method;
		EXPECT_TRUE(check_integrity(out.m).ok());
		// the vertices moved: the bounding boxes differ
		const auto out_pos = positions(out.m);
		const auto b0 = geometry::bounding_box(in.m, *in_pos), b1 = geometry::bounding_box(out.m, *out_pos);
		EXPECT_GT((b0.min() - b1.min()).norm() + (b0.max() - b1.max()).norm(), 1e-6) << method;
	}
}

TEST(ToolModeling, SmoothRejectsBadOptionsAndVolumes)
{
	TempDir dir;
	ToolRun r = run_tool("smooth " + spot() + " " + quoted(dir.file("s.off")) + " --method nope", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--method"), std::string::npos) << r.err;
	r = run_tool("smooth " + spot() + " " + quoted(dir.file("s.off")) + " --method taubin --lambda 0.5 --mu -0.1", dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--mu must be smaller than -lambda"), std::string::npos) << r.err;
	r = run_tool("smooth " + spot() + " " + quoted(dir.file("s.off")) + " -n 0", dir);
	EXPECT_EQ(r.status, 2);
	r = run_tool("smooth " + quoted(write_volume(dir)) + " " + quoted(dir.file("s.off")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("volume"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("s.off"))) << "nothing written on error";
}

TEST(ToolModeling, TriangulateCutsEveryPolygon)
{
	TempDir dir;
	const ToolRun r = run_tool("triangulate " + spot() + " " + quoted(dir.file("t.ply")) + " --binary", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "");
	const Loaded out(dir.file("t.ply"));
	// 4 triangles, 160 quads, 16 pentagons: 4 + 320 + 48 triangles
	EXPECT_EQ(out.f, 372u);
	EXPECT_EQ(out.v, 188u);
	EXPECT_EQ(out.e, 558u);
	foreach_cell(out.m, [&](CMap2::Face f) { EXPECT_EQ(codegree(out.m, f), 3u); });
	EXPECT_TRUE(check_integrity(out.m).ok());
}

TEST(ToolModeling, TriangulateErrors)
{
	TempDir dir;
	ToolRun r = run_tool("triangulate " + quoted(write_volume(dir)) + " " + quoted(dir.file("t.off")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("volume"), std::string::npos) << r.err;
	r = run_tool("triangulate " + spot() + " " + quoted(dir.file("t.ovm")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("volume-only format"), std::string::npos) << r.err;
	r = run_tool("triangulate " + spot(), dir);
	EXPECT_EQ(r.status, 2) << "OUT is required";
	r = run_tool("triangulate " + quoted(dir.file("missing.off")) + " " + quoted(dir.file("t.off")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("missing.off"), std::string::npos) << r.err;
}

TEST(ToolModeling, FillHolesOnAnLShape)
{
	TempDir dir;
	const std::string l = write_l_shape(dir);
	ToolRun r = run_tool("fill-holes --no-refine " + quoted(l) + " " + quoted(dir.file("f.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "");
	EXPECT_EQ(r.out, "holes: 1 found, 1 filled, 0 skipped; added 0 vertices, 4 faces\n");
	const Loaded out(dir.file("f.off"));
	EXPECT_EQ(out.v, 6u);
	EXPECT_EQ(out.e, 9u);
	EXPECT_EQ(out.f, 5u);
	EXPECT_EQ(nb_boundary_components(out.m), 0u);

	r = run_tool("fill-holes --max-size 5 " + quoted(l) + " " + quoted(dir.file("f.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.out, "holes: 1 found, 0 filled, 1 skipped; added 0 vertices, 0 faces\n");
	EXPECT_EQ(Loaded(dir.file("f.off")).f, 1u);
}

TEST(ToolModeling, FillHolesOnTheHemisphere)
{
	TempDir dir;
	const std::string in = quoted(data_path("hemisphere.off"));
	ToolRun r = run_tool("fill-holes " + in + " " + quoted(dir.file("a.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "");
	const Loaded faired(dir.file("a.off"));
	EXPECT_EQ(nb_boundary_components(faired.m), 0u);
	EXPECT_EQ(euler_characteristic(faired.m), 2);
	EXPECT_GT(faired.v, 1861u);
	EXPECT_EQ(r.out, "holes: 1 found, 1 filled, 0 skipped; added " + std::to_string(faired.v - 1861) + " vertices, " +
						 std::to_string(faired.f - 3600) + " faces\n");

	r = run_tool("fill-holes --no-fair " + in + " " + quoted(dir.file("b.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const Loaded flat(dir.file("b.off"));
	EXPECT_EQ(flat.v, faired.v) << "fairing moves vertices, it does not add any";
	EXPECT_EQ(flat.f, faired.f);
	const auto fp = positions(flat.m), ap = positions(faired.m);
	EXPECT_GT(geometry::bounding_box(flat.m, *fp).min().z(), geometry::bounding_box(faired.m, *ap).min().z() + 0.2)
		<< "the faired patch bulges below the flat one";

	r = run_tool("fill-holes --no-refine " + in + " " + quoted(dir.file("c.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const Loaded coarse(dir.file("c.off"));
	EXPECT_EQ(coarse.v, 1861u);
	EXPECT_EQ(coarse.f, 3600u + 118u);
}

TEST(ToolModeling, FillHolesErrors)
{
	TempDir dir;
	const std::string l = quoted(write_l_shape(dir));
	ToolRun r = run_tool("fill-holes --max-size abc " + l + " " + quoted(dir.file("f.off")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("--max-size"), std::string::npos) << r.err;
	r = run_tool("fill-holes --no-such-flag " + l + " " + quoted(dir.file("f.off")), dir);
	EXPECT_EQ(r.status, 2);
	r = run_tool("fill-holes " + quoted(write_volume(dir)) + " " + quoted(dir.file("f.off")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("volume"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("f.off")));
}

TEST(ToolModeling, DualSwapsVerticesAndFaces)
{
	TempDir dir;
	ToolRun r = run_tool("dual " + spot() + " " + quoted(dir.file("d.obj")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_EQ(r.err, "");
	const Loaded d(dir.file("d.obj"));
	EXPECT_EQ(d.v, 180u);
	EXPECT_EQ(d.e, 366u);
	EXPECT_EQ(d.f, 188u);
	EXPECT_TRUE(check_integrity(d.m).ok());
	// and back: the counts of the original
	r = run_tool("dual " + quoted(dir.file("d.obj")) + " " + quoted(dir.file("dd.off")), dir);
	ASSERT_EQ(r.status, 0) << r.err;
	const Loaded dd(dir.file("dd.off"));
	EXPECT_EQ(dd.v, 188u);
	EXPECT_EQ(dd.e, 366u);
	EXPECT_EQ(dd.f, 180u);
}

TEST(ToolModeling, DualErrors)
{
	TempDir dir;
	ToolRun r = run_tool("dual " + quoted(write_l_shape(dir)) + " " + quoted(dir.file("d.off")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("boundary"), std::string::npos) << r.err;
	EXPECT_FALSE(std::filesystem::exists(dir.file("d.off")));
	r = run_tool("dual " + quoted(write_volume(dir)) + " " + quoted(dir.file("d.off")), dir);
	EXPECT_EQ(r.status, 2);
	EXPECT_NE(r.err.find("volume"), std::string::npos) << r.err;
}

} // namespace cgogn_test_tool_edit
