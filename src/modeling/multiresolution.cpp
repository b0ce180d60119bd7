// SPDX-License-Identifier: MIT
// Analysis and synthesis of the positions of a multiresolution 2-map.
#include <cgogn/core/properties/dimension_properties.h>
#include <cgogn/core/traversals/local_mrmap2.h>
#include <cgogn/modeling/multiresolution.h>

#include <Eigen/SparseCholesky>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn::modeling
{

namespace
{

using V = MRMap2::Vertex;
using E = MRMap2::Edge;
using F = MRMap2::Face;

/// A linear combination of vertex positions of one level: (line, weight).
using Terms = std::vector<std::pair<uint32, double>>;

/// Loop's weight beta of an interior vertex of valence n (the rule of
/// loop_subdivision: n beta = 5/8 - (3/8 + 1/4 cos(2 pi / n))^2).
double loop_beta(uint32 n)
{
	const double c = 3.0 + 2.0 * std::cos(2.0 * std::numbers::pi / double(n));
	return (40.0 - c * c) / 64.0 / double(n);
}

/// Adds the centroid of face f of level view c, times w.
void add_centroid(const MRLevelView2& c, F f, double w, Terms& t)
{
	const double k = double(codegree(c, f));
	foreach_dart_of_orbit(c, f, [&](Dart d) { t.emplace_back(index_of(c, V(d)), w / k); });
}

/// The rule of an old vertex v of level view c (the vertex moving to the
/// next level). The masks are those of loop_subdivision and
/// catmull_clark_subdivision, their boundary rule included.
void even_terms(const MRLevelView2& c, V v, MRBank bank, Terms& t)
{
	const uint32 p = index_of(c, v);
	if (bank == MRBank::Linear)
	{
		t.emplace_back(p, 1.0);
		return;
	}
	// the boundary: 1/8 q0 + 3/4 p + 1/8 q1, or p when pinched
	uint32 nb_boundary = 0;
	foreach_dart_of_orbit(c, v, [&](Dart d) { nb_boundary += is_boundary(c, d) || is_boundary(c, phi2(c, d)); });
	if (nb_boundary > 0)
	{
		if (nb_boundary != 2)
		{
			t.emplace_back(p, 1.0);
			return;
		}
		t.emplace_back(p, 0.75);
		foreach_dart_of_orbit(c, v, [&](Dart d) {
			if (is_boundary(c, d) || is_boundary(c, phi2(c, d)))
				t.emplace_back(index_of(c, V(phi2(c, d))), 0.125);
		});
		return;
	}
	const uint32 n = degree(c, v);
	if (bank == MRBank::Loop)
	{
		const double beta = loop_beta(n);
		t.emplace_back(p, 1.0 - double(n) * beta);
		foreach_dart_of_orbit(c, v, [&](Dart d) { t.emplace_back(index_of(c, V(phi2(c, d))), beta); });
		return;
	}
	// Catmull-Clark: (Q + 2R + (n - 3) p) / n, with 2R = p + mean of the neighbours
	const double dn = double(n);
	t.emplace_back(p, (1.0 + (dn - 3.0)) / dn);
	foreach_dart_of_orbit(c, v, [&](Dart d) {
		add_centroid(c, F(d), 1.0 / (dn * dn), t);
		t.emplace_back(index_of(c, V(phi2(c, d))), 1.0 / (dn * dn));
	});
}

/// The rule of the vertex cutting edge e of level view c.
void edge_terms(const MRLevelView2& c, E e, MRBank bank, Terms& t)
{
	const Dart d = e.dart, d2 = phi2(c, d);
	const uint32 a = index_of(c, V(d)), b = index_of(c, V(d2));
	if (bank == MRBank::Linear || is_boundary(c, d) || is_boundary(c, d2))
	{
		t.insert(t.end(), {{a, 0.5}, {b, 0.5}});
		return;
	}
	if (bank == MRBank::Loop)
	{
		t.insert(t.end(), {{a, 0.375}, {b, 0.375}});
		t.emplace_back(index_of(c, V(phi_1(c, d))), 0.125);
		t.emplace_back(index_of(c, V(phi_1(c, d2))), 0.125);
		return;
	}
	t.insert(t.end(), {{a, 0.25}, {b, 0.25}});
	add_centroid(c, F(d), 0.25, t);
	add_centroid(c, F(d2), 0.25, t);
}

/// The rule giving the position of vertex v of level l from level l - 1.
void rule_terms(const MRMap2& m, uint32 l, V v, MRBank bank, Terms& t)
{
	const MRLevelView2 c = level_view(m, l - 1);
	using Origin = detail::MRVertexOrigin;
	const auto [origin, d] = detail::mr_vertex_origin(detail::mr_state_of(m), l, v.dart);
	switch (origin)
	{
	case Origin::Old:
		even_terms(c, V(d), bank, t);
		break;
	case Origin::Midpoint:
		edge_terms(c, E(d), bank, t);
		break;
	case Origin::Centre:
		if (bank == MRBank::Loop)
			throw std::invalid_argument("Loop bank: level " + std::to_string(l) + " has face centres");
		add_centroid(c, F(d), 1.0, t);
		break;
	default:
		throw std::invalid_argument("multiresolution bank: a vertex of level " + std::to_string(l) +
									" is neither old, nor an edge midpoint, nor a face centre");
	}
}

/// Checks that level l is the bank's refinement of level l - 1.
void check_level(const MRMap2& m, uint32 l, MRBank bank)
{
	if (bank == MRBank::Linear)
		return;
	const std::vector<uint32> below = f_vector(level_view(m, l - 1)), at = f_vector(level_view(m, l));
	bool ok = true;
	if (bank == MRBank::Loop)
	{
		foreach_cell(level_view(m, l - 1), [&](F f) { return ok = codegree(level_view(m, l - 1), f) == 3; });
		ok = ok && at[0] == below[0] + below[1] && at[2] == 4 * below[2];
	}
	else
		ok = at[0] == below[0] + below[1] + below[2];
	if (!ok)
		throw std::invalid_argument(std::string(bank == MRBank::Loop ? "Loop" : "Catmull-Clark") + " bank: level " +
									std::to_string(l) + " is not its refinement of level " + std::to_string(l - 1));
}

Vec3 combine(const Terms& t, const AttributeArray<Vec3>& pos)
{
	Vec3 x = Vec3::Zero();
	for (auto [line, w] : t)
		x += w * pos[line];
	return x;
}

} // namespace

void synthesis(MRMap2& m, AttributeArray<Vec3>& pos, const AttributeArray<Vec3>& details, MRBank bank, uint32 from)
{
	if (from > max_level(m))
		throw std::out_of_range("synthesis: level " + std::to_string(from) + " above the finest level");
	Terms t;
	for (uint32 l = from + 1; l <= max_level(m); ++l)
	{
		check_level(m, l, bank);
		const MRLevelView2 f = level_view(m, l);
		// the rules read level l - 1, whose lines differ from those written
		foreach_cell(f, [&](V v) {
			t.clear();
			rule_terms(m, l, v, bank, t);
			const uint32 i = index_of(f, v);
			pos[i] = combine(t, pos) + details[i];
		});
	}
}

void analysis(MRMap2& m, AttributeArray<Vec3>& pos, AttributeArray<Vec3>& details, MRBank bank, uint32 to)
{
	if (to > max_level(m))
		throw std::out_of_range("analysis: level " + std::to_string(to) + " above the finest level");
	Terms t;
	struct OldVertex
	{
		Dart dart;
		uint32 below, at; // its lines at levels l - 1 and l
	};
	std::vector<OldVertex> old;
	std::vector<uint32> dense;
	std::vector<Eigen::Triplet<double>> entries;
	for (uint32 l = max_level(m); l > to; --l)
	{
		check_level(m, l, bank);
		const MRLevelView2 c = level_view(m, l - 1), f = level_view(m, l);
		old.clear();
		foreach_cell(c, [&](V v) { old.push_back({v.dart, index_of(c, v), index_of(f, v)}); });
		if (bank == MRBank::Linear)
			for (const OldVertex& v : old)
				pos[v.below] = pos[v.at];
		else
		{
			// the positions of level l - 1 whose prediction of level l is
			// closest (least squares) to level l: a well-conditioned coarse
			// fit, and the level below itself when level l is its prediction
			dense.assign(detail::mr_container<Orbit::PHI21>(detail::mr_state_of(m)).end_index(), INVALID_INDEX);
			for (uint32 i = 0; i < old.size(); ++i)
				dense[old[i].below] = i;
			entries.clear();
			std::vector<uint32> rows;
			foreach_cell(f, [&](V v) {
				t.clear();
				rule_terms(m, l, v, bank, t);
				for (auto [line, w] : t)
					entries.emplace_back(int(rows.size()), int(dense[line]), w);
				rows.push_back(index_of(f, v));
			});
			Eigen::MatrixX3d b(rows.size(), 3);
			for (uint32 r = 0; r < rows.size(); ++r)
				b.row(r) = pos[rows[r]].transpose();
			Eigen::SparseMatrix<double> s(Eigen::Index(rows.size()), Eigen::Index(old.size()));
			s.setFromTriplets(entries.begin(), entries.end()); // sums the repeated entries
			// A prediction may miss some motions of the level below (Catmull-Clark
			// on a cube: the vertices moving +v and -v alternately predict
			// nothing): a tiny pull towards the old vertices' positions at level
			// l decides those, and moves the others by a relative 1e-12.
			const Eigen::SparseMatrix<double> st = s.transpose();
			Eigen::SparseMatrix<double> normal = st * s;
			const double eps = 1e-12 * normal.diagonal().mean();
			Eigen::MatrixX3d rhs = st * b;
			for (uint32 i = 0; i < old.size(); ++i)
			{
				normal.coeffRef(i, i) += eps;
				rhs.row(i) += eps * pos[old[i].at].transpose();
			}
			Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
			if (solver.info() != Eigen::Success)
				throw std::runtime_error("analysis: the prediction of level " + std::to_string(l) + " from level " +
										 std::to_string(l - 1) + " cannot be inverted");
			const Eigen::MatrixX3d x = solver.solve(rhs);
			for (uint32 i = 0; i < old.size(); ++i)
				pos[old[i].below] = x.row(i).transpose();
		}
		// the details: what the rules miss of level l
		foreach_cell(f, [&](V v) {
			t.clear();
			rule_terms(m, l, v, bank, t);
			const uint32 i = index_of(f, v);
			details[i] = pos[i] - combine(t, pos);
		});
	}
}

namespace
{
/// Analysis down to level 0, the details of the levels `drop` says set to
/// zero, synthesis back up.
template <typename DROP>
void filter(MRMap2& m, AttributeArray<Vec3>& pos, MRBank bank, const DROP& drop)
{
	// a scratch attribute, under a name no other attribute has
	std::shared_ptr<AttributeArray<Vec3>> own;
	for (std::string name = "filter details"; !own; name += '\'')
		own = add_attribute<Vec3, MRMap2::Vertex>(m, name);
	struct Remove
	{
		MRMap2& m;
		std::shared_ptr<AttributeArray<Vec3>>& a;
		~Remove()
		{
			remove_attribute(m, a);
		}
	} remove{m, own};
	analysis(m, pos, *own, bank, 0);
	for (uint32 l = 1; l <= max_level(m); ++l)
		if (drop(l))
		{
			const MRLevelView2 f = level_view(m, l);
			foreach_cell(f, [&](V v) { (*own)[index_of(f, v)] = Vec3::Zero(); });
		}
	synthesis(m, pos, *own, bank, 0);
}
} // namespace

void filter_low_pass(MRMap2& m, AttributeArray<Vec3>& pos, MRBank bank, uint32 level)
{
	filter(m, pos, bank, [&](uint32 l) { return l > level; });
}

void filter_high_pass(MRMap2& m, AttributeArray<Vec3>& pos, MRBank bank, uint32 level)
{
	filter(m, pos, bank, [&](uint32 l) { return l <= level; });
}

} // namespace cgogn::modeling
