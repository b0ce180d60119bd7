// check_integrity must catch every kind of corruption it claims to catch.
#include <cgogn/core.h>

#include "map_test_utils.h"

#include <gtest/gtest.h>

namespace cgogn_test_integrity
{

using namespace cgogn;
using Kind = IntegrityError::Kind;

namespace
{
CMap2 indexed_grid()
{
	CMap2 m;
	build_surface(m, grid_soup(3, 3, true));
	add_attribute<int, CMap2::Face>(m, "f");
	add_attribute<int, CMap2::Edge>(m, "e");
	add_attribute<int, CMap2::Volume>(m, "w");
	return m;
}
Dart inner_dart(const CMap2& m)
{
	Dart r;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d) || is_boundary(m, phi2(m, d)))
			return true;
		r = d;
		return false;
	});
	return r;
}
AttributeArray<uint32>& index_attr(CMap2& m, Orbit o)
{
	return *cgogn::detail::state_of(m).cell_index[orbit_index(o)];
}
} // namespace

TEST(Integrity, CleanMapsAreClean)
{
	CMap2 m = indexed_grid();
	IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.ok()) << r.to_string();
	EXPECT_EQ(r.nb_errors, 0u);
}

TEST(Integrity, Phi2NotInvolution)
{
	CMap2 m = indexed_grid();
	Dart d = inner_dart(m);
	Dart other = phi1(m, d);
	detail::set_phi2(m, d, phi2(m, other)); // d -> phi2(other), but phi2(phi2(other)) = other
	EXPECT_TRUE(check_integrity(m).has(Kind::PhiNotInvolution));
}

TEST(Integrity, Phi2FixedPoint)
{
	CMap2 m = indexed_grid();
	phi2_unsew(m, inner_dart(m));
	EXPECT_TRUE(check_integrity(m).has(Kind::PhiFixedPoint));
}

TEST(Integrity, Phi1NotPermutation)
{
	CMap2 m = indexed_grid();
	Dart d = inner_dart(m);
	detail::set_phi1(m, d, phi1(m, phi1(m, d))); // two darts now share a phi1
	EXPECT_TRUE(check_integrity(m).has(Kind::Phi1NotPermutation));
}

TEST(Integrity, RelationToARemovedDart)
{
	CMap2 m = indexed_grid();
	Dart d = inner_dart(m);
	detail::remove_dart(m, phi1(m, d));
	EXPECT_TRUE(check_integrity(m).has(Kind::DeadRelation));
}

TEST(Integrity, BoundaryMarks)
{
	{
		CMap2 m = indexed_grid();
		detail::set_boundary(m, inner_dart(m), true); // one dart of a real face
		const IntegrityReport r = check_integrity(m);
		EXPECT_TRUE(r.has(Kind::BoundaryMarkNotConstant));
	}
	{
		CMap2 m;
		add_face(m, 3);
		// mark the real face too: phi2 now links two boundary darts
		foreach_dart(m, [&](Dart d) { detail::set_boundary(m, d, true); });
		EXPECT_TRUE(check_integrity(m).has(Kind::BoundaryLinked));
	}
}

// The map counts its boundary darts (has_boundary, O(1) is_incident_to_boundary
// of a vertex): the count follows the operators, and a mark written behind
// its back is reported.
TEST(Integrity, BoundaryDartCount)
{
	CMap2 m = indexed_grid();
	ASSERT_TRUE(has_boundary(m));
	EXPECT_TRUE(check_integrity(m).ok());
	uint32 marked = 0;
	foreach_dart(m, [&](Dart d) { marked += is_boundary(m, d); });
	EXPECT_EQ(cgogn::detail::state_of(m).nb_boundary_darts, marked);
	Dart b;
	foreach_dart(m, [&](Dart d) {
		b = d;
		return !is_boundary(m, d);
	});
	fill_hole_with_face(m, b); // the grid's only hole
	EXPECT_FALSE(has_boundary(m));
	EXPECT_EQ(cgogn::detail::state_of(m).nb_boundary_darts, 0u);
	EXPECT_TRUE(check_integrity(m).ok());
	foreach_cell(m, [&](CMap2::Vertex v) { EXPECT_FALSE(is_incident_to_boundary(m, v)); });
	cgogn::detail::state_of(m).boundary->set(inner_dart(m).index); // behind the count's back
	EXPECT_TRUE(check_integrity(m).has(Kind::BoundaryCountWrong));
}

