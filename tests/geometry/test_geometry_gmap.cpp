// SPDX-License-Identifier: MIT
// The geometry functions on a GMap2 against the same functions on the CMap2
// of the same surface, cell by cell, and on non-orientable surfaces.
#include "geometry_test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <numbers>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace cgogn_test_geometry_gmap
{

using namespace cgogn;
using namespace cgogn::geometry;
using cgogn::test::Pos;

namespace
{

constexpr double pi = std::numbers::pi;

/// Builds the soup into a GMap2 and gives its vertices a "position" attribute.
Pos build_gmap_with_positions(GMap2& m, const SurfaceSoup& s)
{
	const BuildReport r = build_surface(m, s);
	Pos pos = add_attribute<Vec3, GMap2::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	return pos;
}

/// The soup with small deterministic displacements of its vertices (so that
/// no two corners, edges or vertices measure the same by symmetry).
SurfaceSoup jitter(SurfaceSoup s, double amount)
{
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		for (uint32 k = 0; k < 3; ++k)
			s.positions[i][k] += amount * test::noise(3 * i + k);
	return s;
}

/// The soup with every other face listed the other way round: the same
/// surface, whose GMap2 faces get darts of both orientations.
SurfaceSoup turn_every_other_face(SurfaceSoup s)
{
	uint32 first = 0;
	for (std::size_t f = 0; f < s.face_sizes.size(); ++f)
	{
		if (f % 2 == 1)
			std::reverse(s.face_vertices.begin() + first, s.face_vertices.begin() + first + s.face_sizes[f]);
		first += s.face_sizes[f];
	}
	return s;
}

/// Area of a soup polygon (half the norm of its Newell vector).
double soup_face_area(const SurfaceSoup& s, uint32 first, uint32 size)
{
	auto p = [&](uint32 k) {
		const auto& a = s.positions[s.face_vertices[first + k]];
		return Vec3(a[0], a[1], a[2]);
	};
	Vec3 n = Vec3::Zero();
	for (uint32 k = 0; k < size; ++k)
		n += p(k).cross(p((k + 1) % size));
	return 0.5 * n.norm();
}

double soup_area(const SurfaceSoup& s)
{
	double a = 0.0;
	uint32 first = 0;
	for (uint32 size : s.face_sizes)
	{
		a += soup_face_area(s, first, size);
		first += size;
	}
	return a;
}

/// The positions of the vertices of m, by line.
template <typename MAP>
std::map<uint32, Vec3> save_positions(const MAP& m, const AttributeArray<Vec3>& pos)
{
	std::map<uint32, Vec3> s;
	foreach_cell(m, [&](typename mesh_traits<MAP>::Vertex v) { s[index_of(m, v)] = value<Vec3>(m, pos, v); });
	return s;
}
void restore_positions(AttributeArray<Vec3>& pos, const std::map<uint32, Vec3>& s)
{
	for (const auto& [line, x] : s)
		pos[line] = x;
}

using EdgeKey = std::pair<uint32, uint32>;
using FaceKey = std::vector<uint32>;
using CornerKey = std::array<uint32, 3>; // three vertex lines
using WalkKey = std::array<uint32, 4>;   // four vertex lines along a face

/// A surface as a CMap2 and as a GMap2, with equal vertex lines, and the
/// matching of their cells: edges by their end lines, faces by their sets of
/// vertex lines.
struct Pair
{
	std::string name;
	CMap2 c;
	GMap2 g;
	Pos pc, pg;
	bool closed = false;
	/// the lines of the origins of d, phi1(d), phi1^2(d) and phi1^3(d) for
	/// every dart d of c, boundary darts included: a direction along a face
	/// (three vertices are not enough: a corner of degree 2 is seen the same
	/// way from its real face and, turned over, from the boundary face)
	std::set<WalkKey> c_darts;

	std::map<uint32, CMap2::Vertex> c_vertex;
	std::map<uint32, GMap2::Vertex> g_vertex;
	std::map<EdgeKey, CMap2::Edge> c_edge;
	std::map<EdgeKey, GMap2::Edge> g_edge;
	std::map<FaceKey, CMap2::Face> c_face;
	std::map<FaceKey, GMap2::Face> g_face;

	uint32 line(CMap2::Vertex v) const
	{
		return index_of(c, v);
	}
	uint32 line(GMap2::Vertex v) const
	{
		return index_of(g, v);
	}
	/// Whether the GMap2 dart d runs its face as the CMap2 does (the CMap2
	/// has the vertices of d, beta0(d) and the next two in this order).
	bool same_orientation(Dart d) const
	{
		WalkKey k;
		for (uint32 i = 0; i < 4; ++i, d = beta<0, 1>(g, d))
			k[i] = line(GMap2::Vertex(d));
		return c_darts.count(k) > 0;
	}

	void index_cells()
	{
		foreach_dart(c, [&](Dart d) {
			WalkKey k;
			for (uint32 i = 0; i < 4; ++i, d = phi1(c, d))
				k[i] = line(CMap2::Vertex(d));
			c_darts.insert(k);
			return true;
		});
		foreach_cell(c, [&](CMap2::Vertex v) { c_vertex[line(v)] = v; });
		foreach_cell(g, [&](GMap2::Vertex v) { g_vertex[line(v)] = v; });
		foreach_cell(c, [&](CMap2::Edge e) {
			c_edge[edge_key(line(CMap2::Vertex(e.dart)), line(CMap2::Vertex(phi1(c, e.dart))))] = e;
		});
		foreach_cell(g, [&](GMap2::Edge e) {
			g_edge[edge_key(line(GMap2::Vertex(e.dart)), line(GMap2::Vertex(beta0(g, e.dart))))] = e;
		});
		foreach_cell(c, [&](CMap2::Face f) {
			FaceKey k;
			foreach_incident_vertex(c, f, [&](CMap2::Vertex v) { k.push_back(line(v)); });
			std::sort(k.begin(), k.end());
			c_face[k] = f;
		});
		foreach_cell(g, [&](GMap2::Face f) {
			FaceKey k;
			foreach_incident_vertex(g, f, [&](GMap2::Vertex v) { k.push_back(line(v)); });
			std::sort(k.begin(), k.end());
			g_face[k] = f;
		});
	}

	static EdgeKey edge_key(uint32 a, uint32 b)
	{
		return {std::min(a, b), std::max(a, b)};
	}
};

enum class Variant
{
	ToGmap,      ///< the GMap2 converted from the CMap2 (to_gmap carries the positions)
	SameSoup,    ///< both built from the same soup
	TurnedFaces, ///< the GMap2 built from the soup with every other face turned over
};

std::unique_ptr<Pair> make_pair(const std::string& name, const SurfaceSoup& soup, Variant variant, bool closed)
{
	auto p = std::make_unique<Pair>();
	p->name = name;
	p->closed = closed;
	p->pc = test::build_with_positions(p->c, soup);
	switch (variant)
	{
	case Variant::ToGmap:
		p->g = to_gmap(p->c);
		p->pg = get_attribute<Vec3, GMap2::Vertex>(p->g, "position");
		break;
	case Variant::SameSoup:
		p->pg = build_gmap_with_positions(p->g, soup);
		break;
	case Variant::TurnedFaces:
		p->pg = build_gmap_with_positions(p->g, turn_every_other_face(soup));
		break;
	}
	p->index_cells();
	return p;
}

/// The orientable test surfaces, jittered, each with the three GMap2 variants.
std::vector<std::unique_ptr<Pair>> orientable_pairs()
{
	struct Mesh
	{
		std::string name;
		SurfaceSoup soup;
		bool closed;
	};
	std::vector<Mesh> meshes;
	meshes.push_back({"sphere quads", jitter(sphere_soup(10, 7), 0.02), true});
	meshes.push_back({"sphere triangles", jitter(sphere_soup(9, 6, true), 0.02), true});
	meshes.push_back({"torus quads", jitter(torus_soup(8, 6), 0.02), true});
	meshes.push_back({"torus triangles", jitter(torus_soup(7, 5, true), 0.02), true});
	meshes.push_back({"grid triangles", jitter(grid_soup(6, 5, true), 0.05), false});
	meshes.push_back({"grid quads", jitter(grid_soup(5, 4), 0.05), false});
	meshes.push_back({"cylinder quads", jitter(cylinder_soup(8, 3), 0.02), false});
	std::vector<std::unique_ptr<Pair>> pairs;
	for (const Mesh& mesh : meshes)
	{
		pairs.push_back(make_pair(mesh.name + " (to_gmap)", mesh.soup, Variant::ToGmap, mesh.closed));
		pairs.push_back(make_pair(mesh.name + " (same soup)", mesh.soup, Variant::SameSoup, mesh.closed));
		pairs.push_back(make_pair(mesh.name + " (turned faces)", mesh.soup, Variant::TurnedFaces, mesh.closed));
	}
	return pairs;
}

// Relative tolerance of the comparisons: the two maps sum the same terms,
// sometimes in another order.
constexpr double tol = 1e-12;

void expect_close(double a, double b, double scale = 1.0, double t = tol)
{
	EXPECT_NEAR(a, b, t * (scale + std::abs(b)));
}
void expect_close(const Vec3& a, const Vec3& b, double scale = 1.0, double t = tol)
{
	EXPECT_LE((a - b).norm(), t * (scale + b.norm())) << a.transpose() << " vs " << b.transpose();
}
/// a == b when `same`, a == -b otherwise.
void expect_signed(const Vec3& a, const Vec3& b, bool same, double t = tol)
{
	expect_close(same ? a : Vec3(-a), b, 1.0, t);
}

} // namespace

TEST(GeometryGMap, CellsMatch)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		ASSERT_EQ(p->c_vertex.size(), p->g_vertex.size());
		ASSERT_EQ(p->c_edge.size(), p->g_edge.size());
		ASSERT_EQ(p->c_face.size(), p->g_face.size());
		ASSERT_EQ(nb_cells<GMap2::Vertex>(p->g), p->g_vertex.size());
		ASSERT_EQ(nb_cells<GMap2::Edge>(p->g), p->g_edge.size());
		ASSERT_EQ(nb_cells<GMap2::Face>(p->g), p->g_face.size());
		EXPECT_TRUE(is_orientable(p->g));
		for (const auto& [l, v] : p->c_vertex)
			EXPECT_EQ(value<Vec3>(p->c, *p->pc, v), value<Vec3>(p->g, *p->pg, p->g_vertex.at(l)));
		for (const auto& [k, e] : p->c_edge)
			EXPECT_TRUE(p->g_edge.count(k));
		for (const auto& [k, f] : p->c_face)
			EXPECT_TRUE(p->g_face.count(k));
	}
}

