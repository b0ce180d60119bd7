// `cgogn` under mpiexec: info prints the serial counts, convert writes a
// .pvtu that the serial tool and VTK's parallel reader read as the whole
// mesh, smooth --deterministic gives the same bits with 2 and 3 ranks, and
// subdivide gives the serial tool's mesh.
#include <cgogn/cgogn.h>

#include "../io/io_test_utils.h"
#include "cgogn_test_data.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <map>

namespace cgogn_test_mpi_tool
{

using namespace cgogn;
using cgogn::io_test::TempDir;

// Runs the tool on `ranks` ranks (oversubscribed, as root too; without
// AddressSanitizer's leak check, which Open MPI's unloaded components defeat).
cgogn::io_test::ToolRun run_mpi(int ranks, const std::string& args, const TempDir& dir)
{
	const std::string out = dir.file("stdout"), err = dir.file("stderr");
	const std::string cmd =
		std::string("OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 "
					"OMPI_MCA_rmaps_base_oversubscribe=1 ASAN_OPTIONS=detect_leaks=0:abort_on_error=1 '") +
		CGOGN_MPIEXEC + "' -n " + std::to_string(ranks) + " '" + CGOGN_TOOL_PATH + "' " + args + " >'" + out + "' 2>'" +
		err + "'";
	cgogn::io_test::ToolRun r;
	const int s = std::system(cmd.c_str());
	r.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
	r.out = cgogn::io_test::read_text(out);
	r.err = cgogn::io_test::read_text(err);
	return r;
}

const std::string armadillo = std::string(CGOGN_DATA_DIR) + "/volume/armadillo_tet_4k.mesh";

TEST(MpiTool, InfoPrintsTheSerialCounts)
{
	TempDir dir;
	for (const std::string& in : {armadillo, std::string(CGOGN_DATA_DIR) + "/surface/hemisphere.off"})
	{
		SCOPED_TRACE(in);
		const auto serial = cgogn::io_test::run_tool("info --json '" + in + "'", dir);
		ASSERT_EQ(serial.status, 0) << serial.err;
		const auto spread = run_mpi(3, "info --json '" + in + "'", dir);
		ASSERT_EQ(spread.status, 0) << spread.err;
		const nlohmann::json s = nlohmann::json::parse(serial.out), p = nlohmann::json::parse(spread.out);
		for (const char* k : {"dimension", "map", "vertices", "edges", "faces", "volumes", "boundary_faces",
							  "boundary_edges", "euler_characteristic", "face_degrees", "bbox"})
			EXPECT_EQ(s.contains(k) ? s[k] : nullptr, p.contains(k) ? p[k] : nullptr) << k;
		EXPECT_NEAR(s["edge_length"]["mean"].get<double>(), p["edge_length"]["mean"].get<double>(), 1e-12);
		EXPECT_EQ(s["edge_length"]["max"], p["edge_length"]["max"]);
		EXPECT_EQ(p["ranks"], 3);
	}
}

TEST(MpiTool, ConvertWritesPvtuThatReadsBackWhole)
{
	TempDir dir;
	const auto r = run_mpi(3, "convert --binary '" + armadillo + "' '" + dir.file("armadillo.pvtu") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap3 whole, back;
	io::load_volume(whole, armadillo);
	io::load_volume(back, dir.file("armadillo.pvtu"));
	EXPECT_EQ(nb_cells<CMap3::Vertex>(back), nb_cells<CMap3::Vertex>(whole));
	EXPECT_EQ(nb_cells<CMap3::Edge>(back), nb_cells<CMap3::Edge>(whole));
	EXPECT_EQ(nb_cells<CMap3::Face>(back), nb_cells<CMap3::Face>(whole));
	EXPECT_EQ(nb_cells<CMap3::Volume>(back), nb_cells<CMap3::Volume>(whole));
	EXPECT_TRUE(check_integrity(back).ok());

	// VTK's reader sees every piece; without the ghosts, the serial count
	const std::string script = std::string(CGOGN_SOURCE_DIR) + "/tests/distributed/read_pvtu_with_vtk.py";
	const int s = std::system((std::string(CGOGN_SYSTEM_PYTHON) + " '" + script + "' '" + dir.file("armadillo.pvtu") +
							   "' >'" + dir.file("vtk.txt") + "' 2>&1")
								  .c_str());
	if (WIFEXITED(s) && WEXITSTATUS(s) == 3)
		GTEST_SKIP() << "the VTK Python module is not installed: " << cgogn::io_test::read_text(dir.file("vtk.txt"));
	ASSERT_TRUE(WIFEXITED(s) && WEXITSTATUS(s) == 0) << cgogn::io_test::read_text(dir.file("vtk.txt"));
	std::istringstream counts(cgogn::io_test::read_text(dir.file("vtk.txt")));
	uint64 with_ghosts = 0, without = 0;
	counts >> with_ghosts >> without;
	EXPECT_EQ(without, nb_cells<CMap3::Volume>(whole));
	EXPECT_GT(with_ghosts, without);
}

// The positions of a .pvtu's vertices by their global ids.
std::map<uint64, Vec3> positions_by_id(const std::string& path)
{
	CMap3 m;
	io::load_volume(m, path);
	auto ids = get_attribute<uint64, CMap3::Vertex>(m, "GlobalNodeIds");
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	std::map<uint64, Vec3> out;
	if (ids && pos)
		foreach_cell(m, [&](CMap3::Vertex v) { out[(*ids)[v]] = (*pos)[v]; });
	return out;
}

TEST(MpiTool, DeterministicSmoothingGivesTheSameBitsOnAnyNumberOfRanks)
{
	TempDir dir;
	for (int ranks : {2, 3})
	{
		const auto r = run_mpi(ranks,
							   "smooth --binary --deterministic --method laplacian -n 5 '" + armadillo + "' '" +
								   dir.file("smooth" + std::to_string(ranks) + ".pvtu") + "'",
							   dir);
		ASSERT_EQ(r.status, 0) << r.err;
	}
	const auto two = positions_by_id(dir.file("smooth2.pvtu")), three = positions_by_id(dir.file("smooth3.pvtu"));
	ASSERT_EQ(two.size(), three.size());
	ASSERT_FALSE(two.empty());
	bool same = true, moved = false;
	CMap3 whole;
	io::load_volume(whole, armadillo);
	for (const auto& [id, p] : two)
		same = same && std::memcmp(p.data(), three.at(id).data(), 3 * sizeof(double)) == 0;
	EXPECT_TRUE(same);
	auto original = get_attribute<Vec3, CMap3::Vertex>(whole, "position");
	std::vector<Vec3> by_id;
	foreach_cell(whole, [&](CMap3::Vertex v) { by_id.push_back((*original)[v]); });
	for (const auto& [id, p] : two)
		moved = moved || p != by_id[id];
	EXPECT_TRUE(moved);
}

// The vertex positions of a volume file, sorted.
std::vector<std::array<double, 3>> sorted_positions(const CMap3& m)
{
	auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	std::vector<std::array<double, 3>> out;
	foreach_cell(m, [&](CMap3::Vertex v) { out.push_back({(*pos)[v][0], (*pos)[v][1], (*pos)[v][2]}); });
	std::sort(out.begin(), out.end());
	return out;
}

TEST(MpiTool, SubdivideGivesTheSerialMesh)
{
	TempDir dir;
	const auto serial =
		cgogn::io_test::run_tool("subdivide --scheme tet '" + armadillo + "' '" + dir.file("serial.vtu") + "'", dir);
	ASSERT_EQ(serial.status, 0) << serial.err;
	const auto r =
		run_mpi(3, "subdivide --binary --scheme tet '" + armadillo + "' '" + dir.file("spread.pvtu") + "'", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	CMap3 one, spread;
	io::load_volume(one, dir.file("serial.vtu"));
	io::load_volume(spread, dir.file("spread.pvtu"));
	EXPECT_EQ(nb_cells<CMap3::Vertex>(spread), nb_cells<CMap3::Vertex>(one));
	EXPECT_EQ(nb_cells<CMap3::Edge>(spread), nb_cells<CMap3::Edge>(one));
	EXPECT_EQ(nb_cells<CMap3::Face>(spread), nb_cells<CMap3::Face>(one));
	EXPECT_EQ(nb_cells<CMap3::Volume>(spread), nb_cells<CMap3::Volume>(one));
	EXPECT_TRUE(check_integrity(spread).ok());
	EXPECT_EQ(sorted_positions(spread), sorted_positions(one));

	// surfaces are refined without mpiexec
	const auto surface = run_mpi(2,
								 "subdivide --scheme tet '" + std::string(CGOGN_DATA_DIR) +
									 "/surface/hemisphere.off' '" + dir.file("s.pvtu") + "'",
								 dir);
	EXPECT_NE(surface.status, 0);
	EXPECT_NE(surface.err.find("volume meshes"), std::string::npos) << surface.err;
}

TEST(MpiTool, OtherCommandsAreRefusedWithMoreThanOneRank)
{
	TempDir dir;
	const auto r = run_mpi(2, "remesh '" + armadillo + "' '" + dir.file("x.off") + "'", dir);
	EXPECT_NE(r.status, 0);
	EXPECT_NE(r.err.find("info, smooth, subdivide and convert"), std::string::npos) << r.err;
}

} // namespace cgogn_test_mpi_tool
