// An outside project using the installed DMPlex bridge: a generated
// tetrahedral grid distributed over the ranks (one, when run alone), handed
// to PETSc, which checks the plex.
#include <cgogn/core.h>
#include <cgogn/distributed/distribute.h>
#include <cgogn/distributed/dmplex.h>
#include <cgogn/geometry/types/vector_traits.h>

#include <iostream>

int main(int argc, char** argv)
{
	PetscInitialize(&argc, &argv, nullptr, nullptr);
	int status = 1;
	{
		cgogn::CMap3 m;
		const cgogn::VolumeSoup s = cgogn::tet_grid_soup(3, 3, 3);
		const cgogn::BuildReport r = cgogn::build_volume(m, s);
		auto pos = cgogn::add_attribute<cgogn::Vec3, cgogn::CMap3::Vertex>(m, "position");
		for (cgogn::uint32 i = 0; i < s.nb_vertices; ++i)
			(*pos)[r.vertex_offset + i] = cgogn::Vec3(s.positions[i][0], s.positions[i][1], s.positions[i][2]);
		cgogn::dist::DistributedCMap3 dm = cgogn::dist::distribute(PETSC_COMM_WORLD, &m);
		const cgogn::dist::PlexMesh plex = cgogn::dist::to_dmplex(dm);
		PetscInt start = 0, end = 0;
		DMPlexGetHeightStratum(plex.dm(), 0, &start, &end);
		std::cout << "installed cgogn: " << end - start << " tetrahedra in a DMPlex\n";
		status = DMPlexCheck(plex.dm()) == 0 && end - start == 162 ? 0 : 1;
	}
	PetscFinalize();
	return status;
}
