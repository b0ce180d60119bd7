// check_integrity on maps large enough to be checked in parallel: with 1, 2
// and 3 workers, a clean map is clean, and each corruption is reported with
// its kind wherever it lies in the dart range (in the first or the last
// chunk, in the first or the last worker's range of phi1 targets).
#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

namespace cgogn_test_integrity_parallel
{

using namespace cgogn;
using Kind = IntegrityError::Kind;

class ParallelIntegrity : public ::testing::TestWithParam<uint32>
{
protected:
	void SetUp() override
	{
		set_nb_workers(GetParam());
	}
	void TearDown() override
	{
		set_nb_workers(0);
	}
};

// A triangulated grid of 2 x 120 x 120 faces (86,400 darts, beyond the
// parallel threshold), with its vertices, edges and faces indexed.
CMap2 large_grid()
{
	CMap2 m;
	build_surface(m, grid_soup(120, 120, true));
	add_attribute<int, CMap2::Vertex>(m, "v");
	add_attribute<int, CMap2::Edge>(m, "e");
	add_attribute<int, CMap2::Face>(m, "f");
	return m;
}

// The inner darts (neither they nor their phi2 on the boundary) nearest to
// the start and to the end of the dart range.
std::vector<Dart> inner_darts_at_both_ends(const CMap2& m)
{
	std::vector<Dart> inner;
	foreach_dart(m, [&](Dart d) {
		if (!is_boundary(m, d) && !is_boundary(m, phi2(m, d)))
			inner.push_back(d);
	});
	return {inner.front(), inner.back()};
}

AttributeArray<uint32>& index_attr(CMap2& m, Orbit o)
{
	return *cgogn::detail::state_of(m).cell_index[orbit_index(o)];
}

struct Corruption
{
	std::string name;
	Kind expected;
	std::function<void(CMap2&, Dart)> apply;
};

std::vector<Corruption> corruptions()
{
	return {
		{"phi2 not an involution", Kind::PhiNotInvolution,
		 [](CMap2& m, Dart d) { detail::set_phi2(m, d, phi2(m, phi1(m, d))); }},
		{"phi2 fixed point", Kind::PhiFixedPoint, [](CMap2& m, Dart d) { phi2_unsew(m, d); }},
		{"phi1 not a permutation", Kind::Phi1NotPermutation,
		 [](CMap2& m, Dart d) { detail::set_phi1(m, d, phi1(m, phi1(m, d))); }},
		{"relation to a removed dart", Kind::DeadRelation,
		 [](CMap2& m, Dart d) { detail::remove_dart(m, phi1(m, d)); }},
		{"boundary mark not constant", Kind::BoundaryMarkNotConstant,
		 [](CMap2& m, Dart d) { detail::set_boundary(m, d, true); }},
		{"boundary count", Kind::BoundaryCountWrong,
		 [](CMap2& m, Dart d) { cgogn::detail::state_of(m).boundary->set(d.index); }},
		{"index not constant", Kind::IndexNotConstant,
		 [](CMap2& m, Dart d) {
			 AttributeArray<uint32>& f = index_attr(m, Orbit::PHI1);
			 f[d.index] = f[phi2(m, d).index];
		 }},
		{"missing index", Kind::MissingIndex,
		 [](CMap2& m, Dart d) {
			 foreach_dart_of_orbit(m, CMap2::Edge(d),
								   [&](Dart x) { index_attr(m, Orbit::PHI2)[x.index] = INVALID_INDEX; });
		 }},
		{"dead index", Kind::DeadIndex,
		 [](CMap2& m, Dart d) { container_of<Orbit::PHI2>(m).release_line(index_of(m, CMap2::Edge(d))); }},
		{"bad representative", Kind::BadRepresentative,
		 [](CMap2& m, Dart d) {
			 container_of<Orbit::PHI21>(m).key()[index_of(m, CMap2::Vertex(d))] = phi1(m, d).index;
		 }},
		{"two cells share a line", Kind::IndexShared,
		 [](CMap2& m, Dart d) {
			 const uint32 shared = index_of(m, CMap2::Vertex(d));
			 const CMap2::Vertex other(phi1(m, d));
			 const uint32 old = index_of(m, other);
			 foreach_dart_of_orbit(m, other, [&](Dart x) { index_attr(m, Orbit::PHI21)[x.index] = shared; });
			 container_of<Orbit::PHI21>(m).release_line(old);
		 }},
	};
}

TEST_P(ParallelIntegrity, CleanLargeMapsAreClean)
{
	CMap2 m = large_grid();
	ASSERT_GT(nb_darts(m), 65536u);
	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.ok()) << r.to_string();

	CMap3 v;
	build_volume(v, tet_grid_soup(12, 12, 12)); // 10,368 tetrahedra, 124,416 darts
	add_attribute<int, CMap3::Vertex>(v, "v");
	add_attribute<int, CMap3::Face>(v, "f");
	add_attribute<int, CMap3::Volume>(v, "w");
	const IntegrityReport r3 = check_integrity(v);
	EXPECT_TRUE(r3.ok()) << r3.to_string();
}

TEST_P(ParallelIntegrity, EachCorruptionIsFoundWhereverItLies)
{
	for (const Corruption& c : corruptions())
		for (std::size_t end = 0; end < 2; ++end)
		{
			SCOPED_TRACE(c.name + (end == 0 ? " near the first dart" : " near the last dart"));
			CMap2 m = large_grid();
			c.apply(m, inner_darts_at_both_ends(m)[end]);
			const IntegrityReport r = check_integrity(m);
			EXPECT_TRUE(r.has(c.expected)) << r.to_string();
		}
}

// Two darts of different faces given the same phi1, the shared target in the
// lower or in the upper half of the darts (two workers check a half each).
TEST_P(ParallelIntegrity, SharedPhi1TargetsInEitherHalf)
{
	for (std::size_t end = 0; end < 2; ++end)
	{
		CMap2 m = large_grid();
		const std::vector<Dart> ds = inner_darts_at_both_ends(m);
		const Dart target = phi1(m, ds[end]);
		detail::set_phi1(m, ds[1 - end], target);
		EXPECT_TRUE(check_integrity(m).has(Kind::Phi1NotPermutation));
	}
}

TEST_P(ParallelIntegrity, Phi3Phi1NotInvolution)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(12, 12, 12));
	// the last inner dart
	Dart d;
	foreach_dart(m, [&](Dart x) {
		if (!is_boundary(m, x) && !is_boundary(m, phi3(m, x)))
			d = x;
	});
	cgogn::test::cross_phi3_inside_face(m, d);
	EXPECT_TRUE(check_integrity(m).has(Kind::Phi1Phi3NotInvolution));
}

INSTANTIATE_TEST_SUITE_P(Workers, ParallelIntegrity, ::testing::Values(1u, 2u, 3u));

} // namespace cgogn_test_integrity_parallel
