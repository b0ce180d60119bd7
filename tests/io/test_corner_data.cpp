// SPDX-License-Identifier: MIT
// Per-corner data: OBJ texture coordinates and normals that differ between
// the corners of a vertex (UV seams, creases), and PLY's per-corner
// `texcoord`, load as dart attributes and are written back, to OBJ with one
// vt/vn line per distinct value.
#include <cgogn/cgogn.h>

#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <tuple>

namespace cgogn_test_corner_data
{

using namespace cgogn;
using namespace cgogn::io_test;

// A cube whose every face maps the whole texture (vt 1 to 4): each vertex
// has three corners of different texture coordinates. Flat normals (one vn
// per face): each vertex has three corners of different normals.
const char* const SEAMED_CUBE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
								"vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
								"vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n"
								"f 1/1/1 4/2/1 3/3/1 2/4/1\n"
								"f 5/1/2 6/2/2 7/3/2 8/4/2\n"
								"f 1/1/3 2/2/3 6/3/3 5/4/3\n"
								"f 2/1/4 3/2/4 7/3/4 6/4/4\n"
								"f 3/1/5 4/2/5 8/3/5 7/4/5\n"
								"f 4/1/6 1/2/6 5/3/6 8/4/6\n";

// Each corner of m: (its vertex's position, its face's centroid, the
// corner's tex_coord, its normal),
// sorted: equal lists mean the same data on the same corners, whatever the
// numbering.
using CornerRow =
	std::tuple<std::array<double, 3>, std::array<double, 3>, std::array<double, 2>, std::array<double, 3>>;
template <typename MAP>
std::vector<CornerRow> corners(const MAP& m)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	auto tex = get_attribute<Vec2, Cell<Orbit::DART>>(m, "tex_coord");
	auto normal = get_attribute<Vec3, Cell<Orbit::DART>>(m, "normal");
	std::vector<CornerRow> out;
	foreach_cell(m, [&](Face f) {
		// the face: its centroid (a G-map's face has two darts per corner)
		std::array<double, 3> face_sum{0, 0, 0};
		double nb = 0;
		foreach_dart_of_orbit(m, f, [&](Dart d) {
			for (int k = 0; k < 3; ++k)
				face_sum[std::size_t(k)] += (*pos)[Vertex(d)][k];
			++nb;
		});
		for (double& x : face_sum)
			x /= nb;
		foreach_dart_of_orbit(m, f, [&](Dart d) {
			const Vec3& p = (*pos)[Vertex(d)];
			CornerRow r{{p[0], p[1], p[2]}, face_sum, {0, 0}, {0, 0, 0}};
			if (tex)
				std::get<2>(r) = {(*tex)[d.index][0], (*tex)[d.index][1]};
			if (normal)
				std::get<3>(r) = {(*normal)[d.index][0], (*normal)[d.index][1], (*normal)[d.index][2]};
			out.push_back(r);
		});
	});
	std::sort(out.begin(), out.end());
	out.erase(std::unique(out.begin(), out.end()), out.end()); // a G-map's two darts of a corner
	return out;
}

TEST(CornerData, ObjSeamsLoadAsDartAttributes)
{
	TempDir dir;
	write_text(dir.file("cube.obj"), SEAMED_CUBE);
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, dir.file("cube.obj"));
	EXPECT_TRUE(r.dropped.empty());
	EXPECT_EQ((get_attribute<Vec2, CMap2::Vertex>(m, "tex_coord")), nullptr) << "a vertex has 3 texture coordinates";
	auto tex = get_attribute<Vec2, CMap2::HalfEdge>(m, "tex_coord");
	auto normal = get_attribute<Vec3, CMap2::HalfEdge>(m, "normal");
	ASSERT_NE(tex, nullptr);
	ASSERT_NE(normal, nullptr);
	// the corner of face 1 at vertex 4 has vt 2 = (1, 0); every normal is its face's
	auto pos = get_attribute<Vec3, CMap2::Vertex>(m, "position");
	uint32 checked = 0;
	foreach_cell(m, [&](CMap2::Face f) {
		const Vec3 n = geometry::face_normal(m, f, *pos);
		foreach_dart_of_orbit(m, f, [&](Dart d) {
			EXPECT_NEAR(((*normal)[d.index] - n).norm(), 0.0, 1e-12);
			if ((*pos)[CMap2::Vertex(d)] == Vec3(0, 1, 0) && std::abs(n.z() + 1) < 1e-12)
			{
				EXPECT_EQ((*tex)[d.index], Vec2(1, 0));
				++checked;
			}
		});
	});
	EXPECT_EQ(checked, 1u);
	EXPECT_TRUE(check_integrity(m).ok());
}