TEST(GeometryGMap, LengthsAreasCentroidsBoxes)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		const CMap2& c = p->c;
		const GMap2& g = p->g;
		for (const auto& [k, e] : p->c_edge)
		{
			const GMap2::Edge ge = p->g_edge.at(k);
			expect_close(edge_length(g, ge, *p->pg), edge_length(c, e, *p->pc));
			expect_close(centroid(g, ge, *p->pg), centroid(c, e, *p->pc));
		}
		for (const auto& [k, f] : p->c_face)
		{
			const GMap2::Face gf = p->g_face.at(k);
			expect_close(face_area(g, gf, *p->pg), face_area(c, f, *p->pc));
			expect_close(centroid(g, gf, *p->pg), centroid(c, f, *p->pc));
		}
		expect_close(mean_edge_length(g, *p->pg), mean_edge_length(c, *p->pc));
		expect_close(surface_area(g, *p->pg), surface_area(c, *p->pc));
		expect_close(mean_position(g, *p->pg), mean_position(c, *p->pc));
		GMap2::Volume gw;
		foreach_cell(g, [&](GMap2::Volume w) { gw = w; });
		CMap2::Volume cw;
		foreach_cell(c, [&](CMap2::Volume w) { cw = w; });
		expect_close(centroid(g, gw, *p->pg), centroid(c, cw, *p->pc));
		const BoundingBox bg = bounding_box(g, *p->pg), bc = bounding_box(c, *p->pc);
		EXPECT_EQ(bg.min(), bc.min());
		EXPECT_EQ(bg.max(), bc.max());

		// the compute_ functions into attributes of the GMap2's cells
		auto gl = add_attribute<double, GMap2::Edge>(p->g, "length");
		compute_edge_lengths(g, *p->pg, *gl);
		auto ga = add_attribute<double, GMap2::Face>(p->g, "area");
		compute_face_areas(g, *p->pg, *ga);
		auto gc = add_attribute<Vec3, GMap2::Face>(p->g, "center");
		compute_centroids<GMap2::Face>(g, *p->pg, *gc);
		for (const auto& [k, e] : p->c_edge)
			expect_close(value<double>(g, gl, p->g_edge.at(k)), edge_length(c, e, *p->pc));
		for (const auto& [k, f] : p->c_face)
		{
			expect_close(value<double>(g, ga, p->g_face.at(k)), face_area(c, f, *p->pc));
			expect_close(value<Vec3>(g, gc, p->g_face.at(k)), centroid(c, f, *p->pc));
		}

		// the same vertex lines: the same numbering and Morton keys
		const VertexNumbering nc = vertex_numbering(c), ng = vertex_numbering(g);
		EXPECT_EQ(nc.line_of_dense_, ng.line_of_dense_);
		auto kc = add_attribute<uint64, CMap2::Vertex>(p->c, "key");
		auto kg = add_attribute<uint64, GMap2::Vertex>(p->g, "key");
		compute_morton_keys<CMap2::Vertex>(c, *p->pc, *kc);
		compute_morton_keys<GMap2::Vertex>(g, *p->pg, *kg);
		for (const auto& [l, v] : p->c_vertex)
			EXPECT_EQ(value<uint64>(c, kc, v), value<uint64>(g, kg, p->g_vertex.at(l)));
	}
}

