// SPDX-License-Identifier: MIT
// Data whose name is taken by an attribute of another type in the target map:
// every format that carries named data refuses the load with an io::Error
// naming the data, before the map is touched. Writers refuse attributes whose
// names would collide in the file. (Files that collide with themselves are in
// the malformed corpus, test_bad_files.cpp.)
#include <cgogn/cgogn.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

namespace cgogn_test_name_collisions
{

using namespace cgogn;
using namespace cgogn::io_test;

struct Collision
{
	const char* name;
	const char* file;                // written in a temporary folder
	const char* text;                // its content
	void (*prepare)(CMap2&, CMap3&); // adds the attribute that collides
	const char* data;                // the data's name, which the message must give
};

std::string case_name(const testing::TestParamInfo<Collision>& i)
{
	return i.param.name;
}

class NameCollision : public testing::TestWithParam<Collision>
{
};

constexpr const char* tet_vtk = "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
								"0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"
								"POINT_DATA 4\nSCALARS q double 1\nLOOKUP_TABLE default\n0 1 2 3\n";

constexpr const char* tet_vtu =
	"<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"
	"<UnstructuredGrid>\n<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n"
	"<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 1</DataArray>\n"
	"</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 3</DataArray>\n"
	"<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray>\n"
	"<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray>\n</Cells>\n"
	"<CellData>\n<DataArray type=\"Float64\" Name=\"q\" NumberOfComponents=\"2\" format=\"ascii\">7 8</DataArray>\n"
	"</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";

// two triangles that share only vertex 0: the builder splits it and records
// the file's ids in `original_vertex`
constexpr const char* bowtie_off = "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n";

TEST_P(NameCollision, ThrowsNamingTheDataAndLeavesTheMapUntouched)
{
	const Collision& c = GetParam();
	TempDir dir;
	const std::string path = dir.file(c.file);
	write_text(path, c.text);
	CMap2 surface;
	build_with_positions(surface, grid_soup(2, 2, true));
	CMap3 volume;
	build_with_positions(volume, tet_grid_soup(1, 1, 1));
	c.prepare(surface, volume);

	auto check = [&](auto& m, auto load) {
		using MAP = std::decay_t<decltype(m)>;
		const MapSnapshot<MAP> before(m);
		try
		{
			load(m);
			ADD_FAILURE() << c.file << " loaded without error";
		}
		catch (const io::Error& e)
		{
			const std::string msg = e.what();
			EXPECT_EQ(e.path(), path);
			EXPECT_NE(msg.find("'" + std::string(c.data) + "'"), std::string::npos) << msg;
			EXPECT_NE(msg.find("another type"), std::string::npos) << msg;
		}
		EXPECT_TRUE(MapSnapshot<MAP>(m) == before);
		EXPECT_TRUE(check_integrity(m).ok());
	};
	if (io::format_from_extension(path) == io::Format::Vtu || io::format_from_extension(path) == io::Format::VtkLegacy)
		check(volume, [&](CMap3& m) { io::load_volume(m, path); });
	else
		check(surface, [&](CMap2& m) { io::load_surface(m, path); });
}

INSTANTIATE_TEST_SUITE_P(
	EveryFormatWithNamedData, NameCollision,
	testing::Values(
		Collision{"off_vertex_normal", "n.off", "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n",
				  [](CMap2& m, CMap3&) { add_attribute<double, CMap2::Vertex>(m, "normal"); }, "normal"},
		Collision{"off_face_color", "c.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 255 0 0\n",
				  [](CMap2& m, CMap3&) { add_attribute<Vec2, CMap2::Face>(m, "color"); }, "color"},
		Collision{"off_original_vertex", "bowtie.off", bowtie_off,
				  [](CMap2& m, CMap3&) { add_attribute<double, CMap2::Vertex>(m, "original_vertex"); },
				  "original_vertex"},
		Collision{"obj_normal", "n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\n",
				  [](CMap2& m, CMap3&) { add_attribute<Vec2, CMap2::Vertex>(m, "normal"); }, "normal"},
		Collision{"obj_tex_coord", "t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n",
				  [](CMap2& m, CMap3&) { add_attribute<double, CMap2::Vertex>(m, "tex_coord"); }, "tex_coord"},
		Collision{"ply_vertex_scalar", "q.ply",
				  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
				  "property float q\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
				  "0 0 0 1\n1 0 0 2\n0 1 0 3\n3 0 1 2\n",
				  [](CMap2& m, CMap3&) { add_attribute<Vec3, CMap2::Vertex>(m, "q"); }, "q"},
		Collision{"ply_face_vector", "f.ply",
				  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
				  "element face 1\nproperty list uchar int vertex_indices\nproperty float w_x\nproperty float w_y\n"
				  "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 5 6\n",
				  [](CMap2& m, CMap3&) { add_attribute<double, CMap2::Face>(m, "w"); }, "w"},
		Collision{"stl_face_normal", "n.stl",
				  "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
				  "endfacet\nendsolid t\n",
				  [](CMap2& m, CMap3&) { add_attribute<double, CMap2::Face>(m, "normal"); }, "normal"},
		Collision{"vtk_point_scalar", "q.vtk", tet_vtk,
				  [](CMap2&, CMap3& m) { add_attribute<Vec3, CMap3::Vertex>(m, "q"); }, "q"},
		Collision{"vtu_cell_vector", "q.vtu", tet_vtu,
				  [](CMap2&, CMap3& m) { add_attribute<double, CMap3::Volume>(m, "q"); }, "q"}),
	case_name);

TEST(NameCollision, SameTypeAppends)
{
	// an attribute of the file's name and type receives the new cells' values
	TempDir dir;
	const std::string path = dir.file("q.vtk");
	write_text(path, tet_vtk);
	CMap3 m;
	build_with_positions(m, tet_grid_soup(1, 1, 1));
	auto q = add_attribute<double, CMap3::Vertex>(m, "q");
	const uint32 before = nb_cells<CMap3::Vertex>(m);
	io::load_volume(m, path);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), before + 4);
	EXPECT_EQ((get_attribute<double, CMap3::Vertex>(m, "q")), q);
	double sum = 0;
	foreach_cell(m, [&](CMap3::Vertex v) { sum += value<double>(m, *q, v); });
	EXPECT_EQ(sum, 0.0 + 1.0 + 2.0 + 3.0);
}

