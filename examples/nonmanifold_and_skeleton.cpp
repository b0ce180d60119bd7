// Non-manifold surfaces and curve skeletons: a file whose edges carry three
// faces loaded exactly into an IncidenceGraph (its true counts, and what a
// CMap2 makes of it), then the curve skeleton of a closed surface as a Graph,
// written as a .cg file and drawn into a PNG.
//   nonmanifold_and_skeleton NON_MANIFOLD.off CLOSED_SURFACE OUT_DIR
#include <cgogn/cgogn.h>
#include <cgogn/render/render.h>

#include <iostream>

using namespace cgogn;

int main(int argc, char** argv)
{
	if (argc != 4)
	{
		std::cerr << "usage: " << argv[0] << " NON_MANIFOLD.off CLOSED_SURFACE OUT_DIR\n";
		return 1;
	}
	const std::string out = argv[3];

	// 1. the file as written: no vertex split, no face torn off
	IncidenceGraph ig;
	io::load_surface(ig, argv[1]);
	std::cout << "as written: " << nb_cells<IncidenceGraph::Vertex>(ig) << " vertices, "
			  << nb_cells<IncidenceGraph::Edge>(ig) << " edges, " << nb_cells<IncidenceGraph::Face>(ig)
			  << " faces, chi " << euler_characteristic(ig) << ", " << nb_non_manifold_edges(ig)
			  << " edges with 3 faces or more\n";
	BuildReport repair;
	const CMap2 torn = to_cmap2(ig, &repair);
	std::cout << "as a CMap2: " << nb_cells<CMap2::Vertex>(torn) << " vertices, " << nb_cells<CMap2::Edge>(torn)
			  << " edges (" << repair.nb_nonmanifold_edges << " edges detached)\n";
	io::save_surface(ig, out + "/as_written.off"); // the same vertices and faces, in the same order

	// 2. the curve skeleton of a closed surface
	CMap2 surface;
	io::load_surface(surface, argv[2]);
	modeling::SkeletonOptions options;
	options.progress = [](double f) {
		std::cout << "\rskeleton " << int(100 * f) << "%" << std::flush;
		return true;
	};
	const Graph skeleton =
		modeling::skeleton(surface, *get_attribute<Vec3, CMap2::Vertex>(surface, "position"), options);
	std::cout << "\nskeleton: " << nb_cells<Graph::Vertex>(skeleton) << " vertices, " << nb_cells<Graph::Edge>(skeleton)
			  << " edges, " << nb_connected_components(skeleton) << " component(s), cycle rank " << cycle_rank(skeleton)
			  << ", " << branches(skeleton).size() << " branches\n";
	io::save_graph(skeleton, out + "/skeleton.cg");
	render::RenderOptions picture;
	picture.width = 600;
	picture.height = 450;
	render::write_png(
		render::render_graph(skeleton, *get_attribute<Vec3, Graph::Vertex>(skeleton, "position"), picture),
		out + "/skeleton.png");
	std::cout << "wrote " << out << "/as_written.off, skeleton.cg and skeleton.png: "
			  << (check_integrity(skeleton).ok() && check_integrity(ig).ok() ? "valid" : "INVALID") << "\n";
	return 0;
}
