// SPDX-License-Identifier: MIT
// The variants each reader must accept (headers, layouts, index forms,
// endianness), and how loads append to maps and repair non-manifold input.
#include <cgogn/cgogn.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <cstring>

#ifdef CGOGN_TEST_HAS_ZLIB
#include <zlib.h>

namespace cgogn_test_format_variants
{
#endif

using namespace cgogn;
using namespace cgogn::io_test;
using Vertex = CMap2::Vertex;
using Face = CMap2::Face;

namespace
{

std::vector<Vec3> positions(const CMap2& m)
{
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	return std::vector<Vec3>(pos->begin(), pos->end());
}

template <typename T>
void append_be(std::string& s, T v)
{
	char b[sizeof(T)];
	std::memcpy(b, &v, sizeof(T));
	for (std::size_t i = sizeof(T); i-- > 0;)
		s.push_back(b[i]);
}
template <typename T>
void append_le(std::string& s, T v)
{
	s.append(reinterpret_cast<const char*>(&v), sizeof(T));
}

std::string base64(const std::string& in)
{
	static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
	std::string out;
	std::size_t i = 0;
	for (; i + 2 < in.size(); i += 3)
	{
		const uint32 v = (uint8(in[i]) << 16) | (uint8(in[i + 1]) << 8) | uint8(in[i + 2]);
		for (int k = 3; k >= 0; --k)
			out += t[(v >> (6 * k)) & 63];
	}
	if (i < in.size())
	{
		uint32 v = uint8(in[i]) << 16;
		if (i + 1 < in.size())
			v |= uint8(in[i + 1]) << 8;
		out += t[(v >> 18) & 63];
		out += t[(v >> 12) & 63];
		out += i + 1 < in.size() ? t[(v >> 6) & 63] : '=';
		out += '=';
	}
	return out;
}

const char* tet_points = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

} // namespace

TEST(OffVariants, ColorsNormalsCommentsAndCountsOnTheHeaderLine)
{
	TempDir dir;
	write_text(dir.file("c.off"), "# a comment\nCOFF 3 1 0 # counts here\n0 0 0 255 0 0 255\n1 0 0 0 255 0 "
								  "255\n# between\n0 1 0 0 0 255 128\n3 0 1 2 10 20 30\n");
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, dir.file("c.off"));
	EXPECT_EQ(r.nb_cells_built, 1u);
	auto color = get_attribute<Vec3, Vertex>(m, "color");
	ASSERT_TRUE(color);
	EXPECT_EQ(std::vector<Vec3>(color->begin(), color->end()),
			  (std::vector<Vec3>{{255, 0, 0}, {0, 255, 0}, {0, 0, 255}}));
	auto fcolor = get_attribute<Vec3, Face>(m, "color");
	ASSERT_TRUE(fcolor);
	EXPECT_EQ(*fcolor->begin(), Vec3(10, 20, 30));

	write_text(dir.file("n.off"), "NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n");
	CMap2 n;
	io::load_surface(n, dir.file("n.off"));
	auto normal = get_attribute<Vec3, Vertex>(n, "normal");
	ASSERT_TRUE(normal);
	EXPECT_EQ(*normal->begin(), Vec3(0, 0, 1));
}

