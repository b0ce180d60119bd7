// SPDX-License-Identifier: MIT
// Every data mesh loads, and what `cgogn info` reports matches the counts of
// the data folders' READMEs. Only a large mesh that is not available skips.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "mesh_info.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <set>

namespace cgogn_test_data_files
{

using namespace cgogn;

std::string data_file(const std::string& name)
{
	return cgogn_test_data::path(name);
}

// Files over this size are only loaded by optimized builds (the debug build
// takes tens of seconds on them).
bool too_big_for_this_build(const std::string& path)
{
#ifdef __OPTIMIZE__
	(void)path;
	return false;
#else
	return std::filesystem::file_size(path) > 4'000'000;
#endif
}

struct SurfaceFile
{
	const char* file;
	int64 vertices; // file vertices used by a face
	int64 faces;
	int64 boundary_loops;
	int64 components; // -1: not stated
	int64 isolated;
	bool manifold;
	int64 genus; // -1: not closed or not stated
};

std::string surface_name(const testing::TestParamInfo<SurfaceFile>& i)
{
	std::string n = i.param.file;
	for (char& c : n)
		if (!std::isalnum(static_cast<unsigned char>(c)))
			c = '_';
	return n;
}

class DataSurface : public testing::TestWithParam<SurfaceFile>
{
};

TEST_P(DataSurface, InfoMatchesTheReadme)
{
	const SurfaceFile& s = GetParam();
	CGOGN_DATA_PATH_OR_SKIP(path, std::string("surface/") + s.file);
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, path);
	const nlohmann::json j = tool::surface_info(m, r);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(j["manifold"].get<bool>(), s.manifold);
	EXPECT_EQ(j["faces"].get<int64>(), s.faces) << "every face is kept";
	EXPECT_EQ(j["isolated_vertices"].get<int64>(), s.isolated);
	EXPECT_EQ(r.nb_cells_skipped, 0u);
	if (s.manifold)
	{
		EXPECT_EQ(j["vertices"].get<int64>(), s.vertices);
		EXPECT_EQ(j["boundary_components"].get<int64>(), s.boundary_loops);
		if (s.components >= 0)
		{
			EXPECT_EQ(j["connected_components"].get<int64>(), s.components);
		}
		if (s.genus >= 0)
		{
			EXPECT_EQ(j["genus"].get<int64>(), s.genus);
		}
		EXPECT_EQ(j["nonmanifold_vertices"].get<int64>(), 0);
		EXPECT_EQ(j["nonmanifold_edges"].get<int64>(), 0);
	}
	else
	{
		// repaired: each extra fan of a vertex became a vertex of its own, and
		// detached faces opened boundaries
		EXPECT_GT(j["nonmanifold_vertices"].get<int64>() + j["nonmanifold_edges"].get<int64>(), 0);
		EXPECT_EQ(j["vertices"].get<int64>(), s.vertices + j["split_vertex_copies"].get<int64>());
		auto orig = get_attribute<uint32, CMap2::Vertex>(m, "original_vertex");
		if (j["split_vertex_copies"].get<int64>() > 0)
		{
			ASSERT_TRUE(orig);
			// split copies sit where their original vertex is
			auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
			std::vector<std::optional<Vec3>> at(std::size_t(s.vertices));
			foreach_cell(m, [&](CMap2::Vertex v) {
				const uint32 o = value<uint32>(m, *orig, v);
				ASSERT_LT(o, at.size());
				if (!at[o])
					at[o] = value<Vec3>(m, *pos, v);
				EXPECT_EQ(*at[o], value<Vec3>(m, *pos, v));
			});
		}
	}
}

