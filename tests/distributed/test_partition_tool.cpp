// `cgogn partition`: one .vtu per part, which together hold every volume of
// the input once, with global vertex ids that name the same points in every
// part, and the report on standard output.
#include <cgogn/cgogn.h>

#include "../io/io_test_utils.h"
#include "cgogn_test_data.h"

#include <gtest/gtest.h>

#include <map>

namespace cgogn_test_partition_tool
{

using namespace cgogn;
using cgogn::io_test::run_tool;
using cgogn::io_test::TempDir;

TEST(PartitionTool, PartsHoldEveryVolumeOnceWithGlobalIds)
{
	const std::string in = std::string(CGOGN_DATA_DIR) + "/volume/armadillo_tet_4k.mesh";
	TempDir dir;
	const auto r = run_tool("partition '" + in + "' '" + dir.file("parts") + "' --parts 3 --binary", dir);
	ASSERT_EQ(r.status, 0) << r.err;
	EXPECT_NE(r.out.find("in 3 parts"), std::string::npos) << r.out;
	EXPECT_NE(r.out.find("every part in one piece"), std::string::npos) << r.out;

	CMap3 whole;
	io::load_volume(whole, in);
	auto position = get_attribute<Vec3, CMap3::Vertex>(whole, "position");
	std::vector<Vec3> by_gid; // the tool numbers the vertices in traversal order
	foreach_cell(whole, [&](CMap3::Vertex v) { by_gid.push_back((*position)[v]); });
	const uint32 nb_volumes = nb_cells<CMap3::Volume>(whole);

	std::vector<uint32> seen(nb_volumes, 0);
	for (uint32 p = 0; p < 3; ++p)
	{
		SCOPED_TRACE(p);
		CMap3 piece;
		io::load_volume(piece, dir.file("parts/armadillo_tet_4k_" + std::to_string(p) + ".vtu"));
		EXPECT_TRUE(check_integrity(piece).ok());
		auto cell_gid = get_attribute<uint64, CMap3::Volume>(piece, "GlobalCellIds");
		auto node_gid = get_attribute<uint64, CMap3::Vertex>(piece, "GlobalNodeIds");
		auto part = get_attribute<uint32, CMap3::Volume>(piece, "part");
		auto pos = get_attribute<Vec3, CMap3::Vertex>(piece, "position");
		ASSERT_TRUE(cell_gid && node_gid && part && pos);
		EXPECT_GT(nb_cells<CMap3::Volume>(piece), 0u);
		foreach_cell(piece, [&](CMap3::Volume w) {
			ASSERT_LT((*cell_gid)[w], nb_volumes);
			++seen[(*cell_gid)[w]];
			EXPECT_EQ((*part)[w], p);
		});
		foreach_cell(piece, [&](CMap3::Vertex v) {
			ASSERT_LT((*node_gid)[v], by_gid.size());
			EXPECT_EQ((*pos)[v], by_gid[(*node_gid)[v]]);
		});
	}
	for (uint32 k = 0; k < nb_volumes; ++k)
		ASSERT_EQ(seen[k], 1u) << "volume " << k;
}

TEST(PartitionTool, BadArgumentsExitWithAnError)
{
	const std::string in = std::string(CGOGN_DATA_DIR) + "/volume/liver_hex_624.mesh";
	TempDir dir;
	EXPECT_EQ(run_tool("partition '" + in + "' '" + dir.file("parts") + "' --parts 625", dir).status, 2);
	EXPECT_EQ(run_tool("partition '" + in + "' '" + dir.file("parts") + "' --parts 0", dir).status, 2);
}

} // namespace cgogn_test_partition_tool