TEST(Integrity, IndexNotConstantOnAnOrbit)
{
	CMap2 m = indexed_grid();
	Dart d = inner_dart(m);
	AttributeArray<uint32>& f = index_attr(m, Orbit::PHI1);
	f[d.index] = f[phi2(m, d).index]; // one dart of a face takes the neighbour's index
	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.has(Kind::IndexNotConstant));
	EXPECT_TRUE(r.has(Kind::IndexShared));
}

TEST(Integrity, MissingIndex)
{
	CMap2 m = indexed_grid();
	Dart d = inner_dart(m);
	foreach_dart_of_orbit(m, CMap2::Edge(d), [&](Dart x) { index_attr(m, Orbit::PHI2)[x.index] = INVALID_INDEX; });
	EXPECT_TRUE(check_integrity(m).has(Kind::MissingIndex));
}

TEST(Integrity, BoundaryCellIndexed)
{
	CMap2 m = indexed_grid();
	Dart b;
	foreach_dart(m, [&](Dart d) {
		if (!is_boundary(m, d))
			return true;
		b = d;
		return false;
	});
	const uint32 line = container_of<Orbit::PHI1>(m).new_line(b.index);
	foreach_dart_of_orbit(m, CMap2::Face(b), [&](Dart x) { index_attr(m, Orbit::PHI1)[x.index] = line; });
	EXPECT_TRUE(check_integrity(m).has(Kind::BoundaryCellIndexed));
}

TEST(Integrity, DeadIndex)
{
	CMap2 m = indexed_grid();
	container_of<Orbit::PHI2>(m).release_line(index_of(m, CMap2::Edge(inner_dart(m))));
	EXPECT_TRUE(check_integrity(m).has(Kind::DeadIndex));
}

TEST(Integrity, BadRepresentative)
{
	CMap2 m = indexed_grid();
	Dart d = inner_dart(m);
	container_of<Orbit::PHI21>(m).key()[index_of(m, CMap2::Vertex(d))] = phi1(m, d).index;
	EXPECT_TRUE(check_integrity(m).has(Kind::BadRepresentative));
}

TEST(Integrity, TwoCellsShareALine)
{
	CMap2 m = indexed_grid();
	Dart d = inner_dart(m);
	const uint32 shared = index_of(m, CMap2::Vertex(d));
	const CMap2::Vertex other(phi1(m, d));
	const uint32 old = index_of(m, other);
	foreach_dart_of_orbit(m, other, [&](Dart x) { index_attr(m, Orbit::PHI21)[x.index] = shared; });
	container_of<Orbit::PHI21>(m).release_line(old);
	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.has(Kind::IndexShared));
	EXPECT_FALSE(r.has(Kind::IndexNotConstant));
}

TEST(Integrity, LiveLineInTheFreeList)
{
	CMap2 m = indexed_grid();
	AttributeContainer& faces = container_of<Orbit::PHI1>(m);
	const uint32 i = index_of(m, CMap2::Face(inner_dart(m)));
	const uint32 rep = faces.key()[i];
	faces.release_line(i);
	faces.key()[i] = rep; // live again, but still in the free list
	EXPECT_TRUE(check_integrity(m).has(Kind::FreeLineLive));
}