TEST(GeometryGMap, FaceNormalsFollowTheFaceDart)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		const GMap2& g = p->g;
		auto gn = add_attribute<Vec3, GMap2::Face>(p->g, "normal");
		compute_face_normals(g, *p->pg, *gn);
		uint32 nb_same = 0, nb_turned = 0;
		for (const auto& [k, f] : p->c_face)
		{
			const GMap2::Face gf = p->g_face.at(k);
			const Vec3 nc = face_normal(p->c, f, *p->pc);
			const bool same = p->same_orientation(gf.dart);
			(same ? nb_same : nb_turned)++;
			expect_signed(face_normal(g, gf, *p->pg), nc, same);
			expect_signed(value<Vec3>(g, gn, gf), nc, same);
			// the other orientation of the face: beta0 turns it over
			expect_signed(face_normal(g, GMap2::Face(beta0(g, gf.dart)), *p->pg), nc, !same);
			expect_signed(newell_vector(g, *p->pg, gf.dart), newell_vector(p->c, *p->pc, f.dart), same);
		}
		EXPECT_GT(nb_same, 0u);
		if (p->name.find("turned") != std::string::npos)
		{
			EXPECT_GT(nb_turned, 0u);
		}
	}
}

TEST(GeometryGMap, VertexNormals)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		const GMap2& g = p->g;
		for (NormalWeighting w : {NormalWeighting::Uniform, NormalWeighting::Area, NormalWeighting::Angle})
		{
			auto nc = add_attribute<Vec3, CMap2::Vertex>(p->c, "vn");
			auto ng = add_attribute<Vec3, GMap2::Vertex>(p->g, "vn");
			compute_vertex_normals(p->c, *p->pc, *nc, w);
			compute_vertex_normals(g, *p->pg, *ng, w);
			for (const auto& [l, v] : p->c_vertex)
			{
				const GMap2::Vertex gv = p->g_vertex.at(l);
				const bool same = p->same_orientation(gv.dart);
				const Vec3 ref = vertex_normal(p->c, v, *p->pc, w);
				expect_signed(vertex_normal(g, gv, *p->pg, w), ref, same);
				expect_signed(value<Vec3>(g, ng, gv), value<Vec3>(p->c, nc, v), same);
				// a vertex seen from its other darts: the side of their face
				const GMap2::Vertex turned(beta1(g, gv.dart));
				expect_signed(vertex_normal(g, turned, *p->pg, w), ref, !same);
			}
			remove_attribute<CMap2::Vertex>(p->c, nc);
			remove_attribute<GMap2::Vertex>(p->g, ng);
		}
	}
}

