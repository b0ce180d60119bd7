// SPDX-License-Identifier: MIT
// CGAL Linear_cell_complex_for_combinatorial_map<3>'s side of the volume
// suite: vertex attributes with the point and the soup
// index (info), 3-attributes holding the stored barycenter. Built with
// Linear_cell_complex_incremental_builder_3 (one closed surface per tet,
// 3-sewn to its neighbours by the builder); cells walked through their
// attribute containers and one_dart_per_incident_cell ranges.
// Split: the LCC has no operator that inserts a vertex in a 3-cell
// (insert_point_in_cell is for 1- and 2-cells), so each tet is replaced by
// four with its public construction API: make_tetrahedron on the existing
// vertex attributes and the new centre, sew<3> between them, remove_cell<3>
// of the old tet, sew<3> to its former neighbours, all without attribute
// updates (every dart of the new tets already holds the right vertex
// attribute; with updates, remove_cell<3> walks the 3-D star of each of the
// four vertices to see whether it was split: 29.8 s instead of 1.5 s on
// armadillo_tet_461k). Collapse: the LCC has no tet-mesh edge collapse
// either; contract_cell<1> of the edge, then contract_cell<2> of the
// triangles around it (2-gons by then) and contract_cell<3> of the tets
// around it (two faces left each) do it. See bench/README.md.
#include "harness.h"
#include "inputs.h"
#include "workload_rules.h"

