// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap3.h>
#include <cgogn/core/map/gmap2.h>

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace cgogn
{

/// What compact() did: for the darts and for each orbit, old index -> new
/// index (INVALID_INDEX for lines that were free).
struct CompactMaps
{
	std::vector<uint32> darts; ///< Old dart index -> new dart index.
	/// For each orbit (by orbit_index()), old line -> new line in its
	/// container; empty for an orbit whose container never had a line.
	std::array<std::vector<uint32>, NB_ORBITS> cells;
};

/// Removes every dart and every cell of m. Its attributes stay (empty), and
/// each orbit stays indexed or not as it was. Incidence caches are dropped.
/// Precondition: no marker alive. O(darts + cells).
void clear(CMapBase& m);

/// Renumbers the darts and the lines of every orbit container densely (live
/// lines first, in their order), so that a long run of edits recovers
/// contiguous memory; attribute values follow their cells, relations and
/// indices are remapped, free memory chunks are released. Invalidates Dart
/// and Cell values held by the caller (use the returned maps) and incidence
/// caches. Precondition: no marker alive. O(darts + cells).
CompactMaps compact(CMap1& m);
/// The same for the G-maps (GMap1, GMap2).
CompactMaps compact(GMap1& m);

/// Permutes darts and cells so that memory order follows `key`, given per
/// vertex (e.g. a Morton code of its position): vertices sorted by key, the
/// darts of each vertex stored together in that order, other cells sorted by
/// their first dart. Neighbourhood traversals then walk memory nearly in
/// order. Compacts first. Invalidates Dart and Cell values held by the caller.
/// O(n log n).
void reorder(CMap2& m, const std::function<uint64(CMap2::Vertex)>& key);
void reorder(CMap3& m, const std::function<uint64(CMap3::Vertex)>& key);
void reorder(GMap2& m, const std::function<uint64(GMap2::Vertex)>& key);

} // namespace cgogn