TEST(ObjVariants, CornerFormsNegativeIndicesPolygonsAndIgnoredStatements)
{
	TempDir dir;
	write_text(dir.file("q.obj"), "mtllib x.mtl\no quad\ng group one\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
								  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\ns off\nusemtl m\n"
								  "f 1/1/1 2/2/1 3/3/1 4/4/1\nv 2 0 0\nf -4//1 -1//1 -3//1\nl 1 2\n");
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, dir.file("q.obj"));
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(nb_cells<Vertex>(m), 5u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 6u);
	std::vector<uint32> degrees;
	foreach_cell(m, [&](Face f) { degrees.push_back(codegree(static_cast<const CMap1&>(m), CMap1::Face(f.dart))); });
	std::sort(degrees.begin(), degrees.end());
	EXPECT_EQ(degrees, (std::vector<uint32>{3, 4}));
	// every corner of a vertex uses the same normal: kept; the new vertex has no texture coordinate
	auto normal = get_attribute<Vec3, Vertex>(m, "normal");
	ASSERT_TRUE(normal);
	for (const Vec3& x : *normal)
		EXPECT_EQ(x, Vec3(0, 0, 1));
	EXPECT_FALSE((get_attribute<Vec2, Vertex>(m, "tex_coord"))) << "the second face has no texture coordinates";
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(ObjVariants, TextureSeamsAreNotForcedOnVertices)
{
	TempDir dir;
	// vertex 1 has two different texture coordinates
	write_text(dir.file("s.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 0.5 0.5\n"
								  "f 1/1 2/2 3/3\nf 2/2 4/3 3/4\n");
	CMap2 m;
	io::load_surface(m, dir.file("s.obj"));
	EXPECT_FALSE((get_attribute<Vec2, Vertex>(m, "tex_coord")));
	EXPECT_EQ(nb_cells<Face>(m), 2u);
}

TEST(PlyVariants, BigEndianBinaryWithExtraPropertiesAndElements)
{
	TempDir dir;
	std::string s = "ply\nformat binary_big_endian 1.0\ncomment made by a test\nobj_info none\n"
					"element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
					"property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float quality\n"
					"element face 2\nproperty int flags\nproperty list uint int vertex_index\n"
					"element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
	const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0.5}};
	for (int v = 0; v < 4; ++v)
	{
		for (double x : p[v])
			append_be(s, x);
		for (int k = 0; k < 3; ++k)
			s.push_back(char(uint8(v * 10 + k)));
		append_be(s, float(v) * 0.5f);
	}
	const int32 faces[2][3] = {{0, 1, 2}, {1, 3, 2}};
	for (int f = 0; f < 2; ++f)
	{
		append_be(s, int32(7 + f));
		append_be(s, uint32(3));
		for (int32 i : faces[f])
			append_be(s, i);
	}
	append_be(s, int32(0));
	append_be(s, int32(1));
	write_text(dir.file("be.ply"), s);

	CMap2 m;
	const io::LoadReport r = io::load_surface(m, dir.file("be.ply"));
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(positions(m)[3], Vec3(1, 1, 0.5));
	auto color = get_attribute<Vec3, Vertex>(m, "color");
	auto quality = get_attribute<double, Vertex>(m, "quality");
	auto flags = get_attribute<int32, Face>(m, "flags"); // an int property stays an int
	ASSERT_TRUE(color && quality && flags);
	EXPECT_EQ(std::vector<Vec3>(color->begin(), color->end())[2], Vec3(20, 21, 22));
	EXPECT_EQ(std::vector<double>(quality->begin(), quality->end()), (std::vector<double>{0, 0.5, 1, 1.5}));
	EXPECT_EQ(std::vector<int32>(flags->begin(), flags->end()), (std::vector<int32>{7, 8}));
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(StlVariants, AsciiVerticesAreWeldedExactly)
{
	TempDir dir;
	write_text(dir.file("w.stl"),
			   "solid w\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
			   "vertex 0 1 0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\n"
			   "vertex 1 1 0\nvertex 0 1 -0\nendloop\nendfacet\nfacet normal 0 0 1\nouter loop\n"
			   "vertex 5 5 5\nvertex 6 5 5.000000001\nvertex 5 6 5\nendloop\nendfacet\nendsolid w\n");
	CMap2 m;
	io::load_surface(m, dir.file("w.stl"));
	EXPECT_EQ(nb_cells<Vertex>(m), 7u) << "0 1 -0 is 0 1 0; nearly equal points stay apart";
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 8u);
	EXPECT_EQ(nb_connected_components(m), 2u);
	auto normal = get_attribute<Vec3, Face>(m, "normal");
	ASSERT_TRUE(normal);
}

