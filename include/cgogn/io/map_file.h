// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap3.h>
#include <cgogn/core/map/graph.h>
#include <cgogn/core/map/mesh_traits.h>
#include <cgogn/core/map/mrmap2.h>
#include <cgogn/core/map/mrmap3.h>
#include <cgogn/core/map/nmap.h>
#include <cgogn/io/error.h>

#include <string>
#include <string_view>
#include <vector>

namespace cgogn::io
{

// Whole maps in one binary file (.cgmap, docs/map_file_format.md): the darts
// in their order with every relation, the boundary marks, the indexing of
// every orbit (cell lines and free lines as they are) and every attribute of
// a type the format holds, so that a loaded map is the saved map, dart for
// dart and line for line. A multiresolution map is its finest map so saved,
// with its levels: its labels, per-level lines and counters, and its
// current level, so that every level of the loaded hierarchy is the saved
// one.

/// The multiresolution maps a .cgmap file holds: MRMap2 and MRMap3.
template <typename MAP>
concept MultiresolutionMapFileType = std::same_as<MAP, MRMap2> || std::same_as<MAP, MRMap3>;

/// The maps a .cgmap file holds: CMap1, CMap2, CMap3, GMap1, GMap2, GMap3,
/// Graph, CMapN<D>, GMapN<D> and the multiresolution MRMap2 and MRMap3.
template <typename MAP>
concept MapFileType = std::same_as<MAP, CMap1> || std::same_as<MAP, CMap2> || std::same_as<MAP, CMap3> ||
	std::same_as<MAP, GMap1> || std::same_as<MAP, GMap2> || std::same_as<MAP, GMap3> || std::same_as<MAP, Graph> ||
	is_nmap_v<MAP> || MultiresolutionMapFileType<MAP>;

/// The name a .cgmap file gives the type of its map: "CMap2", "GMap3",
/// "Graph", "CMapN<4>", "MRMap2", "MRMap3", ... O(1).
template <typename MAP>
requires MapFileType<MAP> std::string map_type_name()
{
	if constexpr (std::same_as<MAP, MRMap2>)
		return "MRMap2";
	else if constexpr (std::same_as<MAP, MRMap3>)
		return "MRMap3";
	else if constexpr (std::same_as<MAP, CMap1>)
		return "CMap1";
	else if constexpr (std::same_as<MAP, CMap2>)
		return "CMap2";
	else if constexpr (std::same_as<MAP, CMap3>)
		return "CMap3";
	else if constexpr (std::same_as<MAP, GMap1>)
		return "GMap1";
	else if constexpr (std::same_as<MAP, GMap2>)
		return "GMap2";
	else if constexpr (std::same_as<MAP, GMap3>)
		return "GMap3";
	else if constexpr (std::same_as<MAP, Graph>)
		return "Graph";
	else
		return std::string(is_gmap_v<MAP> ? "GMapN<" : "CMapN<") + std::to_string(MAP::dimension) + ">";
}

/// An attribute that save_map did not write.
struct SkippedAttribute
{
	std::string orbit;  ///< The orbit of its cells ("PHI21", "CELL0", "DART", ...).
	std::string name;   ///< Its name.
	std::string reason; ///< Why, e.g. "its value type has no encoding in the format".
};

/// What save_map wrote, and what it left out.
struct MapFileReport
{
	uint32 nb_attributes_written = 0;      ///< Attributes written, the library's own (relations, indices) included.
	std::vector<SkippedAttribute> skipped; ///< Attributes whose type the format does not hold.
};

/// What the header of a .cgmap file says.
struct MapFileHeader
{
	uint32 version = 0;   ///< The format's version (1 is the only one so far).
	std::string map_type; ///< The map's type, as map_type_name<MAP>() names it.
};

/// The value types a .cgmap file holds, by the names the format gives them:
/// bool, int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32,
/// float64, Vec2, Vec3, Vec4 (Eigen vectors of double), float64[K] (K = 1
/// ... 8: std::array<double, K>, such as PointD<K>), float32[K], int32[K],
/// uint32[K] (K = 2 ... 4) and string (std::string).
std::vector<std::string> map_file_value_types();

/// The name the format gives the value type of attribute a ("float64",
/// "Vec3", ...: one of map_file_value_types()); empty when the format does
/// not hold it. O(number of value types).
std::string map_file_value_type(const AttributeBase& a);

/// Writes m to a .cgmap file: everything a map holds but the marks reserved
/// at that moment and the quick incidence caches (which enable_incidence_cache
/// rebuilds). Attributes of other value types than map_file_value_types()
/// are left out and listed in the report. An MRMap2 or MRMap3 is written as its
/// finest map (its labels, indices and per-level lines are attributes of
/// it) after a block giving its levels' dart counts and its current level.
/// Throws io::Error when the file cannot be written. O(size of m x
/// attributes).
template <typename MAP>
requires MapFileType<MAP> MapFileReport save_map(const MAP& m, const std::string& path);

/// The bytes save_map would write (for Python's pickle, or a socket).
/// O(size of m x attributes).
template <typename MAP>
requires MapFileType<MAP> std::string save_map_to_bytes(const MAP& m, MapFileReport* report = nullptr);

/// Replaces m by the map of a .cgmap file: the same darts, relations,
/// boundary, cell lines, free lines and attributes (each created with its
/// saved type and default value). The whole file is read and checked
/// (bounds, every invariant of check_integrity) before m is replaced, so a
/// failure leaves m as it was; m's attributes are replaced by the file's
/// (handles to them stay usable but see no map). Throws io::Error naming the
/// file, the byte offset and the problem for a file that is not a .cgmap
/// file, of a newer version, of another map type than MAP (the message names
/// both), truncated or invalid. An MRMap2 or MRMap3 is checked at every level
/// (check_integrity(m)): its per-level dart counts against the darts'
/// labels, its current level, and its labels and lines (the offset is then
/// that of the label of the dart at fault, or of the counters); its current
/// level is the saved one. O(size of the file), O(darts x levels) for a
/// multiresolution map.
template <typename MAP>
requires MapFileType<MAP>
void load_map(MAP& m, const std::string& path);

/// load_map from bytes in memory; `name` stands for the path in error
/// messages. O(size of the bytes).
template <typename MAP>
requires MapFileType<MAP>
void load_map_from_bytes(MAP& m, std::string_view bytes, const std::string& name = "(bytes)");

/// Reads the header of a .cgmap file: the type of map a program needs to
/// load it. Throws io::Error for a file that is not a .cgmap file or is of a
/// newer version. O(1): reads the first bytes only.
MapFileHeader read_map_header(const std::string& path);

/// read_map_header for bytes in memory. O(1).
MapFileHeader read_map_header_from_bytes(std::string_view bytes, const std::string& name = "(bytes)");

} // namespace cgogn::io