TEST(Integrity, Phi3Phi1NotInvolution)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(1, 1, 1));
	// re-pair phi3 inside an inner face: still an involution, but not face-compatible
	Dart d;
	foreach_dart(m, [&](Dart x) {
		if (is_boundary(m, x) || is_boundary(m, phi3(m, x)))
			return true;
		d = x;
		return false;
	});
	ASSERT_TRUE(d.is_valid());
	cgogn::test::cross_phi3_inside_face(m, d);
	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.has(Kind::Phi1Phi3NotInvolution));
}

TEST(Integrity, ReportCountsBeyondTheDescribedOnes)
{
	CMap2 m;
	build_surface(m, torus_soup(40, 40));
	// break every edge: thousands of fixed points
	foreach_dart(m, [&](Dart d) { detail::set_phi2(m, d, d); });
	const IntegrityReport r = check_integrity(m);
	EXPECT_EQ(r.nb_errors, nb_darts(m));
	EXPECT_EQ(r.errors.size(), 1000u);
	EXPECT_NE(r.to_string().find("more"), std::string::npos);
}

TEST(Integrity, FreeListDuplicate)
{
	CMap2 m = indexed_grid();
	AttributeContainer& faces = *cgogn::detail::state_of(m).cells[orbit_index(Orbit::PHI1)];
	const Dart d = inner_dart(m);
	// a face released twice: its line is twice in the free list
	const uint32 line = index_attr(m, Orbit::PHI1)[d.index];
	faces.release_line(line);
	faces.release_unkeyed_line(line);
	const IntegrityReport r = check_integrity(m);
	EXPECT_TRUE(r.has(Kind::FreeLineDuplicate)) << r.to_string();
}

TEST(Integrity, LiveLineOnTheFreeList)
{
	CMap2 m = indexed_grid();
	AttributeContainer& faces = *cgogn::detail::state_of(m).cells[orbit_index(Orbit::PHI1)];
	const Dart d = inner_dart(m);
	const uint32 line = index_attr(m, Orbit::PHI1)[d.index];
	faces.release_line(line);
	faces.key()[line] = d.index; // live again, still listed as free
	EXPECT_TRUE(check_integrity(m).has(Kind::FreeLineLive));
}

TEST(Integrity, StaleValuesPastTheEnd)
{
	{
		// a dart line never handed out that holds an index
		CMap2 m = indexed_grid();
		ASSERT_LT(cgogn::detail::state_of(m).darts->end_index(), cgogn::detail::state_of(m).darts->capacity());
		index_attr(m, Orbit::PHI2)[cgogn::detail::state_of(m).darts->end_index()] = 0;
		const IntegrityReport r = check_integrity(m);
		EXPECT_TRUE(r.has(Kind::StaleUnusedLine)) << r.to_string();
	}
	{
		// a cell line never handed out that holds a representative
		CMap2 m = indexed_grid();
		AttributeContainer& vertices = *cgogn::detail::state_of(m).cells[orbit_index(Orbit::PHI21)];
		ASSERT_LT(vertices.end_index(), vertices.capacity());
		vertices.key()[vertices.end_index()] = 0;
		EXPECT_TRUE(check_integrity(m).has(Kind::StaleUnusedLine));
	}
	{
		// compaction leaves none
		CMap2 m = indexed_grid();
		remove_face(m, CMap2::Face(inner_dart(m)));
		compact(m);
		const IntegrityReport r = check_integrity(m);
		EXPECT_TRUE(r.ok()) << r.to_string();
	}
}

TEST(Integrity, FacesOfOneOrTwoEdges)
{
	{
		CMap2 m;
		add_face(m, 2);
		EXPECT_TRUE(check_integrity(m).has(Kind::ShortFace));
	}
	{
		CMap2 m;
		add_face(m, 1);
		EXPECT_TRUE(check_integrity(m).has(Kind::ShortFace));
	}
	{
		// a triangle and its boundary face are fine
		CMap2 m;
		add_face(m, 3);
		EXPECT_TRUE(check_integrity(m).ok());
	}
}

} // namespace cgogn_test_integrity