TEST(GeometryGMap, Angles)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		const CMap2& c = p->c;
		const GMap2& g = p->g;
		// corner angles, matched by (vertex, its two neighbours in the face)
		std::map<CornerKey, double> corners;
		foreach_dart(c, [&](Dart d) {
			if (!is_boundary(c, d))
			{
				const uint32 a = p->line(CMap2::Vertex(phi1(c, d))), b = p->line(CMap2::Vertex(phi_1(c, d)));
				corners[{p->line(CMap2::Vertex(d)), std::min(a, b), std::max(a, b)}] = corner_angle(c, d, *p->pc);
			}
			return true;
		});
		uint32 nb = 0;
		foreach_dart(g, [&](Dart d) {
			if (!is_boundary(g, d))
			{
				const uint32 a = p->line(GMap2::Vertex(beta0(g, d))), b = p->line(GMap2::Vertex(beta0(g, beta1(g, d))));
				expect_close(corner_angle(g, d, *p->pg),
							 corners.at({p->line(GMap2::Vertex(d)), std::min(a, b), std::max(a, b)}));
				++nb;
			}
			return true;
		});
		EXPECT_EQ(nb, 2 * corners.size());

		auto ac = add_attribute<double, CMap2::Edge>(p->c, "dihedral");
		auto ag = add_attribute<double, GMap2::Edge>(p->g, "dihedral");
		compute_dihedral_angles(c, *p->pc, *ac);
		compute_dihedral_angles(g, *p->pg, *ag);
		for (const auto& [k, e] : p->c_edge)
		{
			const GMap2::Edge ge = p->g_edge.at(k);
			const double sign = p->same_orientation(ge.dart) ? 1.0 : -1.0;
			const double ref = dihedral_angle(c, e, *p->pc);
			expect_close(sign * dihedral_angle(g, ge, *p->pg), ref);
			expect_close(sign * value<double>(g, ag, ge), value<double>(c, ac, e));
			expect_close(-sign * dihedral_angle(g, GMap2::Edge(beta0(g, ge.dart)), *p->pg), ref);
			expect_close(sign * dihedral_angle(g, GMap2::Edge(beta2(g, ge.dart)), *p->pg), -ref);
		}
		for (const auto& [l, v] : p->c_vertex)
		{
			const GMap2::Vertex gv = p->g_vertex.at(l);
			expect_close(vertex_angle_sum(g, gv, *p->pg), vertex_angle_sum(c, v, *p->pc));
			expect_close(vertex_angle_sum(g, GMap2::Vertex(beta1(g, gv.dart)), *p->pg), vertex_angle_sum(c, v, *p->pc));
		}
	}
}

