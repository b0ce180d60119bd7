#include <cgogn/cgogn.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <unistd.h>

int main()
{
	cgogn::CMap2 m;
	cgogn::build_surface(m, cgogn::torus_soup(8, 6));
	const auto v = cgogn::nb_cells<cgogn::CMap2::Vertex>(m);
	std::cout << "installed cgogn: torus with " << v << " vertices\n";
	if (v != 48 || !cgogn::check_integrity(m).ok())
		return 1;

	// the renderer, and libpng through it: a picture of a generated sphere
	cgogn::CMap2 s;
	const cgogn::SurfaceSoup soup = cgogn::sphere_soup(16, 8);
	cgogn::build_surface(s, soup);
	auto pos = cgogn::add_attribute<cgogn::Vec3, cgogn::CMap2::Vertex>(s, "position");
	for (cgogn::uint32 i = 0; i < soup.nb_vertices; ++i)
		(*pos)[i] = cgogn::Vec3(soup.positions[i][0], soup.positions[i][1], soup.positions[i][2]);
	cgogn::render::RenderOptions o;
	o.width = 64;
	o.height = 48;
	const cgogn::render::Image img = cgogn::render::render_surface(s, *pos, o);
	if (img.width != 64 || img.height != 48 || img.rgb.size() != 64u * 48u * 3u || img.at(32, 24) == o.background)
		return 1;
	const std::string png =
		(std::filesystem::temp_directory_path() / ("cgogn_consumer_" + std::to_string(::getpid()) + ".png")).string();
	cgogn::render::write_png(img, png);
	std::ifstream f(png, std::ios::binary);
	char sig[8] = {};
	f.read(sig, 8);
	std::filesystem::remove(png);
	if (std::string(sig + 1, 3) != "PNG")
		return 1;
	std::cout << "installed cgogn: rendered a " << img.width << "x" << img.height << " picture and wrote it as PNG\n";
	return 0;
}
