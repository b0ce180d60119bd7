// An outside project using the installed distributed layer: partitions a
// generated tetrahedral grid with METIS.
#include <cgogn/core.h>
#include <cgogn/distributed/partition.h>

#include <iostream>

int main()
{
	cgogn::CMap3 m;
	cgogn::build_volume(m, cgogn::tet_grid_soup(4, 4, 4));
	const cgogn::dist::PartitionReport r = cgogn::dist::partition(m, 2);
	std::cout << "installed cgogn: 384 tetrahedra in parts of " << r.part_sizes[0] << " and " << r.part_sizes[1]
			  << "\n";
	return r.part_sizes[0] + r.part_sizes[1] == 384 && r.parts_connected() ? 0 : 1;
}
