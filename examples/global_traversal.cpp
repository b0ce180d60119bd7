// The "Global traversals" section of the CGoGN API guide: foreach_cell deduces the
// cell type from the callable, and a callable returning bool can stop early.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;

int main()
{
	using Vertex = CMap2::Vertex;
	using Edge = CMap2::Edge;
	using Face = CMap2::Face;

	CMap2 m;
	SurfaceSoup soup = sphere_soup(16, 8);
	BuildReport report = build_surface(m, soup);
	auto position = add_attribute<Vec3, Vertex>(m, "position");
	for (uint32 i = 0; i < soup.nb_vertices; ++i)
		(*position)[report.vertex_offset + i] = Vec3(soup.positions[i][0], soup.positions[i][1], soup.positions[i][2]);

	uint32 nv = 0, ne = 0, nf = 0;
	foreach_cell(m, [&](Vertex) { ++nv; });
	foreach_cell(m, [&](Edge) { ++ne; });
	foreach_cell(m, [&](Face) { ++nf; });
	std::cout << nv << " vertices, " << ne << " edges, " << nf << " faces\n";

	// early stop: the first vertex on the negative side of the x = 0 plane
	Vertex looked_up_v;
	foreach_cell(m, [&](Vertex v) -> bool {
		if (value<Vec3>(m, position, v)[0] < 0.0)
		{
			looked_up_v = v;
			return false;
		}
		return true;
	});
	if (!looked_up_v.is_valid())
	{
		std::cout << "no such vertex was found\n";
		return 1;
	}
	const Vec3& p = value<Vec3>(m, position, looked_up_v);
	std::cout << "found vertex " << index_of(m, looked_up_v) << " at (" << p[0] << ", " << p[1] << ", " << p[2]
			  << ")\n";

	// nothing beyond x = 2: the traversal runs to its end, the vertex stays invalid
	Vertex far;
	foreach_cell(m, [&](Vertex v) -> bool {
		if (value<Vec3>(m, position, v)[0] > 2.0)
		{
			far = v;
			return false;
		}
		return true;
	});
	std::cout << "vertex beyond x = 2: " << (far.is_valid() ? "found" : "none") << "\n";
	return far.is_valid() ? 1 : 0;
}