TEST(SurfaceLoad, AppendsToANonEmptyMap)
{
	TempDir dir;
	CMap2 a;
	build_with_positions(a, sphere_soup(6, 4, true));
	io::save_surface(a, dir.file("s.ply"));
	CMap2 m;
	io::load_surface(m, dir.file("s.ply"));
	const io::LoadReport r = io::load_surface(m, dir.file("s.ply"));
	EXPECT_EQ(r.build.vertex_offset, nb_cells<Vertex>(a));
	EXPECT_EQ(nb_cells<Vertex>(m), 2 * nb_cells<Vertex>(a));
	EXPECT_EQ(nb_cells<Face>(m), 2 * nb_cells<Face>(a));
	EXPECT_EQ(nb_connected_components(m), 2u);
	std::vector<Vec3> pa = positions(a), pm = positions(m);
	pa.insert(pa.end(), pa.begin(), pa.end());
	EXPECT_EQ(pa, pm);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(SurfaceLoad, RepairsNonManifoldInputAndSkipsDegenerateFaces)
{
	TempDir dir;
	// a bow tie (vertex 2 shared by two fans), a face with a repeated vertex,
	// a face of two vertices, an unused vertex
	write_text(dir.file("b.off"), "OFF\n6 4 0\n0 0 0\n1 0 0\n2 1 0\n3 0 0\n3 2 0\n9 9 9\n"
								  "3 0 1 2\n3 2 3 4\n3 0 0 1\n2 0 1\n");
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, dir.file("b.off"));
	EXPECT_EQ(r.nb_cells_read, 4u);
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(r.nb_cells_skipped, 2u);
	EXPECT_EQ(r.nb_isolated_vertices, 1u);
	EXPECT_EQ(r.nb_nonmanifold_vertices, 1u);
	EXPECT_EQ(r.nb_vertices_split, 1u);
	EXPECT_FALSE(r.manifold());
	EXPECT_EQ(nb_cells<Vertex>(m), 6u);
	auto orig = get_attribute<uint32, Vertex>(m, "original_vertex");
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	ASSERT_TRUE(orig);
	uint32 copies_of_2 = 0;
	foreach_cell(m, [&](Vertex v) {
		if (value<uint32>(m, *orig, v) == 2)
		{
			++copies_of_2;
			EXPECT_EQ(value<Vec3>(m, *pos, v), Vec3(2, 1, 0));
		}
	});
	EXPECT_EQ(copies_of_2, 2u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(SurfaceLoad, RefusesToOverwriteAnAttributeOfAnotherType)
{
	TempDir dir;
	CMap2 a;
	build_with_positions(a, grid_soup(2, 2));
	io::save_surface(a, dir.file("g.off"));
	CMap2 m;
	add_attribute<double, Vertex>(m, "position");
	EXPECT_THROW(io::load_surface(m, dir.file("g.off")), io::Error);
	EXPECT_EQ(nb_darts(m), 0u);
}

TEST(VtkVariants, Version5OffsetsConnectivityWedgesAndVoxels)
{
	TempDir dir;
	// a VTK wedge (base normal pointing away from the top) and a voxel
	write_text(dir.file("w.vtk"),
			   "# vtk DataFile Version 5.1\nw\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 14 double\n"
			   "0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 0 1 1\n"
			   "5 0 0 6 0 0 5 1 0 6 1 0 5 0 1 6 0 1 5 1 1 6 1 1\n"
			   "CELLS 3 14\nOFFSETS vtktypeint64\n0 6 14\nCONNECTIVITY vtktypeint64\n"
			   "0 2 1 3 5 4 6 7 8 9 10 11 12 13\nCELL_TYPES 2\n13\n11\n"
			   "CELL_DATA 2\nSCALARS id int 1\nLOOKUP_TABLE default\n4 5\n"
			   "POINT_DATA 14\nVECTORS v float\n"
			   "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0\n");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("w.vtk"));
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(r.nb_cells_reoriented, 0u) << "a proper VTK wedge and voxel need no turning over";
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 2u);
	EXPECT_EQ(nb_cells<CMap3::Face>(m), 11u);
	auto id = get_attribute<int32, CMap3::Volume>(m, "id"); // SCALARS of type int
	ASSERT_TRUE(id);
	std::vector<int32> ids(id->begin(), id->end());
	std::sort(ids.begin(), ids.end());
	EXPECT_EQ(ids, (std::vector<int32>{4, 5}));
	EXPECT_TRUE((get_attribute<Vec3, CMap3::Vertex>(m, "v")));
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(VtuVariants, InlineBase64AndCompressedBlocks)
{
	TempDir dir;
	auto array = [](const std::string& raw, bool header64) {
		std::string h;
		if (header64)
			append_le(h, uint64(raw.size()));
		else
			append_le(h, uint32(raw.size()));
		return base64(h) + base64(raw);
	};
	std::string pts, conn, offs, types;
	for (double x : {0., 0., 0., 1., 0., 0., 0., 1., 0., 0., 0., 1.})
		append_le(pts, x);
	for (int32 i : {0, 1, 2, 3})
		append_le(conn, i);
	append_le(offs, int32(4));
	types.push_back(char(10));
	auto file = [&](const std::string& p, const std::string& c, const std::string& o, const std::string& t,
					const char* extra) {
		return std::string("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" "
						   "byte_order=\"LittleEndian\"") +
			   extra +
			   ">\n<UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points><DataArray "
			   "type=\"Float64\" NumberOfComponents=\"3\" format=\"binary\">" +
			   p + "</DataArray></Points>\n<Cells><DataArray type=\"Int32\" Name=\"connectivity\" format=\"binary\">" +
			   c + "</DataArray><DataArray type=\"Int32\" Name=\"offsets\" format=\"binary\">" + o +
			   "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"binary\">" + t +
			   "</DataArray></Cells></Piece></UnstructuredGrid></VTKFile>\n";
	};
	write_text(dir.file("b.vtu"),
			   file(array(pts, false), array(conn, false), array(offs, false), array(types, false), ""));
	CMap3 m;
	io::load_volume(m, dir.file("b.vtu"));
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 1u);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), 4u);
#ifdef CGOGN_TEST_HAS_ZLIB
	auto compressed = [](const std::string& raw) {
		uLongf n = compressBound(uLong(raw.size()));
		std::string z(n, '\0');
		compress(reinterpret_cast<Bytef*>(z.data()), &n, reinterpret_cast<const Bytef*>(raw.data()), uLong(raw.size()));
		z.resize(n);
		std::string h;
		for (uint64 v : {uint64(1), uint64(raw.size()), uint64(raw.size()), uint64(z.size())})
			append_le(h, v);
		return base64(h) + base64(z);
	};
	write_text(dir.file("z.vtu"), file(compressed(pts), compressed(conn), compressed(offs), compressed(types),
									   " header_type=\"UInt64\" compressor=\"vtkZLibDataCompressor\""));
	CMap3 z;
	io::load_volume(z, dir.file("z.vtu"));
	EXPECT_EQ(nb_cells<CMap3::Volume>(z), 1u);
	EXPECT_EQ(std::vector<Vec3>(get_attribute<Vec3, CMap3::Vertex>(z, "position")->begin(),
								get_attribute<Vec3, CMap3::Vertex>(z, "position")->end())[3],
			  Vec3(0, 0, 1));
