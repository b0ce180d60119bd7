// SPDX-License-Identifier: MIT
// From a CMap2 (its faces) or a CMap3 (some of its faces) to a Scene: shared
// by the rasterizer's entry points and by the HTML viewer.
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/geometry/algos/area.h>
#include <cgogn/geometry/algos/gaussian_curvature.h>
#include <cgogn/geometry/algos/mean_curvature.h>
#include <cgogn/geometry/algos/normal.h>

#include "scene.h"

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <typeindex>

namespace cgogn::render::detail
{

inline constexpr uint32_t NO_VERTEX = ~uint32_t(0);

/// The double or float attributes of a container, by name (position excluded).
inline std::vector<std::string> scalar_attribute_names(const AttributeContainer& c)
{
	std::vector<std::string> out;
	for (const auto& a : c.attributes())
		if ((a->type() == std::type_index(typeid(double)) || a->type() == std::type_index(typeid(float))) &&
			a->name() != "position" && a->name().rfind("__", 0) != 0)
			out.push_back(a->name());
	return out;
}

/// The value of a double or float attribute `name` of cell c; false when the
/// orbit has no such attribute.
template <typename CELL, typename MAP>
bool attribute_reader(const MAP& m, const std::string& name, std::function<double(CELL)>& read)
{
	if (auto a = get_attribute<double, CELL>(m, name))
	{
		read = [a](CELL c) { return (*a)[c]; };
		return true;
	}
	if (auto a = get_attribute<float, CELL>(m, name))
	{
		read = [a](CELL c) { return double((*a)[c]); };
		return true;
	}
	return false;
}

template <typename MAP>
class Extractor
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;

public:
	Extractor(const MAP& m, const AttributeArray<Vec3>& pos, const RenderOptions& o) : m_(m), pos_(pos), o_(o)
	{
	}

	/// rendered(d): whether the face of the non-boundary dart d is drawn.
	template <typename PRED>
	Scene run(const PRED& rendered)
	{
		foreach_cell(m_, [&](Face f) {
			if (rendered(f.dart))
				add_face(f.dart);
		});
		return finish();
	}

	/// Per triangle flags (Scene::triangle_flags) instead of the edge lists;
	/// all_edges: every edge of every face is marked, not each edge once.
	void use_flags(bool all_edges)
	{
		flags_ = true;
		all_edges_ = all_edges;
	}

	/// The polygon of dart d (phi1 orbit), fanned into triangles.
	void add_face(Dart d)
	{
		const uint32_t face = uint32_t(face_darts_.size());
		face_darts_.push_back(d);
		const Vec3 nv = geometry::newell_vector(m_, pos_, d);
		const double l = nv.norm();
		s_.face_normal.push_back(l > 0.0 ? Eigen::Vector3f((nv / l).cast<float>()) : Eigen::Vector3f::Zero());
		corners_.clear();
		edge_bits_.clear();
		Dart x = d;
		do
		{
			const uint32_t v = vertex_of(x);
			corners_.push_back(v);
			normal_sum_[v] += nv;
			const Dart next = phi1(m_, x);
			if (o_.edges || o_.show_defects || flags_)
			{
				bool boundary = false;
				if constexpr (MAP::dimension == 2)
					boundary = is_boundary(m_, phi2(m_, x));
				// each inner edge is met from both of its faces: drawn once
				const bool draw = all_edges_ || boundary || index_of(m_, Vertex(x)) < index_of(m_, Vertex(next));
				if (flags_)
					edge_bits_.push_back(uint8_t((draw ? 1 : 0) | (boundary ? 2 : 0)));
				else
				{
					if (boundary && o_.show_defects)
					{
						s_.boundary_edges.push_back(v);
						s_.boundary_edges.push_back(vertex_of(next));
					}
					if (o_.edges && draw)
					{
						s_.edges.push_back(v);
						s_.edges.push_back(vertex_of(next));
					}
				}
			}
			x = next;
		} while (x != d);
		const std::size_t k = corners_.size();
		for (std::size_t i = 1; i + 1 < k; ++i)
		{
			s_.triangles.insert(s_.triangles.end(), {corners_[0], corners_[i], corners_[i + 1]});
			s_.triangle_face.push_back(face);
			if (flags_)
			{
				// the polygon edges of the fan triangle (c0, ci, ci+1): c0 ci is
				// edge 0 when i = 1, ci ci+1 is edge i, ci+1 c0 is edge k-1 when
				// i = k - 2
				auto bits = [&](std::size_t e, uint8_t draw, uint8_t boundary) {
					return uint8_t(((edge_bits_[e] & 1) ? draw : 0) | ((edge_bits_[e] & 2) ? boundary : 0));
				};
				uint8_t f = bits(i, Scene::EDGE_BC, Scene::BOUNDARY_BC);
				if (i == 1)
					f |= bits(0, Scene::EDGE_AB, Scene::BOUNDARY_AB);
				if (i + 2 == k)
					f |= bits(k - 1, Scene::EDGE_CA, Scene::BOUNDARY_CA);
				s_.triangle_flags.push_back(f);
			}
		}
	}

