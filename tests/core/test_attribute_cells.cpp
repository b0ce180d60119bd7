// Attributes indexed by a cell of their orbit (`attr[c]`), and value() on a
// const map.
#include <cgogn/core.h>
#include <cgogn/geometry.h>

#include <gtest/gtest.h>

#include <type_traits>
#include <utility>

namespace cgogn_test_attribute_cells
{

using namespace cgogn;

namespace
{

using Vertex = CMap2::Vertex;
using Face = CMap2::Face;

CMap2 make_grid()
{
	CMap2 m;
	build_surface(m, grid_soup(4, 3));
	return m;
}

template <typename A, typename C>
concept IndexableBy = requires(A& a, C c)
{
	a[c];
};

} // namespace

// The handle knows its orbit: only its cells (and lines) index it.
static_assert(IndexableBy<CellAttribute<double, Orbit::PHI1>, Face>);
static_assert(IndexableBy<CellAttribute<double, Orbit::PHI1>, LocatedCell<Orbit::PHI1>>);
static_assert(IndexableBy<CellAttribute<double, Orbit::PHI1>, uint32>);
static_assert(!IndexableBy<CellAttribute<double, Orbit::PHI1>, Dart>);
// value() on a const map, or through a const attribute, is read-only
static_assert(std::is_same_v<decltype(value(std::declval<const CMap2&>(), std::declval<AttributeArray<double>&>(),
											std::declval<Face>())),
							 const double&>);
static_assert(std::is_same_v<decltype(value(std::declval<const CMap2&>(),
											std::declval<const std::shared_ptr<CellAttribute<double, Orbit::PHI1>>&>(),
											std::declval<Face>())),
							 const double&>);
static_assert(std::is_same_v<decltype(value(std::declval<CMap2&>(), std::declval<AttributeArray<double>&>(),
											std::declval<Face>())),
							 double&>);
// the guide's type names and CGoGN_3's geometry::Vec3
static_assert(std::is_same_v<mesh_traits<CMap2>::Attribute<double>, AttributeArray<double>>);
static_assert(std::is_same_v<geometry::Vec3, Vec3>);
static_assert(std::is_same_v<geometry::Vec2, Vec2>);

TEST(AttributeCells, ReadAndWriteByCellAsValueDoes)
{
	CMap2 m = make_grid();
	auto area = add_attribute<double, Face>(m, "area");
	auto deg = add_attribute<uint32, Vertex>(m, "deg");
	double k = 1.0;
	foreach_cell(m, [&](Face f) { (*area)[f] = k++; });
	foreach_cell(m, [&](Vertex v) { (*deg)[v] = degree(m, v); });
	double sum = 0.0;
	foreach_cell(m, [&](Face f) {
		EXPECT_EQ((*area)[f], value<double>(m, area, f));
		EXPECT_EQ(&(*area)[f], &(*area)[index_of(m, f)]);
		sum += (*area)[f];
	});
	EXPECT_EQ(sum, 12.0 * 13.0 / 2.0);
	// every dart of a vertex reads the same line
	foreach_dart(m, [&](Dart d) {
		if (!is_boundary(m, d))
		{
			EXPECT_EQ((*deg)[Vertex(d)], degree(m, Vertex(d)));
		}
	});
	// through the orbit-erased type generic code takes (mesh_traits<M>::Attribute<T>)
	const mesh_traits<CMap2>::Attribute<double>& erased = *area;
	foreach_cell(m, [&](Face f) { EXPECT_EQ(erased[f], value<double>(m, area, f)); });
	// with the line a traversal reports
	foreach_cell(m, [&](Located<Face> f) { EXPECT_EQ((*area)[f], erased[Face(f)]); });
}

TEST(AttributeCells, FollowTheIndexThroughOperatorsAndCopies)
{
	CMap2 m = make_grid();
	auto tag = add_attribute<int, Vertex>(m, "tag");
	foreach_cell(m, [&](Vertex v) { (*tag)[v] = 7; });
	// a new vertex gets a new line, the old ones keep theirs
	Vertex nv;
	foreach_cell(m, [&](CMap2::Edge e) {
		nv = cut_edge(m, e);
		return false;
	});
	(*tag)[nv] = 9;
	int sevens = 0, nines = 0;
	foreach_cell(m, [&](Vertex v) {
		sevens += (*tag)[v] == 7;
		nines += (*tag)[v] == 9;
	});
	EXPECT_EQ(sevens, 20);
	EXPECT_EQ(nines, 1);
	EXPECT_TRUE(check_integrity(m).ok());
	// an empty map merged from m: the copied attribute reads by cell too
	CMap2 copy;
	merge(copy, m);
	auto copied = get_attribute<int, Vertex>(copy, "tag");
	ASSERT_NE(copied, nullptr);
	int total = 0;
	foreach_cell(copy, [&](Vertex v) { total += (*copied)[v]; });
	EXPECT_EQ(total, 20 * 7 + 9);
}

TEST(AttributeCells, DartAttributesIndexByHalfEdge)
{
	CMap2 m = make_grid();
	auto h = add_attribute<uint32, CMap2::HalfEdge>(m, "h");
	foreach_dart(m, [&](Dart d) { (*h)[CMap2::HalfEdge(d)] = d.index; });
	foreach_dart(m, [&](Dart d) { EXPECT_EQ((*h)[d.index], d.index); });
}

TEST(AttributeCells, ThreeMapCells)
{
	CMap3 m;
	build_volume(m, tet_grid_soup(2, 2, 2));
	auto vol = add_attribute<double, CMap3::Volume>(m, "vol");
	auto v2 = add_attribute<uint32, CMap3::Vertex2>(m, "v2");
	foreach_cell(m, [&](CMap3::Volume w) { (*vol)[w] = 1.0; });
	foreach_cell(m, [&](CMap3::Vertex2 v) { (*v2)[v] = 3; });
	double total = 0.0;
	foreach_cell(m, [&](CMap3::Volume w) { total += value<double>(m, vol, w); });
	EXPECT_EQ(total, double(nb_cells<CMap3::Volume>(m)));
	uint64 threes = 0;
	foreach_cell(m, [&](CMap3::Vertex2 v) { threes += (*v2)[v]; });
	EXPECT_EQ(threes, 3u * nb_cells<CMap3::Vertex2>(m));
}

} // namespace cgogn_test_attribute_cells
