// SPDX-License-Identifier: MIT
// Multiresolution 3-maps in .cgmap files: regular and adaptive hierarchies
// come back equal at every level, and broken face ids, types and
// truncations are refused without touching the map.
#include <cgogn/core.h>
#include <cgogn/geometry/types/vector_traits.h>
#include <cgogn/io.h>

#include "cgogn_test_data.h"
#include "io_test_utils.h"
#include "volume_test_meshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

namespace cgogn_test_mrmap3_file
{

using namespace cgogn;
using io_test::TempDir;

namespace
{

MRMap3 grid_hierarchy(uint32 a, uint32 b, uint32 c)
{
	MRMap3 m(test::hex_grid_with_positions(a, b, c));
	add_attribute<int32, MRMap3::Volume>(m, "tag");
	return m;
}

// Gives every volume and edge of every level a value of its own there.
void write_values(MRMap3& m)
{
	auto tag = get_attribute<int32, MRMap3::Volume>(m, "tag");
	auto weight = get_attribute<double, MRMap3::Edge>(m, "weight");
	const uint32 current = current_level(m);
	int32 k = 0;
	for (uint32 l = 0; l <= max_level(m); ++l)
	{
		set_current_level(m, l);
		foreach_cell(m, [&](MRMap3::Volume w) { value<int32>(m, *tag, w) = 1000 * int32(l) + ++k; });
		foreach_cell(m, [&](MRMap3::Edge e) { value<double>(m, *weight, e) = double(l) + 1e-3 * ++k; });
	}
	set_current_level(m, current);
}

// Two regular levels of a 2 x 1 x 1 grid; an edge attribute added after
// them; read at level 1.
MRMap3 regular_hierarchy()
{
	MRMap3 m = grid_hierarchy(2, 1, 1);
	add_level(m, Refinement::Hexahedral);
	add_level(m, Refinement::Hexahedral);
	add_attribute<double, MRMap3::Edge>(m, "weight");
	write_values(m);
	set_current_level(m, 1);
	return m;
}

// A 2 x 2 x 1 grid refined hexahedron by hexahedron, then partly coarsened
// (free darts and lines kept in place); read at level 1.
MRMap3 adaptive_hierarchy()
{
	MRMap3 m = grid_hierarchy(2, 2, 1);
	add_attribute<double, MRMap3::Edge>(m, "weight");
	for (uint32 k = 0; k < 2; ++k)
	{
		set_current_level(m, k);
		std::vector<MRMap3::Volume> ws;
		foreach_cell(m, [&](MRMap3::Volume w) {
			if (volume_level(m, w) == k)
				ws.push_back(w);
		});
		subdivide_volume(m, ws.front());
	}
	set_current_level(m, 1);
	std::vector<MRMap3::Volume> ws;
	foreach_cell(m, [&](MRMap3::Volume w) { ws.push_back(w); });
	uint32 coarsened = 0;
	for (MRMap3::Volume w : ws)
		if (can_coarsen_volume(m, w))
		{
			coarsen_volume(m, w);
			++coarsened;
		}
	EXPECT_EQ(coarsened, 1u);
	subdivide_volume(m, ws.back());
	EXPECT_EQ(max_level(m), 2u);
	write_values(m);
	set_current_level(m, 1);
	return m;
}

void expect_same_hierarchy(const MRMap3& a, const MRMap3& b)
{
	ASSERT_EQ(max_level(a), max_level(b));
	EXPECT_EQ(current_level(a), current_level(b));
	const auto pa = get_attribute<Vec3, MRMap3::Vertex>(a, "position");
	const auto pb = get_attribute<Vec3, MRMap3::Vertex>(b, "position");
	const auto ta = get_attribute<int32, MRMap3::Volume>(a, "tag");
	const auto tb = get_attribute<int32, MRMap3::Volume>(b, "tag");
	const auto wa = get_attribute<double, MRMap3::Edge>(a, "weight");
	const auto wb = get_attribute<double, MRMap3::Edge>(b, "weight");
	ASSERT_TRUE(pa && pb && ta && tb && wa && wb);
	for (uint32 l = 0; l <= max_level(a); ++l)
	{
		SCOPED_TRACE("level " + std::to_string(l));
		const MRLevelView3 va = level_view(a, l), vb = level_view(b, l);
		EXPECT_EQ(nb_darts_at_level(a, l), nb_darts_at_level(b, l));
		EXPECT_EQ(f_vector(va), f_vector(vb));
		foreach_dart(va, [&](Dart d) {
			EXPECT_EQ(phi1(va, d), phi1(vb, d)) << "phi1 of dart " << d.index;
			EXPECT_EQ(phi2(va, d), phi2(vb, d)) << "phi2 of dart " << d.index;
			EXPECT_EQ(phi3(va, d), phi3(vb, d)) << "phi3 of dart " << d.index;
			EXPECT_EQ(index_of(va, MRMap3::Vertex(d)), index_of(vb, MRMap3::Vertex(d))) << "dart " << d.index;
			EXPECT_EQ(index_of(va, MRMap3::Edge(d)), index_of(vb, MRMap3::Edge(d))) << "dart " << d.index;
		});
		foreach_cell(va, [&](MRMap3::Vertex v) { EXPECT_EQ(value<Vec3>(va, *pa, v), value<Vec3>(vb, *pb, v)); });
		foreach_cell(va, [&](MRMap3::Volume w) { EXPECT_EQ(value<int32>(va, *ta, w), value<int32>(vb, *tb, w)); });
		foreach_cell(va, [&](MRMap3::Edge e) { EXPECT_EQ(value<double>(va, *wa, e), value<double>(vb, *wb, e)); });
	}
	const IntegrityReport r = check_integrity(b);
	EXPECT_TRUE(r.ok()) << r.to_string();
	EXPECT_EQ(io::save_map_to_bytes(a), io::save_map_to_bytes(b));
}

// The offset of the values of attribute `name` in the first container that
// has it (after its default value).
std::size_t label_values(const std::string& bytes, const std::string& name)
{
	const std::string key = std::string(1, char(name.size())) + std::string(3, '\0') + name;
	const std::size_t at = bytes.find(key);
	EXPECT_NE(at, std::string::npos) << name;
	const std::size_t type_at = at + key.size();
	return type_at + 4 + uint32(uint8(bytes[type_at])) + 8 + 1;
}

/// The sum of the volumes of the cells of a map of triangles, each from its
/// triangles (divergence): the volume of the mesh when the cells neither
/// overlap nor turn over.
double sum_of_cell_volumes(const CMap3& m)
{
	const auto pos = get_attribute<Vec3, CMap3::Vertex>(m, "position");
	double sum = 0;
	foreach_cell(m, [&](CMap3::Volume w) {
		double sixfold = 0;
		foreach_dart_of_orbit(m, w, [&](Dart x) {
			const Vec3& a = value<Vec3>(m, *pos, CMap3::Vertex(x));
			const Vec3& b = value<Vec3>(m, *pos, CMap3::Vertex(phi1(m, x)));
			const Vec3& c = value<Vec3>(m, *pos, CMap3::Vertex(phi_1(m, x)));
			sixfold += a.dot(b.cross(c)) / 3; // each triangle is met from its 3 darts
		});
		sum += std::abs(sixfold) / 6;
	});
	return sum;
}

} // namespace

TEST(MRMap3File, TetraOctaLevelOfATetrahedralMeshRoundTrips)
{
	CMap3 base;
	io::load_volume(base, cgogn_test_data::path("volume/armadillo_tet_4k.mesh"));
	MRMap3 m(std::move(base));
	add_attribute<int32, MRMap3::Volume>(m, "tag");
	const std::vector<uint32> c0 = f_vector(m);
	add_level(m, Refinement::TetraOcta);
	add_attribute<double, MRMap3::Edge>(m, "weight");
	write_values(m);
	const IntegrityReport r = check_integrity(m);
	ASSERT_TRUE(r.ok()) << r.to_string();
	// every edge cut, every triangle cut in 4, every tetrahedron into 4
	// tetrahedra and an octahedron (4 inner triangles)
	EXPECT_EQ(f_vector(m),
			  (std::vector<uint32>{c0[0] + c0[1], 2 * c0[1] + 3 * c0[2], 4 * c0[2] + 4 * c0[3], 5 * c0[3]}));
	// the cells of level 1 fill the mesh without overlapping
	const double v0 = sum_of_cell_volumes(extract_level(m, 0)), v1 = sum_of_cell_volumes(extract_level(m, 1));
	EXPECT_NEAR(v1, v0, 1e-12 * v0);
	MRMap3 back{CMap3()};
	io::load_map_from_bytes(back, io::save_map_to_bytes(m));
	expect_same_hierarchy(m, back);
}

TEST(MRMap3File, RegularAndAdaptiveHierarchiesRoundTripAtEveryLevel)
{
	TempDir dir;
	for (MRMap3 (*make)() : {&regular_hierarchy, &adaptive_hierarchy})
	{
		const MRMap3 m = make();
		const std::string path = dir.file("h.cgmap");
		EXPECT_TRUE(io::save_map(m, path).skipped.empty());
		EXPECT_EQ(io::read_map_header(path).map_type, "MRMap3");
		MRMap3 r{CMap3()};
		io::load_map(r, path);
		expect_same_hierarchy(m, r);
		// and the loaded one goes on as the saved one
		MRMap3 a{CMap3()}, b{CMap3()};
		io::load_map_from_bytes(a, io::save_map_to_bytes(m));
		io::load_map_from_bytes(b, io::save_map_to_bytes(m));
		for (MRMap3* x : {&a, &b})
		{
			set_current_level(*x, max_level(*x) - 1);
			std::vector<MRMap3::Volume> ws;
			foreach_cell(*x, [&](MRMap3::Volume w) {
				if (can_coarsen_volume(*x, w))
					ws.push_back(w);
			});
			ASSERT_FALSE(ws.empty());
			coarsen_volume(*x, ws.front());
		}
		expect_same_hierarchy(a, b);
	}
}

TEST(MRMap3File, BrokenFilesAreRefusedAndTheMapKept)
{
	const MRMap3 m = regular_hierarchy();
	const std::string bytes = io::save_map_to_bytes(m);
	MRMap3 target = adaptive_hierarchy();
	const std::string before = io::save_map_to_bytes(target);
	const auto load_error = [&](const std::string& b) -> std::string {
		try
		{
			io::load_map_from_bytes(target, b, "f.cgmap");
		}
		catch (const io::Error& e)
		{
			EXPECT_EQ(io::save_map_to_bytes(target), before) << "a failed load changed the map";
			return e.what();
		}
		return "";
	};
	// a face id changed on one side of a face, at its offset
	const std::size_t ids = label_values(bytes, "__mr_face_id");
	Dart d;
	foreach_dart(finest_map(m), [&](Dart x) {
		d = x;
		return dart_level(m, x) < 2;
	});
	std::string b = bytes;
	b[ids + d.index] = char(uint8(b[ids + d.index]) + 7);
	std::string e = load_error(b);
	EXPECT_NE(e.find("f.cgmap: byte "), std::string::npos) << e;
	EXPECT_NE(e.find("the file's hierarchy is not valid"), std::string::npos) << e;
	// a file of the finest map alone, a truncated file
	e = load_error(io::save_map_to_bytes(finest_map(m)));
	EXPECT_NE(e.find("the file holds a CMap3, not a MRMap3"), std::string::npos) << e;
	for (std::size_t cut : {std::size_t(10), bytes.size() / 2, bytes.size() - 1})
		EXPECT_NE(load_error(bytes.substr(0, cut)), "") << "cut at " << cut;
	CMap3 flat;
	EXPECT_THROW(io::load_map_from_bytes(flat, bytes), io::Error);
	// and the file itself loads
	EXPECT_EQ(load_error(bytes), "");
	EXPECT_EQ(max_level(target), 2u);
}

} // namespace cgogn_test_mrmap3_file
