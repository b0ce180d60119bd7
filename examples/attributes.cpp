// The "Attributes" section of the CGoGN API guide, as a program.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

// The generic style of the guide: everything comes from mesh_traits<Mesh>.
template <typename Mesh>
double total_area(const Mesh& m, const typename mesh_traits<Mesh>::template Attribute<double>& area)
{
	using Face = typename mesh_traits<Mesh>::Face;
	double sum = 0.0;
	foreach_cell(m, [&](Face f) { sum += value<double>(m, area, f); });
	return sum;
}

int main()
{
	using Mesh = CMap2;
	using Vertex = mesh_traits<Mesh>::Vertex;
	using Face = mesh_traits<Mesh>::Face;

	Mesh m;
	build_surface(m, grid_soup(4, 3)); // 12 unit squares

	// add an attribute, get it back by name and type
	auto attr = add_attribute<uint32, Vertex>(m, "attr");
	auto area = add_attribute<double, Face>(m, "area");
	if (get_attribute<double, Face>(m, "area") != area || get_attribute<float, Face>(m, "area") != nullptr)
		return 1;
	if (get_attribute<double, Face>(m, "nothing") == nullptr)
		std::cout << "no Face attribute of type double named \"nothing\"\n";

	// write through value(), read through the index
	foreach_cell(m, [&](Face f) { value<double>(m, area, f) = 1.0; });
	foreach_cell(m, [&](Vertex v) { value<uint32>(m, attr, v) = degree(m, v); });

	Face f1, f2;
	foreach_cell(m, [&](Face f) {
		(f1.is_valid() ? f2 : f1) = f;
		return !f2.is_valid();
	});
	value<double>(m, area, f1) = 3.4;
	const double sum = value<double>(m, area, f1) + value<double>(m, area, f2);
	std::cout << "area(f1) + area(f2) = " << sum << "\n";

	// several attributes of one orbit share the cell's index
	auto attr2 = add_attribute<double, Face>(m, "attr2");
	auto attr3 = add_attribute<double, Face>(m, "attr3");
	const uint32 findex = index_of(m, f1);
	(*attr2)[findex] = 2.0;
	(*attr3)[findex] = (*attr2)[findex] + (*area)[findex];
	std::cout << "attr3(f1) = " << (*attr3)[findex] << "\n";

	// range-for over the values of the live cells
	double total = 0.0;
	for (const double& v : *area)
		total += v;
	uint32 valence_sum = 0;
	for (uint32 d : *attr)
		valence_sum += d;
	std::cout << "sum of areas: " << total << " (generic: " << total_area(m, *area) << "), sum of valences "
			  << valence_sum << " = 2 x " << nb_cells<CMap2::Edge>(m) << " edges\n";

	remove_attribute(m, attr);
	std::cout << "after removal, get_attribute gives "
			  << (get_attribute<uint32, Vertex>(m, "attr") == nullptr ? "nullptr" : "something") << "\n";
	return (valence_sum == 2 * nb_cells<CMap2::Edge>(m) && sum > 4.3 && sum < 4.5) ? 0 : 1;
}
