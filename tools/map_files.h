// SPDX-License-Identifier: MIT
// Whole-map files (.cgmap) in the `cgogn` program: loaded into the map type
// their header names.
#pragma once

#include <cgogn/io/map_file.h>

#include "tool_common.h"

#include <string>
#include <utility>

namespace cgogn::tool
{

/// Loads the .cgmap file at path into the map its header names (CMap2,
/// CMap3, GMap2, GMap3, Graph, CMapN<D> or GMapN<D>) and calls f(map).
/// Throws io::Error as io::load_map does, and for a map of dimension 1
/// (CMap1, GMap1), which no subcommand handles.
template <typename FUNC>
void with_loaded_map_file(const std::string& path, Progress& progress, const FUNC& f)
{
	progress.stage("loading " + path);
	const io::MapFileHeader h = io::read_map_header(path);
	bool found = false;
	const auto load = [&]<typename MAP>() {
		if (found || h.map_type != io::map_type_name<MAP>())
			return;
		found = true;
		MAP m;
		io::load_map(m, path);
		f(m);
	};
	load.template operator()<CMap2>();
	load.template operator()<CMap3>();
	load.template operator()<GMap2>();
	load.template operator()<GMap3>();
	load.template operator()<Graph>();
	[&]<uint32... D>(std::integer_sequence<uint32, D...>)
	{
		(load.template operator()<CMapN<D + 2>>(), ...);
		(load.template operator()<GMapN<D + 2>>(), ...);
	}
	(std::make_integer_sequence<uint32, MAX_DIMENSION - 1>{});
	if (!found)
		throw io::Error(path, "a map of type " + h.map_type +
								  ": the program reads 2- and 3-maps, G-maps, graphs and maps of dimension 2 and more");
}

} // namespace cgogn::tool
