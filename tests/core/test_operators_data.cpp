// Randomized operator sequences on real meshes of the test data: check_integrity after every step, Euler
// characteristic unchanged, untouched vertices keep their positions.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>

namespace cgogn_test_operators_data
{

using namespace cgogn;

namespace
{
template <typename MAP>
int64 euler(const MAP& m)
{
	int64 chi =
		int64(nb_cells<typename MAP::Vertex>(m)) - nb_cells<typename MAP::Edge>(m) + nb_cells<typename MAP::Face>(m);
	if constexpr (MAP::dimension == 3)
		chi -= nb_cells<typename MAP::Volume>(m);
	return chi;
}

template <typename MAP, typename STEP>
void run_randomized(MAP& m, uint32 steps, STEP step)
{
	using Vertex = typename MAP::Vertex;
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	ASSERT_NE(pos, nullptr);
	const int64 chi = euler(m);
	std::mt19937 rng(11);
	uint32 applied = 0;
	for (uint32 s = 0; s < steps; ++s)
	{
		std::vector<std::pair<uint32, Vec3>> before;
		foreach_cell(m, [&](Vertex v) { before.emplace_back(index_of(m, v), value<Vec3>(m, pos, v)); });
		applied += step(rng);
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << "step " << s << "\n" << r.to_string();
		ASSERT_EQ(euler(m), chi) << "step " << s;
		const AttributeContainer& vc = container_of<Vertex::ORBIT>(m);
		for (const auto& [line, p] : before)
		{
			if (vc.is_live(line))
			{
				ASSERT_TRUE((*pos)[line] == p || (*pos)[line] == Vec3::Zero()) << "step " << s;
			}
		}
	}
	EXPECT_GT(applied, steps / 4);
}

template <typename CELL, typename MAP>
CELL random_cell(const MAP& m, std::mt19937& rng)
{
	std::vector<CELL> all;
	foreach_cell(m, [&](CELL c) { all.push_back(c); });
	return all[rng() % all.size()];
}
} // namespace

TEST(OperatorsOnData, SurfaceWithHoles)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "surface/hemisphere.off");
	CMap2 m;
	io::load_surface(m, path);
	add_attribute<int, CMap2::Face>(m, "f");
	add_attribute<int, CMap2::Edge>(m, "e");
	run_randomized(m, 300, [&](std::mt19937& rng) {
		switch (rng() % 4)
		{
		case 0: {
			auto e = random_cell<CMap2::Edge>(m, rng);
			if (!can_collapse_edge(m, e))
				return false;
			collapse_edge(m, e);
			return true;
		}
		case 1: {
			auto e = random_cell<CMap2::Edge>(m, rng);
			if (!can_flip_edge(m, e))
				return false;
			flip_edge(m, e);
			return true;
		}
		case 2:
			cut_edge(m, random_cell<CMap2::Edge>(m, rng));
			return true;
		default:
			triangulate_face(m, random_cell<CMap2::Face>(m, rng));
			return true;
		}
	});
}

TEST(OperatorsOnData, TetMeshWithANonManifoldVertex)
{
	CGOGN_DATA_PATH_OR_SKIP(path, "volume/armadillo_tet_4k.mesh");
	CMap3 m;
	io::load_volume(m, path);
	add_attribute<int, CMap3::Volume>(m, "w");
	add_attribute<int, CMap3::Face>(m, "f");
	run_randomized(m, 60, [&](std::mt19937& rng) {
		switch (rng() % 4)
		{
		case 0: {
			auto e = random_cell<CMap3::Edge>(m, rng);
			if (!can_collapse_edge(m, e))
				return false;
			collapse_edge(m, e);
			return true;
		}
		case 1: {
			auto f = random_cell<CMap3::Face>(m, rng);
			if (!can_flip_face(m, f))
				return false;
			flip_face(m, f);
			return true;
		}
		case 2: {
			auto e = random_cell<CMap3::Edge>(m, rng);
			if (!can_flip_edge(m, e))
				return false;
			flip_edge(m, e);
			return true;
		}
		default:
			split_tetra(m, random_cell<CMap3::Volume>(m, rng));
			return true;
		}
	});
}

} // namespace cgogn_test_operators_data