#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Linear_cell_complex_incremental_builder.h>
#include <CGAL/Simple_cartesian.h>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace cgogn_bench
{

namespace
{

using K = CGAL::Simple_cartesian<double>;
using Point = K::Point_3;
using Vector = K::Vector_3;

struct Items
{
	template <class LCC>
	struct Dart_wrapper
	{
		using Vertex_attribute = CGAL::Cell_attribute_with_point<LCC, uint32_t>; // info: soup index
		using Volume_attribute = CGAL::Cell_attribute<LCC, Point>;               // info: barycenter
		using Attributes = std::tuple<Vertex_attribute, void, void, Volume_attribute>;
	};
};

using Lcc = CGAL::Linear_cell_complex_for_combinatorial_map<3, 3, CGAL::Linear_cell_complex_traits<3, K>, Items>;
using DH = Lcc::Dart_handle;
using VAH = Lcc::Vertex_attribute_handle;

struct LccVolume
{
	Lcc m;
	std::vector<VAH> vertices; // in soup order
	std::vector<Point> buffer; // second buffer of the Jacobi smoothing, by soup index

	LccVolume(const cgogn::VolumeSoup& s, bool with_volume_attributes)
	{
		CGAL::Linear_cell_complex_incremental_builder_3<Lcc> b(m);
		for (uint32_t i = 0; i < s.nb_vertices; ++i)
		{
			const auto& p = s.positions[i];
			vertices.push_back(b.add_vertex(Point(p[0], p[1], p[2])));
			vertices.back()->info() = i;
		}
		std::size_t k = 0;
		for (uint32_t n : s.cell_sizes)
		{
			if (n == 4) // a positive tet (a, b, c, d): its four faces oriented outwards
			{
				const uint32_t* t = &s.cell_vertices[k];
				b.begin_surface();
				b.add_facet({t[0], t[2], t[1]});
				b.add_facet({t[0], t[1], t[3]});
				b.add_facet({t[1], t[2], t[3]});
				b.add_facet({t[2], t[0], t[3]});
				b.end_surface();
			}
			k += n;
		}
		if (with_volume_attributes)
		{
			for (auto d = m.one_dart_per_cell<3>().begin(); d != m.one_dart_per_cell<3>().end(); ++d)
				m.set_attribute<3>(d, m.create_attribute<3>(Point(0, 0, 0)));
			buffer.resize(s.nb_vertices);
		}
	}
	void reset_positions()
	{
		const auto& s = volume_soup();
		for (uint32_t i = 0; i < s.nb_vertices; ++i)
			vertices[i]->point() = Point(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
	}
};

LccVolume& mesh()
{
	return Cache::get<LccVolume>("cgal_lcc/volume", [] { return std::make_unique<LccVolume>(volume_soup(), true); });
}

void circulator(benchmark::State& state, bool first)
{
	Lcc& m = mesh().m;
	int64_t c = 0, incidences = 0;
	timed(
		state, first, [] {},
		[&] {
			c = 0;
			for (auto& v : m.vertex_attributes())
				for (auto it = m.one_dart_per_incident_cell<3, 0>(v.dart()).begin(),
						  end = m.one_dart_per_incident_cell<3, 0>(v.dart()).end();
					 it != end; ++it)
					++c;
			incidences = c;
			for (auto& w : m.attributes<3>())
				for (auto it = m.one_dart_per_incident_cell<0, 3, 2>(w.dart()).begin(),
						  end = m.one_dart_per_incident_cell<0, 3, 2>(w.dart()).end();
					 it != end; ++it)
					--c;
			benchmark::DoNotOptimize(c);
		});
	set_check(state, "check", double(c));
	set_check(state, "check_incidences", double(incidences));
}

void circulator2(benchmark::State& state, bool first)
{
	LccVolume& me = mesh();
	Lcc& m = me.m;
	int64_t total = 0;
	std::vector<uint32_t> last(me.vertices.size());
	timed(
		state, first, [&] { std::fill(last.begin(), last.end(), std::numeric_limits<uint32_t>::max()); },
		[&] {
			total = 0;
			for (auto& v : m.vertex_attributes())
			{
				const uint32_t i = v.info();
				for (auto w = m.one_dart_per_incident_cell<3, 0>(v.dart()).begin(),
						  wend = m.one_dart_per_incident_cell<3, 0>(v.dart()).end();
					 w != wend; ++w)
					for (auto u = m.one_dart_per_incident_cell<0, 3, 2>(w).begin(),
							  uend = m.one_dart_per_incident_cell<0, 3, 2>(w).end();
						 u != uend; ++u)
					{
						const uint32_t j = m.vertex_attribute(u)->info();
						if (j != i && last[j] != i)
						{
							last[j] = i;
							++total;
						}
					}
			}
			benchmark::DoNotOptimize(total);
		});
	set_check(state, "check", double(total));
}

void barycenter(benchmark::State& state, bool first)
{
	Lcc& m = mesh().m;
	timed(
		state, first, [] {},
		[&] {
			// the vertices of a tet as 2-D vertices of its own surface (<0, 3, 2>):
			// (barycenter<3> and <0, 3> mark whole 3-D vertex orbits: much slower)
			for (auto& w : m.attributes<3>())
			{
				Vector b(0, 0, 0);
				int n = 0;
				for (auto it = m.one_dart_per_incident_cell<0, 3, 2>(w.dart()).begin(),
						  end = m.one_dart_per_incident_cell<0, 3, 2>(w.dart()).end();
					 it != end; ++it, ++n)
					b = b + (m.point(it) - CGAL::ORIGIN);
				w.info() = CGAL::ORIGIN + b / double(n);
			}
		});
	double s = 0;
	for (auto& w : m.attributes<3>())
		s += w.info().x() + w.info().y() + w.info().z();
	set_check(state, "check", s);
}

void smoothing_pass(LccVolume& me)
{
	Lcc& m = me.m;
	for (auto& v : m.vertex_attributes())
	{
		Vector s(0, 0, 0);
		int n = 0;
		for (auto it = m.one_dart_per_incident_cell<1, 0>(v.dart()).begin(),
				  end = m.one_dart_per_incident_cell<1, 0>(v.dart()).end();
			 it != end; ++it, ++n)
			s = s + (m.point(m.other_extremity(it)) - CGAL::ORIGIN);
		me.buffer[v.info()] = CGAL::ORIGIN + s / double(n);
	}
	for (auto& v : m.vertex_attributes())
		v.point() = me.buffer[v.info()];
}

/// The sum of every vertex's coordinates (the checks of smoothing and split).
double position_sum(Lcc& m)
{
	double s = 0;
	for (auto& v : m.vertex_attributes())
		s += v.point().x() + v.point().y() + v.point().z();
	return s;
}

void smoothing(benchmark::State& state, bool first)
{
	LccVolume& me = mesh();
	timed(
		state, first, [&] { me.reset_positions(); }, [&] { smoothing_pass(me); });
	me.reset_positions();
	for (uint32_t i = 0; i < volume_smoothing_check_passes; ++i)
		smoothing_pass(me);
	set_check(state, "check", position_sum(me.m));
}

// ---- split: every original tet 1-to-4 at its barycenter

// Sews the triangle of dart a to the triangle of dart b (opposite
// orientations): beta3 links the two darts of an edge, one from each face,
// that run in opposite directions (beta3 of A->B is B->A), so b is first
// turned to the dart starting where a ends.
void sew_triangles(Lcc& m, DH a, DH b)
{
	const VAH end_of_a = m.vertex_attribute(m.beta<1>(a));
	for (int k = 0; k < 3 && m.vertex_attribute(b) != end_of_a; ++k)
		b = m.beta<1>(b);
	m.sew<3>(a, b, false);
}

// Replaces the tet of w by four tets around a new vertex at its barycenter.
// The tet's faces, seen from w = A->B in face (A, B, C), with D the fourth
// vertex: F0 = (A, B, C) at w, F1 = (B, A, D) at beta2(w), F2 = (C, B, D) at
// beta2(beta1(w)), F3 = (A, C, D) at beta2(beta0(w)); the new tet i is
// make_tetrahedron(Fi, X), whose returned dart is the old face's dart at the
// same edge in the same direction, so it is 3-sewn to the old face's
// neighbour directly.
void split_tet(Lcc& m, DH w, uint32_t new_info)
{
	const DH face[4] = {w, m.beta<2>(w), m.beta<2>(m.beta<1>(w)), m.beta<2>(m.beta<0>(w))};
	VAH v[4][3];
	DH outside[4];
	for (int i = 0; i < 4; ++i)
	{
		v[i][0] = m.vertex_attribute(face[i]);
		v[i][1] = m.vertex_attribute(m.beta<1>(face[i]));
		v[i][2] = m.vertex_attribute(m.beta<0>(face[i]));
		outside[i] = m.is_free<3>(face[i]) ? m.null_handle : m.beta<3>(face[i]);
	}
	const VAH A = v[0][0], B = v[0][1], C = v[0][2], D = v[1][2];
	const Vector b = ((A->point() - CGAL::ORIGIN) + (B->point() - CGAL::ORIGIN) + (C->point() - CGAL::ORIGIN) +
					  (D->point() - CGAL::ORIGIN)) /
					 4.0;
	const VAH X = m.create_vertex_attribute(CGAL::ORIGIN + b);
	X->info() = new_info;
	DH t[4];
	for (int i = 0; i < 4; ++i)
		t[i] = m.make_tetrahedron(v[i][0], v[i][1], v[i][2], X);
	// the six inner faces, each at the shared edge of two outer faces (see the
	// faces of make_tetrahedron(h0, h1, h2, h3): beta2 of its dart h0->h1 is
	// (h1, h0, h3), of h1->h2 is (h1, h3, h2), of h2->h0 is (h3, h0, h2))
	auto e01 = [&](DH d) { return m.beta<2>(d); };
	auto e12 = [&](DH d) { return m.beta<2>(m.beta<1>(d)); };
	auto e20 = [&](DH d) { return m.beta<2>(m.beta<0>(d)); };
	sew_triangles(m, e01(t[0]), e01(t[1])); // edge AB
	sew_triangles(m, e12(t[0]), e01(t[2])); // edge BC
	sew_triangles(m, e20(t[0]), e01(t[3])); // edge CA
	sew_triangles(m, e12(t[1]), e20(t[3])); // edge AD
	sew_triangles(m, e20(t[1]), e12(t[2])); // edge DB
	sew_triangles(m, e20(t[2]), e12(t[3])); // edge DC
	m.remove_cell<3>(w, false);
	for (int i = 0; i < 4; ++i)
		if (outside[i] != m.null_handle)
			m.sew<3>(t[i], outside[i], false);
}

void split(benchmark::State& state, bool)
{
	std::unique_ptr<LccVolume> me;
	timed(
		state, false, [&] { me = fresh_structure<LccVolume>(volume_soup(), false); },
		[&] {
			Lcc& m = me->m;
			std::vector<DH> tets;
			for (auto d = m.one_dart_per_cell<3>().begin(); d != m.one_dart_per_cell<3>().end(); ++d)
				tets.push_back(d);
			uint32_t next = uint32_t(me->vertices.size());
			for (DH w : tets)
				split_tet(m, w, next++);
		});
	Lcc& m = me->m;
	set_check(state, "check_V", double(m.vertex_attributes().size()));
	set_check(state, "check_T", double(m.one_dart_per_cell<3>().size()));
	set_check(state, "check_position_sum", position_sum(m)); // the new vertices at the barycenters
	set_check(state, "check_valid", m.is_valid() ? 1.0 : 0.0);
}

// ---- collapse: 7 times the shortest edge with both end points interior

bool on_boundary(const Lcc& m, Lcc::Dart_const_handle d)
{
	for (auto it = m.darts_of_cell<0>(d).begin(), end = m.darts_of_cell<0>(d).end(); it != end; ++it)
		if (m.is_free<3>(it))
			return true;
	return false;
}

// Collapses the interior edge of e to its midpoint mid, with the LCC's cell
// contractions: the edge (contract_cell<1>, which merges the two vertex
// attributes), then each triangle around it, a 2-gon now (contract_cell<2>),
// then each tet around it, whose two remaining faces are now the same
// triangle (contract_cell<3>). Darts of the cells contracted later are taken
// before: around the edge, x and beta2(x) are the two faces of one tet at the
// edge, beta3 goes to the next tet; beta1 of a dart of a face at the edge
// survives the edge's contraction, and beta2(beta1(x)) is in a face of x's
// tet away from the edge, which survives the 2-gons' contractions. Returns
// the kept vertex.
VAH collapse_edge(Lcc& m, DH e, const Point& mid)
{
	std::vector<DH> two_gons, tets;
	DH x = e;
	do
	{
		tets.push_back(m.beta<2>(m.beta<1>(x)));
		const DH y = m.beta<2>(x);
		two_gons.push_back(m.beta<1>(y));
		x = m.beta<3>(y);
	} while (x != e);
	m.contract_cell<1>(e);
	const VAH kept = m.vertex_attribute(two_gons.front());
	for (DH f : two_gons)
		m.contract_cell<2>(f);
	for (DH t : tets)
		m.contract_cell<3>(t);
	kept->point() = mid;
	return kept;
}

void collapse(benchmark::State& state, bool)
{
	std::unique_ptr<LccVolume> me;
	std::vector<double> lengths;
	timed(
		state, false, [&] { me = fresh_structure<LccVolume>(volume_soup(), false); },
		[&] {
			Lcc& m = me->m;
			lengths.clear();
			// boundary status cached per vertex (by soup index)
			std::vector<uint8_t> boundary(me->vertices.size());
			for (auto& v : m.vertex_attributes())
				boundary[v.info()] = on_boundary(m, v.dart());
			for (uint32_t k = 0; k < volume_collapses; ++k)
			{
				DH best = m.null_handle;
				ShortestEdge shortest;
				for (auto d = m.one_dart_per_cell<1>().begin(), end = m.one_dart_per_cell<1>().end(); d != end; ++d)
				{
					const VAH a = m.vertex_attribute(d), b = m.vertex_attribute(m.other_extremity(d));
					if (boundary[a->info()] || boundary[b->info()])
						continue;
					if (shortest.offer(std::sqrt(CGAL::squared_distance(a->point(), b->point())), a->point(),
									   b->point()))
						best = d;
				}
				lengths.push_back(shortest.length);
				const Point mid(shortest.midpoint[0], shortest.midpoint[1], shortest.midpoint[2]);
				const VAH kept = collapse_edge(m, best, mid);
				boundary[kept->info()] = on_boundary(m, kept->dart());
			}
		});
	Lcc& m = me->m;
	for (uint32_t k = 0; k < lengths.size(); ++k)
		set_check(state, "check_len" + std::to_string(k), lengths[k]);
	set_check(state, "check_V", double(m.vertex_attributes().size()));
	set_check(state, "check_T", double(m.one_dart_per_cell<3>().size()));
	set_check(state, "check_valid", m.is_valid() ? 1.0 : 0.0);
}

void memory(benchmark::State& state, bool)
{
	Cache::clear();
	const auto& s = volume_soup();
	std::size_t bytes = 0;
	for (auto _ : state)
	{
		trim_heap();
		const std::size_t before = heap_bytes();
		auto me = std::make_unique<LccVolume>(s, false);
		me->vertices = {};
		me->vertices.shrink_to_fit(); // the handle table is the benchmark's, not the structure's
		bytes = heap_bytes() - before;
		state.SetIterationTime(1e-9);
		benchmark::DoNotOptimize(me.get());
	}
	state.counters["bytes"] = double(bytes);
	state.counters["bytes_per_tet"] = double(bytes) / double(s.cell_sizes.size());
	state.counters["bytes_per_vertex"] = double(bytes) / double(s.nb_vertices);
	state.counters["peak_rss_MB"] = double(peak_resident_bytes()) / 1e6;
}

const bool registered = [] {
	register_bench("volume/circulator/cgal_lcc", Kind::read_only, circulator);
	register_bench("volume/circulator2/cgal_lcc", Kind::read_only, circulator2);
	register_bench("volume/barycenter/cgal_lcc", Kind::read_only, barycenter);
	register_bench("volume/smoothing/cgal_lcc", Kind::read_only, smoothing);
	register_bench("volume/split/cgal_lcc", Kind::topology, split);
	register_bench("volume/collapse/cgal_lcc", Kind::topology, collapse);
	register_bench("memory/volume/cgal_lcc", Kind::single, memory);
	return true;
}();

} // namespace

} // namespace cgogn_bench