	/// Normals and split vertices, once every face is added; throws when no
	/// face was added.
	Scene finish()
	{
		if (face_darts_.empty())
			throw RenderError(MAP::dimension == 2 ? "the mesh has no face to render"
												  : "the volume mesh has no boundary face to render");
		finish_normals();
		if (o_.show_defects || flags_)
			find_split_vertices();
		return std::move(s_);
	}

	/// The scene as built so far.
	const Scene& scene() const
	{
		return s_;
	}
	const std::vector<Dart>& face_darts() const
	{
		return face_darts_;
	}
	const std::vector<Dart>& vertex_darts() const
	{
		return vertex_darts_;
	}

private:
	uint32_t vertex_of(Dart d)
	{
		const uint32_t line = index_of(m_, Vertex(d));
		if (line >= compact_.size())
			compact_.resize(std::size_t(line) + 1 + compact_.size() / 2, NO_VERTEX);
		uint32_t& c = compact_[line];
		if (c == NO_VERTEX)
		{
			const Vec3& p = pos_[line];
			if (!p.allFinite())
				throw RenderError("vertex " + std::to_string(line) + " has a non-finite position");
			c = uint32_t(s_.points.size());
			s_.points.push_back(p);
			vertex_darts_.push_back(d);
			normal_sum_.push_back(Vec3::Zero());
		}
		return c;
	}

	void finish_normals()
	{
		s_.vertex_normal.resize(normal_sum_.size());
		for (std::size_t i = 0; i < normal_sum_.size(); ++i)
		{
			const double l = normal_sum_[i].norm();
			s_.vertex_normal[i] =
				l > 0.0 ? Eigen::Vector3f((normal_sum_[i] / l).cast<float>()) : Eigen::Vector3f::Zero();
		}
		normal_sum_ = {};
	}

	/// The vertices the loader made by splitting a non-manifold one: those
	/// sharing their `original_vertex` with another vertex.
	void find_split_vertices()
	{
		auto orig = get_attribute<uint32, Vertex>(m_, "original_vertex");
		if (!orig)
			return;
		std::vector<uint32_t> count;
		foreach_cell(m_, [&](Vertex v) {
			const uint32_t o = (*orig)[v];
			if (o >= count.size())
				count.resize(std::size_t(o) + 1 + count.size() / 2, 0);
			++count[o];
		});
		for (uint32_t i = 0; i < vertex_darts_.size(); ++i)
			if (count[(*orig)[Vertex(vertex_darts_[i])]] > 1)
				s_.split_vertices.push_back(i);
	}

	const MAP& m_;
	const AttributeArray<Vec3>& pos_;
	const RenderOptions& o_;
	Scene s_;
	std::vector<uint32_t> compact_; // vertex line -> rendered vertex number
	std::vector<Dart> face_darts_, vertex_darts_;
	std::vector<Vec3> normal_sum_;
	std::vector<uint32_t> corners_;
	std::vector<uint8_t> edge_bits_; // per polygon edge: 1 drawn, 2 boundary
	bool flags_ = false, all_edges_ = false;
};

