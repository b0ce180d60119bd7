// SPDX-License-Identifier: MIT
// From an incidence graph (its faces and wires) or a graph (its edges, as
// tubes or lines) to a Scene.
#include <cgogn/core/properties/incidence_graph_properties.h>
#include <cgogn/core/traversals/local_graph.h>
#include <cgogn/core/traversals/local_incidence_graph.h>

#include "extract.h"

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace cgogn::render
{

namespace
{

using detail::Scene;

Eigen::Vector3f unit_or_zero(const Vec3& v)
{
	const double l = v.norm();
	return l > 0.0 ? Eigen::Vector3f((v / l).cast<float>()) : Eigen::Vector3f::Zero();
}

void check_finite(const Vec3& p, uint32 line)
{
	if (!p.allFinite())
		throw RenderError("vertex " + std::to_string(line) + " has a non-finite position");
}

std::string usable_names(const std::vector<std::string>& a, const std::vector<std::string>& b = {})
{
	std::string list;
	for (const auto* v : {&a, &b})
		for (const std::string& n : *v)
			list += (list.empty() ? "" : ", ") + n;
	return list.empty() ? std::string("none") : list;
}

} // namespace

Image render_surface(const IncidenceGraph& ig, const AttributeArray<Vec3>& pos, const RenderOptions& o)
{
	using Vertex = IncidenceGraph::Vertex;
	using Face = IncidenceGraph::Face;
	Scene s;
	// every vertex, numbered in line order
	std::vector<uint32_t> number(container_of<Orbit::IG_VERTEX>(ig).end_index(), detail::NO_VERTEX);
	std::vector<Vertex> vertices;
	foreach_cell(ig, [&](Vertex v) {
		check_finite(pos[v.dart.index], v.dart.index);
		number[v.dart.index] = uint32_t(s.points.size());
		s.points.push_back(pos[v.dart.index]);
		vertices.push_back(v);
	});
	if (s.points.empty())
		throw RenderError("the complex has no vertex to render");
	std::vector<Vec3> normal_sum(s.points.size(), Vec3::Zero());
	std::vector<Face> faces;
	std::vector<uint32_t> corners;
	foreach_cell(ig, [&](Face f) {
		corners.clear();
		foreach_incident_vertex(ig, f, [&](Vertex v) { corners.push_back(number[v.dart.index]); });
		Vec3 nv = Vec3::Zero(); // Newell's vector: twice the area, along the normal
		for (std::size_t i = 0; i < corners.size(); ++i)
			nv += s.points[corners[i]].cross(s.points[corners[(i + 1) % corners.size()]]);
		const uint32_t face = uint32_t(faces.size());
		faces.push_back(f);
		s.face_normal.push_back(unit_or_zero(nv));
		for (uint32_t c : corners)
			normal_sum[c] += nv;
		for (std::size_t i = 1; i + 1 < corners.size(); ++i)
		{
			s.triangles.insert(s.triangles.end(), {corners[0], corners[i], corners[i + 1]});
			s.triangle_face.push_back(face);
		}
	});
	for (const Vec3& n : normal_sum)
		s.vertex_normal.push_back(unit_or_zero(n));
	foreach_cell(ig, [&](IncidenceGraph::Edge e) {
		const uint32_t a = number[first_vertex(ig, e).dart.index], b = number[second_vertex(ig, e).dart.index];
		const uint32 d = degree(ig, e);
		if (o.show_defects && d != 2)
			s.boundary_edges.insert(s.boundary_edges.end(), {a, b});
		else if (o.edges || d == 0) // a wire is drawn anyway: it has no face to show it
			s.edges.insert(s.edges.end(), {a, b});
	});
	if (o.show_defects)
		for (std::size_t i = 0; i < vertices.size(); ++i)
			if (degree(ig, vertices[i]) > 0 && !is_manifold_vertex(ig, vertices[i]))
				s.split_vertices.push_back(uint32_t(i));

	switch (o.color)
	{
	case ColorSource::Uniform:
		break;
	case ColorSource::MeanCurvature:
	case ColorSource::GaussianCurvature:
		throw RenderError("curvature colours are not defined on a non-manifold surface");
	case ColorSource::Area:
		s.scalar_on = Scene::ScalarOn::Faces;
		for (Face f : faces)
		{
			Vec3 nv = Vec3::Zero();
			foreach_dart_of_orbit(ig, f, [&](Dart u) {
				nv += pos[use_origin(ig, u).dart.index].cross(pos[use_target(ig, u).dart.index]);
			});
			s.scalar.push_back(0.5 * nv.norm());
		}
		break;
	case ColorSource::Quality:
		s.scalar_on = Scene::ScalarOn::Faces;
		s.scalar.assign(faces.size(), std::numeric_limits<double>::quiet_NaN());
		detail::polygon_quality(s.points, s.triangles, s.triangle_face, s.scalar);
		break;
	case ColorSource::Attribute: {
		std::function<double(Vertex)> vr;
		std::function<double(Face)> fr;
		if (detail::attribute_reader<Vertex>(ig, o.attribute, vr))
		{
			s.scalar_on = Scene::ScalarOn::Vertices;
			for (Vertex v : vertices)
				s.scalar.push_back(vr(v));
		}
		else if (is_indexed<Face>(ig) && detail::attribute_reader<Face>(ig, o.attribute, fr))
		{
			s.scalar_on = Scene::ScalarOn::Faces;
			for (Face f : faces)
				s.scalar.push_back(fr(f));
		}
		else
			throw RenderError("no double or float vertex or face attribute named '" + o.attribute + "' (available: " +
							  usable_names(detail::scalar_attribute_names(container_of<Orbit::IG_VERTEX>(ig)),
										   is_indexed<Face>(ig)
											   ? detail::scalar_attribute_names(container_of<Orbit::PHI1>(ig))
											   : std::vector<std::string>{}) +
							  ")");
		break;
	}
	}
	// flat: the faces around a vertex of a non-manifold surface have no
	// common normal (a fan of three pages, faces turned either way)
	RenderOptions flat = o;
	flat.shading = Shading::Flat;
	return detail::rasterize(s, flat);
}

Image render_graph(const Graph& g, const AttributeArray<Vec3>& pos, const RenderOptions& o, const GraphDrawing& drawing)
{
	using Vertex = Graph::Vertex;
	using Edge = Graph::Edge;
	if (o.color != ColorSource::Uniform && o.color != ColorSource::Attribute)
		throw RenderError("a graph is coloured uniformly or by a vertex attribute (it has no face)");
	std::vector<Vertex> vertices;
	Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
	foreach_cell(g, [&](Vertex v) {
		const Vec3& p = pos[index_of(g, v)];
		check_finite(p, index_of(g, v));
		lo = lo.cwiseMin(p);
		hi = hi.cwiseMax(p);
		vertices.push_back(v);
	});
	if (vertices.empty())
		throw RenderError("the graph has no vertex to render");
	std::vector<uint32_t> number(container_of<Orbit::ALPHA1>(g).end_index(), detail::NO_VERTEX);
	for (std::size_t i = 0; i < vertices.size(); ++i)
		number[index_of(g, vertices[i])] = uint32_t(i);
	std::function<double(Vertex)> value_of;
	if (o.color == ColorSource::Attribute && !detail::attribute_reader<Vertex>(g, o.attribute, value_of))
		throw RenderError("no double or float vertex attribute named '" + o.attribute + "' (available: " +
						  usable_names(detail::scalar_attribute_names(container_of<Orbit::ALPHA1>(g))) + ")");

	Scene s;
	if (!drawing.tubes)
	{
		for (Vertex v : vertices)
			s.points.push_back(pos[index_of(g, v)]);
		s.vertex_normal.assign(s.points.size(), Eigen::Vector3f::Zero());
		foreach_cell(g, [&](Edge e) {
			s.edges.insert(s.edges.end(),
						   {number[index_of(g, Vertex(e.dart))], number[index_of(g, Vertex(alpha0(g, e.dart)))]});
		});
		return detail::rasterize(s, o);
	}

	// tubes and balls, one face per triangle (flat-shaded sides, smooth
	// normals per corner)
	std::function<double(Vertex)> radius_of;
	if (!(drawing.radius > 0.0) && !detail::attribute_reader<Vertex>(g, "radius", radius_of))
	{
		const double r = 0.005 * (hi - lo).norm();
		radius_of = [r](Vertex) { return r > 0.0 ? r : 1.0; };
	}
	else if (drawing.radius > 0.0)
		radius_of = [r = drawing.radius](Vertex) { return r; };
	if (value_of)
		s.scalar_on = Scene::ScalarOn::Vertices;
	auto point = [&](const Vec3& p, const Vec3& n, double value) {
		s.points.push_back(p);
		s.vertex_normal.push_back(unit_or_zero(n));
		if (value_of)
			s.scalar.push_back(value);
		return uint32_t(s.points.size() - 1);
	};
	auto triangle = [&](uint32_t a, uint32_t b, uint32_t c) {
		s.triangles.insert(s.triangles.end(), {a, b, c});
		s.triangle_face.push_back(uint32_t(s.face_normal.size()));
		s.face_normal.push_back(unit_or_zero((s.points[b] - s.points[a]).cross(s.points[c] - s.points[a])));
	};
	constexpr int sides = 8;
	foreach_cell(g, [&](Edge e) {
		const Vertex va(e.dart), vb(alpha0(g, e.dart));
		const Vec3 a = pos[index_of(g, va)], b = pos[index_of(g, vb)];
		const Vec3 axis = b - a;
		if (!(axis.norm() > 0.0))
			return; // a self-loop or a zero-length edge: its ball shows it
		const Vec3 t = axis.normalized();
		const Vec3 u = (std::abs(t[0]) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(t).normalized();
		const Vec3 w = t.cross(u);
		const double ra = radius_of(va), rb = radius_of(vb);
		const double fa = value_of ? value_of(va) : 0.0, fb = value_of ? value_of(vb) : 0.0;
		std::array<uint32_t, sides> ring_a{}, ring_b{};
		for (int k = 0; k < sides; ++k)
		{
			const double angle = 2.0 * std::numbers::pi * k / sides;
			const Vec3 n = std::cos(angle) * u + std::sin(angle) * w;
			ring_a[k] = point(a + ra * n, n, fa);
			ring_b[k] = point(b + rb * n, n, fb);
		}
		for (int k = 0; k < sides; ++k)
		{
			const int l = (k + 1) % sides;
			triangle(ring_a[k], ring_a[l], ring_b[l]);
			triangle(ring_a[k], ring_b[l], ring_b[k]);
		}
	});
	for (Vertex v : vertices)
	{
		const Vec3 c = pos[index_of(g, v)];
		const double r = radius_of(v), f = value_of ? value_of(v) : 0.0;
		std::array<uint32_t, 6> tip{};
		const std::array<Vec3, 6> dirs = {Vec3::UnitX(),  -Vec3::UnitX(), Vec3::UnitY(),
										  -Vec3::UnitY(), Vec3::UnitZ(),  -Vec3::UnitZ()};
		for (int k = 0; k < 6; ++k)
			tip[k] = point(c + r * dirs[k], dirs[k], f);
		for (int x : {0, 1})
			for (int y : {2, 3})
				for (int z : {4, 5})
					triangle(tip[x], tip[y], tip[z]);
	}
	return detail::rasterize(s, o);
}

} // namespace cgogn::render
