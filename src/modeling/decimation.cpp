// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attribute_rules.h>
#include <cgogn/core/operators/cmap2.h>
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/utils/error.h>
#include <cgogn/modeling/decimation.h>
#include <cgogn/modeling/quadric.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <string>
#include <vector>

namespace cgogn::modeling
{

namespace
{

using Vertex = CMap2::Vertex;
using Edge = CMap2::Edge;
using Face = CMap2::Face;

/// A heap entry: an edge (one of its darts, from the vertex that would go)
/// with its error; valid while the dart's stamp still equals `stamp`.
struct Candidate
{
	double error;
	Dart dart;
	uint32 stamp;
	bool operator<(const Candidate& o) const
	{
		return error > o.error; // std::push_heap builds a max-heap: invert for the smallest error on top
	}
};

class Decimator
{
public:
	Decimator(CMap2& m, AttributeArray<Vec3>& pos, const DecimationOptions& o, const ProgressCallback& progress)
		: m_(m), pos_(pos), o_(o), progress_(progress)
	{
	}

	DecimationResult run()
	{
		DecimationResult r;
		nb_faces_ = 0;
		foreach_cell(m_, [&](Face f) {
			if (codegree(m_, f) != 3)
				throw Error("decimate: the face of dart " + std::to_string(f.dart.index) + " has " +
							std::to_string(codegree(m_, f)) + " edges; the input must be triangulated");
			++nb_faces_;
		});
		const uint32 initial_faces = nb_faces_;
		init_quadrics();
		stamp_.assign(container_of<Orbit::DART>(m_).end_index(), 0);
		foreach_cell(m_, [&](Edge e) { push(e.dart); });

		const uint32 to_remove = initial_faces > o_.target_faces ? initial_faces - o_.target_faces : 0;
		while (nb_faces_ > o_.target_faces && !heap_.empty())
		{
			std::pop_heap(heap_.begin(), heap_.end());
			const Candidate c = heap_.back();
			heap_.pop_back();
			if (stamp_[c.dart.index] != c.stamp || !is_dart_live(c.dart))
				continue;
			if (c.error > o_.max_error)
				break;
			if (!can_collapse_edge(m_, Edge(c.dart)))
				continue;
			Vec3 target;
			placement(c.dart, target);
			if (!normals_stay(c.dart, target))
				continue;
			collapse(c.dart, target);
			++r.collapses;
			r.max_error = std::max(r.max_error, c.error);
			if (!progress_.report(uint64(initial_faces - nb_faces_), uint64(to_remove)))
				break;
		}
		r.faces = nb_faces_;
		r.cancelled = progress_.cancelled();
		return r;
	}

private:
	bool is_dart_live(Dart d) const
	{
		return is_dart_valid(m_, d);
	}

	const Vec3& position(Dart d) const
	{
		return pos_[index_of(m_, Vertex(d))];
	}

	Quadric& quadric(Dart d)
	{
		return quadric_[index_of(m_, Vertex(d))];
	}

	void init_quadrics()
	{
		quadric_.assign(container_of<Vertex::ORBIT>(m_).end_index(), Quadric());
		boundary_.assign(container_of<Vertex::ORBIT>(m_).end_index(), 0);
		foreach_cell(m_, [&](Face f) {
			const Dart d0 = f.dart, d1 = phi1(m_, d0), d2 = phi1(m_, d1);
			const Vec3 &p0 = position(d0), &p1 = position(d1), &p2 = position(d2);
			const Vec3 n = (p1 - p0).cross(p2 - p0);
			const double len = n.norm();
			if (len == 0.0)
				return; // a degenerate face has no plane
			const Quadric q = Quadric::plane(n / len, p0);
			for (Dart d : {d0, d1, d2})
				quadric(d) += q;
		});
		// boundary edges: the plane through the edge perpendicular to its face
		foreach_dart(m_, [&](Dart d) {
			if (!is_boundary(m_, d))
				return;
			const Dart inner = phi2(m_, d); // from b to a inside the real face
			boundary_[index_of(m_, Vertex(inner))] = 1;
			if (o_.keep_boundary)
				return;
			const Vec3 &a = position(inner), &b = position(phi1(m_, inner)), &c = position(phi_1(m_, inner));
			const Vec3 face_n = (b - a).cross(c - a);
			Vec3 n = (b - a).cross(face_n);
			const double len = n.norm();
			if (len == 0.0)
				return;
			const Quadric q = Quadric::plane(n / len, a, o_.boundary_weight);
			quadric(inner) += q;
			quadric(phi1(m_, inner)) += q;
		});
	}