INSTANTIATE_TEST_SUITE_P(
	Readme, DataSurface,
	testing::Values(SurfaceFile{"nefertiti.obj", 49971, 99938, 0, 1, 0, true, 0},
					SurfaceFile{"refined_elephant.off", 44460, 88928, 0, -1, 0, true, 3},
					SurfaceFile{"stanford-bunny.obj", 35947 - 1113, 69451, 5, -1, 1113, true, -1},
					SurfaceFile{"hemisphere.off", 1861, 3600, 1, -1, 0, true, -1},
					SurfaceFile{"elephant-with-holes.off", 2798, 4463, 106, -1, 0, true, -1},
					SurfaceFile{"spot_quadrangulated.obj", 2930, 2928, 0, -1, 0, true, 0},
					SurfaceFile{"spot_control_mesh.obj", 188, 180, 0, -1, 0, true, 0},
					SurfaceFile{"fandisk_quads.off", 766, 764, 0, -1, 0, true, 0},
					SurfaceFile{"suzanne.obj", 507, 500, 4, 3, 0, true, -1},
					SurfaceFile{"torus_quad.off", 25, 25, 0, -1, 0, true, 1},
					SurfaceFile{"polygon_mesh.off", 16344, 32245, 14, -1, 0, false, -1},
					SurfaceFile{"Wuson.off", 3205, 3732, -1, -1, 0, false, -1},
					SurfaceFile{"geomview_cam.off", 5, 2, -1, -1, 0, false, -1},
					SurfaceFile{"geomview_simplex_2skeleton.off", 5, 10, -1, -1, 0, false, -1},
					SurfaceFile{"geomview_orthoplex_2skeleton.off", 8, 32, -1, -1, 0, false, -1},
					SurfaceFile{"geomview_tetraplex_2skeleton.off", 120, 1200, -1, -1, 0, false, -1},
					SurfaceFile{"geomview_hypercube_2skeleton.off", 16, 24, -1, -1, 0, false, -1},
					SurfaceFile{"icositetrachoron_2skeleton.off", 24, 96, -1, -1, 0, false, -1},
					SurfaceFile{"tetrahedron.off", 4, 4, 0, 1, 0, true, 0},
					SurfaceFile{"cube_quad.off", 8, 6, 0, 1, 0, true, 0},
					SurfaceFile{"triangle.off", 3, 1, 1, 1, 0, true, -1}, SurfaceFile{"L.off", 6, 1, 1, 1, 0, true, -1},
					SurfaceFile{"vertex_onering.off", 7, 6, 1, 1, 0, true, -1},
					SurfaceFile{"edge_onering.off", 10, 10, 1, 1, 0, true, -1}),
	surface_name);

TEST(DataSurfaceDetails, BoundaryEdgeCountsMatchTheReadme)
{
	// the large mesh last: when it is not available, the others are checked before the skip
	const std::pair<const char*, int64> files[] = {{"hemisphere.off", 120}, {"elephant-with-holes.off", 1353},
												   {"suzanne.obj", 42},     {"polygon_mesh.off", 489},
												   {"Wuson.off", 2338},     {"stanford-bunny.obj", 223}};
	for (const auto& [file, boundary_edges] : files)
	{
		CGOGN_DATA_PATH_OR_SKIP(path, std::string("surface/") + file);
		SCOPED_TRACE(file);
		CMap2 m;
		const nlohmann::json j = tool::surface_info(m, io::load_surface(m, path));
		EXPECT_EQ(j["boundary_edges"].get<int64>(), boundary_edges);
	}
}

struct VolumeFile
{
	const char* file;
	int64 vertices;
	int64 cells;
	int64 faces;
	int64 boundary_faces;
	int64 edges;
	int64 nonmanifold_vertices;
};

std::string volume_name(const testing::TestParamInfo<VolumeFile>& i)
{
	return surface_name(testing::TestParamInfo<SurfaceFile>(SurfaceFile{i.param.file, 0, 0, 0, 0, 0, true, 0}, 0));
}

class DataVolume : public testing::TestWithParam<VolumeFile>
{
};

TEST_P(DataVolume, InfoMatchesTheReadme)
{
	const VolumeFile& v = GetParam();
	CGOGN_DATA_PATH_OR_SKIP(path, std::string("volume/") + v.file);
	if (too_big_for_this_build(path))
		GTEST_SKIP() << path << " is only loaded by optimized builds (release, asan presets)";
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, path);
	const nlohmann::json j = tool::volume_info(m, r);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
	EXPECT_EQ(r.nb_cells_reoriented, 0u) << "the README says every cell is positively oriented";
	EXPECT_EQ(j["volumes"].get<int64>(), v.cells);
	EXPECT_EQ(j["faces"].get<int64>(), v.faces);
	EXPECT_EQ(j["boundary_faces"].get<int64>(), v.boundary_faces);
	EXPECT_EQ(j["nonmanifold_vertices"].get<int64>(), v.nonmanifold_vertices);
	EXPECT_EQ(j["manifold"].get<bool>(), v.nonmanifold_vertices == 0);
	// a vertex whose cells form k face-connected groups is k vertices of the map
	EXPECT_EQ(j["vertices"].get<int64>(), v.vertices + j["split_vertex_copies"].get<int64>());
	if (v.nonmanifold_vertices == 0)
	{
		EXPECT_EQ(j["edges"].get<int64>(), v.edges);
	}
	else
	{
		EXPECT_GE(j["edges"].get<int64>(), v.edges);
	}
	EXPECT_EQ(j["boundary_components"].get<int64>() > 0, true);
}