TEST(GeometryGMap, Curvatures)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		const CMap2& c = p->c;
		const GMap2& g = p->g;
		// curvatures divide by small areas: a looser tolerance
		constexpr double t = 1e-10;
		for (const auto& [l, v] : p->c_vertex)
		{
			const GMap2::Vertex gv = p->g_vertex.at(l);
			const bool same = p->same_orientation(gv.dart);
			const double sign = same ? 1.0 : -1.0;
			expect_close(voronoi_area(g, gv, *p->pg), voronoi_area(c, v, *p->pc));
			expect_close(angle_defect(g, gv, *p->pg), angle_defect(c, v, *p->pc));
			expect_close(gaussian_curvature(g, gv, *p->pg), gaussian_curvature(c, v, *p->pc), 1.0, t);
			expect_close(cotan_laplacian_of_position(g, gv, *p->pg), cotan_laplacian_of_position(c, v, *p->pc), 1.0, t);
			expect_close(sign * mean_curvature(g, gv, *p->pg), mean_curvature(c, v, *p->pc), 1.0, t);

			const PrincipalCurvatures kc = principal_curvatures(c, v, *p->pc);
			const PrincipalCurvatures kg = principal_curvatures(g, gv, *p->pg);
			expect_close(same ? kg.kmin : -kg.kmax, kc.kmin, 1.0, t);
			expect_close(same ? kg.kmax : -kg.kmin, kc.kmax, 1.0, t);
			if (kc.kmax - kc.kmin > 1e-3) // the directions are defined
			{
				EXPECT_NEAR(std::abs((same ? kg.dmin : kg.dmax).dot(kc.dmin)), 1.0, 1e-8);
				EXPECT_NEAR(std::abs((same ? kg.dmax : kg.dmin).dot(kc.dmax)), 1.0, 1e-8);
			}
		}
		auto ac = add_attribute<double, CMap2::Vertex>(p->c, "a");
		auto ag = add_attribute<double, GMap2::Vertex>(p->g, "a");
		auto hc = add_attribute<double, CMap2::Vertex>(p->c, "h");
		auto hg = add_attribute<double, GMap2::Vertex>(p->g, "h");
		auto kc = add_attribute<double, CMap2::Vertex>(p->c, "k");
		auto kg = add_attribute<double, GMap2::Vertex>(p->g, "k");
		auto ic = add_attribute<double, CMap2::Vertex>(p->c, "ki");
		auto ig = add_attribute<double, GMap2::Vertex>(p->g, "ki");
		auto k1c = add_attribute<double, CMap2::Vertex>(p->c, "kmin");
		auto k1g = add_attribute<double, GMap2::Vertex>(p->g, "kmin");
		auto k2c = add_attribute<double, CMap2::Vertex>(p->c, "kmax");
		auto k2g = add_attribute<double, GMap2::Vertex>(p->g, "kmax");
		auto d1c = add_attribute<Vec3, CMap2::Vertex>(p->c, "dmin");
		auto d1g = add_attribute<Vec3, GMap2::Vertex>(p->g, "dmin");
		auto d2c = add_attribute<Vec3, CMap2::Vertex>(p->c, "dmax");
		auto d2g = add_attribute<Vec3, GMap2::Vertex>(p->g, "dmax");
		compute_voronoi_areas(c, *p->pc, *ac);
		compute_voronoi_areas(g, *p->pg, *ag);
		compute_mean_curvatures(c, *p->pc, *hc);
		compute_mean_curvatures(g, *p->pg, *hg);
		compute_gaussian_curvatures(c, *p->pc, *kc);
		compute_gaussian_curvatures(g, *p->pg, *kg);
		compute_gaussian_curvatures(c, *p->pc, *ic, true);
		compute_gaussian_curvatures(g, *p->pg, *ig, true);
		compute_principal_curvatures(c, *p->pc, *k1c, *k2c, *d1c, *d2c);
		compute_principal_curvatures(g, *p->pg, *k1g, *k2g, *d1g, *d2g);
		double total = 0.0;
		for (const auto& [l, v] : p->c_vertex)
		{
			const GMap2::Vertex gv = p->g_vertex.at(l);
			const bool same = p->same_orientation(gv.dart);
			expect_close(value<double>(g, ag, gv), value<double>(c, ac, v));
			expect_close((same ? 1.0 : -1.0) * value<double>(g, hg, gv), value<double>(c, hc, v), 1.0, t);
			expect_close(value<double>(g, kg, gv), value<double>(c, kc, v), 1.0, t);
			expect_close(value<double>(g, ig, gv), value<double>(c, ic, v));
			expect_close(same ? value<double>(g, k1g, gv) : -value<double>(g, k2g, gv), value<double>(c, k1c, v), 1.0,
						 t);
			total += value<double>(g, ag, gv);
		}
		expect_close(total, surface_area(c, *p->pc));
	}
}

