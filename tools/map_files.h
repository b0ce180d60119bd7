// SPDX-License-Identifier: MIT
// Whole-map files (.cgmap) in the `cgogn` program: loaded into the map type
// their header names.
#pragma once

#include <cgogn/core/operators/mrmap2.h>
#include <cgogn/core/operators/mrmap3.h>
#include <cgogn/io/map_file.h>

#include "tool_common.h"

#include <optional>
#include <string>
#include <utility>

namespace cgogn::tool
{

/// Loads the .cgmap file at path into the map its header names (CMap2,
/// CMap3, GMap2, GMap3, Graph, CMapN<D>, GMapN<D>, MRMap2 or MRMap3) and calls
/// f(map).
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
		if constexpr (io::MultiresolutionMapFileType<MAP>)
		{
			MAP m{decltype(extract_level(std::declval<const MAP&>(), 0))()};
			io::load_map(m, path);
			f(m);
		}
		else
		{
			MAP m;
			io::load_map(m, path);
			f(m);
		}
	};
	load.template operator()<MRMap2>();
	load.template operator()<MRMap3>();
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
		throw io::Error(path,
						"a map of type " + h.map_type +
							": the program reads 2- and 3-maps, G-maps, graphs, multiresolution 2- and 3-maps and "
							"maps of dimension 2 and more");
}

/// Loads the .cgmap file at path for drawing and calls f(map) with a CMap2
/// or a CMap3 (const): an MRMap2 (MRMap3) at `level` (default: the current
/// level saved in the file) as a flat CMap2 (CMap3) (extract_level), a CMap2
/// or CMap3 as it is. Throws io::Error for other
/// map types, and for a level given to a map without levels or above the
/// file's finest level.
template <typename FUNC>
void with_drawable_map_file(const std::string& path, std::optional<uint32> level, Progress& progress, const FUNC& f)
{
	with_loaded_map_file(path, progress, [&]<typename MAP>(const MAP& m) {
		if constexpr (io::MultiresolutionMapFileType<MAP>)
		{
			const uint32 l = level.value_or(current_level(m));
			if (l > max_level(m))
				throw io::Error(path, "--level " + std::to_string(l) + ": the file's finest level is " +
										  std::to_string(max_level(m)));
			progress.stage("extracting level " + std::to_string(l));
			f(extract_level(m, l));
		}
		else if (level.has_value())
			throw io::Error(path,
							"--level applies to multiresolution maps; the file holds a " + io::map_type_name<MAP>());
		else if constexpr (std::same_as<MAP, CMap2> || std::same_as<MAP, CMap3>)
			f(m);
		else
			throw io::Error(path, "a " + io::map_type_name<MAP>() +
									  ": render and view draw the CMap2, CMap3, MRMap2 and MRMap3 of .cgmap files");
	});
}

} // namespace cgogn::tool
