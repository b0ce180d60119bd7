// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/geometry/algos/angle.h>
#include <cgogn/geometry/algos/length.h>
#include <cgogn/modeling/remeshing.h>
#include <cgogn/modeling/triangle_tree.h>

#include <Eigen/Geometry>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace cgogn::modeling
{

namespace
{

using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

class Remesher
{
public:
	Remesher(CMap2& m, AttributeArray<Vec3>& pos, const RemeshingOptions& o, const ProgressCallback& progress)
		: m_(m), pos_(pos), o_(o), progress_(progress)
	{
	}

	RemeshingResult run()
	{
		foreach_cell(m_, [&](Face f) {
			if (codegree(m_, f) != 3)
				throw Error("isotropic_remeshing: the face of dart " + std::to_string(f.dart.index) + " has " +
							std::to_string(codegree(m_, f)) + " edges; the input must be triangulated");
		});
		double length = o_.target_edge_length;
		if (length == 0.0)
			length = geometry::mean_edge_length(m_, pos_);
		if (!(length > 0.0) || !std::isfinite(length))
			throw Error("isotropic_remeshing: the target edge length must be a positive number (got " +
						std::to_string(length) + ")");
		r_.target_edge_length = length;
		high2_ = (4.0 / 3.0 * length) * (4.0 / 3.0 * length);
		low2_ = (4.0 / 5.0 * length) * (4.0 / 5.0 * length);
		mark_features();
		init_vertex_flags();
		if (o_.project)
			reference_ = std::make_unique<TriangleTree>(m_, pos_);

		const double phases = 5.0 * o_.iterations;
		for (uint32 it = 0; it < o_.iterations; ++it)
		{
			const double base = 5.0 * it;
			split_long_edges();
			if (!progress_.report((base + 1) / phases))
				break;
			collapse_short_edges();
			if (!progress_.report((base + 2) / phases))
				break;
			equalize_valences();
			if (!progress_.report((base + 3) / phases))
				break;
			tangential_relaxation();
			if (!progress_.report((base + 4) / phases))
				break;
			if (o_.project)
				project();
			r_.iterations = it + 1;
			if (!progress_.report((base + 5) / phases))
				break;
		}
		r_.cancelled = progress_.cancelled();
		return r_;
	}

private:
	const Vec3& position(Dart d) const
	{
		return pos_[index_of(m_, Vertex(d))];
	}
	Vec3& position(Dart d)
	{
		return pos_[index_of(m_, Vertex(d))];
	}

	double squared_length(Dart d) const
	{
		return (position(phi2(m_, d)) - position(d)).squaredNorm();
	}

	// ---- feature edges: a flag per dart, set on both darts of the edge

	void grow_flags()
	{
		const uint32 n = container_of<Orbit::DART>(m_).end_index();
		if (feature_.size() < n)
			feature_.resize(n, 0);
	}

	bool is_feature(Dart d) const
	{
		return d.index < feature_.size() && feature_[d.index] != 0;
	}

	void set_feature(Dart d, bool f)
	{
		feature_[d.index] = f ? 1 : 0;
		feature_[phi2(m_, d).index] = f ? 1 : 0;
	}

	void mark_features()
	{
		grow_flags();
		if (!(o_.feature_angle > 0.0))
			return;
		const double angle = o_.feature_angle * std::numbers::pi / 180.0;
		foreach_cell(m_, [&](Edge e) {
			if (std::abs(geometry::dihedral_angle(m_, e, pos_)) > angle)
				set_feature(e.dart, true);
		});
	}

	// ---- vertex flags, per vertex line, kept up to date through the
	// operations (walking around a vertex at each test cost 18% of the time)

	static constexpr uint8 ON_BOUNDARY = 1;
	static constexpr uint8 ON_FEATURE = 2;

	uint8& flags(Dart d)
	{
		const uint32 line = index_of(m_, Vertex(d));
		if (line >= vflags_.size())
			vflags_.resize(container_of<Vertex::ORBIT>(m_).end_index(), 0);
		return vflags_[line];
	}
	uint8 flags(Dart d) const
	{
		const uint32 line = index_of(m_, Vertex(d));
		return line < vflags_.size() ? vflags_[line] : 0;
	}

	void init_vertex_flags()
	{
		vflags_.assign(container_of<Vertex::ORBIT>(m_).end_index(), 0);
		foreach_cell(m_, [&](Vertex v) {
			uint8 f = 0;
			foreach_dart_of_orbit(m_, v, [&](Dart s) {
				f |= is_boundary(m_, s) ? ON_BOUNDARY : 0;
				f |= is_feature(s) ? ON_FEATURE : 0;
			});
			flags(v.dart) = f;
		});
	}

	/// Boundary and feature vertices neither move nor disappear.
	bool is_locked(Vertex v) const
	{
		return flags(v.dart) != 0;
	}

	bool is_on_boundary(Vertex v) const
	{
		return (flags(v.dart) & ON_BOUNDARY) != 0;
	}

	// ---- (1) splits

	void split_long_edges()
	{
		std::vector<Dart> longs;
		for (int pass = 0; pass < 64; ++pass)
		{
			longs.clear();
			foreach_cell(m_, [&](Edge e) {
				if (squared_length(e.dart) > high2_)
					longs.push_back(e.dart);
			});
			if (longs.empty())
				return;
			for (Dart d : longs)
				split(d);
		}
	}

	void split(Dart d)
	{
		const Vec3 mid = 0.5 * (position(d) + position(phi2(m_, d)));
		const bool feature = is_feature(d);
		const bool boundary = is_boundary(m_, d) || is_boundary(m_, phi2(m_, d));
		const Vertex v = cut_edge(m_, Edge(d));
		position(v.dart) = mid;
		// the new vertex lies on the boundary or the feature line when its edge did
		flags(v.dart) = uint8((boundary ? ON_BOUNDARY : 0) | (feature ? ON_FEATURE : 0));
		grow_flags();
		set_feature(d, feature);
		set_feature(v.dart, feature);
		++r_.splits;
		// v.dart leaves v in d's face, phi2(d) leaves v in the other one
		for (Dart s : {v.dart, phi2(m_, d)})
		{
			if (is_boundary(m_, s))
				continue;
			const Dart opposite = phi1(m_, phi1(m_, s));
			const Edge cut = cut_face(m_, Vertex(s), Vertex(opposite));
			grow_flags();
			set_feature(cut.dart, false); // its darts may reuse lines of removed feature darts
		}
	}

	// ---- (2) collapses

	/// True when no face around the ends of d's edge, other than the two that
	/// vanish, degenerates or turns over when both ends go to x.
	bool normals_stay(Dart d, const Vec3& x) const
	{
		const Dart d2 = phi2(m_, d);
		bool ok = true;
		for (Dart start : {d, d2})
		{
			foreach_dart_of_orbit(m_, Vertex(start), [&](Dart s) {
				if (is_boundary(m_, s))
					return true;
				const Dart t = phi1(m_, s), u = phi1(m_, t);
				if (s == d || s == d2 || t == d || t == d2 || u == d || u == d2)
					return true;
				const Vec3 &q = position(t), &w = position(u);
				const Vec3 before = (q - position(s)).cross(w - position(s));
				const Vec3 after = (q - x).cross(w - x);
				// a degenerate face has no orientation to keep: it only must not stay degenerate
				ok = after.squaredNorm() > 0.0 && (before.squaredNorm() == 0.0 || after.dot(before) > 0.0);
				return ok;
			});
			if (!ok)
				return false;
		}
		return true;
	}

	/// No neighbour of either end of d's edge is farther than 4/3 L from x.
	bool stays_short(Dart d, const Vec3& x) const
	{
		bool ok = true;
		for (Dart start : {d, phi2(m_, d)})
		{
			foreach_dart_of_orbit(m_, Vertex(start), [&](Dart s) {
				ok = (position(phi2(m_, s)) - x).squaredNorm() <= high2_;
				return ok;
			});
			if (!ok)
				return false;
		}
		return true;
	}

	bool try_collapse(Dart d)
	{
		const Dart d2 = phi2(m_, d);
		const bool locked_a = is_locked(Vertex(d)), locked_b = is_locked(Vertex(d2));
		if (locked_a && locked_b)
			return false;
		// the origin of `gone` disappears; the other end takes position x
		const Dart gone = locked_a ? d2 : d;
		const Vec3 x = locked_a ? position(d) : (locked_b ? position(d2) : 0.5 * (position(d) + position(d2)));
		// the geometric tests first: they are cheaper than the link condition and fail more often
		if (!stays_short(gone, x) || !normals_stay(gone, x) || !can_collapse_edge(m_, Edge(gone)))
			return false;
		const uint8 kept_flags = uint8(flags(d) | flags(d2)); // at most one end is locked
		// a vanished triangle merges its two other edges (collapse_edge keeps
		// one of them whole): flag both beforehand, so the survivor is a
		// feature if either was
		for (Dart side : {d, d2})
			if (phi<1, 1, 1>(m_, side) == side)
			{
				const Dart a = phi1(m_, side), b = phi_1(m_, side);
				const bool f = is_feature(a) || is_feature(b);
				set_feature(a, f);
				set_feature(b, f);
			}
		const Vertex v = collapse_edge(m_, Edge(gone));
		position(v.dart) = x;
		flags(v.dart) = kept_flags;
		++r_.collapses;
		return true;
	}

	void collapse_short_edges()
	{
		std::vector<Dart> shorts;
		for (int pass = 0; pass < 64; ++pass)
		{
			shorts.clear();
			foreach_cell(m_, [&](Edge e) {
				if (squared_length(e.dart) < low2_)
					shorts.push_back(e.dart);
			});
			uint64 done = 0;
			for (Dart d : shorts)
			{
				// earlier collapses of this pass may have removed d or changed its edge
				if (!is_dart_valid(m_, d) || squared_length(d) >= low2_)
					continue;
				done += try_collapse(d) ? 1 : 0;
			}
			if (done == 0)
				return;
		}
	}

	// ---- (3) flips

	int valence_excess(Dart d) const
	{
		const int target = is_on_boundary(Vertex(d)) ? 4 : 6;
		return int(degree(m_, Vertex(d))) - target;
	}

	bool flip_keeps_orientation(Dart d) const
	{
		const Dart d2 = phi2(m_, d);
		const Vec3 &a = position(d), &b = position(d2), &c = position(phi_1(m_, d)), &e = position(phi_1(m_, d2));
		const Vec3 before = (b - a).cross(c - a) + (a - b).cross(e - b);
		const Vec3 t1 = (a - c).cross(e - c), t2 = (b - e).cross(c - e); // (c, a, e) and (e, b, c)
		return t1.dot(before) > 0.0 && t2.dot(before) > 0.0;
	}

	void equalize_valences()
	{
		std::vector<Dart> edges;
		foreach_cell(m_, [&](Edge e) { edges.push_back(e.dart); });
		for (Dart d : edges)
		{
			const Dart d2 = phi2(m_, d);
			if (is_boundary(m_, d) || is_boundary(m_, d2) || is_feature(d))
				continue;
			const Dart c = phi_1(m_, d), e = phi_1(m_, d2);
			const int va = valence_excess(d), vb = valence_excess(d2), vc = valence_excess(c), ve = valence_excess(e);
			const int before = std::abs(va) + std::abs(vb) + std::abs(vc) + std::abs(ve);
			const int after = std::abs(va - 1) + std::abs(vb - 1) + std::abs(vc + 1) + std::abs(ve + 1);
			if (after >= before || !can_flip_edge(m_, Edge(d)) || !flip_keeps_orientation(d))
				continue;
			flip_edge(m_, Edge(d));
			++r_.flips;
		}
	}

	// ---- (4) relaxation, (5) projection

	void tangential_relaxation()
	{
		moves_.clear();
		foreach_cell(m_, [&](Vertex v) {
			if (is_locked(v))
				return;
			const Vec3& p = position(v.dart);
			Vec3 centroid = Vec3::Zero(), normal = Vec3::Zero();
			uint32 n = 0;
			foreach_dart_of_orbit(m_, v, [&](Dart s) {
				const Vec3& q = position(phi2(m_, s));
				centroid += q;
				++n;
				normal += (q - p).cross(position(phi_1(m_, s)) - p); // twice the area of the face of s
			});
			centroid /= double(n);
			const double len = normal.norm();
			if (len == 0.0)
				return;
			normal /= len;
			moves_.push_back({index_of(m_, v), centroid + normal * normal.dot(p - centroid)});
		});
		for (const auto& [line, x] : moves_)
			pos_[line] = x;
	}

	void project()
	{
		for (const auto& [line, x] : moves_)
			pos_[line] = reference_->closest_point(x).point;
	}

	CMap2& m_;
	AttributeArray<Vec3>& pos_;
	const RemeshingOptions& o_;
	ProgressReporter progress_;
	RemeshingResult r_;
	double high2_ = 0.0, low2_ = 0.0;
	std::vector<uint8> feature_; // per dart
	std::vector<uint8> vflags_;  // per vertex line: ON_BOUNDARY | ON_FEATURE
	std::unique_ptr<TriangleTree> reference_;
	std::vector<std::pair<uint32, Vec3>> moves_; // vertex line, new position
};

} // namespace

RemeshingResult isotropic_remeshing(CMap2& m, AttributeArray<Vec3>& pos, const RemeshingOptions& options,
									const ProgressCallback& progress)
{
	// positions are the algorithm's own: no rule interpolates them
	const SuspendedRule own_positions(pos);
	return Remesher(m, pos, options, progress).run();
}

} // namespace cgogn::modeling