TEST(CornerData, ObjRoundTripKeepsEveryCornerWithSharedIndices)
{
	TempDir dir;
	write_text(dir.file("cube.obj"), SEAMED_CUBE);
	CMap2 m;
	io::load_surface(m, dir.file("cube.obj"));
	io::save_surface(m, dir.file("back.obj"));
	const std::string text = read_text(dir.file("back.obj"));
	auto count = [&](const char* prefix) {
		std::size_t n = 0, at = 0;
		while ((at = text.find(prefix, at)) != std::string::npos)
			++n, ++at;
		return n;
	};
	EXPECT_EQ(count("\nvt "), 4u) << "the 24 corners share the 4 texture coordinates";
	EXPECT_EQ(count("\nvn "), 6u) << "and the 6 normals";
	CMap2 back;
	io::load_surface(back, dir.file("back.obj"));
	EXPECT_EQ(corners(back), corners(m));
	EXPECT_EQ(corners(m).size(), 24u);
}

TEST(CornerData, PlyTexcoordRoundTripAndGMap2)
{
	TempDir dir;
	write_text(dir.file("cube.obj"), SEAMED_CUBE);
	CMap2 m;
	io::load_surface(m, dir.file("cube.obj"));
	for (bool binary : {false, true})
	{
		SCOPED_TRACE(binary ? "binary" : "ascii");
		io::SaveOptions o;
		o.binary = binary;
		io::save_surface(m, dir.file("cube.ply"), o);
		EXPECT_NE(read_text(dir.file("cube.ply")).find("texcoord"), std::string::npos);
		CMap2 back;
		const io::LoadReport r = io::load_surface(back, dir.file("cube.ply"));
		// PLY holds the texture coordinates per corner; the per-corner normals it cannot
		auto tex_only = [](std::vector<CornerRow> rows) {
			for (auto& row : rows)
				std::get<3>(row) = {0, 0, 0};
			std::sort(rows.begin(), rows.end());
			return rows;
		};
		EXPECT_EQ(corners(back), tex_only(corners(m)));
		EXPECT_TRUE(r.dropped.empty());
	}
	GMap2 g;
	io::load_surface(g, dir.file("cube.obj"));
	EXPECT_EQ(corners(g), corners(m));
	io::save_surface(g, dir.file("g.obj"));
	CMap2 from_g;
	io::load_surface(from_g, dir.file("g.obj"));
	EXPECT_EQ(corners(from_g), corners(m));
}

TEST(CornerData, PlyTexcoordOfTheWrongLengthIsRefused)
{
	TempDir dir;
	write_text(dir.file("bad.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
									"property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
									"property list uchar float texcoord\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
									"3 0 1 2 4 0 0 1 0\n");
	CMap2 m;
	try
	{
		io::load_surface(m, dir.file("bad.ply"));
		ADD_FAILURE() << "accepted";
	}
	catch (const io::Error& e)
	{
		EXPECT_NE(std::string(e.what()).find("4 texcoord values for 3 corners"), std::string::npos) << e.what();
	}
	EXPECT_EQ(nb_darts(m), 0u);
}

TEST(CornerData, PlyElementsAndListsNotLoadedAreReported)
{
	TempDir dir;
	write_text(dir.file("e.ply"), "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
								  "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
								  "property list uchar int flags\nelement edge 1\nproperty int vertex1\n"
								  "property int vertex2\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 7\n0 1\n");
	CMap2 m;
	const io::LoadReport r = io::load_surface(m, dir.file("e.ply"));
	ASSERT_EQ(r.dropped.size(), 2u);
	EXPECT_NE(r.dropped[0].find("list property 'flags'"), std::string::npos) << r.dropped[0];
	EXPECT_NE(r.dropped[1].find("element 'edge' (1)"), std::string::npos) << r.dropped[1];
}

} // namespace cgogn_test_corner_data
