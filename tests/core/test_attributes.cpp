// The attribute section of the CGoGN API guide, as tests.
#include <cgogn/core.h>

#include <gtest/gtest.h>

namespace cgogn_test_attributes
{

using namespace cgogn;

namespace
{
CMap2 make_grid()
{
	CMap2 m;
	build_surface(m, grid_soup(3, 2));
	return m;
}
} // namespace

TEST(Attributes, AddGetRemove)
{
	using Mesh = CMap2;
	using Vertex = mesh_traits<Mesh>::Vertex;
	using Face = mesh_traits<Mesh>::Face;
	Mesh m = make_grid();
	auto attr = add_attribute<uint32, Vertex>(m, "attr");
	ASSERT_NE(attr, nullptr);
	EXPECT_EQ((add_attribute<uint32, Vertex>(m, "attr")), nullptr); // the name is taken on this orbit
	EXPECT_NE((add_attribute<uint32, Face>(m, "attr")), nullptr);   // but free on another
	EXPECT_EQ((get_attribute<uint32, Vertex>(m, "attr")), attr);
	EXPECT_EQ((get_attribute<double, Vertex>(m, "attr")), nullptr); // another type
	EXPECT_EQ((get_attribute<double, Face>(m, "area")), nullptr);   // absent
	EXPECT_TRUE(remove_attribute(m, attr));
	EXPECT_EQ((get_attribute<uint32, Vertex>(m, "attr")), nullptr);
	EXPECT_FALSE(remove_attribute(m, attr));
	// the explicit form of the guide
	auto area = add_attribute<double, Face>(m, "area");
	EXPECT_TRUE((remove_attribute<double, Face>(m, area)));
	// reserved names
	EXPECT_EQ((add_attribute<int, Vertex>(m, "__phi1")), nullptr);
	EXPECT_EQ((get_attribute<uint32, Vertex>(m, "__dart")), nullptr);
}

TEST(Attributes, AnotherMapsAttributeIsNotRemoved)
{
	CMap2 a = make_grid(), b = make_grid();
	auto x = add_attribute<int, CMap2::Vertex>(a, "x");
	EXPECT_FALSE(remove_attribute(b, x));
	EXPECT_NE(x->container(), nullptr);
}

TEST(Attributes, ValueIndexAndRangeFor)
{
	using Face = CMap2::Face;
	CMap2 m = make_grid();
	auto area = add_attribute<double, Face>(m, "area");
	auto attr2 = add_attribute<double, Face>(m, "a2");
	auto attr3 = add_attribute<double, Face>(m, "a3");
	double expected = 0;
	int k = 1;
	foreach_cell(m, [&](Face f) {
		value<double>(m, area, f) = double(k);
		(*attr2)[index_of(m, f)] = 10.0 * k;
		expected += k;
		++k;
	});
	double sum = 0;
	for (const double& v : *area)
		sum += v;
	EXPECT_DOUBLE_EQ(sum, expected);
	EXPECT_EQ(k - 1, 6);
	foreach_cell(m, [&](Face f) {
		const uint32 findex = index_of(m, f);
		(*attr3)[findex] = (*attr2)[findex] + (*area)[findex];
		EXPECT_DOUBLE_EQ(value<double>(m, attr3, f), 11.0 * value<double>(m, *area, f));
	});
	// value() through any dart of the face
	foreach_cell(m, [&](Face f) {
		foreach_dart_of_orbit(m, f,
							  [&](Dart d) { EXPECT_EQ(value<double>(m, area, Face(d)), value<double>(m, area, f)); });
	});
}

TEST(Attributes, DartAttributesLiveInTheDartContainer)
{
	CMap2 m = make_grid();
	auto a = add_attribute<int, CMap2::HalfEdge>(m, "he");
	foreach_dart(m, [&](Dart d) { value<int>(m, a, CMap2::HalfEdge(d)) = 1; });
	int n = 0;
	for (int v : *a)
		n += v;
	EXPECT_EQ(uint32(n), nb_darts(m));
}

TEST(Attributes, ValuesOfVerticesFollowSoupIds)
{
	SurfaceSoup s = grid_soup(4, 3);
	CMap2 m;
	BuildReport r = build_surface(m, s);
	auto pos = add_attribute<std::array<double, 3>, CMap2::Vertex>(m, "position");
	for (uint32 i = 0; i < s.nb_vertices; ++i)
		(*pos)[r.vertex_offset + i] = s.positions[i];
	// vertex 0 = (0,0,0) is a corner: its only face goes on to (1,0,0)
	bool checked = false;
	foreach_dart(m, [&](Dart d) {
		if (is_boundary(m, d) || index_of(m, CMap2::Vertex(d)) != r.vertex_offset)
			return;
		using P = std::array<double, 3>;
		EXPECT_EQ(value<P>(m, pos, CMap2::Vertex(d))[0], 0.0);
		EXPECT_EQ(value<P>(m, pos, CMap2::Vertex(phi1(m, d)))[0], 1.0);
		EXPECT_EQ(value<P>(m, pos, CMap2::Vertex(phi1(m, d)))[1], 0.0);
		checked = true;
	});
	EXPECT_TRUE(checked);
}

} // namespace cgogn_test_attributes