#endif
}

TEST(VtuVariants, AsciiArraysWithoutSeparatorsAroundTheValues)
{
	// `<DataArray ...>4</DataArray>`: the last value needs no separator
	TempDir dir;
	write_text(dir.file("i.vtu"),
			   "<VTKFile type=\"UnstructuredGrid\"><UnstructuredGrid><Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">"
			   "<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">0 0 0 1 0 0 0 1 0 0 0 "
			   "1</DataArray></Points><Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">0 1 2 "
			   "3</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4</DataArray><DataArray "
			   "type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells><CellData><DataArray "
			   "type=\"Float64\" Name=\"q\" format=\"ascii\">7</DataArray></CellData></Piece></UnstructuredGrid>"
			   "</VTKFile>");
	CMap3 m;
	io::load_volume(m, dir.file("i.vtu"));
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 1u);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), 4u);
	auto q = get_attribute<double, CMap3::Volume>(m, "q");
	ASSERT_NE(q, nullptr);
	foreach_cell(m, [&](CMap3::Volume v) { EXPECT_EQ(value<double>(m, *q, v), 7.0); });
}

TEST(GmshVariants, Version2AsciiAndBinaryWithSurfaceElements)
{
	TempDir dir;
	write_text(dir.file("a.msh"), std::string("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n3 1 "
											  "\"v\"\n$EndPhysicalNames\n$Nodes\n5\n10 0 0 0\n20 1 0 0\n30 0 1 0\n"
											  "40 0 0 1\n50 0 0 -1\n$EndNodes\n$Elements\n3\n1 2 2 0 1 10 20 30\n"
											  "2 4 2 1 1 10 20 30 40\n3 4 0 10 30 20 50\n$EndElements\n"));
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("a.msh"));
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(r.nb_cells_reoriented, 0u);
	EXPECT_EQ(nb_cells<CMap3::Face>(m), 7u);

	std::string s = "$MeshFormat\n2.2 1 8\n";
	append_le(s, int32(1));
	s += "\n$EndMeshFormat\n$Nodes\n4\n";
	const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
	for (int32 i = 0; i < 4; ++i)
	{
		append_le(s, i + 1);
		for (double x : p[i])
			append_le(s, x);
	}
	s += "\n$EndNodes\n$Elements\n1\n";
	for (int32 v : {4, 1, 2, 1, 0, 0, 1, 2, 3, 4})
		append_le(s, v);
	s += "\n$EndElements\n";
	write_text(dir.file("b.msh"), s);
	CMap3 b;
	io::load_volume(b, dir.file("b.msh"));
	EXPECT_EQ(nb_cells<CMap3::Volume>(b), 1u);
	EXPECT_TRUE(check_integrity(b).ok());
}

