// SPDX-License-Identifier: MIT
// Polyhedra (VTK cell type 42) through .vtu and .vtk files: exact round
// trips of prisms on any polygon with their cell data, faces listed in
// either direction made consistent and outward, the formats that cannot
// hold them, and malformed face streams.
#include <cgogn/core.h>
#include <cgogn/io.h>

#include "cgogn_test_data.h"
#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace cgogn_test_polyhedra_io
{

using namespace cgogn;
using io_test::TempDir;

namespace
{

std::vector<uint32> counts(const CMap3& m)
{
	return {nb_cells<CMap3::Vertex>(m), nb_cells<CMap3::Edge>(m), nb_cells<CMap3::Face>(m), nb_cells<CMap3::Volume>(m)};
}

std::vector<double> values(const CMap3& m, const std::string& name)
{
	std::vector<double> v;
	auto a = get_attribute<double, CMap3::Volume>(m, name);
	if (a)
		foreach_cell(m, [&](CMap3::Volume w) { v.push_back((*a)[w]); });
	return v;
}

std::string load_error(const std::string& path)
{
	CMap3 m;
	try
	{
		io::load_volume(m, path);
	}
	catch (const io::Error& e)
	{
		EXPECT_EQ(nb_darts(m), 0u);
		return e.what();
	}
	return "";
}

} // namespace

TEST(PolyhedraIo, PrismsRoundTripThroughVtuAndVtk)
{
	TempDir dir;
	for (uint32 n : {5u, 7u})
	{
		CMap3 m;
		io_test::build_with_positions(m, prism_column_soup(n, 3));
		auto pressure = add_attribute<double, CMap3::Volume>(m, "pressure");
		double p = 0.5;
		foreach_cell(m, [&](CMap3::Volume w) { (*pressure)[w] = p *= 3; });
		for (const char* ext : {".vtu", ".vtk"})
			for (bool binary : {false, true})
			{
				SCOPED_TRACE(std::string(ext) + (binary ? " binary" : " ascii") + " n=" + std::to_string(n));
				const std::string path = dir.file(std::string("p") + ext);
				const std::string again = dir.file(std::string("again") + ext);
				io::save_volume(m, path, {.binary = binary});
				CMap3 r;
				const io::LoadReport rep = io::load_volume(r, path);
				EXPECT_EQ(rep.nb_cells_built, 3u);
				EXPECT_EQ(rep.nb_cells_reoriented, 0u);
				EXPECT_TRUE(rep.manifold());
				EXPECT_TRUE(check_integrity(r).ok()) << check_integrity(r).to_string();
				EXPECT_EQ(counts(r), counts(m));
				EXPECT_EQ(counts(r), (std::vector<uint32>{4 * n, 7 * n, 4 + 3 * n, 3}));
				EXPECT_EQ(values(r, "pressure"), values(m, "pressure"));
				EXPECT_NEAR(geometry::solid_volume(r, *get_attribute<Vec3, CMap3::Vertex>(r, "position")),
							geometry::solid_volume(m, *get_attribute<Vec3, CMap3::Vertex>(m, "position")), 1e-12);
				// and the same file again
				io::save_volume(r, again, {.binary = binary});
				EXPECT_EQ(io_test::read_text(again), io_test::read_text(path));
			}
		// formats that cannot hold them
		for (const char* ext : {".mesh", ".msh"})
		{
			try
			{
				io::save_volume(m, dir.file(std::string("p") + ext));
				ADD_FAILURE() << ext << " accepted polyhedra";
			}
			catch (const io::Error& e)
			{
				EXPECT_NE(std::string(e.what()).find("3 volume(s) that are not tetrahedra"), std::string::npos)
					<< e.what();
			}
		}
		// and into a G-map, with its cell data; written back, the same mesh
		io::save_volume(m, dir.file("p.vtu"));
		GMap3 g;
		const io::LoadReport rg = io::load_volume(g, dir.file("p.vtu"));
		EXPECT_EQ(rg.nb_cells_built, 3u);
		EXPECT_TRUE(check_integrity(g).ok());
		EXPECT_EQ(nb_darts(g), 2 * nb_darts(m));
		EXPECT_EQ(nb_cells<GMap3::Face>(g), 4 + 3 * n);
		std::vector<double> gp;
		auto gpressure = get_attribute<double, GMap3::Volume>(g, "pressure");
		ASSERT_TRUE(gpressure);
		foreach_cell(g, [&](GMap3::Volume w) { gp.push_back((*gpressure)[w]); });
		EXPECT_EQ(gp, values(m, "pressure"));
		io::save_volume(g, dir.file("g.vtu"));
		CMap3 back;
		io::load_volume(back, dir.file("g.vtu"));
		EXPECT_EQ(counts(back), counts(m));
		EXPECT_NEAR(geometry::solid_volume(back, *get_attribute<Vec3, CMap3::Vertex>(back, "position")),
					geometry::solid_volume(m, *get_attribute<Vec3, CMap3::Vertex>(m, "position")), 1e-12);
	}
}

TEST(PolyhedraIo, StandardCellsBesidePolyhedraKeepTheirKind)
{
	// two unit cubes sewn through a square: one a hexahedron (type 12), the
	// other a polyhedron (type 42) given by its faces
	TempDir dir;
	io_test::write_text(dir.file("mixed.vtu"), R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<UnstructuredGrid>
<Piece NumberOfPoints="12" NumberOfCells="2">
<Points>
<DataArray type="Float64" NumberOfComponents="3" format="ascii">
0 0 0 1 0 0 1 1 0 0 1 0 0 0 1 1 0 1 1 1 1 0 1 1 0 0 2 1 0 2 1 1 2 0 1 2
</DataArray>
</Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3 4 5 6 7 4 5 6 7 8 9 10 11</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">8 16</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">12 42</DataArray>
<DataArray type="Int64" Name="faces" format="ascii">
6 4 4 7 6 5 4 8 9 10 11 4 4 5 9 8 4 5 6 10 9 4 6 7 11 10 4 7 4 8 11
</DataArray>
<DataArray type="Int64" Name="faceoffsets" format="ascii">-1 31</DataArray>
</Cells>
<CellData>
<DataArray type="Float64" Name="material" format="ascii">1 2</DataArray>
</CellData>
</Piece>
</UnstructuredGrid>
</VTKFile>
)");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("mixed.vtu"));
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(counts(m), (std::vector<uint32>{12, 20, 11, 2})); // two cubes sharing a face
	EXPECT_EQ(values(m, "material"), (std::vector<double>{1, 2}));
	// written back, both are hexahedra now (the polyhedron is recognised by its faces)
	io::save_volume(m, dir.file("back.vtu"));
	EXPECT_EQ(io_test::read_text(dir.file("back.vtu")).find("faceoffsets"), std::string::npos);
}

TEST(PolyhedraIo, FacesInEitherDirectionAreMadeConsistentAndOutward)
{
	TempDir dir;
	// a tetrahedron whose faces are listed in no consistent direction, and a
	// cube whose faces all point inward (legacy layout: the face stream is
	// the cell's entry)
	io_test::write_text(dir.file("mixed_directions.vtk"), R"(# vtk DataFile Version 3.0
polyhedra
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 12 double
0 0 0 1 0 0 0.5 1 0 0.5 0.5 1
5 0 0 6 0 0 6 1 0 5 1 0 5 0 1 6 0 1 6 1 1 5 1 1
CELLS 2 50
17 4 3 0 1 2 3 0 1 3 3 1 2 3 3 0 2 3
31 6 4 4 5 6 7 4 8 11 10 9 4 4 8 9 5 4 5 9 10 6 4 6 10 11 7 4 7 11 8 4
CELL_TYPES 2
42
42
)");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("mixed_directions.vtk"));
	EXPECT_EQ(r.nb_cells_built, 2u);
	EXPECT_EQ(r.nb_cells_reoriented, 2u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_NEAR(geometry::solid_volume(m, *get_attribute<Vec3, CMap3::Vertex>(m, "position")), 1.0 + 1.0 / 6.0, 1e-12);
}

TEST(PolyhedraIo, MalformedFaceStreamsAreErrors)
{
	TempDir dir;
	const auto vtk = [&](const std::string& cells, std::size_t size) {
		const std::string path = dir.file("bad.vtk");
		io_test::write_text(path, "# vtk DataFile Version 3.0\nbad\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 "
								  "double\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 " +
									  std::to_string(size) + "\n" + cells + "\nCELL_TYPES 1\n42\n");
		return load_error(path);
	};
	EXPECT_EQ(vtk("17 4 3 0 2 1 3 0 1 3 3 1 2 3 3 0 3 2", 18), "");
	EXPECT_NE(vtk("5 4 3 0 2 1", 6).find("face 1 runs past the end of its face stream"), std::string::npos);
	EXPECT_NE(vtk("6 1 3 0 2 1 3", 7).find("values after its faces"), std::string::npos);
	EXPECT_NE(vtk("5 1 3 0 2 9", 6).find("point index 9 out of range"), std::string::npos);
	EXPECT_NE(vtk("1 0", 2).find("does not start with a number of faces"), std::string::npos);
	// a VTU polyhedron without its faces, and with a face offset out of range
	const auto vtu = [&](const std::string& extra) {
		const std::string path = dir.file("bad.vtu");
		io_test::write_text(path, R"(<?xml version="1.0"?>
<VTKFile type="UnstructuredGrid" version="0.1" byte_order="LittleEndian">
<UnstructuredGrid>
<Piece NumberOfPoints="4" NumberOfCells="1">
<Points><DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 0 1 0 0 0 1</DataArray></Points>
<Cells>
<DataArray type="Int64" Name="connectivity" format="ascii">0 1 2 3</DataArray>
<DataArray type="Int64" Name="offsets" format="ascii">4</DataArray>
<DataArray type="UInt8" Name="types" format="ascii">42</DataArray>
)" + extra + R"(</Cells>
</Piece>
</UnstructuredGrid>
</VTKFile>
)");
		return load_error(path);
	};
	EXPECT_NE(vtu("").find("without the 'faces' and 'faceoffsets' arrays"), std::string::npos);
	EXPECT_NE(vtu(R"(<DataArray type="Int64" Name="faces" format="ascii">4 3 0 2 1</DataArray>
<DataArray type="Int64" Name="faceoffsets" format="ascii">40</DataArray>
)")
				  .find("faceoffsets entry 40 out of the faces array"),
			  std::string::npos);
	EXPECT_EQ(vtu(R"(<DataArray type="Int64" Name="faces" format="ascii">4 3 0 2 1 3 0 1 3 3 1 2 3 3 0 3 2</DataArray>
<DataArray type="Int64" Name="faceoffsets" format="ascii">17</DataArray>
)"),
			  "");
}

TEST(PolyhedraIo, PentagonalAndHexagonalPrismsAreReadAsPolyhedra)
{
	// VTK types 15 and 16: the k-gon below, then the k-gon above, both listed
	// the same way round (one prism of each kind)
	TempDir dir;
	for (uint32 k : {5u, 6u})
	{
		std::string points;
		for (uint32 l = 0; l < 2; ++l)
			for (uint32 i = 0; i < k; ++i)
			{
				const double a = 2 * std::numbers::pi * i / k;
				points +=
					std::to_string(std::cos(a)) + " " + std::to_string(std::sin(a)) + " " + std::to_string(l) + "\n";
			}
		std::string cell = std::to_string(2 * k);
		for (uint32 i = 0; i < 2 * k; ++i)
			cell += " " + std::to_string(i);
		const std::string path = dir.file("prism.vtk");
		io_test::write_text(path, "# vtk DataFile Version 3.0\nprism\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS " +
									  std::to_string(2 * k) + " double\n" + points + "CELLS 1 " +
									  std::to_string(2 * k + 1) + "\n" + cell + "\nCELL_TYPES 1\n" +
									  std::to_string(k + 10) + "\n");
		CMap3 m;
		const io::LoadReport r = io::load_volume(m, path);
		EXPECT_EQ(r.nb_cells_built, 1u);
		EXPECT_TRUE(check_integrity(m).ok());
		EXPECT_EQ(counts(m), (std::vector<uint32>{2 * k, 3 * k, k + 2, 1}));
		const double area = 0.5 * k * std::sin(2 * std::numbers::pi / k);
		EXPECT_NEAR(geometry::solid_volume(m, *get_attribute<Vec3, CMap3::Vertex>(m, "position")), area, 1e-5);
	}
}

namespace
{
// A unit cube in OpenVolumeMesh's layout: the cell lists the half-faces
// whose normals point into it; an extra triangle in no cell, and an edge
// property the map does not take.
const char* const ovm_cube = R"(OVM ASCII
Vertices
8
0 0 0
1 0 0
1 1 0
0 1 0
0 0 1
1 0 1
1 1 1
0 1 1
Edges
13
0 1
1 2
2 3
3 0
4 5
5 6
6 7
7 4
0 4
1 5
2 6
3 7
0 2
Faces
7
4 0 2 4 6
4 8 10 12 14
4 0 18 9 17
4 2 20 11 19
4 4 22 13 21
4 6 16 15 23
3 0 2 25
Polyhedra
1
6 0 3 5 7 9 11
vprop double "t"
0 1 2 3 4 5 6 7
eprop int "e"
0 0 0 0 0 0 0 0 0 0 0 0 0
cprop vec3d "c"
1 2 3
)";
} // namespace

TEST(PolyhedraIo, OvmFilesLoadWithTheirPropertiesAndSayWhatTheyDrop)
{
	TempDir dir;
	io_test::write_text(dir.file("cube.ovm"), ovm_cube);
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("cube.ovm"));
	EXPECT_EQ(r.format, io::Format::Ovm);
	EXPECT_EQ(r.nb_cells_built, 1u);
	EXPECT_EQ(r.nb_cells_reoriented, 0u); // OVM's inward half-faces are its convention, not a flaw
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(counts(m), (std::vector<uint32>{8, 12, 6, 1}));
	EXPECT_NEAR(geometry::solid_volume(m, *get_attribute<Vec3, CMap3::Vertex>(m, "position")), 1.0, 1e-12);
	auto t = get_attribute<double, CMap3::Vertex>(m, "t");
	auto c = get_attribute<Vec3, CMap3::Volume>(m, "c");
	ASSERT_TRUE(t && c);
	EXPECT_EQ((*c)[CMap3::Volume(Dart(0))], Vec3(1, 2, 3));
	double sum = 0;
	foreach_cell(m, [&](CMap3::Vertex v) { sum += (*t)[v]; });
	EXPECT_EQ(sum, 28.0);
	ASSERT_EQ(r.dropped.size(), 2u);
	EXPECT_NE(r.dropped[0].find("1 face(s) in no polyhedron"), std::string::npos) << r.dropped[0];
	EXPECT_NE(r.dropped[1].find("eprop 'e' of type int"), std::string::npos) << r.dropped[1];
	EXPECT_NE(r.summary("CMap3").find("not loaded: eprop 'e'"), std::string::npos);
}

