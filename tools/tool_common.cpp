// SPDX-License-Identifier: MIT
#include "tool_common.h"

#include <cctype>
#include <cstdio>
#include <unistd.h>

namespace cgogn::tool
{

Progress::Progress() : on_(isatty(STDERR_FILENO) != 0)
{
}

Progress::~Progress()
{
	if (on_ && shown_)
		std::fputs("\r\033[K", stderr);
}

void Progress::stage(const std::string& what)
{
	if (!on_)
		return;
	std::fprintf(stderr, "\r\033[K%s...", what.c_str());
	std::fflush(stderr);
	shown_ = true;
}

modeling::ProgressCallback Progress::percent(const std::string& what)
{
	if (!on_)
		return {};
	return [this, what](double fraction) {
		std::fprintf(stderr, "\r\033[K%s... %3d%%", what.c_str(), int(fraction * 100.0));
		std::fflush(stderr);
		shown_ = true;
		return true;
	};
}

bool is_volume_format(io::Format f)
{
	return f == io::Format::Medit || f == io::Format::VtkLegacy || f == io::Format::Vtu || f == io::Format::Gmsh ||
		   f == io::Format::TetGen || f == io::Format::Ovm || f == io::Format::Pvtu;
}

bool holds_surfaces(io::Format f)
{
	return f != io::Format::TetGen && f != io::Format::Ovm;
}

namespace
{
// The extension of path from its last dot, lower-cased; empty without a dot.
std::string lower_extension(const std::string& path)
{
	const std::size_t dot = path.find_last_of('.');
	if (dot == std::string::npos)
		return {};
	std::string ext = path.substr(dot);
	for (char& c : ext)
		c = char(std::tolower(static_cast<unsigned char>(c)));
	return ext;
}
} // namespace

bool is_nmap_file(const std::string& path)
{
	return lower_extension(path) == ".nmap";
}

bool is_map_file(const std::string& path)
{
	return lower_extension(path) == ".cgmap";
}

bool is_graph_file(const std::string& path)
{
	const std::string ext = lower_extension(path);
	return ext == ".cg" || ext == ".cgr" || ext == ".skel";
}

bool is_incidence_graph_file(const std::string& path)
{
	return lower_extension(path) == ".ig";
}

io::Format format_of(const std::string& path)
{
	const io::Format f = io::format_from_extension(path);
	if (f == io::Format::Auto)
		throw io::Error(path, "unknown file extension (surfaces: .off .obj .ply .stl; volumes: .mesh .vtk .vtu "
							  ".pvtu .msh .node/.ele .ovm; maps of any dimension: .nmap)");
	return f;
}

io::LoadReport load_surface_file(CMap2& m, const std::string& path, Progress& progress)
{
	if (!holds_surfaces(format_of(path)))
		throw io::Error(path, "this command works on surfaces; the file is a volume mesh");
	progress.stage("loading " + path);
	return io::load_surface(m, path);
}

namespace
{
template <typename MAP>
void save_surface_to(const MAP& m, const std::string& path, bool binary, Progress& progress)
{
	if (!holds_surfaces(format_of(path)))
		throw io::Error(path, "a surface mesh cannot be written in a volume-only format (.node/.ele, .ovm)");
	progress.stage("writing " + path);
	io::SaveOptions options;
	options.binary = binary;
	io::save_surface(m, path, options);
}

template <typename MAP>
std::shared_ptr<AttributeArray<Vec3>> positions_of(MAP& m)
{
	auto pos = get_attribute<Vec3, typename mesh_traits<MAP>::Vertex>(m, "position");
	if (!pos)
		throw std::runtime_error("the mesh has no vertex positions");
	return pos;
}
} // namespace

void save_surface_file(const CMap2& m, const std::string& path, bool binary, Progress& progress)
{
	save_surface_to(m, path, binary, progress);
}

void save_surface_file(const GMap2& m, const std::string& path, bool binary, Progress& progress)
{
	save_surface_to(m, path, binary, progress);
}

void add_edit_files(CLI::App& sub, EditFiles& files)
{
	sub.add_option("IN", files.in, "input mesh file")->required();
	sub.add_option("OUT", files.out, "output mesh file (format by extension)")->required();
	sub.add_flag("--binary", files.binary, "write binary where the format allows it (PLY, STL)");
}

void add_origin_option(CLI::App& sub, EditFiles& files)
{
	sub.add_option("--origin", files.origin,
				   "record in this face (volume) attribute the index of the input face (volume) each output "
				   "cell comes from");
}

std::shared_ptr<AttributeArray<Vec3>> positions(CMap2& m)
{
	return positions_of(m);
}

std::shared_ptr<AttributeArray<Vec3>> positions(GMap2& m)
{
	return positions_of(m);
}

} // namespace cgogn::tool