INSTANTIATE_TEST_SUITE_P(
	Readme, DataVolume,
	testing::Values(VolumeFile{"armadillo_tet_461k.mesh", 125094, 460656, 1017778, 192932, 682215, 0},
					VolumeFile{"heart_tet_205k.mesh", 37923, 204841, 417850, 16336, 250931, 0},
					VolumeFile{"elephant_tet_27k.mesh", 8305, 27474, 62116, 14336, 42949, 0},
					VolumeFile{"elephant_tet_8k.mesh", 2775, 8284, 19347, 5558, 13840, 0},
					VolumeFile{"armadillo_tet_4k.mesh", 1446, 4406, 10078, 2532, 7118, 1},
					VolumeFile{"elephant_hex_110k.mesh", 140844, 109896, 351192, 43008, 382142, 0},
					VolumeFile{"liver_hex_624.mesh", 891, 624, 2067, 390, 2333, 0},
					VolumeFile{"hex_dominant_11k.mesh", 7708, 4442 + 5520 + 908 + 317, 33970, 10927, 27504, 1604}),
	volume_name);

TEST(DataVolumeDetails, MixedMeshCellKinds)
{
	const std::string path = data_file("volume/hex_dominant_11k.mesh");
	CMap3 m;
	const nlohmann::json j = tool::volume_info(m, io::load_volume(m, path));
	EXPECT_EQ(j["cell_kinds"]["tetrahedra"].get<int64>(), 4442);
	EXPECT_EQ(j["cell_kinds"]["hexahedra"].get<int64>(), 5520);
	EXPECT_EQ(j["cell_kinds"]["prisms"].get<int64>(), 908);
	EXPECT_EQ(j["cell_kinds"]["pyramids"].get<int64>(), 317);
}

struct NonOrientableFile
{
	const char* file;
	int64 vertices, edges, faces, boundary_loops, chi, crosscaps; // crosscaps: -1 when not closed
};

// The non-orientable surfaces: a GMap2 holds them whole, with their exact
// counts; a CMap2 holds them cut, and its load report says so.
TEST(NonOrientableFiles, LoadWholeIntoAGMap2AndCutIntoACMap2)
{
	for (const NonOrientableFile& s : {NonOrientableFile{"mobius_strip.off", 48, 72, 24, 1, 0, -1},
									   NonOrientableFile{"klein_bottle.off", 128, 256, 128, 0, 0, 2},
									   NonOrientableFile{"hemi_icosahedron.off", 6, 15, 10, 0, 1, 1}})
	{
		SCOPED_TRACE(s.file);
		const std::string path = data_file(std::string("surface/") + s.file);
		GMap2 g;
		const io::LoadReport rg = io::load_surface(g, path);
		EXPECT_FALSE(rg.orientable);
		EXPECT_TRUE(rg.manifold());
		EXPECT_GT(rg.nb_orientation_conflicts, 0u);
		EXPECT_TRUE(check_integrity(g).ok()) << check_integrity(g).to_string();
		EXPECT_FALSE(is_orientable(g));
		const nlohmann::json j = tool::surface_info(g, rg);
		EXPECT_EQ(j["map"].get<std::string>(), "GMap2");
		EXPECT_EQ(j["vertices"].get<int64>(), s.vertices);
		EXPECT_EQ(j["edges"].get<int64>(), s.edges);
		EXPECT_EQ(j["faces"].get<int64>(), s.faces);
		EXPECT_EQ(j["boundary_components"].get<int64>(), s.boundary_loops);
		EXPECT_EQ(j["euler_characteristic"].get<int64>(), s.chi);
		EXPECT_FALSE(j["orientable"].get<bool>());
		if (s.crosscaps >= 0)
		{
			EXPECT_EQ(j["genus"].get<int64>(), s.crosscaps);
		}
		EXPECT_EQ(rg.summary("GMap2"), "the surface is not orientable\n");
		// the file is the core's generator written out: same vertices, same places
		const SurfaceSoup soup = std::string(s.file) == "mobius_strip.off"   ? mobius_soup(24)
								 : std::string(s.file) == "klein_bottle.off" ? klein_bottle_soup(16, 8)
																			 : hemi_icosahedron_soup();
		EXPECT_EQ(soup.face_sizes.size(), std::size_t(s.faces));
		auto pos = get_attribute<Vec3, GMap2::Vertex>(g, "position");
		ASSERT_TRUE(pos);
		foreach_cell(g, [&](GMap2::Vertex v) {
			const auto& p = soup.positions[index_of(g, v)];
			EXPECT_LT((value<Vec3>(g, *pos, v) - Vec3(p[0], p[1], p[2])).norm(), 1e-8);
		});

		CMap2 c;
		const io::LoadReport rc = io::load_surface(c, path);
		EXPECT_FALSE(rc.orientable);
		EXPECT_EQ(rc.nb_orientation_conflicts, rg.nb_orientation_conflicts);
		EXPECT_GE(rc.nb_nonmanifold_edges, rc.nb_orientation_conflicts);
		EXPECT_NE(rc.summary("CMap2").find("load it into a GMap2"), std::string::npos) << rc.summary("CMap2");
		EXPECT_TRUE(check_integrity(c).ok());
		EXPECT_EQ(nb_cells<CMap2::Face>(c), uint32(s.faces));
		// cut along the conflicts: each of those edges is two edges there
		EXPECT_EQ(nb_cells<CMap2::Edge>(c), uint32(s.edges) + rc.nb_orientation_conflicts);
	}
}

