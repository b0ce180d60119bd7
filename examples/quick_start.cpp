// The README's quick start: load a surface, add a face attribute, walk the
// faces around every vertex, subdivide, save. Arguments: the input file and
// the output file (defaults: the README's paths, from the repository root).
#include <cgogn/cgogn.h>

#include <algorithm>
#include <iostream>

using namespace cgogn;
using Vertex = CMap2::Vertex;
using Face = CMap2::Face;

int main(int argc, char** argv)
{
	const std::string in = argc > 1 ? argv[1] : "examples/data/spot_control_mesh.obj";
	const std::string out = argc > 2 ? argv[2] : "spot.ply";
	CMap2 m;
	io::load_surface(m, in);                               // throws io::Error on a bad file
	auto pos = get_attribute<Vec3, Vertex>(m, "position"); // made by the loader
	auto area = add_attribute<double, Face>(m, "area");    // indexes the faces once: O(darts)
	foreach_cell(m, [&](Face f) { (*area)[f] = geometry::face_area(m, f, *pos); });
	double largest_star = 0.0;
	foreach_cell(m, [&](Vertex v) {
		double a = 0.0;
		foreach_incident_face(m, v, [&](Face f) { a += (*area)[f]; }); // O(degree of v)
		largest_star = std::max(largest_star, a);
	});
	modeling::subdivide(m, *pos, modeling::SurfaceScheme::CatmullClark, 2);
	io::save_surface(m, out, {.binary = true});
	std::cout << nb_cells<Face>(m) << " faces, largest star " << largest_star
			  << (check_integrity(m).ok() ? ", valid\n" : ", broken\n");
}
