// SPDX-License-Identifier: MIT
// The .cgmap files of whole maps: exact round trips of every map type (darts,
// relations, boundary, cell lines, free lines, attributes), maps that go on
// behaving as the saved one after a load, skipped types, wrong map types,
// truncated and corrupted files, and the version-1 compatibility file.
#include <cgogn/core.h>
#include <cgogn/io.h>

#include "cgogn_test_data.h"
#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <random>

namespace cgogn_test_map_file
{

using namespace cgogn;
using io_test::TempDir;

namespace
{

// a and b hold the same darts, relations, boundary marks, cell lines, free
// lines and attribute values: checked on the states themselves, then on
// what the writer makes of them.
void expect_same_state(const CMapBase& a, const CMapBase& b)
{
	const detail::MapState& sa = detail::state_of(a);
	const detail::MapState& sb = detail::state_of(b);
	ASSERT_EQ(sa.darts->end_index(), sb.darts->end_index());
	EXPECT_EQ(sa.darts->free_lines(), sb.darts->free_lines());
	ASSERT_EQ(sa.relations.size(), sb.relations.size());
	EXPECT_EQ(sa.nb_boundary_darts, sb.nb_boundary_darts);
	for (uint32 d = 0; d < sa.darts->end_index(); ++d)
	{
		for (std::size_t k = 0; k < sa.relations.size(); ++k)
			ASSERT_EQ((*sa.relations[k])[d], (*sb.relations[k])[d]) << "relation " << k + 1 << " of dart " << d;
		ASSERT_EQ(sa.boundary->test(d), sb.boundary->test(d)) << "boundary mark of dart " << d;
	}
	for (uint32 o = 1; o < NB_ORBITS; ++o)
	{
		SCOPED_TRACE(std::string(orbit_name(Orbit(o))));
		ASSERT_EQ(sa.cell_index[o] == nullptr, sb.cell_index[o] == nullptr);
		const AttributeContainer& ca = *sa.cells[o];
		const AttributeContainer& cb = *sb.cells[o];
		ASSERT_EQ(ca.end_index(), cb.end_index());
		EXPECT_EQ(ca.free_lines(), cb.free_lines());
		ASSERT_EQ(ca.attributes().size(), cb.attributes().size());
		for (std::size_t k = 0; k < ca.attributes().size(); ++k)
		{
			EXPECT_EQ(ca.attributes()[k]->name(), cb.attributes()[k]->name());
			EXPECT_EQ(ca.attributes()[k]->type(), cb.attributes()[k]->type());
		}
		for (uint32 i = 0; i < ca.end_index(); ++i)
			ASSERT_EQ(ca.key()[i], cb.key()[i]) << "line " << i;
		if (sa.cell_index[o] != nullptr)
		{
			for (uint32 d = 0; d < sa.darts->end_index(); ++d)
				ASSERT_EQ((*sa.cell_index[o])[d], (*sb.cell_index[o])[d]) << "index of dart " << d;
		}
	}
}

template <typename MAP>
void expect_same_map(const MAP& a, const MAP& b)
{
	expect_same_state(a, b);
	EXPECT_EQ(io::save_map_to_bytes(a), io::save_map_to_bytes(b));
	EXPECT_TRUE(check_integrity(b).ok()) << check_integrity(b).to_string();
}

// Saves m to a file, loads it into a map of the same type, checks that the
// two are the same, and returns the loaded one.
template <typename MAP>
MAP round_trip(const MAP& m, const TempDir& dir)
{
	SCOPED_TRACE(io::map_type_name<MAP>());
	const std::string path = dir.file("m.cgmap");
	const io::MapFileReport report = io::save_map(m, path);
	EXPECT_TRUE(report.skipped.empty());
	EXPECT_EQ(io::read_map_header(path).map_type, io::map_type_name<MAP>());
	EXPECT_EQ(io::read_map_header(path).version, 1u);
	MAP r;
	io::load_map(r, path);
	expect_same_map(m, r);
	return r;
}

// A surface with holes, attributes of every kind of value type, and free
// lines left by edits (collapses and removed faces), so that the round trip
// has lines to keep in place.
CMap2 edited_surface()
{
	CMap2 m;
	io::load_surface(m, cgogn_test_data::path("surface/elephant-with-holes.off"));
	auto region = add_attribute<int32, CMap2::Face>(m, "region");
	auto flag = add_attribute<bool, CMap2::Vertex>(m, "flag");
	auto small = add_attribute<int8, CMap2::Edge>(m, "small");
	auto label = add_attribute<std::string, CMap2::Face>(m, "label");
	auto uv = add_attribute<Vec2, CMap2::HalfEdge>(m, "uv");
	auto frame = add_attribute<std::array<double, 5>, CMap2::Vertex>(m, "frame");
	auto colour = add_attribute<Vec4, CMap2::Vertex>(m, "colour");
	add_attribute<uint16, CMap2::Volume>(m, "component");
	uint32 k = 0;
	foreach_cell(m, [&](CMap2::Face f) {
		(*region)[f] = int32(k % 7) - 3;
		(*label)[f] = k % 5 == 0 ? std::string("face ") + std::to_string(k) : std::string();
		++k;
	});
	foreach_cell(m, [&](CMap2::Vertex v) {
		(*flag)[v] = k % 3 == 0;
		(*frame)[v] = {double(k), -0.5, 1e300, 0.1, -0.0};
		(*colour)[v] = Vec4(0.25, 0.5, 1.0 / 3.0, double(k));
		++k;
	});
	foreach_cell(m, [&](CMap2::Edge e) {
		(*small)[e] = int8(k % 256 - 128);
		++k;
	});
	foreach_dart(m, [&](Dart d) { (*uv)[CMap2::HalfEdge(d)] = Vec2(double(d.index) / 7.0, -double(k++)); });
	std::mt19937 rng(7);
	for (uint32 step = 0; step < 60; ++step)
	{
		std::vector<CMap2::Edge> edges;
		foreach_cell(m, [&](CMap2::Edge e) { edges.push_back(e); });
		const CMap2::Edge e = edges[rng() % edges.size()];
		if (step % 3 == 0)
			cut_edge(m, e);
		else if (can_collapse_edge(m, e))
			collapse_edge(m, e);
	}
	return m;
}

} // namespace

TEST(MapFile, EditedSurfaceRoundTripsExactly)
{
	TempDir dir;
	const CMap2 m = edited_surface();
	ASSERT_FALSE(detail::state_of(m).darts->free_lines().empty()); // the edits left free darts
	CMap2 r = round_trip(m, dir);
	// the attributes come back by name and type, with their values
	auto region = get_attribute<int32, CMap2::Face>(r, "region");
	auto label = get_attribute<std::string, CMap2::Face>(r, "label");
	auto uv = get_attribute<Vec2, CMap2::HalfEdge>(r, "uv");
	ASSERT_TRUE(region && label && uv);
	auto mregion = get_attribute<int32, CMap2::Face>(m, "region");
	auto mlabel = get_attribute<std::string, CMap2::Face>(m, "label");
	foreach_cell(m, [&](CMap2::Face f) {
		EXPECT_EQ((*region)[f], (*mregion)[f]);
		EXPECT_EQ((*label)[f], (*mlabel)[f]);
	});
	EXPECT_EQ(nb_cells<CMap2::Vertex>(r), nb_cells<CMap2::Vertex>(m));
	EXPECT_EQ(nb_boundary_components(r), nb_boundary_components(m));
	EXPECT_EQ((get_attribute<double, CMap2::Face>(r, "region")), nullptr); // not another type
}

TEST(MapFile, LoadedMapGoesOnAsTheSavedOne)
{
	// the free lists come back in their order: the same edits on the saved
	// and the loaded map give the same darts and lines
	TempDir dir;
	CMap2 m = edited_surface();
	CMap2 r = round_trip(m, dir);
	std::mt19937 rm(11), rr(11);
	for (CMap2* map : {&m, &r})
	{
		std::mt19937& rng = map == &m ? rm : rr;
		for (uint32 step = 0; step < 40; ++step)
		{
			std::vector<CMap2::Edge> edges;
			foreach_cell(*map, [&](CMap2::Edge e) { edges.push_back(e); });
			const CMap2::Edge e = edges[rng() % edges.size()];
			if (step % 2 == 0 && can_flip_edge(*map, e))
				flip_edge(*map, e);
			else
				cut_edge(*map, e);
		}
	}
	expect_same_map(m, r);
}

TEST(MapFile, EveryMapTypeRoundTrips)
{
	TempDir dir;
	{
		CMap1 m;
		add_face(m, 5);
		add_face(m, 3);
		add_attribute<float, CMap1::Face>(m, "w");
		remove_face(m, CMap1::Face(Dart(5)));
		add_face(m, 2);
		round_trip(m, dir);
	}
	{
		GMap1 m;
		add_face(m, 4);
		round_trip(m, dir);
	}
	{
		CMap3 m;
		build_volume(m, hex_grid_soup(3, 2, 2));
		auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
		add_attribute<uint64, CMap3::Volume>(m, "cell_id");
		add_attribute<double, CMap3::Face>(m, "flux");
		add_attribute<Vec3, CMap3::Edge>(m, "tangent");
		cut_edge(m, CMap3::Edge(Dart(0)));
		CMap3 r = round_trip(m, dir);
		EXPECT_EQ(f_vector(r), f_vector(m));
	}
	{
		GMap2 m;
		build_surface(m, sphere_soup(6, 4));
		add_attribute<int64, GMap2::Face>(m, "id");
		add_attribute<std::array<double, 8>, GMap2::Vertex>(m, "p8");
		round_trip(m, dir);
	}
	{
		GMap3 m;
		build_volume(m, tet_grid_soup(2, 2, 1));
		add_attribute<uint8, GMap3::Volume>(m, "material");
		round_trip(m, dir);
	}
	{
		Graph g;
		std::vector<Graph::Vertex> v;
		for (uint32 i = 0; i < 6; ++i)
			v.push_back(add_vertex(g));
		for (uint32 i = 0; i + 1 < 6; ++i)
			connect_vertices(g, v[i], v[i + 1]);
		connect_vertices(g, v[0], v[3]);
		add_attribute<double, Graph::Vertex>(g, "radius");
		add_attribute<int32, Graph::Edge>(g, "branch");
		remove_vertex(g, v[4]);
		round_trip(g, dir);
	}
	{
		CMapN<4> m;
		generate_cube_grid(m, 2);
		add_attribute<int32, CellD<3>>(m, "tag");
		round_trip(m, dir);
	}
	{
		GMapN<3> m;
		generate_simplex(m);
		add_attribute<std::string, CellD<2>>(m, "name");
		round_trip(m, dir);
	}
}

TEST(MapFile, UnheldTypesAreReportedAndLeftOut)
{
	CMap2 m;
	build_surface(m, grid_soup(2, 2));
	add_attribute<std::vector<int>, CMap2::Face>(m, "lists");
	add_attribute<int32, CMap2::Face>(m, "kept");
	io::MapFileReport report;
	const std::string bytes = io::save_map_to_bytes(m, &report);
	ASSERT_EQ(report.skipped.size(), 1u);
	EXPECT_EQ(report.skipped[0].name, "lists");
	EXPECT_EQ(report.skipped[0].orbit, "PHI1");
	EXPECT_NE(report.skipped[0].reason.find("no encoding"), std::string::npos);
	CMap2 r;
	io::load_map_from_bytes(r, bytes);
	EXPECT_EQ((get_attribute<std::vector<int>, CMap2::Face>(r, "lists")), nullptr);
	EXPECT_NE((get_attribute<int32, CMap2::Face>(r, "kept")), nullptr);
	EXPECT_EQ(io::map_file_value_types().size(), 23u);
}

namespace
{
// The message of the io::Error that loading `bytes` into a MAP throws ("" when none).
template <typename MAP>
std::string load_error(std::string_view bytes)
{
	MAP m;
	build_surface(m, grid_soup(1, 1));
	const std::string before = io::save_map_to_bytes(m);
	try
	{
		io::load_map_from_bytes(m, bytes, "f.cgmap");
	}
	catch (const io::Error& e)
	{
		EXPECT_EQ(io::save_map_to_bytes(m), before) << "a failed load changed the map";
		return e.what();
	}
	return "";
}
} // namespace

TEST(MapFile, TheHeaderNamesTheTypeAndTheVersion)
{
	CMap2 m;
	build_surface(m, grid_soup(2, 1));
	const std::string bytes = io::save_map_to_bytes(m);
	EXPECT_EQ(io::read_map_header_from_bytes(bytes).map_type, "CMap2");
	EXPECT_NE(load_error<GMap2>(bytes).find("the file holds a CMap2, not a GMap2"), std::string::npos);
	EXPECT_NE(load_error<CMap2>("CGOGNMAQ" + bytes.substr(8)).find("not a .cgmap file"), std::string::npos);
	std::string newer = bytes;
	newer[8] = 2;
	EXPECT_NE(load_error<CMap2>(newer).find("f.cgmap: byte 12: format version 2 (this library reads version 1)"),
			  std::string::npos);
	EXPECT_NE(load_error<CMap2>(bytes + "xy").find("2 bytes after the end of the map"), std::string::npos);
	EXPECT_EQ(load_error<CMap2>(bytes), "");
	EXPECT_THROW(io::read_map_header("/nonexistent/m.cgmap"), io::Error);
}

TEST(MapFile, EveryTruncationIsAnError)
{
	CMap2 m;
	build_surface(m, grid_soup(2, 1, true));
	add_attribute<std::string, CMap2::Face>(m, "s");
	const std::string bytes = io::save_map_to_bytes(m);
	for (std::size_t n = 0; n < bytes.size(); ++n)
		ASSERT_NE(load_error<CMap2>(std::string_view(bytes).substr(0, n)), "") << "prefix of " << n << " bytes";
}

TEST(MapFile, CorruptedBytesAreRefusedOrGiveAValidMap)
{
	// each byte changed in turn: the load throws io::Error or gives a map
	// that passes check_integrity (a changed attribute value is still a map)
	CMap2 m;
	build_surface(m, grid_soup(2, 2, true));
	add_attribute<int32, CMap2::Face>(m, "tag");
	const std::string bytes = io::save_map_to_bytes(m);
	uint32 refused = 0;
	for (std::size_t i = 0; i < bytes.size(); ++i)
		for (uint8 x : {uint8(1), uint8(0x80), uint8(0xff)})
		{
			std::string b = bytes;
			b[i] = char(uint8(b[i]) ^ x);
			CMap2 r;
			try
			{
				io::load_map_from_bytes(r, b);
				ASSERT_TRUE(check_integrity(r).ok()) << "byte " << i;
			}
			catch (const io::Error&)
			{
				++refused;
			}
		}
	EXPECT_GT(refused, bytes.size()); // most changes hit the structure
}

namespace
{
// The map of the compatibility file: a quadrangle and a triangle sharing an
// edge, one attribute of each value type, and a free dart.
CMap2 compatibility_map()
{
	CMap2 m;
	SurfaceSoup s;
	s.nb_vertices = 5;
	s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0.5, 0}};
	s.face_sizes = {4, 3};
	s.face_vertices = {0, 1, 2, 3, 1, 4, 2};
	build_surface(m, s);
	add_attribute<bool, CMap2::Vertex>(m, "b");
	add_attribute<int8, CMap2::Vertex>(m, "i8");
	add_attribute<uint8, CMap2::Vertex>(m, "u8");
	add_attribute<std::int16_t, CMap2::Vertex>(m, "i16");
	add_attribute<uint16, CMap2::Vertex>(m, "u16");
	add_attribute<int32, CMap2::Face>(m, "i32");
	add_attribute<uint32, CMap2::Face>(m, "u32");
	add_attribute<int64, CMap2::Edge>(m, "i64");
	add_attribute<uint64, CMap2::Edge>(m, "u64");
	add_attribute<float, CMap2::Edge>(m, "f32");
	add_attribute<double, CMap2::Volume>(m, "f64");
	add_attribute<Vec2, CMap2::HalfEdge>(m, "uv");
	add_attribute<Vec4, CMap2::Vertex>(m, "rgba");
	add_attribute<std::array<double, 2>, CMap2::Vertex>(m, "p2");
	add_attribute<std::string, CMap2::Face>(m, "name");
	uint32 k = 1;
	foreach_cell(m, [&](CMap2::Vertex v) {
		(*get_attribute<bool, CMap2::Vertex>(m, "b"))[v] = k % 2 == 1;
		(*get_attribute<int8, CMap2::Vertex>(m, "i8"))[v] = int8(-int32(k));
		(*get_attribute<uint8, CMap2::Vertex>(m, "u8"))[v] = uint8(200 + k);
		(*get_attribute<std::int16_t, CMap2::Vertex>(m, "i16"))[v] = std::int16_t(-300 * int32(k));
		(*get_attribute<uint16, CMap2::Vertex>(m, "u16"))[v] = uint16(60000 + k);
		(*get_attribute<Vec4, CMap2::Vertex>(m, "rgba"))[v] = Vec4(k, 0.5, 0.25, 1);
		(*get_attribute<std::array<double, 2>, CMap2::Vertex>(m, "p2"))[v] = {double(k), -double(k)};
		++k;
	});
	foreach_cell(m, [&](CMap2::Face f) {
		(*get_attribute<int32, CMap2::Face>(m, "i32"))[f] = -int32(k) * 100000;
		(*get_attribute<uint32, CMap2::Face>(m, "u32"))[f] = 4000000000u + k;
		(*get_attribute<std::string, CMap2::Face>(m, "name"))[f] = "face " + std::to_string(k);
		++k;
	});
	foreach_cell(m, [&](CMap2::Edge e) {
		(*get_attribute<int64, CMap2::Edge>(m, "i64"))[e] = -(int64(1) << 40) - k;
		(*get_attribute<uint64, CMap2::Edge>(m, "u64"))[e] = (uint64(1) << 63) + k;
		(*get_attribute<float, CMap2::Edge>(m, "f32"))[e] = 0.1f * float(k);
		++k;
	});
	foreach_cell(m, [&](CMap2::Volume w) { (*get_attribute<double, CMap2::Volume>(m, "f64"))[w] = 1.0 / 3.0; });
	foreach_dart(m, [&](Dart d) {
		(*get_attribute<Vec2, CMap2::HalfEdge>(m, "uv"))[CMap2::HalfEdge(d)] = Vec2(d.index, 0.125);
	});
	// the file was written before attribute rules existed: the cut's new
	// cells hold default values
	const auto no_rules = [](AttributeContainer& c) {
		for (const auto& a : c.attributes())
			c.set_rule(*a, AttributeRule::None);
	};
	no_rules(container_of<CMap2::Vertex::ORBIT>(m));
	no_rules(container_of<CMap2::Edge::ORBIT>(m));
	no_rules(container_of<CMap2::Face::ORBIT>(m));
	no_rules(container_of<Orbit::DART>(m));
	const CMap2::Vertex v = cut_edge(m, CMap2::Edge(Dart(0)));
	collapse_edge(m, CMap2::Edge(v.dart)); // leaves free darts and lines
	return m;
}
} // namespace

TEST(MapFile, VersionOneFilesStillLoad)
{
	// The file was written by the first version of the format. A change of
	// the format that reads it differently must change the version.
	const std::string path = cgogn_test_data::path("maps/compatibility_v1.cgmap");
	const CMap2 expected = compatibility_map();
	EXPECT_EQ(io_test::read_text(path), io::save_map_to_bytes(expected));
	CMap2 m;
	io::load_map(m, path);
	expect_same_map(expected, m);
	auto name = get_attribute<std::string, CMap2::Face>(m, "name");
	ASSERT_TRUE(name);
	std::vector<std::string> names;
	foreach_cell(m, [&](CMap2::Face f) { names.push_back((*name)[f]); });
	EXPECT_EQ(names, (std::vector<std::string>{"face 6", "face 7"}));
}

} // namespace cgogn_test_map_file
