// Multiresolution editing: a coarse vertex moved, the fine details kept.
// A control mesh gets three Catmull-Clark levels; a bump is carved into the
// finest level; the analysis stores it as detail vectors; a coarse vertex is
// moved at level 0; the synthesis rebuilds the fine levels, bump included.
#include <cgogn/cgogn.h>

#include <iostream>

using namespace cgogn;
using Vertex = MRMap2::Vertex;

int main(int argc, char** argv)
{
	CMap2 coarse;
	io::load_surface(coarse, argc > 1 ? argv[1] : "spot_control_mesh.obj");
	MRMap2 m(std::move(coarse)); // the mesh becomes level 0, its positions included
	auto pos = get_attribute<Vec3, Vertex>(m, "position");
	auto details = add_attribute<Vec3, Vertex>(m, "details");

	for (int i = 0; i < 3; ++i)
		add_level(m, Refinement::Quadrangular);
	modeling::synthesis(m, *pos, *details, modeling::MRBank::CatmullClark); // zero details: the CC surface

	// a bump: the finest vertices near one coarse vertex pushed along x
	const MRLevelView2 level0 = level_view(m, 0);
	const Vertex handle = [&] {
		Vertex v;
		foreach_cell(level0, [&](Vertex x) {
			v = x;
			return false;
		});
		return v;
	}();
	set_current_level(m, max_level(m));
	const Vec3 centre = value<Vec3>(m, pos, handle);
	uint32 bumped = 0;
	foreach_cell(m, [&](Vertex v) {
		if ((value<Vec3>(m, pos, v) - centre).norm() < 0.05)
		{
			value<Vec3>(m, pos, v) += Vec3(0.02, 0.0, 0.0);
			++bumped;
		}
	});

	// analysis: level 0 and the details; then edit level 0 and synthesise
	modeling::analysis(m, *pos, *details, modeling::MRBank::CatmullClark);
	const Vec3 before = value<Vec3>(m, pos, handle);
	set_current_level(m, 0);
	value<Vec3>(m, pos, handle) += Vec3(0.0, 0.1, 0.0);
	modeling::synthesis(m, *pos, *details, modeling::MRBank::CatmullClark);
	set_current_level(m, max_level(m));
	const Vec3 after = value<Vec3>(m, pos, handle);

	std::cout << "levels 0 to " << max_level(m) << ": ";
	for (uint32 l = 0; l <= max_level(m); ++l)
		std::cout << nb_cells<MRMap2::Face>(level_view(m, l)) << (l < max_level(m) ? ", " : " faces\n");
	std::cout << bumped << " finest vertices bumped; the handle moved by " << (after - before).transpose()
			  << " at the finest level\n";
	std::cout << (check_integrity(m).ok() ? "valid" : "INVALID") << "\n";
	return check_integrity(m).ok() ? 0 : 1;
}
