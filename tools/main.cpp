// SPDX-License-Identifier: MIT
// The `cgogn` command-line program: info, check and convert mesh files.
#include <cgogn/core/functions/integrity.h>
#include <cgogn/io/surface.h>
#include <cgogn/io/volume.h>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "mesh_info.h"

#include <cstdio>
#include <iostream>
#include <unistd.h>

using namespace cgogn;
using nlohmann::json;

namespace
{

// Exit codes: 0 success, 1 `check` found a broken map, 2 any error.
constexpr int EXIT_BROKEN = 1;
constexpr int EXIT_ERROR = 2;

// Progress goes to stderr, and only when it is a terminal.
class Progress
{
public:
	Progress() : on_(isatty(STDERR_FILENO) != 0)
	{
	}
	~Progress()
	{
		if (on_ && shown_)
			std::fputs("\r\033[K", stderr);
	}
	void stage(const std::string& what)
	{
		if (!on_)
			return;
		std::fprintf(stderr, "\r\033[K%s...", what.c_str());
		std::fflush(stderr);
		shown_ = true;
	}

private:
	bool on_;
	bool shown_ = false;
};

bool is_volume_format(io::Format f)
{
	return f == io::Format::Medit || f == io::Format::VtkLegacy || f == io::Format::Vtu || f == io::Format::Gmsh ||
		   f == io::Format::TetGen;
}

io::Format format_of(const std::string& path)
{
	const io::Format f = io::format_from_extension(path);
	if (f == io::Format::Auto)
		throw io::Error(path, "unknown file extension (surfaces: .off .obj .ply .stl; volumes: .mesh .vtk .vtu "
							  ".msh .node/.ele)");
	return f;
}

// Loads path into a CMap2 or a CMap3 (by format) and calls f(map, report).
template <typename FUNC>
void with_loaded(const std::string& path, Progress& progress, const FUNC& f)
{
	progress.stage("loading " + path);
	if (is_volume_format(format_of(path)))
	{
		CMap3 m;
		const io::LoadReport r = io::load_volume(m, path);
		f(m, r);
	}
	else
	{
		CMap2 m;
		const io::LoadReport r = io::load_surface(m, path);
		f(m, r);
	}
}

int run_info(const std::string& path, bool as_json)
{
	Progress progress;
	json j;
	with_loaded(path, progress, [&](const auto& m, const io::LoadReport& r) {
		progress.stage("measuring");
		if constexpr (std::decay_t<decltype(m)>::dimension == 3)
			j = tool::volume_info(m, r);
		else
			j = tool::surface_info(m, r);
	});
	j["file"] = path;
	progress.stage("done");
	if (as_json)
		std::cout << j.dump(2) << "\n";
	else
		std::cout << tool::info_text(j);
	return 0;
}

int run_check(const std::string& path, bool as_json)
{
	Progress progress;
	IntegrityReport report;
	io::LoadReport load;
	with_loaded(path, progress, [&](const auto& m, const io::LoadReport& r) {
		progress.stage("checking");
		report = check_integrity(m);
		load = r;
	});
	progress.stage("done");
	if (as_json)
	{
		json j;
		j["file"] = path;
		j["ok"] = report.ok();
		j["nb_errors"] = report.nb_errors;
		json errors = json::array();
		for (const auto& e : report.errors)
			errors.push_back(e.message);
		j["errors"] = errors;
		j["manifold"] = load.manifold();
		j["nonmanifold_vertices"] = load.nb_nonmanifold_vertices;
		j["nonmanifold_edges"] = load.nb_nonmanifold_edges;
		j["nonmanifold_faces"] = load.nb_nonmanifold_faces;
		j["skipped_cells"] = load.nb_cells_skipped;
		std::cout << j.dump(2) << "\n";
	}
	else if (report.ok())
		std::cout << path << ": integrity ok\n";
	else
		std::cout << path << ": " << report.nb_errors << " integrity error(s)\n" << report.to_string() << "\n";
	return report.ok() ? 0 : EXIT_BROKEN;
}

int run_convert(const std::string& in, const std::string& out, bool binary, bool attributes)
{
	Progress progress;
	const bool volume_out = is_volume_format(format_of(out));
	io::SaveOptions options;
	options.binary = binary;
	options.attributes = attributes;
	with_loaded(in, progress, [&](const auto& m, const io::LoadReport&) {
		progress.stage("writing " + out);
		if constexpr (std::decay_t<decltype(m)>::dimension == 3)
		{
			if (!volume_out)
				throw io::Error(out, "a volume mesh cannot be written in a surface format");
			io::save_volume(m, out, options);
		}
		else
		{
			if (volume_out)
				throw io::Error(out, "a surface mesh cannot be written in a volume format");
			io::save_surface(m, out, options);
		}
	});
	return 0;
}

} // namespace

int main(int argc, char** argv)
{
	CLI::App app{"cgogn: inspect, check and convert surface and volume mesh files"};
	app.require_subcommand(1);
	std::string file, in, out;
	bool as_json = false, binary = false, no_attributes = false;

	auto* info = app.add_subcommand("info", "Counts, topology, geometry summary of a mesh file");
	info->add_option("FILE", file, "mesh file (.off .obj .ply .stl .mesh .vtk .vtu .msh .node/.ele)")->required();
	info->add_flag("--json", as_json, "print one JSON object");

	auto* check = app.add_subcommand("check", "Load a mesh and check every invariant of the map (exit 1 if broken)");
	check->add_option("FILE", file, "mesh file")->required();
	check->add_flag("--json", as_json, "print one JSON object");

	auto* convert = app.add_subcommand("convert", "Convert a mesh file to another format (by extension)");
	convert->add_option("IN", in, "input mesh file")->required();
	convert->add_option("OUT", out, "output mesh file")->required();
	convert->add_flag("--binary", binary, "write binary where the format allows it (PLY, STL, VTK, VTU, msh)");
	convert->add_flag("--no-attributes", no_attributes, "write positions and connectivity only");

	try
	{
		app.parse(argc, argv);
	}
	catch (const CLI::ParseError& e)
	{
		const int code = app.exit(e);
		return code == 0 ? 0 : EXIT_ERROR;
	}
	try
	{
		if (*info)
			return run_info(file, as_json);
		if (*check)
			return run_check(file, as_json);
		return run_convert(in, out, binary, !no_attributes);
	}
	catch (const std::exception& e)
	{
		std::cerr << "cgogn: " << e.what() << "\n";
		return EXIT_ERROR;
	}
}