inline void polygon_quality(const std::vector<Vec3>& p, const std::vector<uint32_t>& tri,
							const std::vector<uint32_t>& face_of, std::vector<double>& out)
{
	for (std::size_t t = 0; t < face_of.size(); ++t)
	{
		const double q = triangle_quality(p[tri[3 * t]], p[tri[3 * t + 1]], p[tri[3 * t + 2]]);
		double& f = out[face_of[t]];
		f = std::isnan(f) ? q : std::min(f, q);
	}
}

template <typename MAP>
void add_scalar(const MAP& m, const AttributeArray<Vec3>& pos, const RenderOptions& o, Scene& s,
				const std::vector<Dart>& face_darts, const std::vector<Dart>& vertex_darts)
{
	using Vertex = typename mesh_traits<MAP>::Vertex;
	using Face = typename mesh_traits<MAP>::Face;
	const double nan = std::numeric_limits<double>::quiet_NaN();
	auto per_vertex = [&](const auto& f) {
		s.scalar_on = Scene::ScalarOn::Vertices;
		s.scalar.resize(vertex_darts.size());
		for (std::size_t i = 0; i < vertex_darts.size(); ++i)
			s.scalar[i] = f(Vertex(vertex_darts[i]));
	};
	auto per_face = [&](const auto& f) {
		s.scalar_on = Scene::ScalarOn::Faces;
		s.scalar.resize(face_darts.size());
		for (std::size_t i = 0; i < face_darts.size(); ++i)
			s.scalar[i] = f(face_darts[i]);
	};
	switch (o.color)
	{
	case ColorSource::Uniform:
		return;
	case ColorSource::MeanCurvature:
	case ColorSource::GaussianCurvature:
		if constexpr (MAP::dimension == 2)
		{
			if (o.color == ColorSource::MeanCurvature)
				per_vertex([&](Vertex v) { return geometry::mean_curvature(m, v, pos); });
			else
				per_vertex([&](Vertex v) { return geometry::gaussian_curvature(m, v, pos); });
			return;
		}
		else
			throw RenderError("curvature colours are defined on surfaces, not on volume meshes");
	case ColorSource::Area:
		per_face([&](Dart d) { return geometry::face_area(m, Face(d), pos); });
		return;
	case ColorSource::Quality:
		s.scalar_on = Scene::ScalarOn::Faces;
		s.scalar.assign(face_darts.size(), nan);
		polygon_quality(s.points, s.triangles, s.triangle_face, s.scalar);
		return;
	case ColorSource::Attribute:
		break;
	}
	std::function<double(Vertex)> vr;
	if (attribute_reader<Vertex>(m, o.attribute, vr))
	{
		per_vertex(vr);
		return;
	}
	std::function<double(Face)> fr;
	if (attribute_reader<Face>(m, o.attribute, fr))
	{
		per_face([&](Dart d) { return fr(Face(d)); });
		return;
	}
	std::vector<std::string> names = scalar_attribute_names(container_of<Vertex::ORBIT>(m));
	for (const std::string& n : scalar_attribute_names(container_of<Face::ORBIT>(m)))
		names.push_back(n);
	if constexpr (MAP::dimension == 3)
	{
		using Volume = typename mesh_traits<MAP>::Volume;
		std::function<double(Volume)> wr;
		if (attribute_reader<Volume>(m, o.attribute, wr))
		{
			per_face([&](Dart d) { return wr(Volume(d)); });
			return;
		}
		for (const std::string& n : scalar_attribute_names(container_of<Volume::ORBIT>(m)))
			names.push_back(n);
	}
	std::string list;
	for (const std::string& n : names)
		list += (list.empty() ? "" : ", ") + n;
	throw RenderError("no double or float vertex or cell attribute named '" + o.attribute +
					  "' (available: " + (list.empty() ? std::string("none") : list) + ")");
}

} // namespace cgogn::render::detail
