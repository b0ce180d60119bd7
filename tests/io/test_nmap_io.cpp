// SPDX-License-Identifier: MIT
// The files of the maps of any dimension: .nmap round trips with attributes,
// malformed files, and the VTU of cells and boundaries.
#include <cgogn/core.h>
#include <cgogn/io.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <regex>

namespace cgogn_test_nmap_io
{

using namespace cgogn;
using io_test::TempDir;

namespace
{

template <typename MAP>
void check_round_trip(const TempDir& dir)
{
	constexpr uint32 D = MAP::dimension;
	SCOPED_TRACE(std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(D) + ">");
	MAP m;
	generate_cube_grid(m, 2);
	auto tag = add_attribute<int32, CellD<D - 1>>(m, "tag");
	int32 k = -5;
	foreach_cell(m, [&](CellD<D - 1> c) { (*tag)[c] = k++; });
	add_attribute<std::string, CellD<1>>(m, "note"); // not a type of the format
	const std::string path = dir.file("m" + std::to_string(D) + ".nmap");
	EXPECT_EQ(io::save_nmap(m, path), std::vector<std::string>{"note"});
	MAP r;
	io::load_nmap(r, path);
	EXPECT_TRUE(check_integrity(r).ok()) << check_integrity(r).to_string();
	EXPECT_EQ(nb_darts(r), nb_darts(m));
	EXPECT_EQ(f_vector(r), f_vector(m));
	// the same values on the same cells: the darts keep their numbers (m is compact)
	auto rtag = get_attribute<int32, CellD<D - 1>>(r, "tag");
	auto rpos = get_attribute<PointD<D>, CellD<0>>(r, "position");
	auto pos = get_attribute<PointD<D>, CellD<0>>(m, "position");
	ASSERT_TRUE(rtag && rpos);
	foreach_cell(m, [&](CellD<D - 1> c) { EXPECT_EQ((*rtag)[CellD<D - 1>(c.dart)], (*tag)[c]); });
	foreach_cell(m, [&](CellD<0> v) { EXPECT_EQ((*rpos)[CellD<0>(v.dart)], (*pos)[v]); });
	// and the same file again
	io::save_nmap(r, path + "2");
	EXPECT_EQ(io_test::read_text(path + "2"), io_test::read_text(path));
}

// The message of the io::Error that loading `text` throws ("" when none).
template <typename MAP>
std::string load_error(const TempDir& dir, const std::string& text)
{
	const std::string path = dir.file("bad.nmap");
	io_test::write_text(path, text);
	MAP m;
	try
	{
		io::load_nmap(m, path);
	}
	catch (const io::Error& e)
	{
		EXPECT_EQ(nb_darts(m), 0u);
		return e.what();
	}
	return "";
}

} // namespace

TEST(NMapFiles, RoundTripsForDimensions2To5)
{
	TempDir dir;
	check_round_trip<CMapN<2>>(dir);
	check_round_trip<GMapN<2>>(dir);
	check_round_trip<CMapN<3>>(dir);
	check_round_trip<GMapN<3>>(dir);
	check_round_trip<CMapN<4>>(dir);
	check_round_trip<GMapN<4>>(dir);
	check_round_trip<CMapN<5>>(dir);
	check_round_trip<GMapN<5>>(dir);
}

TEST(NMapFiles, MalformedFilesNameTheLineAndTheProblem)
{
	TempDir dir;
	// a 1-map: one cycle of two darts and its boundary... two real darts in a cycle
	const std::string head = "cgogn_nmap 1\nmodel cmap\ndimension 1\ndarts 2\n";
	EXPECT_EQ(load_error<CMapN<1>>(dir, head + "1 0\n0 0\nend\n"), "");
	EXPECT_NE(load_error<CMapN<1>>(dir, "cgogn_map 1\n").find("bad.nmap:1: not a .nmap file"), std::string::npos);
	EXPECT_NE(load_error<GMapN<1>>(dir, head).find(":2: the file holds a cmap"), std::string::npos);
	EXPECT_NE(load_error<CMapN<2>>(dir, head).find(":3: the file holds a map of dimension 1"), std::string::npos);
	EXPECT_NE(load_error<CMapN<1>>(dir, head + "1 0\n7 0\n").find(":6: relation 1 points to dart 7, out of range"),
			  std::string::npos);
	EXPECT_NE(load_error<CMapN<1>>(dir, head + "0 0\n0 0\nend\n").find("the darts do not make a valid map"),
			  std::string::npos);
	EXPECT_NE(load_error<CMapN<1>>(dir, head + "1 0\n0 x\n").find(":6: the boundary mark: 'x' is not a number"),
			  std::string::npos);
	EXPECT_NE(load_error<CMapN<1>>(dir, head + "1 0\n").find(":5: the file ends where a dart is expected"),
			  std::string::npos);
	EXPECT_NE(load_error<CMapN<1>>(dir, head + "1 0\n0 0\nattribute 0 w complex 1\n0 1\nend\n")
				  .find(":7: unknown value type 'complex'"),
			  std::string::npos);
	EXPECT_NE(load_error<CMapN<1>>(dir, head + "1 0\n0 0\nattribute 0 w float64 1\n0 nan\nend\n")
				  .find(":8: the value is not finite"),
			  std::string::npos);
	EXPECT_NE(
		load_error<CMapN<1>>(dir, head + "1 0\n0 0\nattribute 2 w float64 0\nend\n").find(":7: no cell of dimension 2"),
		std::string::npos);
	EXPECT_NE(load_error<CMapN<1>>(dir, head + "1 0\n0 1\nattribute 1 w float64 1\n1 2\nend\n")
				  .find(":8: dart 1 is in a boundary cell"),
			  std::string::npos);
}

TEST(NMapFiles, TheHeaderNamesTheMapType)
{
	TempDir dir;
	GMapN<5> g;
	generate_simplex(g);
	io::save_nmap(g, dir.file("s.nmap"));
	const io::NMapHeader h = io::read_nmap_header(dir.file("s.nmap"));
	EXPECT_TRUE(h.gmap);
	EXPECT_EQ(h.dimension, 5u);
	const auto header_error = [&](const std::string& text) {
		io_test::write_text(dir.file("bad.nmap"), text);
		try
		{
			io::read_nmap_header(dir.file("bad.nmap"));
		}
		catch (const io::Error& e)
		{
			return std::string(e.what());
		}
		return std::string();
	};
	EXPECT_EQ(header_error("# a comment\ncgogn_nmap 1\nmodel cmap\ndimension 7\n"), "");
	EXPECT_NE(header_error("cgogn_nmap 2\n").find("bad.nmap:1: not a .nmap file of version 1"), std::string::npos);
	EXPECT_NE(header_error("cgogn_nmap 1\nmodel map\n").find("bad.nmap:2: unknown model 'map'"), std::string::npos);
	EXPECT_NE(header_error("cgogn_nmap 1\nmodel gmap\ndimension 0\n").find(":3: the dimension 0 is out of"),
			  std::string::npos);
	EXPECT_NE(header_error("cgogn_nmap 1\nmodel gmap\n").find(":2: the file ends where dimension is expected"),
			  std::string::npos);
}

TEST(NMapFiles, TheExampleOfTheFormatsPageLoads)
{
	TempDir dir;
	const std::string path = dir.file("triangle.nmap");
	io_test::write_text(path,
						"cgogn_nmap 1\nmodel cmap\ndimension 2\ndarts 6\n1 3 0\n2 5 0\n0 4 0\n4 0 1\n5 2 1\n3 1 1\n"
						"attribute 0 position float64x2 3\n0 0 0\n1 1 0\n2 0 1\nend\n");
	CMapN<2> m;
	io::load_nmap(m, path);
	EXPECT_EQ(f_vector(m), (std::vector<uint32>{3, 3, 1}));
	auto position = get_attribute<PointD<2>, CellD<0>>(m, "position");
	ASSERT_TRUE(position);
	EXPECT_EQ((*position)[CellD<0>(Dart(1))], (PointD<2>{1, 0}));
}

TEST(NMapFiles, ALoadIntoAMapThatHasDartsIsRefused)
{
	TempDir dir;
	CMapN<3> m;
	generate_simplex(m);
	const std::string path = dir.file("s.nmap");
	io::save_nmap(m, path);
	EXPECT_THROW(io::load_nmap(m, path), io::Error);
	EXPECT_EQ(f_vector(m), (std::vector<uint32>{4, 6, 4, 1}));
}

TEST(NMapFiles, TheBoundaryOfA4DGridIsAVTUOfPolyhedra)
{
	TempDir dir;
	CMapN<4> m;
	generate_cube_grid(m, 2);
	const CMapN<3> boundary = extract_boundary(m);
	const std::string path = dir.file("boundary.vtu");
	io::save_vtu(boundary, path, {3});
	const std::string text = io_test::read_text(path);
	// the boundary of the 2^4 grid: 8 facets of 2^3 cubes, on 3^4 - 1 points
	EXPECT_NE(text.find("NumberOfPoints=\"80\" NumberOfCells=\"64\""), std::string::npos);
	EXPECT_NE(text.find("Name=\"faceoffsets\""), std::string::npos);
	// a 3-skeleton of the 4-D grid itself, projected by dropping the last axis
	io::save_vtu(m, path, {0, 1, 2, 3});
	const std::vector<uint32> f = f_vector(m);
	const uint32 cells = f[0] + f[1] + f[2] + f[3];
	EXPECT_NE(io_test::read_text(path).find("NumberOfCells=\"" + std::to_string(cells) + "\""), std::string::npos);
	GMapN<2> g;
	EXPECT_THROW(io::save_vtu(g, path, {2}), io::Error); // no position
}

} // namespace cgogn_test_nmap_io