TEST(PolyhedraIo, OvmRoundTripsPrismsAndTheirData)
{
	TempDir dir;
	CMap3 m;
	io_test::build_with_positions(m, prism_column_soup(6, 3));
	auto pressure = add_attribute<double, CMap3::Volume>(m, "pressure");
	auto velocity = add_attribute<Vec3, CMap3::Vertex>(m, "velocity");
	double p = 1;
	foreach_cell(m, [&](CMap3::Volume w) { (*pressure)[w] = p /= 3; });
	foreach_cell(m, [&](CMap3::Vertex v) {
		p += 1;
		(*velocity)[v] = Vec3(p, -p, 0.5) * p;
	});
	io::save_volume(m, dir.file("p.ovm"));
	const std::string text = io_test::read_text(dir.file("p.ovm"));
	EXPECT_EQ(text.rfind("OVM ASCII\nVertices\n24\n", 0), 0u);
	EXPECT_NE(text.find("\nEdges\n42\n"), std::string::npos);
	EXPECT_NE(text.find("\nFaces\n22\n"), std::string::npos);
	EXPECT_NE(text.find("\ncprop double \"pressure\"\n"), std::string::npos);
	EXPECT_NE(text.find("\nvprop vec3d \"velocity\"\n"), std::string::npos);
	CMap3 r;
	const io::LoadReport rep = io::load_volume(r, dir.file("p.ovm"));
	EXPECT_EQ(rep.nb_cells_reoriented, 0u);
	EXPECT_TRUE(rep.dropped.empty());
	EXPECT_TRUE(check_integrity(r).ok());
	EXPECT_EQ(counts(r), counts(m));
	EXPECT_EQ(values(r, "pressure"), values(m, "pressure"));
	EXPECT_NEAR(geometry::solid_volume(r, *get_attribute<Vec3, CMap3::Vertex>(r, "position")),
				geometry::solid_volume(m, *get_attribute<Vec3, CMap3::Vertex>(m, "position")), 1e-12);
	auto rv = get_attribute<Vec3, CMap3::Vertex>(r, "velocity");
	ASSERT_TRUE(rv);
	std::vector<Vec3> a, b;
	foreach_cell(m, [&](CMap3::Vertex v) { a.push_back((*velocity)[v]); });
	foreach_cell(r, [&](CMap3::Vertex v) { b.push_back((*rv)[v]); });
	EXPECT_EQ(a, b);
}