TEST(NameCollision, PlyWriterRefusesAttributesThatShareAProperty)
{
	TempDir dir;
	CMap2 m;
	build_with_positions(m, grid_soup(2, 2, true));
	auto check = [&](const char* attribute, const char* property) {
		const std::string path = dir.file("out.ply");
		try
		{
			io::save_surface(m, path);
			ADD_FAILURE() << "written with " << attribute;
		}
		catch (const io::Error& e)
		{
			const std::string msg = e.what();
			EXPECT_EQ(e.path(), path);
			EXPECT_NE(msg.find("'" + std::string(attribute) + "'"), std::string::npos) << msg;
			EXPECT_NE(msg.find("property '" + std::string(property) + "'"), std::string::npos) << msg;
		}
	};
	auto x = add_attribute<double, CMap2::Vertex>(m, "x");
	check("x", "x");
	remove_attribute(m, x);
	add_attribute<Vec3, CMap2::Vertex>(m, "normal");
	auto nx = add_attribute<double, CMap2::Vertex>(m, "ny");
	check("ny", "ny");
	remove_attribute(m, nx);
	auto vi = add_attribute<double, CMap2::Face>(m, "vertex_indices");
	check("vertex_indices", "vertex_indices");
	remove_attribute(m, vi);
	// without a collision the file reads back with the same attributes
	add_attribute<Vec2, CMap2::Face>(m, "w");
	const std::string path = dir.file("ok.ply");
	io::save_surface(m, path);
	CMap2 back;
	io::load_surface(back, path);
	EXPECT_NE((get_attribute<Vec3, CMap2::Vertex>(back, "normal")), nullptr);
	EXPECT_NE((get_attribute<Vec2, CMap2::Face>(back, "w")), nullptr);
}

TEST(NameCollision, WritersOfNamedDataRefuseTheLoadersNames)
{
	// a double `original_vertex` would be refused when the file is read back
	TempDir dir;
	CMap2 s;
	build_with_positions(s, grid_soup(2, 2, true));
	add_attribute<double, CMap2::Vertex>(s, "original_vertex");
	EXPECT_THROW(io::save_surface(s, dir.file("s.ply")), io::Error);
	io::save_surface(s, dir.file("s.off")); // OFF writes no such data
	CMap3 v;
	build_with_positions(v, tet_grid_soup(1, 1, 1));
	add_attribute<Vec3, CMap3::Vertex>(v, "original_vertex");
	EXPECT_THROW(io::save_volume(v, dir.file("v.vtk")), io::Error);
	EXPECT_THROW(io::save_volume(v, dir.file("v.vtu")), io::Error);
	io::save_volume(v, dir.file("v.mesh"));
}

TEST(NameCollision, CellDataNamedPositionIsOrdinaryData)
{
	// only the vertices' `position` is the loader's; a volume's is kept
	TempDir dir;
	std::string text = tet_vtu;
	text.replace(text.find("Name=\"q\""), 8, "Name=\"position\"");
	write_text(dir.file("p.vtu"), text);
	CMap3 m;
	io::load_volume(m, dir.file("p.vtu"));
	auto p = get_attribute<Vec2, CMap3::Volume>(m, "position");
	ASSERT_NE(p, nullptr);
	foreach_cell(m, [&](CMap3::Volume w) { EXPECT_EQ((*p)[w], Vec2(7, 8)); });
}

} // namespace cgogn_test_name_collisions
