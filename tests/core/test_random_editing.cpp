// SPDX-License-Identifier: MIT
// Randomized editing of real meshes: every 2-map and 3-map operator, each
// guarded by its predicate, on meshes with boundaries, polygons, several
// components and pinched vertices, with every orbit indexed and an incidence
// cache built. After each step: check_integrity, every line that survived
// still holds the value it had, and every new line holds the value of a
// cell that existed before the step (the tags are integers: their rule
// copies a parent's value) or the default (a cell with no parent of its
// orbit, such as the edge cut_face adds).
//
// A step is an applied edit (draws the predicates refuse do not count). The
// suite runs 20,000 steps per map type (the 3-map steps split 60/40 between
// a tetrahedral and a hexahedral region); CGOGN_RANDOM_EDITING_STEPS=<n> sets
// the steps per map type (1000000 for the long run, see README).
// The meshes are the repository's test data (CGOGN_DATA_DIR): a missing one fails.
#include <cgogn/cgogn.h>

#include "cgogn_test_data.h"
#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace cgogn_test_random_editing
{

using namespace cgogn;

namespace
{
// The steps of one map type: 20,000 in the suite, CGOGN_RANDOM_EDITING_STEPS
// when set; a test takes `percent` of them.
uint32 steps_of_map_type(uint32 percent)
{
	const char* s = std::getenv("CGOGN_RANDOM_EDITING_STEPS");
	const uint64 total = s != nullptr && *s != '\0' ? uint64(std::stoull(s)) : 20000u;
	return uint32(total * percent / 100);
}

// The values of one indexed orbit's tag attribute, line by line: lines that
// survive a step keep their value, new ones copy a parent's tag (or hold 0)
// and get a fresh tag at the next snapshot when they hold 0.
template <typename CELL, typename MAP>
class TagWatch
{
public:
	TagWatch(MAP& m, const std::string& name) : m_(m), tag_(get_attribute<uint32, CELL>(m, name))
	{
		EXPECT_NE(tag_, nullptr) << name;
	}
	// Gives a fresh tag to every line at the default, then remembers all values.
	void snapshot()
	{
		const AttributeContainer& c = container_of<CELL::ORBIT>(m_);
		before_.assign(c.end_index(), 0);
		values_.clear();
		for (uint32 i = 0; i < c.end_index(); ++i)
			if (c.is_live(i))
			{
				if ((*tag_)[i] == 0)
					(*tag_)[i] = next_++;
				before_[i] = (*tag_)[i];
				values_.insert(before_[i]);
			}
	}
	// Follows the lines moved by compact().
	void remap(const CompactMaps& maps)
	{
		const std::vector<uint32>& old_to_new = maps.cells[orbit_index(CELL::ORBIT)];
		std::vector<uint32> moved(before_.size(), 0);
		for (uint32 i = 0; i < before_.size() && i < old_to_new.size(); ++i)
			if (old_to_new[i] != INVALID_INDEX)
				moved[old_to_new[i]] = before_[i];
		before_ = std::move(moved);
	}
	// The first line that is live, was live before and changed value (or INVALID_INDEX).
	uint32 changed_line() const
	{
		const AttributeContainer& c = container_of<CELL::ORBIT>(m_);
		for (uint32 i = 0; i < before_.size(); ++i)
			if (before_[i] != 0 && c.is_live(i) && (*tag_)[i] != before_[i] && (*tag_)[i] != 0)
				return i;
		return INVALID_INDEX;
	}
	// The first line that is live, was not live before and holds a value no
	// line held before (nor 0): a value that no rule gives (or INVALID_INDEX).
	uint32 orphan_line() const
	{
		const AttributeContainer& c = container_of<CELL::ORBIT>(m_);
		for (uint32 i = 0; i < c.end_index(); ++i)
			if (c.is_live(i) && (i >= before_.size() || before_[i] == 0) && (*tag_)[i] != 0 &&
				!values_.contains((*tag_)[i]))
				return i;
		return INVALID_INDEX;
	}

private:
	MAP& m_;
	std::shared_ptr<AttributeArray<uint32>> tag_;
	std::vector<uint32> before_;
	std::unordered_set<uint32> values_; // every value before the step
	uint32 next_ = 1;
};

template <typename CELL, typename MAP>
CELL pick(const MAP& m, std::mt19937& rng)
{
	std::vector<CELL> cells;
	foreach_cell(m, [&](CELL c) { cells.push_back(c); });
	if (cells.empty())
		return CELL();
	return cells[std::uniform_int_distribution<std::size_t>(0, cells.size() - 1)(rng)];
}

// A random live dart satisfying pred (invalid when none does).
template <typename MAP, typename PRED>
Dart pick_dart(const MAP& m, std::mt19937& rng, PRED pred)
{
	std::vector<Dart> darts;
	foreach_dart(m, [&](Dart d) {
		if (pred(d))
			darts.push_back(d);
	});
	if (darts.empty())
		return Dart();
	return darts[std::uniform_int_distribution<std::size_t>(0, darts.size() - 1)(rng)];
}

// Up to `tries` random draws of `draw()`, until `accepts` takes one (an
// invalid cell when none is taken): operators whose predicates refuse most
// cells of an edited region still get their share of the steps.
template <typename DRAW, typename ACCEPTS>
auto first_accepted(uint32 tries, const DRAW& draw, const ACCEPTS& accepts) -> decltype(draw())
{
	for (uint32 i = 0; i < tries; ++i)
	{
		const auto c = draw();
		if (c.dart.is_valid() && accepts(c))
			return c;
	}
	return decltype(draw())();
}

// A random dart of the orbit of c.
template <typename MAP, typename CELL>
Dart dart_of(const MAP& m, CELL c, std::mt19937& rng)
{
	std::vector<Dart> darts;
	foreach_dart_of_orbit(m, c, [&](Dart d) { darts.push_back(d); });
	return darts[std::uniform_int_distribution<std::size_t>(0, darts.size() - 1)(rng)];
}

// ---- 2-maps

using V2 = CMap2::Vertex;
using E2 = CMap2::Edge;
using F2 = CMap2::Face;
using W2 = CMap2::Volume;

// The path of a mesh of the repository's test data; empty when it is missing.
std::string data_file(const char* name)
{
	const std::string path = cgogn_test_data::path(name);
	return std::filesystem::exists(path) ? path : std::string();
}

// Small real meshes with polygons, boundaries and several components, in one map.
bool load_surfaces(CMap2& m)
{
	bool any = false;
	for (const char* name : {"surface/L.off", "surface/edge_onering.off", "surface/vertex_onering.off",
							 "surface/cube_quad.off", "surface/torus_quad.off", "surface/geomview_cam.off",
							 "surface/geomview_hypercube_2skeleton.off", "surface/tetrahedron.off"})
	{
		const std::string path = data_file(name);
		if (path.empty())
			continue;
		CMap2 part;
		io::load_surface(part, path);
		merge(m, part);
		any = true;
	}
	return any;
}

// One random operator; returns its name when it was applied, nullptr otherwise.
const char* edit_surface(CMap2& m, std::mt19937& rng, uint32 initial_darts, CompactMaps& compacted)
{
	const bool may_grow = nb_darts(m) < 3 * initial_darts;
	const bool may_shrink = nb_darts(m) > initial_darts / 2;
	switch (std::uniform_int_distribution<int>(0, 19)(rng))
	{
	case 0:
		if (!may_grow)
			return nullptr;
		cut_edge(m, pick<E2>(m, rng));
		return "cut_edge";
	case 1: {
		const E2 e(pick_dart(m, rng, [](Dart) { return true; }));
		if (!may_shrink || !can_collapse_edge(m, e))
			return nullptr;
		collapse_edge(m, e);
		return "collapse_edge";
	}
	case 2: {
		const E2 e = pick<E2>(m, rng);
		if (!can_flip_edge(m, e))
			return nullptr;
		flip_edge(m, e);
		return "flip_edge";
	}
	case 3: {
		const E2 e(pick_dart(m, rng, [&](Dart d) { return !is_boundary(m, d); }));
		if (!can_flip_back_edge(m, e))
			return nullptr;
		flip_back_edge(m, e);
		return "flip_back_edge";
	}
	case 4: {
		const F2 f = pick<F2>(m, rng);
		const Dart d = dart_of(m, f, rng), e = dart_of(m, f, rng);
		if (!may_grow || !can_cut_face(m, V2(d), V2(e)))
			return nullptr;
		cut_face(m, V2(d), V2(e));
		return "cut_face";
	}
	case 5: {
		const E2 e = pick<E2>(m, rng);
		if (!can_merge_incident_faces(m, e))
			return nullptr;
		merge_incident_faces(m, e);
		return "merge_incident_faces(edge)";
	}
	case 6: {
		const V2 v(pick_dart(m, rng, [](Dart) { return true; }));
		if (!can_merge_incident_faces(m, v))
			return nullptr;
		merge_incident_faces(m, v);
		return "merge_incident_faces(vertex)";
	}
	case 7: {
		const V2 v(pick_dart(m, rng, [](Dart) { return true; }));
		if (!can_merge_incident_edges(m, v))
			return nullptr;
		merge_incident_edges(m, v);
		return "merge_incident_edges";
	}
	case 8: {
		const V2 v = pick<V2>(m, rng);
		const Dart d1 = dart_of(m, v, rng), d2 = dart_of(m, v, rng);
		if (!may_grow || !can_split_vertex(m, d1, d2))
			return nullptr;
		split_vertex(m, d1, d2);
		return "split_vertex";
	}
	case 9: {
		const F2 f = pick<F2>(m, rng);
		if (!may_grow || is_boundary(m, f.dart) || codegree(m, f) > 8)
			return nullptr;
		triangulate_face(m, f);
		return "triangulate_face";
	}
	case 10: {
		const F2 f = pick<F2>(m, rng);
		if (!may_shrink || is_boundary(m, f.dart))
			return nullptr;
		remove_face(m, f);
		return "remove_face";
	}
	case 11: {
		const Dart b = pick_dart(m, rng, [&](Dart d) { return is_boundary(m, d); });
		if (!b.is_valid() || !can_fill_hole_with_face(m, b))
			return nullptr;
		fill_hole_with_face(m, b);
		return "fill_hole_with_face";
	}
	case 12:
	case 13: {
		auto on_boundary = [&](Dart d) { return !is_boundary(m, d) && is_boundary(m, phi2(m, d)); };
		const Dart d1 = pick_dart(m, rng, on_boundary), d2 = pick_dart(m, rng, on_boundary);
		if (!d1.is_valid() || !can_sew_faces(m, E2(d1), E2(d2)))
			return nullptr;
		sew_faces(m, E2(d1), E2(d2));
		return "sew_faces";
	}
	case 14: {
		const E2 e = pick<E2>(m, rng);
		if (!can_unsew_faces(m, e))
			return nullptr;
		unsew_faces(m, e);
		return "unsew_faces";
	}
	case 15: {
		if (!may_grow)
			return nullptr;
		switch (rng() % 3)
		{
		case 0:
			add_tetra(m);
			break;
		case 1:
			add_pyramid(m, 3 + rng() % 3);
			break;
		default:
			add_prism(m, 3 + rng() % 3);
		}
		return "add_polyhedron";
	}
	case 16: {
		const W2 w = pick<W2>(m, rng);
		if (!may_shrink || nb_connected_components(m) < 3)
			return nullptr;
		remove_volume(m, w);
		return "remove_volume";
	}
	case 17:
		if (rng() % 64 != 0)
			return nullptr;
		compacted = compact(m);
		return "compact";
	case 18:
		if (rng() % 32 != 0)
			return nullptr;
		reverse_orientation(m);
		return "reverse_orientation";
	default: {
		if (!may_grow || rng() % 16 != 0)
			return nullptr;
		CMap2 other;
		build_surface(other, grid_soup(2, 1, rng() % 2 == 0));
		merge(m, other);
		return "merge";
	}
	}
}

// ---- 3-maps

using V3 = CMap3::Vertex;
using E3 = CMap3::Edge;
using F3 = CMap3::Face;
using W3 = CMap3::Volume;

// A connected region of about `size` volumes of a real mesh (the rest is
// removed): a mesh with a boundary small enough to check every step.
bool load_region(CMap3& m, const char* name, uint32 size)
{
	const std::string path = data_file(name);
	if (path.empty())
		return false;
	io::load_volume(m, path);
	CellMarker<CMap3, W3> kept(m);
	std::vector<W3> queue{test::all<W3>(m)[0]};
	kept.mark(queue[0]);
	for (std::size_t i = 0; i < queue.size() && queue.size() < size; ++i)
		foreach_adjacent_volume_through_face(m, queue[i], [&](W3 w) {
			if (!kept.is_marked(w) && queue.size() < size)
			{
				kept.mark(w);
				queue.push_back(w);
			}
		});
	std::vector<W3> others;
	foreach_cell(m, [&](W3 w) {
		if (!kept.is_marked(w))
			others.push_back(w);
	});
	for (W3 w : others)
		remove_volume(m, w);
	return true;
}

bool is_tetrahedron(const CMap3& m, W3 w)
{
	uint32 darts = 0;
	bool triangles = true;
	foreach_dart_of_orbit(m, w, [&](Dart d) {
		++darts;
		triangles = triangles && phi<1, 1, 1>(m, d) == d;
		return triangles && darts <= 12;
	});
	return triangles && darts == 12;
}

// A random walk along the edges of one volume, from a random vertex of it back
// to that vertex, never through another vertex twice (empty when it fails).
std::vector<Dart> random_closed_path(const CMap3& m, std::mt19937& rng)
{
	Dart d = pick_dart(m, rng, [&](Dart x) { return !is_boundary(m, x); });
	if (!d.is_valid())
		return {};
	std::vector<Dart> path{d};
	while (path.size() < 12)
	{
		const Dart at = phi1(m, path.back());
		if (same_orbit(m, CMap3::Vertex2(at), CMap3::Vertex2(path[0])))
			return path;
		for (Dart p : path)
			if (same_orbit(m, CMap3::Vertex2(at), CMap3::Vertex2(p)))
				return {};
		Dart next = dart_of(m, CMap3::Vertex2(at), rng);
		if (next == phi2(m, path.back()))
			next = phi2(m, phi_1(m, next)); // not straight back
		path.push_back(next);
	}
	return {};
}

const char* edit_volume(CMap3& m, std::mt19937& rng, uint32 initial_darts, CompactMaps& compacted)
{
	const bool may_grow = nb_darts(m) < 3 * initial_darts;
	const bool may_shrink = nb_darts(m) > initial_darts / 2;
	switch (std::uniform_int_distribution<int>(0, 16)(rng))
	{
	case 0:
	case 13:
		if (!may_grow || rng() % 4 != 0)
			return nullptr;
		cut_edge(m, pick<E3>(m, rng));
		return "cut_edge";
	case 1: {
		if (!may_grow)
			return nullptr;
		for (uint32 i = 0; i < 8; ++i)
		{
			const W3 w = pick<W3>(m, rng);
			const Dart d = dart_of(m, w, rng);
			const Dart e = dart_of(m, F3(d), rng);
			if (can_cut_face(m, d, e))
			{
				cut_face(m, d, e);
				return "cut_face";
			}
		}
		return nullptr;
	}
	case 2: {
		const E3 e = pick<E3>(m, rng);
		if (!can_merge_incident_faces(m, e))
			return nullptr;
		merge_incident_faces(m, e);
		return "merge_incident_faces";
	}
	case 3: {
		const F3 f = pick<F3>(m, rng);
		if (!may_shrink || !can_merge_incident_volumes(m, f))
			return nullptr;
		merge_incident_volumes(m, f);
		return "merge_incident_volumes";
	}
	case 4:
	case 5: {
		const W3 w = pick<W3>(m, rng);
		if (!may_grow || !is_tetrahedron(m, w))
			return nullptr;
		// four triangles that are not glued as a tetrahedron's are refused
		// with an error, the map unchanged
		const uint32 darts = nb_darts(m);
		try
		{
			split_tetra(m, w);
		}
		catch (const TopologyError&)
		{
			EXPECT_EQ(nb_darts(m), darts);
			return nullptr;
		}
		return "split_tetra";
	}
	case 6:
	case 7: {
		if (!may_shrink)
			return nullptr;
		const E3 e = first_accepted(
			8, [&] { return E3(pick_dart(m, rng, [&](Dart d) { return !is_boundary(m, d); })); },
			[&](E3 x) { return can_collapse_edge(m, x); });
		if (!e.dart.is_valid())
			return nullptr;
		collapse_edge(m, e);
		return "collapse_edge";
	}
	case 8: {
		const F3 f = first_accepted(
			8, [&] { return pick<F3>(m, rng); }, [&](F3 x) { return can_flip_face(m, x); });
		if (!f.dart.is_valid())
			return nullptr;
		flip_face(m, f);
		return "flip_face";
	}
	case 9: {
		const E3 e = first_accepted(
			8, [&] { return pick<E3>(m, rng); }, [&](E3 x) { return can_flip_edge(m, x); });
		if (!e.dart.is_valid())
			return nullptr;
		flip_edge(m, e);
		return "flip_edge";
	}
	case 10: {
		if (rng() % 2 != 0) // one draw in two: it is never refused
			return nullptr;
		const F3 f(pick_dart(m, rng, [&](Dart d) { return !is_boundary(m, d) && !is_boundary(m, phi3(m, d)); }));
		if (!f.dart.is_valid())
			return nullptr;
		unsew_volumes(m, f);
		return "unsew_volumes";
	}
	case 11: {
		// mostly a face with the same corners (sewing back what was unsewn),
		// else any face of the mesh's boundary
		const auto on_boundary = [&](Dart d) { return !is_boundary(m, d) && is_boundary(m, phi3(m, d)); };
		const F3 f1(pick_dart(m, rng, on_boundary));
		if (!f1.dart.is_valid())
			return nullptr;
		const auto matches = [&](Dart c) {
			Dart x = f1.dart, y = c;
			do
			{
				if (index_of(m, V3(y)) != index_of(m, V3(phi1(m, x))))
					return false;
				x = phi1(m, x);
				y = phi_1(m, y);
			} while (x != f1.dart && y != c);
			return x == f1.dart && y == c;
		};
		const bool matching = rng() % 4 != 0;
		const F3 f2(pick_dart(m, rng, [&](Dart d) { return on_boundary(d) && (!matching || matches(d)); }));
		if (!f2.dart.is_valid() || !can_sew_volumes(m, f1, f2))
			return nullptr;
		sew_volumes(m, f1, f2);
		return "sew_volumes";
	}
	case 12: {
		// one draw in three: removals would otherwise outnumber the edits
		// that need an interior
		if (!may_shrink || rng() % 3 != 0)
			return nullptr;
		remove_volume(m, pick<W3>(m, rng));
		return "remove_volume";
	}
	case 14: {
		if (!may_grow || rng() % 4 != 0)
			return nullptr;
		if (rng() % 2 == 0)
			add_tetra(m);
		else
			add_hexa(m);
		return "add_volume";
	}
	case 15: {
		const std::vector<Dart> path = random_closed_path(m, rng);
		if (!may_grow || !can_cut_volume(m, path))
			return nullptr;
		cut_volume(m, path);
		return "cut_volume";
	}
	default:
		if (rng() % 64 != 0)
			return nullptr;
		compacted = compact(m);
		return "compact";
	}
}

// The tag watches of every orbit a map indexes (2-maps: vertices, edges,
// faces, components; 3-maps also the sub-cells of one volume and components).
template <typename MAP>
class TagWatches
{
	using V = typename mesh_traits<MAP>::Vertex;
	using E = typename mesh_traits<MAP>::Edge;
	using F = typename mesh_traits<MAP>::Face;
	using W = typename mesh_traits<MAP>::Volume;

public:
	explicit TagWatches(MAP& m) : v_(m, "vtag"), e_(m, "etag"), f_(m, "ftag"), w_(m, "wtag")
	{
		if constexpr (MAP::dimension == 3)
			sub_ = std::make_unique<Sub3>(m);
	}
	void snapshot()
	{
		v_.snapshot();
		e_.snapshot();
		f_.snapshot();
		w_.snapshot();
		if constexpr (MAP::dimension == 3)
			sub_->snapshot();
	}
	void remap(const CompactMaps& c)
	{
		v_.remap(c);
		e_.remap(c);
		f_.remap(c);
		w_.remap(c);
		if constexpr (MAP::dimension == 3)
			sub_->remap(c);
	}
	// The name of the first orbit with a surviving line whose value changed
	// (empty when none).
	std::string changed() const
	{
		if (v_.changed_line() != INVALID_INDEX)
			return "vertex";
		if (e_.changed_line() != INVALID_INDEX)
			return "edge";
		if (f_.changed_line() != INVALID_INDEX)
			return "face";
		if (w_.changed_line() != INVALID_INDEX)
			return MAP::dimension == 2 ? "component" : "volume";
		if constexpr (MAP::dimension == 3)
			return sub_->changed();
		return {};
	}
	// The name of the first orbit with a new line whose value no rule gives
	// (empty when none).
	std::string orphan() const
	{
		if (v_.orphan_line() != INVALID_INDEX)
			return "vertex";
		if (e_.orphan_line() != INVALID_INDEX)
			return "edge";
		if (f_.orphan_line() != INVALID_INDEX)
			return "face";
		if (w_.orphan_line() != INVALID_INDEX)
			return MAP::dimension == 2 ? "component" : "volume";
		return {};
	}

private:
	struct Sub3
	{
		explicit Sub3(CMap3& m) : f2(m, "f2tag"), e2(m, "e2tag"), v2(m, "v2tag"), cc(m, "cctag")
		{
		}
		void snapshot()
		{
			f2.snapshot();
			e2.snapshot();
			v2.snapshot();
			cc.snapshot();
		}
		void remap(const CompactMaps& c)
		{
			f2.remap(c);
			e2.remap(c);
			v2.remap(c);
			cc.remap(c);
		}
		std::string changed() const
		{
			if (f2.changed_line() != INVALID_INDEX)
				return "face of a volume";
			if (e2.changed_line() != INVALID_INDEX)
				return "edge of a volume";
			if (v2.changed_line() != INVALID_INDEX)
				return "vertex of a volume";
			if (cc.changed_line() != INVALID_INDEX)
				return "component";
			return {};
		}
		TagWatch<CMap3::Face2, CMap3> f2;
		TagWatch<CMap3::Edge2, CMap3> e2;
		TagWatch<CMap3::Vertex2, CMap3> v2;
		TagWatch<CMap3::CC, CMap3> cc;
	};
	TagWatch<V, MAP> v_;
	TagWatch<E, MAP> e_;
	TagWatch<F, MAP> f_;
	TagWatch<W, MAP> w_;
	// on the heap: GCC 12 reports a std::optional of it as maybe-uninitialized
	std::unique_ptr<Sub3> sub_;
};

// Applies `steps` random edits (`edit` returns the operator's name, or nullptr
// when its predicate refused the drawn cells and it changed nothing) with
// every orbit indexed and an incidence cache rebuilt every 4 edits; after
// each edit the map passes check_integrity and no surviving line of any
// orbit changed its value. Refused draws do not count as steps; the test
// fails when fewer than one draw in `max_draws_per_step` edits. `after`
// runs after each edit (keeps the map non-empty).
template <typename MAP, typename EDIT, typename AFTER>
void random_editing(MAP& m, uint32 steps, uint32 seed, uint32 max_draws_per_step, const EDIT& edit, const AFTER& after)
{
	using V = typename mesh_traits<MAP>::Vertex;
	using F = typename mesh_traits<MAP>::Face;
	using W = typename mesh_traits<MAP>::Volume;
	using Top = std::conditional_t<MAP::dimension == 2, F, W>;
	test::index_everything(m);
	TagWatches<MAP> tags(m);
	// a field the operators interpolate: new vertices stay in the range of
	// the old ones (or hold 0, the default, when they have no parent)
	auto heat = add_attribute<double, V>(m, "heat");
	std::mt19937 heat_rng(seed + 1);
	// the range of the values, after giving one to the vertices without a
	// parent (those of add_volume), as the tags get fresh values
	const auto heat_range = [&] {
		std::pair<double, double> r{1e300, -1e300};
		foreach_cell(m, [&](V v) {
			double& h = value<double>(m, heat, v);
			if (h == 0.0)
				h = std::uniform_real_distribution<double>(1.0, 2.0)(heat_rng);
			r = {std::min(r.first, h), std::max(r.second, h)};
		});
		return r;
	};
	// the range of the values the step gave (the default, 0, left out)
	const auto heat_given = [&] {
		std::pair<double, double> r{1e300, -1e300};
		foreach_cell(m, [&](V v) {
			if (const double h = value<double>(m, heat, v); h != 0.0)
				r = {std::min(r.first, h), std::max(r.second, h)};
		});
		return r;
	};
	const uint32 initial = nb_darts(m);
	std::mt19937 rng(seed);
	uint32 applied = 0;
	uint64 draws = 0;
	const uint64 max_draws = uint64(steps) * max_draws_per_step;
	std::map<std::string, int> applied_by_operator;
	tags.snapshot();
	std::pair<double, double> heat_before = heat_range();
	while (applied < steps && draws < max_draws)
	{
		++draws;
		if (applied % 4 == 0)
			IncidenceCache<MAP, V, Top>::build(m);
		const uint32 darts = nb_darts(m);
		CompactMaps compacted;
		const char* op = edit(m, rng, initial, compacted);
		if (op == nullptr)
		{
			ASSERT_EQ(nb_darts(m), darts) << "a refused edit changed the map at step " << applied;
			continue;
		}
		const uint32 step = applied++;
		++applied_by_operator[op];
		if (!compacted.darts.empty())
			tags.remap(compacted);
		const IntegrityReport r = check_integrity(m);
		ASSERT_TRUE(r.ok()) << "step " << step << " (" << op << ")\n" << r.to_string();
		const std::string changed = tags.changed();
		ASSERT_TRUE(changed.empty()) << "step " << step << " (" << op << "): a surviving " << changed
									 << " line changed its value";
		const std::string orphan = tags.orphan();
		ASSERT_TRUE(orphan.empty()) << "step " << step << " (" << op << "): a new " << orphan
									<< " line holds a value no cell had before";
		const std::pair<double, double> heat_after = heat_given();
		ASSERT_TRUE(heat_after.first >= heat_before.first - 1e-12 && heat_after.second <= heat_before.second + 1e-12)
			<< "step " << step << " (" << op << "): a vertex field left the range of its parents [" << heat_before.first
			<< ", " << heat_before.second << "] -> [" << heat_after.first << ", " << heat_after.second << "]";
		after(m, step);
		tags.snapshot();
		heat_before = heat_range();
	}
	EXPECT_EQ(applied, steps) << "the predicates refused too many draws (" << draws << ")";
	::testing::Test::RecordProperty("applied", int(applied));
	::testing::Test::RecordProperty("draws", int(draws));
	for (const auto& [op, n] : applied_by_operator)
		::testing::Test::RecordProperty(op, n);
}

void random_surface_editing(CMap2& m, uint32 steps, uint32 seed)
{
	random_editing(m, steps, seed, 8, edit_surface,
				   [](CMap2& map, uint32 step) { ASSERT_GT(nb_darts(map), 0u) << "step " << step; });
}

void random_volume_editing(CMap3& m, uint32 steps, uint32 seed)
{
	random_editing(m, steps, seed, 16, edit_volume, [](CMap3& map, uint32) {
		if (nb_cells<W3>(map) == 0)
			add_tetra(map);
	});
}
} // namespace

TEST(RandomEditing, Surfaces)
{
	CMap2 m;
	if (!load_surfaces(m))
		FAIL() << "the test data folder " << CGOGN_DATA_DIR << " has none of the small surface meshes";
	random_surface_editing(m, steps_of_map_type(100), 1);
}

TEST(RandomEditing, TetrahedralRegion)
{
	CMap3 m;
	if (!load_region(m, "volume/armadillo_tet_4k.mesh", 150))
		FAIL() << "the test data folder " << CGOGN_DATA_DIR << " has no volume/armadillo_tet_4k.mesh";
	random_volume_editing(m, steps_of_map_type(60), 2);
}

TEST(RandomEditing, HexahedralRegion)
{
	CMap3 m;
	if (!load_region(m, "volume/liver_hex_624.mesh", 60))
		FAIL() << "the test data folder " << CGOGN_DATA_DIR << " has no volume/liver_hex_624.mesh";
	random_volume_editing(m, steps_of_map_type(40), 3);
}

// 3-D collapse: the end of e.dart survives with its line and its values, in
// every collapse the predicate accepts on a real region with a boundary.
TEST(RandomEditing, TetCollapseKeepsTheSurvivorsLine)
{
	CMap3 m;
	if (!load_region(m, "volume/armadillo_tet_4k.mesh", 150))
		FAIL() << "the test data folder " << CGOGN_DATA_DIR << " has no volume/armadillo_tet_4k.mesh";
	test::index_everything(m);
	auto pos = get_attribute<Vec3, V3>(m, "position");
	ASSERT_NE(pos, nullptr);
	uint32 collapsed = 0;
	for (uint32 round = 0; round < 400 && collapsed < 60; ++round)
	{
		const E3 e = test::find<E3>(
			m, [&](E3 x) { return (x.dart.index * 7919u + round) % 13u == 0u && can_collapse_edge(m, x); });
		if (!e.dart.is_valid())
			continue;
		const uint32 survivor = index_of(m, V3(phi1(m, e.dart)));
		const uint32 removed = index_of(m, V3(e.dart));
		const Vec3 p = (*pos)[survivor];
		const V3 v = collapse_edge(m, e);
		++collapsed;
		ASSERT_INTEGRITY(m);
		EXPECT_EQ(index_of(m, v), survivor);
		EXPECT_EQ((*pos)[index_of(m, v)], p);
		EXPECT_FALSE(container_of<V3::ORBIT>(m).is_live(removed));
	}
	EXPECT_GT(collapsed, 10u);
}

} // namespace cgogn_test_random_editing
