// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/build/nmap_generators.h>
#include <cgogn/io/error.h>

#include <array>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace cgogn::io
{

// Files of the maps of any dimension.
//
// The .nmap format is a text file that describes itself (the format of
// docs/nmap_format.md): a header line `cgogn_nmap 1`, the model (`cmap` or
// `gmap`) and the dimension, then the darts, one line each with its
// relations (phi1 ... phiD, or beta1 ... betaD: beta0 joins darts 2k and
// 2k + 1) and its boundary mark, then the cell attributes, each as a header
// (cell dimension, name, value type) and one line per cell: a dart of the
// cell and the value. Lines starting with # are comments.

/// What the header of a .nmap file says: the model and the dimension of its map.
struct NMapHeader
{
	bool gmap = false;  ///< a GMapN (model gmap), else a CMapN (model cmap)
	uint32 dimension{}; ///< D, 1 ... MAX_DIMENSION
};

/// Reads the header of a .nmap file: the map type a program needs to load
/// it (GMapN<D> or CMapN<D>). Throws io::Error naming the file and the line
/// for a file that is not a .nmap file of version 1, an unknown model or a
/// dimension out of 1 ... MAX_DIMENSION. O(size of the file): it is read
/// whole.
NMapHeader read_nmap_header(const std::string& path);

/// Writes m to path in the .nmap format: its darts, relations and boundary,
/// and the attributes of its cells (CellD<0> ... CellD<D>) whose values are
/// double, float, int32, uint32, int64, uint64 or std::array<double, K> (K
/// <= 8, such as PointD<K>); the others are not written and their names
/// returned. The darts are numbered in the order of their indices. Throws
/// io::Error when the file cannot be written. O(size of m x attributes).
template <typename MAP>
requires is_nmap_v<MAP> std::vector<std::string> save_nmap(const MAP& m, const std::string& path);

/// Reads a .nmap file into m, which must have no dart: its darts, relations,
/// boundary marks and cell attributes (each created with the file's type).
/// The whole file is read and checked (every invariant of check_integrity)
/// before m is replaced, so a failure leaves m as it was; m's attributes are
/// replaced by the file's. Throws io::Error naming the file, the line and the
/// problem for a malformed file, a file of another model or dimension than
/// m's, or an invalid map. O(size of the file).
template <typename MAP>
requires is_nmap_v<MAP>
void load_nmap(MAP& m, const std::string& path);

/// Writes cells of m as a VTK XML unstructured grid (.vtu, ASCII), which
/// ParaView opens: the cells of the given dimensions (0 to 3: vertices,
/// edges as lines, faces as polygons, 3-cells as polyhedra with their
/// faces), boundary cells excluded, on the vertices' positions (the vertex
/// attribute `position`, a PointD<K> of any K: the boundary of a 4-map
/// keeps the 4-D points of the map) mapped to 3-D by `project` (by default:
/// the first three coordinates, missing ones 0). The 3-D boundary of a 4-D map
/// is save_vtu(extract_boundary(m), path, {3}); a 3-skeleton is
/// save_vtu(m, path, {0, 1, 2, 3}). A cell-data array `dimension` tells each
/// cell's dimension. Throws io::Error when m has no position attribute or
/// the file cannot be written. O(size of m).
template <typename MAP>
requires is_nmap_v<MAP>
void save_vtu(const MAP& m, const std::string& path, const std::vector<uint32>& dimensions = {3},
			  const std::function<std::array<double, 3>(std::span<const double>)>& project = {});

} // namespace cgogn::io
