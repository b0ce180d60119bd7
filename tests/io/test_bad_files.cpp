// SPDX-License-Identifier: MIT
// Malformed files, one test per failure mode: each load throws io::Error
// naming the file, where (line or byte) and the cause, and leaves the target
// map exactly as it was. Text cases are committed under tests/io/bad/; binary
// ones are made here.
#include <cgogn/cgogn.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <cstring>

namespace cgogn_test_bad_files
{

using namespace cgogn;
using namespace cgogn::io_test;
using Where = io::Error::Where;

std::string bytes_of(std::initializer_list<float> v)
{
	std::string s;
	for (float x : v)
		s.append(reinterpret_cast<const char*>(&x), sizeof(float));
	return s;
}

const std::string ply_binary_header = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
									  "property float y\nproperty float z\nelement face 1\nproperty list uchar int "
									  "vertex_indices\nend_header\n";

std::string ply_binary_face()
{
	std::string s(1, char(3));
	for (int32 i : {0, 1, 2})
		s.append(reinterpret_cast<const char*>(&i), 4);
	return s;
}

std::string stl_binary(uint32 declared, std::size_t triangles, float x = 0.0f)
{
	std::string s(80, ' ');
	s.append(reinterpret_cast<const char*>(&declared), 4);
	for (std::size_t t = 0; t < triangles; ++t)
	{
		s += bytes_of({0, 0, 1, x, 0, 0, 1, 0, 0, 0, 1, 0});
		s.append(2, '\0');
	}
	return s;
}

// Deterministic noise with bytes of every value, non-UTF-8 included.
std::string garbage(std::size_t n, uint32 seed)
{
	std::string s;
	uint32 x = seed;
	for (std::size_t i = 0; i < n; ++i)
	{
		x = x * 1664525u + 1013904223u;
		s.push_back(char(x >> 24));
	}
	return s;
}

struct BadCase
{
	const char* name;
	const char* file;      // under tests/io/bad, or the name of the made file
	std::string (*make)(); // nullptr: committed file
	Where where;           // where the error is located
	const char* cause;     // a part of the message
};

std::string case_name(const testing::TestParamInfo<BadCase>& i)
{
	return i.param.name;
}

bool is_volume(const std::string& file)
{
	const io::Format f = io::format_from_extension(file);
	return f == io::Format::Medit || f == io::Format::VtkLegacy || f == io::Format::Vtu || f == io::Format::Gmsh ||
		   f == io::Format::TetGen;
}

class BadFile : public testing::TestWithParam<BadCase>
{
};

TEST_P(BadFile, ThrowsAndLeavesTheMapUntouched)
{
	const BadCase& c = GetParam();
	TempDir dir;
	std::string path;
	if (c.make)
	{
		path = dir.file(c.file);
		write_text(path, c.make());
	}
	else
		path = std::string(CGOGN_IO_BAD_DIR) + "/" + c.file;

	auto check = [&](auto& m) {
		using MAP = std::decay_t<decltype(m)>;
		const MapSnapshot<MAP> before(m);
		try
		{
			if constexpr (MAP::dimension == 3)
				io::load_volume(m, path);
			else
				io::load_surface(m, path);
			ADD_FAILURE() << path << " loaded without error";
		}
		catch (const io::Error& e)
		{
			const std::string msg = e.what();
			// TetGen meshes are two files: the error names the one at fault
			const std::string stem = path.substr(0, path.find_last_of('.'));
			EXPECT_EQ(e.path().substr(0, e.path().find_last_of('.')), stem);
			EXPECT_EQ(msg.rfind(e.path(), 0), 0u) << msg;
			EXPECT_EQ(e.where(), c.where) << msg;
			if (c.where != Where::File)
			{
				EXPECT_GT(e.position(), 0u) << msg;
			}
			EXPECT_NE(msg.find(c.cause), std::string::npos) << "message: " << msg;
		}
		EXPECT_TRUE(MapSnapshot<MAP>(m) == before);
		EXPECT_TRUE(check_integrity(m).ok());
	};
	// the target map already holds a mesh
	if (is_volume(c.file))
	{
		CMap3 m;
		build_with_positions(m, tet_grid_soup(1, 1, 1));
		check(m);
		GMap3 g;
		build_with_positions(g, tet_grid_soup(1, 1, 1));
		check(g);
	}
	else
	{
		CMap2 m;
		build_with_positions(m, grid_soup(2, 2, true));
		check(m);
		GMap2 g;
		build_with_positions(g, grid_soup(2, 2, true));
		check(g);
	}
}

INSTANTIATE_TEST_SUITE_P(
	Corpus, BadFile,
	testing::Values(
		// OFF
		BadCase{"off_truncated", "off_truncated.off", nullptr, Where::Line, "does not fit in the rest of the file"},
		BadCase{"off_wrong_counts", "off_too_many_faces.off", nullptr, Where::Line, "after the 2 declared faces"},
		BadCase{"off_index_out_of_range", "off_index_out_of_range.off", nullptr, Where::Line, "out of range"},
		BadCase{"off_nan", "off_nan.off", nullptr, Where::Line, "not finite"},
		BadCase{"off_inf", "off_inf.off", nullptr, Where::Line, "not finite"},
		BadCase{"off_huge_count", "off_huge_count.off", nullptr, Where::Line, "declared 4000000000 vertices"},
		BadCase{"off_huge_face", "off_huge_face.off", nullptr, Where::Line, "does not fit"},
		BadCase{"off_bad_header", "off_bad_header.off", nullptr, Where::Line, "not an OFF file"},
		BadCase{"off_bad_number", "off_bad_number.off", nullptr, Where::Line, "found 'x'"},
		BadCase{"off_garbage", "garbage.off", [] { return garbage(4096, 1); }, Where::Line, "not an OFF file"},
		// OBJ
		BadCase{"obj_index_out_of_range", "obj_index_out_of_range.obj", nullptr, Where::Line, "out of range"},
		BadCase{"obj_zero_index", "obj_zero_index.obj", nullptr, Where::Line, "index 0 out of range"},
		BadCase{"obj_negative_out_of_range", "obj_negative_out_of_range.obj", nullptr, Where::Line,
				"index -4 out of range"},
		BadCase{"obj_texture_out_of_range", "obj_texture_out_of_range.obj", nullptr, Where::Line,
				"texture coordinate index"},
		BadCase{"obj_nan", "obj_nan.obj", nullptr, Where::Line, "not finite"},
		BadCase{"obj_unknown_statement", "obj_unknown_statement.obj", nullptr, Where::Line, "unknown OBJ statement"},
		BadCase{"obj_malformed_corner", "obj_malformed_corner.obj", nullptr, Where::Line, "malformed face corner"},
		BadCase{"obj_truncated", "obj_truncated_vertex.obj", nullptr, Where::Line, "unexpected end of file"},
		BadCase{"obj_garbage", "garbage.obj", [] { return garbage(4096, 2); }, Where::Line, "unknown OBJ statement"},
		// PLY
		BadCase{"ply_index_out_of_range", "ply_index_out_of_range.ply", nullptr, Where::Line, "out of range"},
		BadCase{"ply_truncated_ascii", "ply_truncated_ascii.ply", nullptr, Where::Line, "declared 3 vertex elements"},
		BadCase{"ply_huge_count", "ply_huge_count.ply", nullptr, Where::Line, "declared 2000000000 vertex elements"},
		BadCase{"ply_no_z", "ply_no_z.ply", nullptr, Where::Line, "lacks x, y or z"},
		BadCase{"ply_unknown_type", "ply_unknown_type.ply", nullptr, Where::Line, "unknown property type"},
		BadCase{"ply_no_end_header", "ply_no_end_header.ply", nullptr, Where::File, "without 'end_header'"},
		BadCase{"ply_duplicate_property", "ply_duplicate_property.ply", nullptr, Where::Line,
				"two properties named 'q'"},
		BadCase{"ply_property_named_like_group", "ply_property_named_like_group.ply", nullptr, Where::Line,
				"two vertex data arrays are named 'normal'"},
		BadCase{"ply_position_group", "ply_position_group.ply", nullptr, Where::Line,
				"collides with the vertex attribute 'position'"},
		BadCase{"ply_vertex_element_twice", "ply_vertex_element_twice.ply", nullptr, Where::Line,
				"element 'vertex' declared twice"},
		BadCase{"ply_binary_truncated", "t.ply",
				[] {
					return ply_binary_header + bytes_of({0, 0, 0, 1, 0});
				},
				Where::Byte, "declared 3 vertex elements"},
		BadCase{"ply_binary_size_mismatch", "x.ply",
				[] {
					return ply_binary_header + bytes_of({0, 0, 0, 1, 0, 0, 0, 1, 0}) + ply_binary_face() + "junk";
				},
				Where::Byte, "unexpected 4 bytes"},
		BadCase{"ply_binary_nan", "n.ply",
				[] {
					return ply_binary_header + bytes_of({0, 0, 0, 1, NAN, 0, 0, 1, 0}) + ply_binary_face();
				},
				Where::Byte, "not finite"},
		BadCase{"ply_binary_huge_list", "l.ply",
				[] {
					return ply_binary_header + bytes_of({0, 0, 0, 1, 0, 0, 0, 1, 0}) + std::string(1, char(200));
				},
				Where::Byte, "bad list count 200"},
		BadCase{"ply_garbage", "garbage.ply", [] { return garbage(4096, 3); }, Where::Line, "not a PLY file"},
		// STL
		BadCase{"stl_binary_size_mismatch", "s.stl", [] { return stl_binary(10, 2); }, Where::Byte,
				"declares 10 triangles"},
		BadCase{"stl_binary_nan", "n.stl", [] { return stl_binary(2, 2, NAN); }, Where::Byte, "not finite"},
		BadCase{"stl_too_short", "short.stl", [] { return garbage(20, 4); }, Where::Byte, "too short"},
		BadCase{"stl_truncated_ascii", "stl_truncated_ascii.stl", nullptr, Where::Line, "unexpected end of file"},
		BadCase{"stl_inf", "stl_inf.stl", nullptr, Where::Line, "not finite"},
		BadCase{"stl_garbage", "garbage.stl", [] { return garbage(4096, 5); }, Where::Byte, "declares"},
		// MEDIT
		BadCase{"mesh_index_out_of_range", "mesh_index_out_of_range.mesh", nullptr, Where::Line, "out of range"},
		BadCase{"mesh_zero_index", "mesh_zero_index.mesh", nullptr, Where::Line, "start at 1"},
		BadCase{"mesh_face_index_out_of_range", "mesh_face_index_out_of_range.mesh", nullptr, Where::Line,
				"vertex index 9 out of range"},
		BadCase{"mesh_truncated", "mesh_truncated.mesh", nullptr, Where::Line, "declared 2 cells"},
		BadCase{"mesh_huge_count", "mesh_huge_count.mesh", nullptr, Where::Line, "declared 3000000000 vertices"},
		BadCase{"mesh_unknown_section", "mesh_unknown_section.mesh", nullptr, Where::Line, "unknown MEDIT section"},
		BadCase{"mesh_nan", "mesh_nan.mesh", nullptr, Where::Line, "not finite"},
		BadCase{"mesh_garbage", "garbage.mesh", [] { return garbage(4096, 6); }, Where::Line, "not a MEDIT file"},
		// VTK legacy
		BadCase{"vtk_index_out_of_range", "vtk_index_out_of_range.vtk", nullptr, Where::Line, "out of range"},
		BadCase{"vtk_wrong_counts", "vtk_wrong_counts.vtk", nullptr, Where::Line, "same number of cells"},
		BadCase{"vtk_polydata", "vtk_polydata.vtk", nullptr, Where::Line, "UNSTRUCTURED_GRID"},
		BadCase{"vtk_unsupported_cell", "vtk_unsupported_cell.vtk", nullptr, Where::Line,
				"unsupported VTK cell type 71"},
		BadCase{"vtk_binary_truncated", "b.vtk",
				[] {
					return std::string("# vtk DataFile Version 3.0\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 "
									   "float\n") +
						   bytes_of({0, 0, 0, 1});
				},
				Where::Byte, "declared 12 values"},
		BadCase{"vtk_point_data_same_name", "vtk_point_data_same_name.vtk", nullptr, Where::Line,
				"two vertex data arrays are named 'q'"},
		BadCase{"vtk_field_same_name", "vtk_field_same_name.vtk", nullptr, Where::Line,
				"two cell data arrays are named 'q'"},
		BadCase{"vtk_point_data_original_vertex", "vtk_point_data_original_vertex.vtk", nullptr, Where::Line,
				"collides with the vertex attribute 'original_vertex'"},
		BadCase{"vtk_garbage", "garbage.vtk", [] { return garbage(4096, 7); }, Where::Line, "not a VTK legacy file"},
		// VTU
		BadCase{"vtu_index_out_of_range", "vtu_index_out_of_range.vtu", nullptr, Where::Byte, "out of range"},
		BadCase{"vtu_bad_base64", "vtu_bad_base64.vtu", nullptr, Where::Byte, "bad base64"},
		BadCase{"vtu_point_data_same_name", "vtu_point_data_same_name.vtu", nullptr, Where::Byte,
				"two vertex data arrays are named 'q'"},
		BadCase{"vtu_cell_data_same_name", "vtu_cell_data_same_name.vtu", nullptr, Where::Byte,
				"two cell data arrays are named 'q'"},
		BadCase{"vtu_point_data_position", "vtu_point_data_position.vtu", nullptr, Where::Byte,
				"collides with the vertex attribute 'position'"},
		BadCase{"vtu_garbage", "garbage.vtu", [] { return garbage(4096, 8); }, Where::Byte, ""},
		// gmsh
		BadCase{"msh_undefined_node", "msh_undefined_node.msh", nullptr, Where::Line, "node 7, which is not defined"},
		BadCase{"msh_face_undefined_node", "msh_face_undefined_node.msh", nullptr, Where::Line,
				"node 9, which is not defined"},
		BadCase{"msh_entities_truncated", "msh_entities_truncated.msh", nullptr, Where::Line,
				"expected a physical tag"},
		BadCase{"msh_bad_version", "msh_bad_version.msh", nullptr, Where::Line, "version 3.0"},
		BadCase{"msh_truncated", "msh_truncated.msh", nullptr, Where::Line, "unexpected end of file"},
		BadCase{"msh_binary_truncated", "b.msh",
				[] {
					std::string s = "$MeshFormat\n2.2 1 8\n";
					const int32 one = 1;
					s.append(reinterpret_cast<const char*>(&one), 4);
					s += "\n$EndMeshFormat\n$Nodes\n4\n";
					return s + bytes_of({0, 0, 0});
				},
				Where::Byte, "declared 4 nodes"},
		BadCase{"msh_garbage", "garbage.msh", [] { return garbage(4096, 9); }, Where::Line, "not a gmsh file"},
		// TetGen
		BadCase{"tetgen_out_of_range", "tetgen_out_of_range.ele", nullptr, Where::Line, "out of range"},
		BadCase{"tetgen_truncated", "tetgen_truncated.ele", nullptr, Where::Line, "declared 4 nodes"}),
	case_name);

TEST(BadFile, MissingFileAndUnknownExtension)
{
	CMap2 m;
	EXPECT_THROW(io::load_surface(m, "/nonexistent/file.off"), io::Error);
	EXPECT_THROW(io::load_surface(m, "mesh.xyz"), io::Error);
	EXPECT_THROW(io::load_surface(m, "mesh.ovm"), io::Error); // a volume format
	CMap3 v;
	EXPECT_THROW(io::load_volume(v, "mesh.off"), io::Error);
	EXPECT_EQ(nb_darts(m), 0u);
}

} // namespace cgogn_test_bad_files