// A GMap2 written in every surface format and read back gives the same cells.
TEST(NonOrientableFiles, RoundTripThroughEveryFormat)
{
	const std::string tmp = testing::TempDir();
	for (const char* file : {"mobius_strip.off", "klein_bottle.off", "hemi_icosahedron.off"})
	{
		GMap2 g;
		io::load_surface(g, data_file(std::string("surface/") + file));
		const bool triangles = std::string(file) == "hemi_icosahedron.off";
		for (const char* ext : {".off", ".obj", ".ply", ".stl"})
			for (bool binary : {false, true})
			{
				if (std::string(ext) == ".stl" && !triangles)
					continue;
				SCOPED_TRACE(std::string(file) + ext + (binary ? " binary" : ""));
				const std::string out = tmp + "/gmap_round_trip" + ext;
				io::SaveOptions o;
				o.binary = binary;
				io::save_surface(g, out, o);
				GMap2 back;
				const io::LoadReport r = io::load_surface(back, out);
				EXPECT_FALSE(r.orientable);
				EXPECT_TRUE(check_integrity(back).ok());
				// STL has no shared vertices: the reader welds equal positions
				EXPECT_EQ(nb_cells<GMap2::Vertex>(back), nb_cells<GMap2::Vertex>(g));
				EXPECT_EQ(nb_cells<GMap2::Edge>(back), nb_cells<GMap2::Edge>(g));
				EXPECT_EQ(nb_cells<GMap2::Face>(back), nb_cells<GMap2::Face>(g));
				EXPECT_EQ(euler_characteristic(back), euler_characteristic(g));
				EXPECT_EQ(nb_boundary_components(back), nb_boundary_components(g));
			}
	}
}

TEST(DataFolder, EveryMeshFileIsCoveredAboveOrNamedHere)
{
	const std::string dir = CGOGN_DATA_DIR;
	const std::set<std::string> known_surface = {"nefertiti.obj",
												 "refined_elephant.off",
												 "stanford-bunny.obj",
												 "hemisphere.off",
												 "elephant-with-holes.off",
												 "spot_quadrangulated.obj",
												 "spot_control_mesh.obj",
												 "fandisk_quads.off",
												 "suzanne.obj",
												 "torus_quad.off",
												 "polygon_mesh.off",
												 "Wuson.off",
												 "geomview_cam.off",
												 "geomview_simplex_2skeleton.off",
												 "geomview_orthoplex_2skeleton.off",
												 "geomview_tetraplex_2skeleton.off",
												 "geomview_hypercube_2skeleton.off",
												 "icositetrachoron_2skeleton.off",
												 "tetrahedron.off",
												 "cube_quad.off",
												 "triangle.off",
												 "L.off",
												 "vertex_onering.off",
												 "edge_onering.off",
												 "mobius_strip.off",
												 "klein_bottle.off",
												 "hemi_icosahedron.off"};
	const std::set<std::string> known_volume = {
		"armadillo_tet_461k.mesh", "heart_tet_205k.mesh", "elephant_tet_27k.mesh", "elephant_tet_8k.mesh",
		"armadillo_tet_4k.mesh", "elephant_hex_110k.mesh", "liver_hex_624.mesh", "hex_dominant_11k.mesh",
		// OpenVolumeMesh polyhedra: its counts are checked by test_polyhedra_io.cpp
		"elephant_poly_4k.ovm"};
	for (const char* sub : {"surface", "volume"})
	{
		if (!std::filesystem::exists(dir + "/" + sub))
			continue;
		for (const auto& e : std::filesystem::directory_iterator(dir + "/" + sub))
		{
			const std::string name = e.path().filename().string();
			if (name == "README.md" || name == "SHA256SUMS")
				continue;
			const bool known = std::string(sub) == "surface" ? known_surface.count(name) : known_volume.count(name);
			EXPECT_TRUE(known) << sub << "/" << name << " is a new data file: add it to the tables above";
		}
	}
}

} // namespace cgogn_test_data_files
