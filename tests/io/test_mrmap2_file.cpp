// SPDX-License-Identifier: MIT
// Multiresolution 2-maps in .cgmap files: regular and adaptive hierarchies
// come back equal at every level (relations dart by dart, f-vectors, lines
// and attribute values), go on as the saved ones, and broken files (labels,
// counters, types, truncations, any changed byte) are refused without
// touching the map.
#include <cgogn/core.h>
#include <cgogn/io.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <random>

namespace cgogn_test_mrmap2_file
{

using namespace cgogn;
using io_test::TempDir;

namespace
{

CMap2 icosahedron_with_positions()
{
	SurfaceSoup s;
	s.nb_vertices = 12;
	const double t = (1.0 + std::sqrt(5.0)) / 2.0;
	s.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
				   {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
	const uint32 f[20][3] = {{0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
							 {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
							 {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
	for (const auto& x : f)
	{
		s.face_sizes.push_back(3);
		s.face_vertices.insert(s.face_vertices.end(), {x[0], x[1], x[2]});
	}
	CMap2 m;
	io_test::build_with_positions(m, s);
	return m;
}

// Gives every vertex, edge and face of every level a value of its own at
// that level (the attributes must exist).
void write_values_at_every_level(MRMap2& m)
{
	auto pos = get_attribute<Vec3, MRMap2::Vertex>(m, "position");
	auto weight = get_attribute<int32, MRMap2::Edge>(m, "weight");
	auto area = get_attribute<double, MRMap2::Face>(m, "area");
	const uint32 current = current_level(m);
	int32 k = 0;
	for (uint32 l = 0; l <= max_level(m); ++l)
	{
		set_current_level(m, l);
		foreach_cell(m, [&](MRMap2::Vertex v) { value<Vec3>(m, *pos, v) += Vec3(0.0, 0.0, 0.001 * ++k); });
		foreach_cell(m, [&](MRMap2::Edge e) { value<int32>(m, *weight, e) = 1000 * int32(l) + ++k; });
		foreach_cell(m, [&](MRMap2::Face f) { value<double>(m, *area, f) = double(l) + 1e-3 * ++k; });
	}
	set_current_level(m, current);
}

// A regular hierarchy: an icosahedron and two Triangular levels, a position
// indexed before level 0 was made, a face attribute before the levels and
// an edge attribute after them (its orbit indexed late), values of their own
// at every level; read at level 1.
MRMap2 regular_hierarchy()
{
	MRMap2 m(icosahedron_with_positions());
	add_attribute<double, MRMap2::Face>(m, "area");
	add_level(m, Refinement::Triangular);
	add_level(m, Refinement::Triangular);
	add_attribute<int32, MRMap2::Edge>(m, "weight");
	add_attribute<Vec2, MRMap2::HalfEdge>(m, "uv");
	write_values_at_every_level(m);
	set_current_level(m, 1);
	return m;
}

// An adaptive hierarchy: a grid with boundary, faces subdivided to three
// levels with balance, then some coarsened again (free lines and free darts
// to keep in place); read at level 2.
MRMap2 adaptive_hierarchy()
{
	CMap2 base;
	io_test::build_with_positions(base, grid_soup(3, 3, false));
	MRMap2 m(std::move(base));
	add_attribute<int32, MRMap2::Edge>(m, "weight");
	add_attribute<double, MRMap2::Face>(m, "area");
	std::mt19937 rng(3);
	for (uint32 step = 0; step < 12; ++step)
	{
		set_current_level(m, max_level(m));
		std::vector<MRMap2::Face> leaves;
		foreach_cell(m, [&](MRMap2::Face f) {
			if (face_level(m, f) < 3)
				leaves.push_back(f);
		});
		subdivide_face(m, leaves[rng() % leaves.size()], step % 3 == 0 ? Refinement::Mixed : Refinement::Quadrangular);
	}
	uint32 coarsened = 0;
	for (uint32 l = max_level(m); l-- > 0 && coarsened < 2;)
	{
		set_current_level(m, l);
		std::vector<MRMap2::Face> faces;
		foreach_cell(m, [&](MRMap2::Face f) { faces.push_back(f); });
		for (MRMap2::Face f : faces)
			if (coarsened < 2 && can_coarsen_face(m, f))
			{
				coarsen_face(m, f);
				++coarsened;
			}
	}
	EXPECT_EQ(coarsened, 2u);
	EXPECT_GE(max_level(m), 2u);
	write_values_at_every_level(m);
	set_current_level(m, 2);
	return m;
}

// a and b are the same hierarchy: levels, counters, current level, and at
// every level the f-vector, phi1 and phi2 dart by dart, every dart's line
// of every indexed orbit, and the attribute values of every cell.
void expect_same_hierarchy(const MRMap2& a, const MRMap2& b)
{
	ASSERT_EQ(max_level(a), max_level(b));
	EXPECT_EQ(current_level(a), current_level(b));
	const CMap2& fa = finest_map(a);
	const CMap2& fb = finest_map(b);
	ASSERT_EQ(detail::state_of(fa).darts->end_index(), detail::state_of(fb).darts->end_index());
	EXPECT_EQ(detail::state_of(fa).darts->free_lines(), detail::state_of(fb).darts->free_lines());
	const auto pa = get_attribute<Vec3, MRMap2::Vertex>(a, "position");
	const auto pb = get_attribute<Vec3, MRMap2::Vertex>(b, "position");
	const auto wa = get_attribute<int32, MRMap2::Edge>(a, "weight");
	const auto wb = get_attribute<int32, MRMap2::Edge>(b, "weight");
	const auto aa = get_attribute<double, MRMap2::Face>(a, "area");
	const auto ab = get_attribute<double, MRMap2::Face>(b, "area");
	ASSERT_TRUE(pa && pb && wa && wb && aa && ab);
	for (uint32 l = 0; l <= max_level(a); ++l)
	{
		SCOPED_TRACE("level " + std::to_string(l));
		const MRLevelView2 va = level_view(a, l), vb = level_view(b, l);
		EXPECT_EQ(nb_darts_at_level(a, l), nb_darts_at_level(b, l));
		EXPECT_EQ(f_vector(va), f_vector(vb));
		uint32 nb = 0;
		foreach_dart(va, [&](Dart d) {
			++nb;
			EXPECT_TRUE(is_dart_valid(vb, d)) << "dart " << d.index;
			EXPECT_EQ(phi1(va, d), phi1(vb, d)) << "phi1 of dart " << d.index;
			EXPECT_EQ(phi2(va, d), phi2(vb, d)) << "phi2 of dart " << d.index;
			EXPECT_EQ(is_boundary(va, d), is_boundary(vb, d)) << "dart " << d.index;
			EXPECT_EQ(index_of(va, MRMap2::Vertex(d)), index_of(vb, MRMap2::Vertex(d))) << "dart " << d.index;
			EXPECT_EQ(index_of(va, MRMap2::Edge(d)), index_of(vb, MRMap2::Edge(d))) << "dart " << d.index;
			EXPECT_EQ(index_of(va, MRMap2::Face(d)), index_of(vb, MRMap2::Face(d))) << "dart " << d.index;
		});
		EXPECT_EQ(nb, nb_darts(vb));
		foreach_cell(va, [&](MRMap2::Vertex v) { EXPECT_EQ(value<Vec3>(va, *pa, v), value<Vec3>(vb, *pb, v)); });
		foreach_cell(va, [&](MRMap2::Edge e) { EXPECT_EQ(value<int32>(va, *wa, e), value<int32>(vb, *wb, e)); });
		foreach_cell(va, [&](MRMap2::Face f) { EXPECT_EQ(value<double>(va, *aa, f), value<double>(vb, *ab, f)); });
	}
	const IntegrityReport r = check_integrity(b);
	EXPECT_TRUE(r.ok()) << r.to_string();
	// and what the writer makes of both, byte for byte
	EXPECT_EQ(io::save_map_to_bytes(a), io::save_map_to_bytes(b));
}

MRMap2 round_trip(const MRMap2& m, const TempDir& dir)
{
	const std::string path = dir.file("m.cgmap");
	const io::MapFileReport report = io::save_map(m, path);
	EXPECT_TRUE(report.skipped.empty());
	EXPECT_EQ(io::read_map_header(path).map_type, "MRMap2");
	EXPECT_EQ(io::read_map_header(path).version, 1u);
	MRMap2 r{CMap2()};
	io::load_map(r, path);
	expect_same_hierarchy(m, r);
	return r;
}

// The message of the io::Error that loading `bytes` into an MRMap2 throws
// ("" when none); a failed load must leave the map as it was.
std::string load_error(std::string_view bytes)
{
	// one map for every call: a failed load leaves it as it was
	static MRMap2 m = regular_hierarchy();
	static const std::string before = io::save_map_to_bytes(m);
	try
	{
		io::load_map_from_bytes(m, bytes, "f.cgmap");
	}
	catch (const io::Error& e)
	{
		EXPECT_EQ(io::save_map_to_bytes(m), before) << "a failed load changed the map";
		EXPECT_EQ(current_level(m), 1u);
		EXPECT_TRUE(check_integrity(m).ok());
		return e.what();
	}
	return "";
}

// The offset of the values of attribute `name` in the first container that
// has it: the bytes of its default value come first.
std::size_t values_offset(const std::string& bytes, const std::string& name)
{
	const std::string key = std::string(1, char(name.size())) + std::string(3, '\0') + name;
	const std::size_t at = bytes.find(key);
	EXPECT_NE(at, std::string::npos) << name;
	// name, type string, payload size (uint64)
	const std::size_t type_at = at + key.size();
	const uint32 type_size = uint32(uint8(bytes[type_at]));
	return type_at + 4 + type_size + 8;
}

} // namespace

TEST(MRMap2File, RegularHierarchyRoundTripsAtEveryLevel)
{
	TempDir dir;
	const MRMap2 m = regular_hierarchy();
	ASSERT_EQ(max_level(m), 2u);
	MRMap2 r = round_trip(m, dir);
	// and in memory
	MRMap2 b{CMap2()};
	io::load_map_from_bytes(b, io::save_map_to_bytes(m));
	expect_same_hierarchy(m, b);
	EXPECT_EQ(f_vector(level_view(r, 2)), (std::vector<uint32>{162, 480, 320}));
}

TEST(MRMap2File, AdaptiveHierarchyRoundTripsAtEveryLevel)
{
	TempDir dir;
	const MRMap2 m = adaptive_hierarchy();
	ASSERT_FALSE(detail::state_of(finest_map(m)).darts->free_lines().empty()) << "coarsening leaves free darts";
	round_trip(m, dir);
}

TEST(MRMap2File, LoadedHierarchyGoesOnAsTheSavedOne)
{
	MRMap2 a = regular_hierarchy();
	MRMap2 b{CMap2()};
	io::load_map_from_bytes(b, io::save_map_to_bytes(a));
	// the same edits on both: a level more, values at the new level, a
	// level removed, adaptive steps; the same hierarchy after each
	add_level(a, Refinement::Triangular);
	add_level(b, Refinement::Triangular);
	expect_same_hierarchy(a, b);
	write_values_at_every_level(a);
	write_values_at_every_level(b);
	remove_finest_level(a);
	remove_finest_level(b);
	expect_same_hierarchy(a, b);
	for (MRMap2* m : {&a, &b})
	{
		set_current_level(*m, 2);
		std::vector<MRMap2::Face> faces;
		foreach_cell(*m, [&](MRMap2::Face f) { faces.push_back(f); });
		subdivide_face(*m, faces[5], Refinement::Triangular);
	}
	expect_same_hierarchy(a, b);
}

TEST(MRMap2File, FlatAndMultiresolutionFilesAreNotMixedUp)
{
	const MRMap2 m = regular_hierarchy();
	const std::string bytes = io::save_map_to_bytes(m);
	EXPECT_EQ(io::read_map_header_from_bytes(bytes).map_type, "MRMap2");
	CMap2 flat;
	EXPECT_THROW(io::load_map_from_bytes(flat, bytes), io::Error);
	EXPECT_NE(load_error(io::save_map_to_bytes(finest_map(m))).find("the file holds a CMap2, not a MRMap2"),
			  std::string::npos);
	EXPECT_EQ(load_error(bytes), "");
}

TEST(MRMap2File, ALabelThatBreaksALevelIsRefusedAtItsOffset)
{
	const MRMap2 m = regular_hierarchy();
	const std::string bytes = io::save_map_to_bytes(m);
	const std::size_t levels = values_offset(bytes, "__mr_level") + 1;
	// a dart of level 2 said to be of level 1: level 1 then holds a dart more
	// than its counter says
	Dart fine;
	foreach_dart(finest_map(m), [&](Dart d) {
		if (dart_level(m, d) == 2)
			fine = d;
		return !fine.is_valid();
	});
	std::string b = bytes;
	ASSERT_EQ(uint8(b[levels + fine.index]), 2u);
	b[levels + fine.index] = 1;
	std::string e = load_error(b);
	EXPECT_NE(e.find("f.cgmap: byte "), std::string::npos) << e;
	EXPECT_NE(e.find("level 1 counts"), std::string::npos) << e;
	// a dart above the finest level
	b = bytes;
	b[levels + fine.index] = 7;
	e = load_error(b);
	EXPECT_NE(e.find("byte " + std::to_string(levels + fine.index) + ": dart " + std::to_string(fine.index) +
					 " has level 7, above the finest level 2"),
			  std::string::npos)
		<< e;
	// two darts exchanging their levels: the counters agree, the levels break
	Dart coarse;
	foreach_dart(finest_map(m), [&](Dart d) {
		if (dart_level(m, d) == 1)
			coarse = d;
		return !coarse.is_valid();
	});
	b = bytes;
	std::swap(b[levels + fine.index], b[levels + coarse.index]);
	e = load_error(b);
	EXPECT_NE(e.find("the file's hierarchy is not valid"), std::string::npos) << e;
	EXPECT_NE(e.find("f.cgmap: byte "), std::string::npos) << e;
	// an edge id changed on one side of an edge
	const std::size_t ids = values_offset(bytes, "__mr_edge_id") + 1;
	b = bytes;
	b[ids + fine.index] = char((uint8(b[ids + fine.index]) + 1) % 3);
	e = load_error(b);
	// the error names the first of the edge's two darts
	const uint32 first = std::min(fine.index, phi2(finest_map(m), fine).index);
	EXPECT_NE(e.find("byte " + std::to_string(ids + first) + ": the file's hierarchy is not valid"), std::string::npos)
		<< e;
}

TEST(MRMap2File, WrongCountersAndLevelsAreRefused)
{
	const MRMap2 m = regular_hierarchy();
	const std::string bytes = io::save_map_to_bytes(m);
	// the block: after the magic, the version and the type "MRMap2"
	const std::size_t block = 8 + 4 + 4 + 6;
	ASSERT_EQ(uint8(bytes[block]), 3u);
	std::string b = bytes;
	b[block + 4 + 4] = char(uint8(b[block + 4 + 4]) + 1); // level 1 counts a dart more
	std::string e = load_error(b);
	EXPECT_NE(e.find("byte " + std::to_string(block + 8) + ": level 1 counts " +
					 std::to_string(nb_darts_at_level(m, 1) + 1) + " darts, but the darts' labels give " +
					 std::to_string(nb_darts_at_level(m, 1))),
			  std::string::npos)
		<< e;
	b = bytes;
	b[block + 16] = 3; // current level
	EXPECT_NE(load_error(b).find("current level 3 above the finest level 2"), std::string::npos);
	b = bytes;
	b[block] = 0;
	EXPECT_NE(load_error(b).find("0 levels"), std::string::npos);
	b = bytes;
	b[block] = 2; // a level less: the counters end early, the rest is read as containers
	EXPECT_NE(load_error(b), "");
}

TEST(MRMap2File, EveryTruncationIsAnError)
{
	MRMap2 m(icosahedron_with_positions());
	add_level(m, Refinement::Triangular);
	const std::string bytes = io::save_map_to_bytes(m);
	for (std::size_t n = 0; n < bytes.size(); n += 7)
		ASSERT_NE(load_error(std::string_view(bytes).substr(0, n)), "") << "prefix of " << n << " bytes";
}

TEST(MRMap2File, ChangedBytesAreRefusedOrGiveAValidHierarchy)
{
	// each byte changed in turn: the load throws io::Error, or gives a
	// hierarchy valid at every level (a changed value is still a hierarchy)
	CMap2 base;
	add_tetra(base);
	MRMap2 m(std::move(base));
	add_attribute<int32, MRMap2::Face>(m, "tag");
	add_level(m, Refinement::Triangular);
	add_attribute<uint8, MRMap2::Vertex>(m, "flag");
	const std::string bytes = io::save_map_to_bytes(m);
	uint32 refused = 0;
	for (std::size_t i = 0; i < bytes.size(); ++i)
	{
		// the lowest bit of even bytes, the highest of odd ones
		std::string b = bytes;
		b[i] = char(uint8(b[i]) ^ (i % 2 == 0 ? 1u : 0x80u));
		MRMap2 r{CMap2()};
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
	EXPECT_GT(refused, bytes.size() / 2); // most changes hit the structure
}

} // namespace cgogn_test_mrmap2_file