TEST(GeometryGMap, LaplacianMatrices)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		const VertexNumbering nc = vertex_numbering(p->c), ng = vertex_numbering(p->g);
		const SparseMatrix lc = cotan_laplacian(p->c, *p->pc, nc), lg = cotan_laplacian(p->g, *p->pg, ng);
		EXPECT_LE(SparseMatrix(lc - lg).norm(), tol * lc.norm());
		const SparseMatrix uc = uniform_laplacian(p->c, nc), ug = uniform_laplacian(p->g, ng);
		EXPECT_EQ(SparseMatrix(uc - ug).norm(), 0.0);
		const SparseMatrix mc = mass_matrix(p->c, *p->pc, nc), mg = mass_matrix(p->g, *p->pg, ng);
		EXPECT_LE(SparseMatrix(mc - mg).norm(), tol * mc.norm());
	}
}

TEST(GeometryGMap, Smoothing)
{
	for (const auto& p : orientable_pairs())
	{
		SCOPED_TRACE(p->name);
		auto run = [&](auto&& smooth_c, auto&& smooth_g, double t) {
			const auto c0 = save_positions(p->c, *p->pc), g0 = save_positions(p->g, *p->pg); // restored after
			smooth_c(*p->pc);
			smooth_g(*p->pg);
			for (const auto& [l, v] : p->c_vertex)
				expect_close(value<Vec3>(p->g, *p->pg, p->g_vertex.at(l)), value<Vec3>(p->c, *p->pc, v), 1.0, t);
			restore_positions(*p->pc, c0);
			restore_positions(*p->pg, g0);
		};
		run([&](AttributeArray<Vec3>& x) { laplacian_smoothing(p->c, x, 5, 0.5); },
			[&](AttributeArray<Vec3>& x) { laplacian_smoothing(p->g, x, 5, 0.5); }, tol);
		run([&](AttributeArray<Vec3>& x) { laplacian_smoothing(p->c, x, 3, 0.7, false); },
			[&](AttributeArray<Vec3>& x) { laplacian_smoothing(p->g, x, 3, 0.7, false); }, tol);
		run([&](AttributeArray<Vec3>& x) { taubin_smoothing(p->c, x, 4); },
			[&](AttributeArray<Vec3>& x) { taubin_smoothing(p->g, x, 4); }, tol);
		// the solvers see matrices equal up to rounding
		const double h2 = std::pow(mean_edge_length(p->c, *p->pc), 2);
		run([&](AttributeArray<Vec3>& x) { implicit_smoothing(p->c, x, h2, 2); },
			[&](AttributeArray<Vec3>& x) { implicit_smoothing(p->g, x, h2, 2); }, 1e-9);
		run([&](AttributeArray<Vec3>& x) { implicit_smoothing(p->c, x, 1.0, 1, true, false); },
			[&](AttributeArray<Vec3>& x) { implicit_smoothing(p->g, x, 1.0, 1, true, false); }, 1e-9);
		BilateralNormalFilteringParams bp;
		bp.normal_iterations = 5;
		bp.vertex_iterations = 3;
		run([&](AttributeArray<Vec3>& x) { bilateral_normal_filtering(p->c, x, bp); },
			[&](AttributeArray<Vec3>& x) { bilateral_normal_filtering(p->g, x, bp); }, 1e-9);
		bp.fix_boundary = false;
		bp.sigma_r = 0.2;
		run([&](AttributeArray<Vec3>& x) { bilateral_normal_filtering(p->c, x, bp); },
			[&](AttributeArray<Vec3>& x) { bilateral_normal_filtering(p->g, x, bp); }, 1e-9);
	}
}