TEST(TetgenVariants, ZeroBasedWithAttributesMarkersAndComments)
{
	TempDir dir;
	write_text(dir.file("t.node"), std::string("# nodes\n4 3 1 1\n0 ") + "0 0 0 7 1\n1 1 0 0 7 1\n2 0 1 0 7 1\n"
																		 "3 0 0 1 7 0\n");
	write_text(dir.file("t.ele"), "1 4 1\n0 0 1 2 3 -1 # region\n");
	CMap3 m;
	io::load_volume(m, dir.file("t.node"));
	EXPECT_EQ(nb_cells<CMap3::Volume>(m), 1u);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), 4u);
	(void)tet_points;
}

TEST(MeditVariants, SkippedSectionsMixedCellsAndDimensionOnItsOwnLine)
{
	TempDir dir;
	write_text(dir.file("m.mesh"), "MeshVersionFormatted\n2\n\nDimension\n3\n# comment\nVertices\n6\n0 0 0 1\n1 0 0 "
								   "1\n0 1 0 1\n0 0 1 1\n1 0 1 1\n0 1 1 1\nEdges\n1\n1 2 0\nTriangles\n1\n1 2 3 "
								   "0\nCorners\n1\n1\nPrisms\n1\n1 2 3 4 5 6 3\nEnd\n");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("m.mesh"));
	EXPECT_EQ(r.nb_cells_built, 1u);
	EXPECT_EQ(nb_cells<CMap3::Face>(m), 5u);
	EXPECT_EQ(nb_cells<CMap3::Edge>(m), 9u);
}

} // namespace cgogn_test_format_variants
