// SPDX-License-Identifier: MIT
// `cgogn info`, `cgogn check`, `cgogn convert`: inspect and convert mesh files.
#include <cgogn/core/properties/integrity.h>

#include "commands.h"
#include "mesh_info.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace cgogn::tool
{

using nlohmann::json;

namespace
{

int run_info(const std::string& path, bool as_json)
{
	Progress progress;
	json j;
	with_loaded_whole(path, progress, [&](const auto& m, const io::LoadReport& r) {
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
	with_loaded_whole(path, progress, [&](const auto& m, const io::LoadReport& r) {
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
		j["orientable"] = load.orientable;
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
	with_loaded_whole(in, progress, [&](const auto& m, const io::LoadReport&) {
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

Command add_info_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("info", "Counts, topology, geometry summary of a mesh file");
	auto file = std::make_shared<std::string>();
	auto as_json = std::make_shared<bool>(false);
	sub->add_option("FILE", *file, "mesh file (.off .obj .ply .stl .mesh .vtk .vtu .msh .node/.ele)")->required();
	sub->add_flag("--json", *as_json, "print one JSON object");
	return {sub, [=] { return run_info(*file, *as_json); }};
}

Command add_check_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("check", "Load a mesh and check every invariant of the map (exit 1 if broken)");
	auto file = std::make_shared<std::string>();
	auto as_json = std::make_shared<bool>(false);
	sub->add_option("FILE", *file, "mesh file")->required();
	sub->add_flag("--json", *as_json, "print one JSON object");
	return {sub, [=] { return run_check(*file, *as_json); }};
}

Command add_convert_command(CLI::App& app)
{
	auto* sub = app.add_subcommand("convert", "Convert a mesh file to another format (by extension)");
	auto files = std::make_shared<EditFiles>();
	auto no_attributes = std::make_shared<bool>(false);
	sub->add_option("IN", files->in, "input mesh file")->required();
	sub->add_option("OUT", files->out, "output mesh file")->required();
	sub->add_flag("--binary", files->binary, "write binary where the format allows it (PLY, STL, VTK, VTU, msh)");
	sub->add_flag("--no-attributes", *no_attributes, "write positions and connectivity only");
	return {sub, [=] { return run_convert(files->in, files->out, files->binary, !*no_attributes); }};
}

} // namespace cgogn::tool