	bool on_boundary(Dart d) const
	{
		return boundary_[index_of(m_, Vertex(d))] != 0;
	}

	/// Where the vertex left by collapsing the edge of d goes; d's origin is
	/// the one that disappears.
	double placement(Dart d, Vec3& x)
	{
		const Dart d2 = phi2(m_, d);
		const Quadric q = quadric(d) + quadric(d2);
		const Vec3 &a = position(d), &b = position(d2);
		if (o_.keep_boundary && on_boundary(d2))
		{
			x = b; // the boundary vertex stays where it is
			return q(x);
		}
		if (o_.placement == CollapsePlacement::Midpoint)
		{
			x = 0.5 * (a + b);
			return q(x);
		}
		if (q.minimizer(x))
			return q(x);
		const Vec3 mid = 0.5 * (a + b);
		double best = q(mid);
		x = mid;
		for (const Vec3* p : {&a, &b})
		{
			const double e = q(*p);
			if (e < best)
			{
				best = e;
				x = *p;
			}
		}
		return best;
	}

	/// Pushes the edge of d, oriented so that with keep_boundary the boundary
	/// end survives; edges that may not collapse are not pushed.
	void push(Dart d)
	{
		Dart from = d;
		if (o_.keep_boundary)
		{
			const bool a = on_boundary(d), b = on_boundary(phi2(m_, d));
			if (a && b)
				return;
			if (a)
				from = phi2(m_, d);
		}
		Vec3 x;
		const double error = placement(from, x);
		heap_.push_back({error, from, stamp_[from.index]});
		std::push_heap(heap_.begin(), heap_.end());
	}

	/// True when every face around the edge's ends that survives the collapse
	/// keeps a non-degenerate normal within the allowed angle of its old one.
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
				// the faces of the edge itself vanish
				if (s == d || s == d2 || t == d || t == d2 || u == d || u == d2)
					return true;
				const Vec3 &p = position(s), &q = position(t), &r = position(u);
				const Vec3 before = (q - p).cross(r - p);
				const Vec3 after = (q - x).cross(r - x);
				const double la = after.norm(), lb = before.norm();
				// a face degenerate in the input has no normal to keep: it only must not stay degenerate
				ok = la > 0.0 && (lb == 0.0 || after.dot(before) > o_.min_normal_cosine * la * lb);
				return ok;
			});
			if (!ok)
				return false;
		}
		return true;
	}

	void collapse(Dart d, const Vec3& x)
	{
		const Dart d2 = phi2(m_, d);
		nb_faces_ -= uint32(!is_boundary(m_, d)) + uint32(!is_boundary(m_, d2));
		const Quadric q = quadric(d) + quadric(d2);
		// every dart of both stars may change edge or disappear: outdate them
		for (Dart start : {d, d2})
			foreach_dart_of_orbit(m_, Vertex(start), [&](Dart s) {
				++stamp_[s.index];
				++stamp_[phi2(m_, s).index];
			});
		// attribute rules: the kept end (origin of d2) gets the values at the
		// parameter of x along the edge, before the other end goes
		if (container_of<Vertex::ORBIT>(m_).has_rules())
		{
			const Vec3 &a = pos_[index_of(m_, Vertex(d2))], &b = pos_[index_of(m_, Vertex(d))];
			const double l2 = (b - a).squaredNorm();
			const double t = l2 > 0.0 ? std::clamp((x - a).dot(b - a) / l2, 0.0, 1.0) : 0.0;
			apply_attribute_rules(m_, Vertex(d2), {Vertex(d2), Vertex(d)}, {1.0 - t, t});
		}
		const Vertex v = collapse_edge(m_, Edge(d));
		pos_[index_of(m_, v)] = x;
		quadric(v.dart) = q;
		foreach_dart_of_orbit(m_, v, [&](Dart s) {
			++stamp_[s.index];
			++stamp_[phi2(m_, s).index];
			push(s);
		});
	}

	CMap2& m_;
	AttributeArray<Vec3>& pos_;
	const DecimationOptions& o_;
	ProgressReporter progress_;
	uint32 nb_faces_ = 0;
	std::vector<Quadric> quadric_; // per vertex line
	std::vector<uint8> boundary_;  // per vertex line: on the boundary of the input
	std::vector<uint32> stamp_;    // per dart
	std::vector<Candidate> heap_;
};

} // namespace

DecimationResult decimate(CMap2& m, AttributeArray<Vec3>& pos, const DecimationOptions& options,
						  const ProgressCallback& progress)
{
	const SuspendedRule own_positions(pos);
	return Decimator(m, pos, options, progress).run();
}

} // namespace cgogn::modeling
