// SPDX-License-Identifier: MIT
// Integer data stays integer: attributes of every integer width load from and
// save to the formats that have integers (PLY, VTK legacy, VTU, .ovm) with
// their type and values; values a type cannot hold are refused; what no
// attribute holds is reported.
#include <cgogn/cgogn.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <limits>

namespace cgogn_test_integer_data
{

using namespace cgogn;
using namespace cgogn::io_test;

// Adds attribute `name` of type T to the cells CELL of m, value i*step+first
// on the i-th cell met, and returns the values by cell line.
template <typename T, typename CELL, typename MAP>
void add_counting(MAP& m, const std::string& name, T first, T step)
{
	auto a = add_attribute<T, CELL>(m, name);
	T v = first;
	foreach_cell(m, [&](CELL c) {
		(*a)[c] = v;
		v = T(v + step);
	});
}

// The values of attribute `name` of type T on the cells CELL, sorted.
template <typename T, typename CELL, typename MAP>
std::vector<T> sorted_values(const MAP& m, const std::string& name)
{
	auto a = get_attribute<T, CELL>(m, name);
	std::vector<T> out;
	if (a == nullptr)
		return out;
	foreach_cell(m, [&](CELL c) { out.push_back((*a)[c]); });
	std::sort(out.begin(), out.end());
	return out;
}

// Every integer type on the cells CELL of m, with values at the ends of
// their ranges (64-bit ones up to the 2^53 - 1 a file carries).
template <typename CELL, typename MAP>
void add_every_integer_type(MAP& m)
{
	add_counting<int8, CELL>(m, "i8", -128, 1);
	add_counting<uint8, CELL>(m, "u8", 200, 1);
	add_counting<std::int16_t, CELL>(m, "i16", -32768, 7);
	add_counting<uint16, CELL>(m, "u16", 65000, 1);
	add_counting<int32, CELL>(m, "i32", std::numeric_limits<int32>::min(), 1000);
	add_counting<uint32, CELL>(m, "u32", 4294967000u, 1);
	add_counting<int64, CELL>(m, "i64", -9007199254740991LL, 3);
	add_counting<uint64, CELL>(m, "u64", 9007199254740000ULL, 1);
}

// The integer attributes of add_every_integer_type in `back` are those of
// `m`, with their types; `narrow_64` when the format has no 64-bit integers
// (PLY: int64 and uint64 come back as int32 and uint32 when they fit,
// else as double).
template <typename CELL, typename MAP>
void expect_same_integers(const MAP& m, const MAP& back, bool narrow_64)
{
	EXPECT_EQ((sorted_values<int8, CELL>(back, "i8")), (sorted_values<int8, CELL>(m, "i8")));
	EXPECT_EQ((sorted_values<uint8, CELL>(back, "u8")), (sorted_values<uint8, CELL>(m, "u8")));
	EXPECT_EQ((sorted_values<std::int16_t, CELL>(back, "i16")), (sorted_values<std::int16_t, CELL>(m, "i16")));
	EXPECT_EQ((sorted_values<uint16, CELL>(back, "u16")), (sorted_values<uint16, CELL>(m, "u16")));
	EXPECT_EQ((sorted_values<int32, CELL>(back, "i32")), (sorted_values<int32, CELL>(m, "i32")));
	EXPECT_EQ((sorted_values<uint32, CELL>(back, "u32")), (sorted_values<uint32, CELL>(m, "u32")));
	if (narrow_64)
	{
		std::vector<double> i64, u64;
		for (int64 v : sorted_values<int64, CELL>(m, "i64"))
			i64.push_back(double(v));
		for (uint64 v : sorted_values<uint64, CELL>(m, "u64"))
			u64.push_back(double(v));
		EXPECT_EQ((sorted_values<double, CELL>(back, "i64")), i64) << "beyond 32 bits: written as double";
		EXPECT_EQ((sorted_values<double, CELL>(back, "u64")), u64);
	}
	else
	{
		EXPECT_EQ((sorted_values<int64, CELL>(back, "i64")), (sorted_values<int64, CELL>(m, "i64")));
		EXPECT_EQ((sorted_values<uint64, CELL>(back, "u64")), (sorted_values<uint64, CELL>(m, "u64")));
	}
}

TEST(IntegerData, PlyKeepsEveryIntegerTypeOfVerticesAndFaces)
{
	TempDir dir;
	CMap2 m;
	build_with_positions(m, grid_soup(4, 3, true));
	add_every_integer_type<CMap2::Vertex>(m);
	add_every_integer_type<CMap2::Face>(m);
	for (bool binary : {false, true})
	{
		SCOPED_TRACE(binary ? "binary" : "ascii");
		io::SaveOptions o;
		o.binary = binary;
		io::save_surface(m, dir.file("m.ply"), o);
		CMap2 back;
		io::load_surface(back, dir.file("m.ply"));
		expect_same_integers<CMap2::Vertex>(m, back, true);
		expect_same_integers<CMap2::Face>(m, back, true);
	}
}

TEST(IntegerData, PlySixtyFourBitValuesThatFitAreWrittenAsThirtyTwoBits)
{
	TempDir dir;
	CMap2 m;
	build_with_positions(m, grid_soup(2, 2, true));
	add_counting<int64, CMap2::Face>(m, "region", -3, 1);
	add_counting<uint64, CMap2::Vertex>(m, "id", 10, 1);
	io::save_surface(m, dir.file("m.ply"));
	EXPECT_NE(read_text(dir.file("m.ply")).find("property int region"), std::string::npos);
	EXPECT_NE(read_text(dir.file("m.ply")).find("property uint id"), std::string::npos);
	CMap2 back;
	io::load_surface(back, dir.file("m.ply"));
	EXPECT_EQ((sorted_values<int32, CMap2::Face>(back, "region")), (std::vector<int32>{-3, -2, -1, 0, 1, 2, 3, 4}));
	EXPECT_EQ((sorted_values<uint32, CMap2::Vertex>(back, "id")).front(), 10u);
}

TEST(IntegerData, VtkLegacyAndVtuKeepEveryIntegerTypeOfVerticesAndVolumes)
{
	TempDir dir;
	CMap3 m;
	build_with_positions(m, tet_grid_soup(2, 2, 1));
	add_every_integer_type<CMap3::Vertex>(m);
	add_every_integer_type<CMap3::Volume>(m);
	for (const char* ext : {"vtk", "vtu", "ovm"})
		for (bool binary : {false, true})
		{
			SCOPED_TRACE(std::string(ext) + (binary ? " binary" : " ascii"));
			io::SaveOptions o;
			o.binary = binary;
			const std::string path = dir.file(std::string("m.") + ext);
			io::save_volume(m, path, o);
			CMap3 back;
			io::load_volume(back, path);
			expect_same_integers<CMap3::Vertex>(m, back, false);
			expect_same_integers<CMap3::Volume>(m, back, false);
		}
}

TEST(IntegerData, ReadersGiveIntegerAttributesOfTheFilesTypes)
{
	TempDir dir;
	const std::string points = "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n";
	write_text(dir.file("t.vtk"), "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points +
									  "CELL_DATA 1\nSCALARS region unsigned_short 1\nLOOKUP_TABLE default\n7\n"
									  "POINT_DATA 4\nSCALARS flag char 1\nLOOKUP_TABLE default\n-1 0 1 2\n");
	CMap3 m;
	io::load_volume(m, dir.file("t.vtk"));
	EXPECT_EQ((sorted_values<uint16, CMap3::Volume>(m, "region")), (std::vector<uint16>{7}));
	EXPECT_EQ((sorted_values<int8, CMap3::Vertex>(m, "flag")), (std::vector<int8>{-1, 0, 1, 2}));

	write_text(dir.file("t.vtu"),
			   "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"><UnstructuredGrid><Piece NumberOfPoints=\"4\" "
			   "NumberOfCells=\"1\"><Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 "
			   "0 1 0 0 0 1 0 0 0 1</DataArray></Points><Cells><DataArray type=\"Int64\" Name=\"connectivity\" "
			   "format=\"ascii\">0 1 2 3</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4"
			   "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells>"
			   "<CellData><DataArray type=\"Int64\" Name=\"GlobalCellIds\" format=\"ascii\">9007199254740991"
			   "</DataArray></CellData></Piece></UnstructuredGrid></VTKFile>\n");
	CMap3 u;
	io::load_volume(u, dir.file("t.vtu"));
	EXPECT_EQ((sorted_values<int64, CMap3::Volume>(u, "GlobalCellIds")), (std::vector<int64>{9007199254740991LL}));
}

TEST(IntegerData, ValuesOutsideTheirTypeAreRefusedAndTheMapIsUnchanged)
{
	TempDir dir;
	// an ascii uchar of 300, an Int64 of 2^53 (rounded by a double), an
	// ascii short that is not an integer
	write_text(dir.file("u8.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
								   "property float z\nproperty uchar level\nelement face 1\nproperty list uchar int "
								   "vertex_indices\nend_header\n0 0 0 1\n1 0 0 300\n0 1 0 2\n3 0 1 2\n");
	write_text(dir.file("i64.vtu"),
			   "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\"><UnstructuredGrid><Piece NumberOfPoints=\"4\" "
			   "NumberOfCells=\"1\"><Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">0 0 "
			   "0 1 0 0 0 1 0 0 0 1</DataArray></Points><Cells><DataArray type=\"Int64\" Name=\"connectivity\" "
			   "format=\"ascii\">0 1 2 3</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">4"
			   "</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">10</DataArray></Cells>"
			   "<CellData><DataArray type=\"Int64\" Name=\"id\" format=\"ascii\">9007199254740993"
			   "</DataArray></CellData></Piece></UnstructuredGrid></VTKFile>\n");
	CMap2 s;
	build_with_positions(s, grid_soup(1, 1, false)); // one quad
	try
	{
		io::load_surface(s, dir.file("u8.ply"));
		ADD_FAILURE() << "a uchar of 300 was accepted";
	}
	catch (const io::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("'level' of type uint8 holds the value 300"), std::string::npos)
			<< e.what();
	}
	EXPECT_EQ(nb_cells<CMap2::Face>(s), 1u);
	EXPECT_EQ((get_attribute<uint8, CMap2::Vertex>(s, "level")), nullptr);

	CMap3 v;
	try
	{
		io::load_volume(v, dir.file("i64.vtu"));
		ADD_FAILURE() << "an Int64 beyond 2^53 was accepted";
	}
	catch (const io::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("below 2^53"), std::string::npos) << e.what();
	}
	EXPECT_EQ(nb_darts(v), 0u);

