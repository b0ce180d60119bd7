// SPDX-License-Identifier: MIT
#include <cgogn/io/options.h>

namespace cgogn::io
{

std::string LoadReport::summary(const std::string& map_type) const
{
	std::string s;
	auto line = [&](uint32 n, const std::string& what) {
		if (n > 0)
			s += std::to_string(n) + " " + what + "\n";
	};
	line(nb_cells_skipped, "degenerate or invalid cell(s) skipped");
	line(nb_isolated_vertices, "vertex(es) used by no cell left out");
	line(nb_nonmanifold_vertices,
		 "non-manifold vertex(es) split into " + std::to_string(nb_vertices_split) + " extra vertex(es)");
	line(nb_nonmanifold_edges, "non-manifold edge(s): the extra faces were detached there");
	line(nb_nonmanifold_faces, "non-manifold face(s): the extra volumes were detached there");
	line(nb_cells_reoriented, "volume cell(s) given in negative orientation turned over");
	for (const std::string& d : dropped)
		s += "not loaded: " + d + "\n";
	if (!orientable)
	{
		if (map_type == "CMap2")
			s += "the surface is not orientable: a CMap2 holds it cut along " +
				 std::to_string(nb_orientation_conflicts) +
				 " edge(s) whose two faces disagree on orientation; load it into a GMap2 to keep it whole\n";
		else if (map_type == "GMap3")
			s += "the volume mesh is not orientable\n";
		else
			s += "the surface is not orientable\n";
	}
	else if (nb_orientation_conflicts > 0 && map_type == "CMap2")
		s += std::to_string(nb_orientation_conflicts) +
			 " edge(s) join faces listed in opposite orientations: the faces were detached there (the surface "
			 "is orientable: turn those faces over, or load it into a GMap2)\n";
	return s;
}

} // namespace cgogn::io