TEST(GeometryGMap, Volumes)
{
	for (const auto& p : orientable_pairs())
	{
		if (!p->closed)
			continue;
		SCOPED_TRACE(p->name);
		// every component oriented as its smallest dart: the value of to_cmap
		const double v = signed_volume(p->c, *p->pc);
		EXPECT_GT(v, 0.0);
		expect_close(signed_volume(p->g, *p->pg), v);
		const CMap2 back = to_cmap(p->g);
		auto pb = get_attribute<Vec3, CMap2::Vertex>(back, "position");
		expect_close(signed_volume(back, *pb), signed_volume(p->g, *p->pg));
		// a component oriented as its dart
		foreach_cell(p->g, [&](GMap2::Volume w) {
			const double sign = p->same_orientation(w.dart) ? 1.0 : -1.0;
			expect_close(sign * volume(p->g, w, *p->pg), v);
			expect_close(-sign * volume(p->g, GMap2::Volume(beta0(p->g, w.dart)), *p->pg), v);
		});
	}
}

TEST(GeometryGMap, NonOrientableSurfaces)
{
	struct Mesh
	{
		std::string name;
		SurfaceSoup soup;
		bool closed;
		int64 chi;
	};
	std::vector<Mesh> meshes;
	// jittered: the Klein bottle's glued ring and the hemi-icosahedron have
	// faces folded flat onto each other, whose dihedral angle (pi) has no sign
	meshes.push_back({"klein bottle quads", jitter(klein_bottle_soup(8, 6), 0.02), true, 0});
	meshes.push_back({"klein bottle triangles", jitter(klein_bottle_soup(8, 6, true), 0.02), true, 0});
	meshes.push_back({"mobius quads", jitter(mobius_soup(12), 0.02), false, 0});
	meshes.push_back({"mobius triangles", jitter(mobius_soup(12, true), 0.02), false, 0});
	meshes.push_back({"hemi-icosahedron", jitter(hemi_icosahedron_soup(), 0.02), true, 1});
	for (const Mesh& mesh : meshes)
	{
		SCOPED_TRACE(mesh.name);
		GMap2 g;
		const Pos pos = build_gmap_with_positions(g, mesh.soup);
		ASSERT_FALSE(is_orientable(g));
		ASSERT_EQ(euler_characteristic(g), mesh.chi);
		const bool triangles = mesh.soup.face_sizes[0] == 3;

		// areas: the soup's, face by face and in total; the vertex areas share it
		const double area = soup_area(mesh.soup);
		expect_close(surface_area(g, *pos), area);
		double sum = 0.0, vertex_sum = 0.0;
		foreach_cell(g, [&](GMap2::Face f) { sum += face_area(g, f, *pos); });
		foreach_cell(g, [&](GMap2::Vertex v) { vertex_sum += voronoi_area(g, v, *pos); });
		expect_close(sum, area);
		expect_close(vertex_sum, area);
		EXPECT_GT(mean_edge_length(g, *pos), 0.0);

		// unit normals, opposite on the two orientations of a face or vertex
		foreach_cell(g, [&](GMap2::Face f) {
			const Vec3 n = face_normal(g, f, *pos);
			EXPECT_NEAR(n.norm(), 1.0, 1e-12);
			expect_close(face_normal(g, GMap2::Face(beta0(g, f.dart)), *pos), -n);
		});
		for (NormalWeighting w : {NormalWeighting::Uniform, NormalWeighting::Area, NormalWeighting::Angle})
		{
			auto vn = add_attribute<Vec3, GMap2::Vertex>(g, "vn");
			compute_vertex_normals(g, *pos, *vn, w);
			foreach_cell(g, [&](GMap2::Vertex v) {
				EXPECT_NEAR(value<Vec3>(g, vn, v).norm(), 1.0, 1e-12);
				expect_close(vertex_normal(g, GMap2::Vertex(beta1(g, v.dart)), *pos, w), -value<Vec3>(g, vn, v));
			});
			remove_attribute<GMap2::Vertex>(g, vn);
		}

		// discrete Gauss-Bonnet on triangles (any embedding: the angles of a
		// triangle add up to pi)
		if (triangles)
		{
			double defects = 0.0;
			foreach_cell(g, [&](GMap2::Vertex v) { defects += angle_defect(g, v, *pos); });
			EXPECT_NEAR(defects, 2.0 * pi * double(mesh.chi), 1e-9);
		}

		// the curvatures are finite; the cotangent Laplacian has zero row sums
		foreach_cell(g, [&](GMap2::Vertex v) {
			EXPECT_TRUE(std::isfinite(mean_curvature(g, v, *pos)));
			EXPECT_TRUE(std::isfinite(gaussian_curvature(g, v, *pos)));
			const PrincipalCurvatures k = principal_curvatures(g, v, *pos);
			EXPECT_LE(k.kmin, k.kmax);
			// turning the one-ring over: (-kmax, -kmin)
			const PrincipalCurvatures t = principal_curvatures(g, GMap2::Vertex(beta1(g, v.dart)), *pos);
			expect_close(t.kmin, -k.kmax, 1.0, 1e-10);
			expect_close(t.kmax, -k.kmin, 1.0, 1e-10);
		});
		const VertexNumbering num = vertex_numbering(g);
		const SparseMatrix L = cotan_laplacian(g, *pos, num);
		const Eigen::VectorXd ones = Eigen::VectorXd::Ones(num.size());
		EXPECT_LE((L * ones).norm(), 1e-10 * L.norm());
		const SparseMatrix M = mass_matrix(g, *pos, num);
		expect_close(Eigen::VectorXd(M.diagonal()).sum(), area);

		// the sign of a volume needs an orientation
		if (mesh.closed)
		{
			EXPECT_THROW(signed_volume(g, *pos), TopologyError);
			foreach_cell(g, [&](GMap2::Volume w) { EXPECT_THROW(volume(g, w, *pos), TopologyError); });
		}

		// flattened onto z = 0 (a flat immersion), the surface stays flat
		const auto p0 = save_positions(g, *pos);
		auto flatten = [&] {
			restore_positions(*pos, p0);
			foreach_cell(g, [&](GMap2::Vertex v) { value<Vec3>(g, *pos, v).z() = 0.0; });
		};
		auto expect_flat = [&](const char* what) {
			SCOPED_TRACE(what);
			foreach_cell(g, [&](GMap2::Vertex v) {
				const Vec3& x = value<Vec3>(g, *pos, v);
				EXPECT_TRUE(x.allFinite());
				EXPECT_NEAR(x.z(), 0.0, 1e-12);
			});
		};
		flatten();
		laplacian_smoothing(g, *pos, 10, 0.5, false);
		expect_flat("laplacian_smoothing");
		flatten();
		taubin_smoothing(g, *pos, 5, 0.5, -0.53, false);
		expect_flat("taubin_smoothing");
		flatten();
		implicit_smoothing(g, *pos, 1.0, 2, true, false);
		expect_flat("implicit_smoothing");
		flatten();
		BilateralNormalFilteringParams bp;
		bp.fix_boundary = false;
		bp.normal_iterations = 3;
		bp.vertex_iterations = 3;
		bilateral_normal_filtering(g, *pos, bp);
		expect_flat("bilateral_normal_filtering");

		// on the surface itself the filters keep finite positions
		restore_positions(*pos, p0);
		bilateral_normal_filtering(g, *pos);
		implicit_smoothing(g, *pos, std::pow(mean_edge_length(g, *pos), 2));
		foreach_cell(g, [&](GMap2::Vertex v) { EXPECT_TRUE(value<Vec3>(g, *pos, v).allFinite()); });
	}
}

} // namespace cgogn_test_geometry_gmap
