// SPDX-License-Identifier: MIT
// `cgogn info`, `cgogn check`, `cgogn convert`: inspect and convert mesh files.
#include <cgogn/core/properties/graph_properties.h>
#include <cgogn/core/properties/integrity.h>
#include <cgogn/io/graph.h>
#include <cgogn/io/incidence_graph.h>
#include <cgogn/io/surface.h>

#include "commands.h"
#include "map_files.h"
#include "mesh_info.h"
#include "nmap_files.h"

#include <nlohmann/json.hpp>

#include <iostream>

namespace cgogn::tool
{

using nlohmann::json;

namespace
{

// Loads a graph file into a graph (see io::load_graph).
Graph load_graph_file(const std::string& path, Progress& progress, io::GraphLoadReport& report)
{
	progress.stage("loading " + path);
	Graph g;
	report = io::load_graph(g, path);
	return g;
}

// What `cgogn info` reports about a map read from a .cgmap file.
template <typename MAP>
json map_file_info(const MAP& m)
{
	json j;
	if constexpr (io::MultiresolutionMapFileType<MAP>)
		j = tool::mrmap_info(m);
	else if constexpr (std::same_as<MAP, Graph>)
		j = tool::graph_info(m, io::GraphLoadReport{});
	else if constexpr (is_nmap_v<MAP>)
		j = tool::nmap_info(m);
	else if constexpr (MAP::dimension == 3)
		j = tool::volume_info(m, io::LoadReport{});
	else
		j = tool::surface_info(m, io::LoadReport{});
	j["map"] = io::map_type_name<MAP>();
	j["format"] = "cgmap";
	return j;
}

int run_info(const std::string& path, bool as_json)
{
	Progress progress;
	json j;
	if (is_graph_file(path))
	{
		io::GraphLoadReport r;
		const Graph g = load_graph_file(path, progress, r);
		progress.stage("measuring");
		j = tool::graph_info(g, r);
	}
	else if (is_nmap_file(path))
		with_loaded_nmap(path, progress, [&](const auto& m) {
			progress.stage("measuring");
			j = tool::nmap_info(m);
		});
	else if (is_map_file(path))
		with_loaded_map_file(path, progress, [&](const auto& m) {
			progress.stage("measuring");
			j = map_file_info(m);
		});
	else if (is_incidence_graph_file(path))
	{
		progress.stage("loading " + path);
		IncidenceGraph ig;
		io::load_incidence_graph(ig, path);
		progress.stage("measuring");
		io::LoadReport counts;
		counts.format = io::Format::Auto;
		j = tool::complex_info(ig, counts);
		j["format"] = "IG";
	}
	else
	{
		bool repaired = false;
		with_loaded_whole(path, progress, [&](const auto& m, const io::LoadReport& r) {
			progress.stage("measuring");
			if constexpr (std::decay_t<decltype(m)>::dimension == 3)
				j = tool::volume_info(m, r);
			else
			{
				j = tool::surface_info(m, r);
				repaired = !r.manifold();
			}
		});
		// a map cannot hold a non-manifold surface: the true counts are the
		// incidence graph's, the repaired map's beside them
		if (repaired)
		{
			progress.stage("loading " + path + " as an incidence graph");
			IncidenceGraph ig;
			const io::LoadReport r = io::load_surface(ig, path);
			json map = j;
			j = tool::complex_info(ig, r);
			json summary;
			for (const char* k : {"map", "vertices", "edges", "faces", "connected_components", "euler_characteristic",
								  "split_vertex_copies", "nonmanifold_edges", "nonmanifold_vertices", "holes_closed"})
				if (map.contains(k))
					summary[k] = map[k];
			j["repaired_map"] = summary;
			j["bbox"] = map["bbox"];
			j["edge_length"] = map["edge_length"];
		}
	}
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
	if (is_graph_file(path))
	{
		io::GraphLoadReport r;
		const Graph g = load_graph_file(path, progress, r);
		progress.stage("checking");
		report = check_integrity(g);
	}
	else if (is_nmap_file(path))
		with_loaded_nmap(path, progress, [&](const auto& m) {
			progress.stage("checking");
			report = check_integrity(m);
		});
	else if (is_map_file(path))
		with_loaded_map_file(path, progress, [&](const auto& m) {
			progress.stage("checking");
			report = check_integrity(m);
		});
	else if (is_incidence_graph_file(path))
	{
		progress.stage("loading " + path);
		IncidenceGraph ig;
		io::load_incidence_graph(ig, path);
		progress.stage("checking");
		report = check_integrity(ig);
	}
	else
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

// A map of any dimension to a .nmap file, or its cells of dimension
// min(D, 3) (of its boundary with `boundary`) to a .vtu file.
template <typename MAP>
void save_nmap_as(const MAP& m, const std::string& out, bool boundary)
{
	constexpr uint32 D = MAP::dimension;
	if (is_nmap_file(out))
	{
		if (boundary)
			throw io::Error(out, "--boundary writes the boundary's cells to a .vtu file");
		io::save_nmap(m, out);
		return;
	}
	if (io::format_from_extension(out) != io::Format::Vtu)
		throw io::Error(out, "a map of any dimension is written to a .nmap or a .vtu file");
	if (!boundary)
		io::save_vtu(m, out, {std::min(D, 3u)});
	else if constexpr (D >= 2)
		io::save_vtu(extract_boundary(m), out, {std::min(D - 1, 3u)});
	else
		throw io::Error(out, "a map of dimension 1 has no boundary cells to write");
}

// A map read from a .cgmap file to `out`: another .cgmap file, or the
// formats of its kind of map (the current level of a multiresolution map).
template <typename MAP>
void save_map_as(const MAP& m, const std::string& out, const io::SaveOptions& options, bool boundary)
{
	if (is_map_file(out))
		io::save_map(m, out);
	else if constexpr (io::MultiresolutionMapFileType<MAP>)
	{
		if (boundary)
			throw io::Error(out, "--boundary applies to the maps of any dimension (CMapN, GMapN)");
		if constexpr (std::same_as<MAP, MRMap2>)
			io::save_surface(extract_level(m, current_level(m)), out, options);
		else
			io::save_volume(extract_level(m, current_level(m)), out, options);
	}
	else if constexpr (is_nmap_v<MAP>)
		save_nmap_as(m, out, boundary);
	else if (boundary)
		throw io::Error(out, "--boundary applies to the maps of any dimension (CMapN, GMapN)");
	else if constexpr (std::same_as<MAP, Graph>)
		io::save_graph(m, out);
	else if constexpr (MAP::dimension == 3)
		io::save_volume(m, out, options);
	else
		io::save_surface(m, out, options);
}

// Any input the program reads as a map to a .cgmap file: surfaces and
// volumes as the map they load into (a G-map when the file needs one),
// graphs, maps of any dimension, .cgmap files.
void convert_to_map_file(const std::string& in, const std::string& out, Progress& progress)
{
	const auto save = [&](const auto& m) {
		progress.stage("writing " + out);
		io::save_map(m, out);
	};
	if (is_map_file(in))
		with_loaded_map_file(in, progress, save);
	else if (is_nmap_file(in))
		with_loaded_nmap(in, progress, save);
	else if (is_graph_file(in))
	{
		io::GraphLoadReport r;
		save(load_graph_file(in, progress, r));
	}
	else if (is_incidence_graph_file(in))
		throw io::Error(in, "an incidence graph is not a map: it is kept whole in .ig files");
	else
		with_loaded_whole(in, progress, [&](const auto& m, const io::LoadReport&) { save(m); });
}

int run_convert(const std::string& in, const std::string& out, bool binary, bool attributes, bool boundary)
{
	Progress progress;
	if (is_map_file(out))
	{
		if (boundary)
			throw io::Error(out, "--boundary writes the boundary's cells to a .vtu file");
		convert_to_map_file(in, out, progress);
		return 0;
	}
	if (is_map_file(in))
	{
		io::SaveOptions options;
		options.binary = binary;
		options.attributes = attributes;
		with_loaded_map_file(in, progress, [&](const auto& m) {
			progress.stage("writing " + out);
			save_map_as(m, out, options, boundary);
		});
		return 0;
	}
	if (is_graph_file(in) || is_graph_file(out))
	{
		// the other side: a graph file, or a format that holds polylines
		const std::string& other = is_graph_file(in) ? out : in;
		const io::Format f = io::format_from_extension(other);
		if (!is_graph_file(other) && f != io::Format::Obj && f != io::Format::VtkLegacy && f != io::Format::Vtu)
			throw io::Error(other, "a graph file converts to a graph file (.cg, .cgr, .skel read only) or to the "
								   "polylines of .obj, .vtk and .vtu");
		if (boundary)
			throw io::Error(in, "--boundary applies to the maps of any dimension (.nmap files)");
		io::GraphLoadReport r;
		const Graph g = load_graph_file(in, progress, r);
		progress.stage("writing " + out);
		io::save_graph(g, out);
		return 0;
	}
	if (is_incidence_graph_file(in) || is_incidence_graph_file(out))
	{
		// an incidence graph (an .ig file) to or from a surface file, exactly
		if (boundary)
			throw io::Error(in, "--boundary applies to the maps of any dimension (.nmap files)");
		progress.stage("loading " + in);
		IncidenceGraph ig;
		if (is_incidence_graph_file(in))
			io::load_incidence_graph(ig, in);
		else
			io::load_surface(ig, in);
		progress.stage("writing " + out);
		if (is_incidence_graph_file(out))
			io::save_incidence_graph(ig, out);
		else
		{
			io::SaveOptions options;
			options.binary = binary;
			options.attributes = attributes;
			io::save_surface(ig, out, options);
		}
		return 0;
	}
	if (is_nmap_file(in))
	{
		with_loaded_nmap(in, progress, [&](const auto& m) {
			progress.stage("writing " + out);
			save_nmap_as(m, out, boundary);
		});
		return 0;
	}
	if (boundary)
		throw io::Error(in, "--boundary applies to the maps of any dimension (.nmap files)");
	if (is_nmap_file(out))
	{
		with_loaded_whole(in, progress, [&](const auto& m, const io::LoadReport&) {
			progress.stage("writing " + out);
			io::save_nmap(mesh_as_nmap(m), out);
		});
		return 0;
	}
	const io::Format out_format = format_of(out);
	io::SaveOptions options;
	options.binary = binary;
	options.attributes = attributes;
	with_loaded_whole(in, progress, [&](const auto& m, const io::LoadReport& r) {
		progress.stage("writing " + out);
		if constexpr (std::decay_t<decltype(m)>::dimension == 3)
		{
			if (!is_volume_format(out_format))
				throw io::Error(out, "a volume mesh cannot be written in a surface format");
			io::save_volume(m, out, options);
		}
		else
		{
			if (!holds_surfaces(out_format))
				throw io::Error(out, "a surface mesh cannot be written in a volume-only format (.node/.ele, .ovm)");
			if (r.manifold())
				io::save_surface(m, out, options);
			else
			{
				// the map was repaired: write the file's own complex, whole
				IncidenceGraph ig;
				io::load_surface(ig, in);
				io::save_surface(ig, out, options);
			}
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
	sub->add_option(
		   "FILE", *file,
		   "mesh file (.off .obj .ply .stl .mesh .vtk .vtu .msh .node/.ele .ovm .nmap .ig .cgmap), or graph (.cg "
		   ".cgr .skel)")
		->required();
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
	auto boundary = std::make_shared<bool>(false);
	sub->add_option("IN", files->in,
					"input mesh file (or .nmap: a map of any dimension; .cg .cgr .skel: a graph; .cgmap: a whole map)")
		->required();
	sub->add_option("OUT", files->out, "output mesh file (or .nmap; .cg .cgr for a graph; .cgmap: the whole map)")
		->required();
	sub->add_flag("--binary", files->binary, "write binary where the format allows it (PLY, STL, VTK, VTU, msh)");
	sub->add_flag("--no-attributes", *no_attributes, "write positions and connectivity only");
	sub->add_flag("--boundary", *boundary, "a .nmap to .vtu: write the cells of the map's boundary");
	return {sub, [=] { return run_convert(files->in, files->out, files->binary, !*no_attributes, *boundary); }};
}

} // namespace cgogn::tool