TEST(PolyhedraIo, MalformedOvmFilesAreErrors)
{
	TempDir dir;
	const auto error_of = [&](std::string text, const std::string& from, const std::string& to) {
		if (!from.empty())
		{
			const std::size_t at = text.find(from);
			EXPECT_NE(at, std::string::npos) << from;
			text.replace(at, from.size(), to);
		}
		io_test::write_text(dir.file("bad.ovm"), text);
		return load_error(dir.file("bad.ovm"));
	};
	EXPECT_EQ(error_of(ovm_cube, "", ""), "");
	EXPECT_NE(error_of(ovm_cube, "OVM ASCII", "OVM BINARY").find("binary .ovm files are not read"), std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "0 2\nFaces", "0 9\nFaces").find(":26: vertex index 9 out of range"),
			  std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "4 0 2 4 6", "4 0 2 4 99").find("half-edge index 99 out of range"), std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "4 0 2 4 6", "4 0 4 2 6").find("does not start where the previous one ends"),
			  std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "6 0 3 5 7 9 11", "6 0 3 5 7 9 40").find("half-face index 40 out of range"),
			  std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "cprop vec3d \"c\"", "cprop vec3d c").find("without its name in quotes"),
			  std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "cprop vec3d", "xprop vec3d").find("unknown property kind 'xprop'"),
			  std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "Polyhedra\n1", "Polyhedra\n2").find("the number of half-faces of a polyhedron"),
			  std::string::npos);
	EXPECT_NE(error_of(ovm_cube, "vprop double \"t\"", "vprop double \"position\"").find("collides"),
			  std::string::npos);
}

TEST(PolyhedraIo, LargeOvmMeshHasTheCountsOfItsReadme)
{
	const std::string path = cgogn_test_data::path("volume/elephant_poly_4k.ovm");
	if (path.empty())
		GTEST_SKIP() << cgogn_test_data::missing_large("volume/elephant_poly_4k.ovm");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, path);
	EXPECT_EQ(r.nb_cells_built, 4392u);
	EXPECT_EQ(r.nb_cells_skipped, 0u);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(counts(m), (std::vector<uint32>{160844, 207618, 51159, 4392}));
	uint32 boundary_faces = 0;
	foreach_cell(m, [&](CMap3::Face f) { boundary_faces += is_incident_to_boundary(m, f); });
	EXPECT_EQ(boundary_faces, 29393u);
}

} // namespace cgogn_test_polyhedra_io
