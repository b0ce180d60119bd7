#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "io_test_utils.h"

#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

namespace cgogn_test_incidence_graph_io
{

using namespace cgogn;
using cgogn::io_test::read_text;
using cgogn::io_test::TempDir;
using cgogn::io_test::write_text;
using IG = IncidenceGraph;

std::string data(const std::string& name)
{
	return cgogn_test_data::path("surface/" + name);
}

// What a surface file holds: positions in order, faces as vertex lists.
struct Soup
{
	std::vector<Vec3> positions;
	std::vector<std::vector<uint32>> faces;
	bool operator==(const Soup&) const = default;
};

Soup soup_of(const IG& ig)
{
	Soup s;
	auto pos = get_attribute<Vec3, IG::Vertex>(ig, "position");
	std::vector<uint32> id(container_of<Orbit::IG_VERTEX>(ig).end_index());
	foreach_cell(ig, [&](IG::Vertex v) {
		id[v.dart.index] = uint32(s.positions.size());
		s.positions.push_back(value<Vec3>(ig, pos, v));
	});
	foreach_cell(ig, [&](IG::Face f) {
		s.faces.emplace_back();
		foreach_incident_vertex(ig, f, [&](IG::Vertex v) { s.faces.back().push_back(id[v.dart.index]); });
	});
	return s;
}

struct Expected
{
	const char* file;
	uint32 v, e, f;
	int64 chi;
	uint32 non_manifold_edges;
};

TEST(IncidenceGraphFiles, NonManifoldFilesLoadWithTheirTrueCounts)
{
	for (const Expected& x : {Expected{"icositetrachoron_2skeleton.off", 24, 96, 96, 24, 96},
							  Expected{"geomview_simplex_2skeleton.off", 5, 10, 10, 5, 10},
							  Expected{"geomview_orthoplex_2skeleton.off", 8, 24, 32, 16, 24},
							  Expected{"geomview_hypercube_2skeleton.off", 16, 32, 24, 8, 32},
							  Expected{"geomview_tetraplex_2skeleton.off", 120, 720, 1200, 600, 720},
							  Expected{"geomview_cam.off", 5, 6, 2, 1, 0}})
	{
		SCOPED_TRACE(x.file);
		IG ig;
		const io::LoadReport r = io::load_surface(ig, data(x.file));
		EXPECT_TRUE(check_integrity(ig).ok());
		EXPECT_EQ(nb_cells<IG::Vertex>(ig), x.v);
		EXPECT_EQ(nb_cells<IG::Edge>(ig), x.e);
		EXPECT_EQ(nb_cells<IG::Face>(ig), x.f);
		EXPECT_EQ(euler_characteristic(ig), x.chi);
		EXPECT_EQ(nb_non_manifold_edges(ig), x.non_manifold_edges);
		EXPECT_EQ(nb_connected_components(ig), 1u);
		EXPECT_EQ(r.nb_cells_built, x.f);
		EXPECT_EQ(r.nb_cells_skipped, 0u);
	}
	// the bow tie: one vertex where two fans meet
	IG cam;
	io::load_surface(cam, data("geomview_cam.off"));
	EXPECT_EQ(nb_non_manifold_vertices(cam), 1u);
}

TEST(IncidenceGraphFiles, SurfaceFormatsRoundTripExactly)
{
	TempDir dir;
	for (const char* file : {"icositetrachoron_2skeleton.off", "geomview_hypercube_2skeleton.off", "Wuson.off",
							 "mobius_strip.off", "suzanne.obj"})
	{
		SCOPED_TRACE(file);
		IG ig;
		io::load_surface(ig, data(file));
		const Soup original = soup_of(ig);
		for (const char* ext : {".off", ".obj", ".ply"})
		{
			SCOPED_TRACE(ext);
			const std::string out = dir.file(std::string("copy") + ext);
			io::save_surface(ig, out);
			IG back;
			io::load_surface(back, out);
			EXPECT_EQ(soup_of(back), original);
		}
		const std::string out = dir.file("copy.ig");
		io::save_incidence_graph(ig, out);
		IG back;
		const io::IncidenceGraphLoadReport r = io::load_incidence_graph(back, out);
		EXPECT_EQ(r.nb_faces_read, nb_cells<IG::Face>(ig));
		EXPECT_TRUE(check_integrity(back).ok());
		EXPECT_EQ(soup_of(back), original);
		EXPECT_EQ(nb_cells<IG::Edge>(back), nb_cells<IG::Edge>(ig));
	}
}

TEST(IncidenceGraphFiles, IgKeepsWiresAndIsolatedVertices)
{
	TempDir dir;
	IG ig;
	auto pos = add_attribute<Vec3, IG::Vertex>(ig, "position");
	std::vector<IG::Vertex> v;
	for (int i = 0; i < 6; ++i)
	{
		v.push_back(add_vertex(ig));
		value<Vec3>(ig, pos, v.back()) = Vec3(0.1 * i, 1.0 / 3.0, -2.5e-7 * i);
	}
	const std::vector<IG::Vertex> tri = {v[2], v[1], v[0]};
	add_face_through_vertices(ig, tri);
	add_edge(ig, v[2], v[3]); // a wire; v[4] and v[5] alone
	const std::string out = dir.file("wire.ig");
	io::save_incidence_graph(ig, out);
	IG back;
	io::load_incidence_graph(back, out);
	EXPECT_EQ(nb_cells<IG::Vertex>(back), 6u);
	EXPECT_EQ(nb_cells<IG::Edge>(back), 4u);
	EXPECT_EQ(nb_cells<IG::Face>(back), 1u);
	EXPECT_EQ(soup_of(back), soup_of(ig)); // positions bit for bit, the face's orientation
	EXPECT_EQ(nb_connected_components(back), 3u);
}

TEST(IncidenceGraphFiles, MalformedIgFilesGiveTypedErrorsAndChangeNothing)
{
	TempDir dir;
	const std::string ok_head = "IG 3 3 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\ne 0 1\ne 1 2\ne 2 0\n";
	const std::vector<std::pair<std::string, std::string>> cases = {
		{"header", "IX 3 3 1\n"},
		{"vertex range", "IG 3 3 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\ne 0 1\ne 1 3\ne 2 0\n"},
		{"loop edge", "IG 3 1 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\ne 1 1\n"},
		{"edge range", ok_head + "f 3 0 1 7\n"},
		{"short face", ok_head + "f 2 0 1\n"},
		{"not a cycle", ok_head + "f 3 0 0 1\n"},
		{"count", ok_head + "f 3 0 1 2\nf 3 0 1 2\n"},
		{"nan", "IG 1 0 0\nv nan 0 0\n"},
		{"missing", ok_head},
	};
	for (const auto& [what, text] : cases)
	{
		SCOPED_TRACE(what);
		const std::string path = dir.file("bad.ig");
		write_text(path, text);
		IG ig;
		add_vertex(ig);
		try
		{
			io::load_incidence_graph(ig, path);
			ADD_FAILURE() << "no error";
		}
		catch (const io::Error& e)
		{
			EXPECT_NE(std::string(e.what()).find("bad.ig"), std::string::npos) << e.what();
		}
		EXPECT_EQ(nb_cells<IG::Vertex>(ig), 1u);
		EXPECT_EQ(nb_cells<IG::Edge>(ig), 0u);
	}
	write_text(dir.file("good.ig"), ok_head + "# a comment\nf 3 2 1 0\n");
	IG ig;
	io::load_incidence_graph(ig, dir.file("good.ig"));
	EXPECT_EQ(nb_cells<IG::Face>(ig), 1u);
}

// CMap2 -> IncidenceGraph -> CMap2 is the identity on every manifold
// (orientable) test mesh: the counts, the darts, and each face with its
// vertices' positions and its attributes.
TEST(IncidenceGraphFiles, CMap2RoundTripOnEveryManifoldMesh)
{
	using Face2 = CMap2::Face;
	for (const char* file : {"hemisphere.off", "fandisk_quads.off", "spot_quadrangulated.obj", "spot_control_mesh.obj",
							 "suzanne.obj", "torus_quad.off", "cube_quad.off", "tetrahedron.off", "triangle.off",
							 "L.off", "vertex_onering.off", "edge_onering.off", "elephant-with-holes.off"})
	{
		SCOPED_TRACE(file);
		CMap2 m;
		const io::LoadReport lr = io::load_surface(m, data(file));
		ASSERT_TRUE(lr.manifold() && lr.orientable);
		auto tag = add_attribute<int, Face2>(m, "tag");
		int k = 0;
		foreach_cell(m, [&](Face2 f) { value<int>(m, tag, f) = k++; });
		const IncidenceGraph ig = to_incidence_graph(m);
		ASSERT_TRUE(check_integrity(ig).ok());
		EXPECT_EQ(nb_non_manifold_edges(ig), 0u);
		BuildReport report;
		const CMap2 back = to_cmap2(ig, &report);
		ASSERT_TRUE(check_integrity(back).ok());
		EXPECT_EQ(report.nb_nonmanifold_edges, 0u);
		EXPECT_TRUE(report.split_vertices.empty());
		EXPECT_EQ(nb_darts(back), nb_darts(m));
		EXPECT_EQ(nb_cells<CMap2::Vertex>(back), nb_cells<CMap2::Vertex>(m));
		EXPECT_EQ(nb_cells<CMap2::Edge>(back), nb_cells<CMap2::Edge>(m));
		EXPECT_EQ(nb_cells<Face2>(back), nb_cells<Face2>(m));
		EXPECT_EQ(nb_boundary_components(back), nb_boundary_components(m));
		// each face by its tag: the positions of its vertices in cycle order
		auto faces = [](const CMap2& map) {
			auto pos = get_attribute<Vec3, CMap2::Vertex>(map, "position");
			auto t = get_attribute<int, Face2>(map, "tag");
			std::map<int, std::vector<Vec3>> out;
			foreach_cell(map, [&](Face2 f) {
				auto& ps = out[value<int>(map, t, f)];
				foreach_incident_vertex(map, f, [&](CMap2::Vertex v) { ps.push_back(value<Vec3>(map, pos, v)); });
			});
			return out;
		};
		ASSERT_TRUE((get_attribute<int, Face2>(back, "tag")));
		EXPECT_EQ(faces(back), faces(m));
	}
}

TEST(IncidenceGraphFiles, ToCMap2RepairsWhatAMapCannotHold)
{
	IG ig;
	io::load_surface(ig, data("icositetrachoron_2skeleton.off"));
	BuildReport report;
	const CMap2 m = to_cmap2(ig, &report);
	EXPECT_TRUE(check_integrity(m).ok());
	EXPECT_EQ(nb_cells<CMap2::Face>(m), 96u);
	EXPECT_GT(report.nb_nonmanifold_edges, 0u);
	// the torn 2-map: faces detached along every edge past the second, vertices split
	EXPECT_EQ(nb_cells<CMap2::Vertex>(m), 192u);
	EXPECT_EQ(nb_cells<CMap2::Edge>(m), 240u);
	// a manifold file: exact
	IG sphere;
	io::load_surface(sphere, data("hemisphere.off"));
	BuildReport exact;
	const CMap2 h = to_cmap2(sphere, &exact);
	EXPECT_EQ(exact.nb_nonmanifold_edges, 0u);
	EXPECT_TRUE(exact.split_vertices.empty());
	EXPECT_EQ(nb_cells<CMap2::Vertex>(h), nb_cells<IG::Vertex>(sphere));
	EXPECT_EQ(nb_cells<CMap2::Edge>(h), nb_cells<IG::Edge>(sphere));
	CMap2 loaded;
	io::load_surface(loaded, data("hemisphere.off"));
	EXPECT_EQ(nb_cells<CMap2::Edge>(loaded), nb_cells<CMap2::Edge>(h));
}

} // namespace cgogn_test_incidence_graph_io
