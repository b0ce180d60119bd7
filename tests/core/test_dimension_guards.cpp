// Operators of a lower dimension do not accept a higher map (CMap3 derives
// from CMap2, which derives from CMap1): the calls are deleted. The same
// checks as tests/compile_fail, as requires-expressions, plus the calls that
// must stay available.
#include <cgogn/core.h>
#include <cgogn/modeling.h>

#include <gtest/gtest.h>

namespace cgogn_test_dimension_guards
{

using namespace cgogn;

namespace
{
template <typename M>
concept CanAddFace = requires(M& m)
{
	add_face(m, 3u);
};
template <typename M, typename E>
concept CanCutEdge = requires(M& m, E e)
{
	cut_edge(m, e);
};
template <typename M, typename E>
concept CanCollapseEdge = requires(M& m, E e)
{
	collapse_edge(m, e);
};
template <typename M, typename E>
concept CanFlipEdge = requires(M& m, E e)
{
	flip_edge(m, e);
};
template <typename M, typename V>
concept CanCutFace = requires(M& m, V v)
{
	cut_face(m, v, v);
};
template <typename M>
concept CanMerge = requires(M& m, const M& o)
{
	merge(m, o);
};
template <typename M>
concept CanTriangulate = requires(M& m, AttributeArray<Vec3>& p)
{
	modeling::triangulate_faces(m, p);
};
template <typename M>
concept CanDecimate = requires(M& m, AttributeArray<Vec3>& p)
{
	modeling::decimate(m, p, {});
};
template <typename M>
concept CanLoop = requires(M& m, AttributeArray<Vec3>& p)
{
	modeling::loop_subdivision(m, p);
};
} // namespace

// creation
static_assert(CanAddFace<CMap1> && CanAddFace<CMap2>);
static_assert(!CanAddFace<CMap3>);
// 1-map operators on 2- and 3-maps
static_assert(CanCutEdge<CMap1, CMap1::Edge>);
static_assert(!CanCutEdge<CMap2, CMap2::HalfEdge> && !CanCutEdge<CMap3, CMap3::HalfEdge>);
static_assert(!CanCollapseEdge<CMap2, CMap2::HalfEdge> && !CanCollapseEdge<CMap3, CMap3::HalfEdge>);
// 2-map operators on 3-maps; each map keeps its own
static_assert(CanCutEdge<CMap2, CMap2::Edge> && CanCutEdge<CMap3, CMap3::Edge>);
static_assert(!CanCutEdge<CMap3, CMap2::Edge>);
static_assert(CanCollapseEdge<CMap3, CMap3::Edge> && !CanCollapseEdge<CMap3, CMap2::Edge>);
static_assert(CanFlipEdge<CMap2, CMap2::Edge> && CanFlipEdge<CMap3, CMap3::Edge>);
static_assert(!CanFlipEdge<CMap3, CMap2::Edge>);
static_assert(CanCutFace<CMap2, CMap2::Vertex> && !CanCutFace<CMap3, CMap2::Vertex>);
static_assert(CanMerge<CMap2> && !CanMerge<CMap3>);
// 1-G-map operators on 2-G-maps; each keeps its own
static_assert(CanAddFace<GMap1> && CanAddFace<GMap2>);
static_assert(CanCutEdge<GMap1, GMap1::Edge> && CanCutEdge<GMap2, GMap2::Edge>);
static_assert(!CanCutEdge<GMap2, GMap1::Edge> && !CanCollapseEdge<GMap2, GMap1::Edge>);
static_assert(CanCollapseEdge<GMap1, GMap1::Edge> && CanCollapseEdge<GMap2, GMap2::Edge>);
static_assert(CanTriangulate<GMap2> && CanLoop<GMap2>);
// 1- and 2-G-map operators and surface algorithms on 3-G-maps
static_assert(!CanAddFace<GMap3>);
static_assert(!CanCutEdge<GMap3, GMap1::Edge> && !CanCutEdge<GMap3, GMap2::Edge>);
static_assert(!CanCollapseEdge<GMap3, GMap2::Edge> && !CanFlipEdge<GMap3, GMap2::Edge>);
static_assert(!CanCutFace<GMap3, GMap2::Vertex>);
static_assert(!CanTriangulate<GMap3> && !CanLoop<GMap3>);
// surface algorithms on 3-maps
static_assert(CanTriangulate<CMap2> && !CanTriangulate<CMap3>);
static_assert(CanDecimate<CMap2> && !CanDecimate<CMap3>);
static_assert(CanLoop<CMap2> && !CanLoop<CMap3>);

// The operators a 3-map is meant to take still work on it.
TEST(DimensionGuards, ThreeMapOperatorsStillApply)
{
	CMap3 m;
	add_pyramid(m, 4);
	add_prism(m, 3);
	close(m);
	const uint32 nv = nb_cells<CMap3::Vertex>(m);
	CMap3::Edge some;
	foreach_cell(m, [&](CMap3::Edge e) {
		some = e;
		return false;
	});
	cut_edge(m, some);
	EXPECT_EQ(nb_cells<CMap3::Vertex>(m), nv + 1);
	EXPECT_TRUE(check_integrity(m).ok()) << check_integrity(m).to_string();
}

} // namespace cgogn_test_dimension_guards
