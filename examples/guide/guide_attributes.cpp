// The CGoGN API guide's "Mesh abstraction" and "Attributes" sections, written as a
// user writes them: `using namespace cgogn;` and the guide's own `using`
// declarations at file scope.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

using Mesh = CMap2;
using Vertex = typename mesh_traits<Mesh>::Vertex;
using Face = typename mesh_traits<Mesh>::Face;
template <typename T>
using Attribute = typename mesh_traits<Mesh>::template Attribute<T>;

// "Instead of using directly Maps class, all our code will use a template
// type parameter Mesh" (the guide declares the alias template at file scope
// here: C++ has no block-scope alias templates).
template <typename Mesh>
uint32 my_algo(const Mesh& m)
{
	using Vertex = typename mesh_traits<Mesh>::Vertex;
	using Face = typename mesh_traits<Mesh>::Face;
	uint32 n = 0;
	foreach_cell(m, [&](Vertex) { ++n; });
	foreach_cell(m, [&](Face) { ++n; });
	return n;
}

int main()
{
	Mesh m;
	build_surface(m, grid_soup(4, 3)); // 20 vertices, 12 unit squares
	if (my_algo(m) != 20 + 12)
		return 1;

	auto attr = add_attribute<uint32, Vertex>(m, "attr");

	auto area = get_attribute<double, Face>(m, "area");
	if (area == nullptr)
	{
		// there were no Face attribute of this type having this name in the map
		area = add_attribute<double, Face>(m, "area");
	}
	for (const double& v : *area)
	{
		if (v != 0.0)
			return 1;
	}

	Face f1, f2;
	foreach_cell(m, [&](Face f) {
		(f1.is_valid() ? f2 : f1) = f;
		return !f2.is_valid();
	});
	value<double>(m, area, f1) = 3.4;
	value<double>(m, area, f2) = 1.0;
	double sum = value<double>(m, area, f1) + value<double>(m, area, f2);
	if (sum != 4.4)
		return 1;

	// attributes indexed by a cell of their orbit (same as value())
	(*area)[f2] = 2.0;
	const Attribute<double>& area_ref = *area;
	if (area_ref[f2] != 2.0 || value<double>(m, area, f2) != 2.0)
		return 1;

	auto attr1 = add_attribute<double, Face>(m, "attr1");
	auto attr2 = add_attribute<double, Face>(m, "attr2");
	auto attr3 = add_attribute<double, Face>(m, "attr3");
	(*attr2)[f1] = 1.5;
	(*attr3)[f1] = 2.5;
	Face f = f1;
	uint32 findex = index_of(m, f);
	(*attr1)[findex] = (*attr2)[findex] + (*attr3)[findex];
	if ((*attr1)[f1] != 4.0)
		return 1;

	foreach_cell(m, [&](Vertex v) { (*attr)[v] = degree(m, v); });
	remove_attribute(m, attr);
	if (get_attribute<uint32, Vertex>(m, "attr") != nullptr)
		return 1;
	std::cout << "sum = " << sum << "\n";
	return 0;
}
