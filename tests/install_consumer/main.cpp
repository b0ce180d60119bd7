#include <cgogn/cgogn.h>

#include <iostream>

int main()
{
	cgogn::CMap2 m;
	cgogn::build_surface(m, cgogn::torus_soup(8, 6));
	const auto v = cgogn::nb_cells<cgogn::CMap2::Vertex>(m);
	std::cout << "installed cgogn: torus with " << v << " vertices\n";
	return v == 48 && cgogn::check_integrity(m).ok() ? 0 : 1;
}