	// and an attribute a file cannot carry exactly is refused when writing
	CMap3 big;
	build_with_positions(big, tet_grid_soup(1, 1, 1));
	add_counting<uint64, CMap3::Volume>(big, "id", 9007199254740992ULL, 1);
	EXPECT_THROW(io::save_volume(big, dir.file("big.vtu")), io::Error);
}

TEST(IntegerData, DataNoAttributeHoldsIsReported)
{
	TempDir dir;
	write_text(dir.file("t.vtk"), "# vtk DataFile Version 3.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n"
								  "POINTS 4 float\n0 0 0 1 0 0 0 1 0 0 0 1\nCELLS 1 5\n4 0 1 2 3\nCELL_TYPES 1\n10\n"
								  "CELL_DATA 1\nTENSORS stress double\n1 2 3 4 5 6 7 8 9\n"
								  "POINT_DATA 4\nVECTORS step int\n1 2 3 4 5 6 7 8 9 10 11 12\n");
	CMap3 m;
	const io::LoadReport r = io::load_volume(m, dir.file("t.vtk"));
	ASSERT_EQ(r.dropped.size(), 2u);
	EXPECT_NE(r.dropped[0].find("'step' as integers: its 3 components are held as a vector of double"),
			  std::string::npos)
		<< r.dropped[0];
	EXPECT_NE(r.dropped[1].find("'stress' of 9 components"), std::string::npos) << r.dropped[1];
	EXPECT_NE((get_attribute<Vec3, CMap3::Vertex>(m, "step")), nullptr);
	EXPECT_NE(r.summary("CMap3").find("stress"), std::string::npos);
}

} // namespace cgogn_test_integer_data
