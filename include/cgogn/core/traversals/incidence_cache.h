// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/core/traversals/local_gmap2.h>
#include <cgogn/core/traversals/local_gmap3.h>
#include <cgogn/core/traversals/parallel.h>

#include <memory>

namespace cgogn
{

namespace detail
{

// The local traversal a cache replaces: incident TO cells of c, or (THROUGH
// not void) TO cells adjacent to c through a THROUGH cell.
template <typename MAP, typename TO, typename THROUGH, typename FROM, typename FUNC>
void foreach_neighbour(const MAP& m, FROM c, const FUNC& f)
{
	using T = mesh_traits<MAP>;
	if constexpr (std::is_void_v<THROUGH>)
	{
		if constexpr (std::is_same_v<TO, typename T::Vertex>)
			foreach_incident_vertex(m, c, f);
		else if constexpr (std::is_same_v<TO, typename T::Edge>)
			foreach_incident_edge(m, c, f);
		else if constexpr (std::is_same_v<TO, typename T::Face>)
			foreach_incident_face(m, c, f);
		else
			foreach_incident_volume(m, c, f);
	}
	else if constexpr (std::is_same_v<TO, typename T::Vertex>)
	{
		if constexpr (std::is_same_v<THROUGH, typename T::Edge>)
			foreach_adjacent_vertex_through_edge(m, c, f);
		else if constexpr (std::is_same_v<THROUGH, typename T::Face>)
			foreach_adjacent_vertex_through_face(m, c, f);
		else
			foreach_adjacent_vertex_through_volume(m, c, f);
	}
	else if constexpr (std::is_same_v<TO, typename T::Edge>)
	{
		if constexpr (std::is_same_v<THROUGH, typename T::Vertex>)
			foreach_adjacent_edge_through_vertex(m, c, f);
		else if constexpr (std::is_same_v<THROUGH, typename T::Face>)
			foreach_adjacent_edge_through_face(m, c, f);
		else
			foreach_adjacent_edge_through_volume(m, c, f);
	}
	else if constexpr (std::is_same_v<TO, typename T::Face>)
	{
		if constexpr (std::is_same_v<THROUGH, typename T::Vertex>)
			foreach_adjacent_face_through_vertex(m, c, f);
		else if constexpr (std::is_same_v<THROUGH, typename T::Edge>)
			foreach_adjacent_face_through_edge(m, c, f);
		else
			foreach_adjacent_face_through_volume(m, c, f);
	}
	else
	{
		if constexpr (std::is_same_v<THROUGH, typename T::Vertex>)
			foreach_adjacent_volume_through_vertex(m, c, f);
		else if constexpr (std::is_same_v<THROUGH, typename T::Edge>)
			foreach_adjacent_volume_through_edge(m, c, f);
		else
			foreach_adjacent_volume_through_face(m, c, f);
	}
}

// The relations whose traversal consults a cache (the others would build a
// table nobody reads).
template <typename MAP, typename FROM, typename TO, typename THROUGH>
constexpr bool incidence_cache_supported()
{
	using T = mesh_traits<MAP>;
	using V = typename T::Vertex;
	using E = typename T::Edge;
	using F = typename T::Face;
	using W = typename T::Volume;
	if constexpr (!std::is_void_v<THROUGH>)
		return std::is_same_v<FROM, TO> && !std::is_same_v<FROM, THROUGH> &&
			   (MAP::dimension == 3 ? !std::is_same_v<FROM, W> || !std::is_same_v<THROUGH, W>
									: !std::is_same_v<FROM, W> && !std::is_same_v<THROUGH, W>);
	else if constexpr (MAP::dimension == 2)
		return (std::is_same_v<FROM, V> && (std::is_same_v<TO, E> || std::is_same_v<TO, F>)) ||
			   (std::is_same_v<FROM, F> && (std::is_same_v<TO, V> || std::is_same_v<TO, E>)) ||
			   (std::is_same_v<FROM, W> && !std::is_same_v<TO, W>);
	else
		return (std::is_same_v<FROM, V> && !std::is_same_v<TO, V>) ||
			   (std::is_same_v<FROM, E> && (std::is_same_v<TO, F> || std::is_same_v<TO, W>)) ||
			   (std::is_same_v<FROM, F> && (std::is_same_v<TO, V> || std::is_same_v<TO, E>)) ||
			   (std::is_same_v<FROM, W> && !std::is_same_v<TO, W>);
}

} // namespace detail

/// Quick incidence (or adjacency) traversal, as in the paper's "quick
/// traversals": an opt-in table, held by the map, of the TO cells incident to
/// each FROM cell (THROUGH void), or of the TO = FROM cells adjacent to it
/// through a THROUGH cell. While built, the matching local traversal
/// (foreach_incident_face(m, Vertex, f) for <Vertex, Face>,
/// foreach_adjacent_vertex_through_edge(m, v, f) for <Vertex, Vertex, Edge>,
/// ...) reads the table instead of walking darts: the rows are the dart walks
/// from each cell's representative dart (other caches bypassed), so the
/// cached traversal reports the same cells, in the same order, as the walk
/// from that dart (other traversals that use this cache internally, e.g. an
/// adjacency walking incidences, report the same cells, possibly through
/// other darts or in another order). The table is a snapshot of the connectivity: it is NOT updated
/// by topological operators: any change of a relation drops the map's tables
/// (they would be stale), so call update() after changing the map (or
/// remove() it); check_integrity reports a table that disagrees with the map
/// (IncidenceCacheStale). Cells created after build() are traversed by
/// walking darts. FROM cells are indexed by build() if they were not.
/// The neighbours are reported as LocatedCell<TO> (their lines stored too,
/// when TO is indexed at build time): a callable taking `auto` reads their
/// attributes at flat-array cost; one taking TO gets the plain cell.
/// Memory: 4 bytes per FROM container line + 4 bytes per stored neighbour
/// (8 with the lines), and 200 KB per map holding any cache (the lookup array
/// of IncidenceTables).
/// Supported: every local traversal of 2- and 3-maps and of 2- and 3-G-maps
/// but the O(1) ones (2-D edge -> vertex/face/volume, 3-D edge -> vertex,
/// face -> volume, * -> connected component of a 2-map).
template <typename MAP, typename FROM, typename TO, typename THROUGH = void>
class IncidenceCache
{
	static_assert(MapType<MAP>, "IncidenceCache<MAP, ...>: MAP must be a map type (CMap2, CMap3, GMap2, GMap3)");
	static_assert(has_cell_type_v<MAP, FROM> && has_cell_type_v<MAP, TO>,
				  "IncidenceCache: FROM and TO must be cell types of MAP");
	static_assert(detail::incidence_cache_supported<MAP, FROM, TO, THROUGH>(),
				  "IncidenceCache: this relation has no cached traversal (see the list in the class comment)");

public:
	/// The key of the relation (FROM, TO, THROUGH): its table in the map's
	/// IncidenceTables.
	static constexpr uint32 key = detail::incidence_key<FROM, TO, THROUGH>();

	/// Builds (or rebuilds) the table from the current connectivity, in
	/// parallel over the FROM cells (two traversals: count, then fill).
	/// O(size of the relation / workers) + O(FROM container lines).
	static void build(MAP& m)
	{
		remove(m);
		if (!is_indexed<FROM>(m))
			index_cells<FROM>(m);
		auto t = std::make_unique<IncidenceTable>();
		t->key = key;
		t->from = FROM::ORBIT;
		t->to = TO::ORBIT;
		if constexpr (!std::is_void_v<THROUGH>)
			t->through = orbit_index(THROUGH::ORBIT);
		t->row_is_valid = &row_is_valid;
		const AttributeContainer& from = container_of<FROM::ORBIT>(m);
		t->nb_rows = from.end_index();
		t->offsets.assign(std::size_t(t->nb_rows) + 1, 0);
		uint32* offsets = t->offsets.data();
		// pass 1: row sizes (row i + 1 of offsets), each FROM cell writes its own slot
		// the rows are the pure dart walks (other caches bypassed), as check_integrity expects
		parallel_foreach_cell(m, [&](FROM c) {
			detail::IncidenceCacheBypass bypass;
			uint32 n = 0;
			detail::foreach_neighbour<MAP, TO, THROUGH>(m, c, [&](TO) { ++n; });
			offsets[index_of(m, c) + 1] = n;
		});
		for (std::size_t i = 1; i < t->offsets.size(); ++i)
			t->offsets[i] += t->offsets[i - 1];
		t->targets.resize(t->offsets.back());
		Dart* targets = t->targets.data();
		// the neighbours' lines too when TO is indexed (LocatedCell traversals)
		const bool with_lines = is_indexed<TO>(m);
		if (with_lines)
			t->target_lines.resize(t->offsets.back());
		uint32* lines = t->target_lines.data();
		// pass 2: fill the rows
		parallel_foreach_cell(m, [&](FROM c) {
			detail::IncidenceCacheBypass bypass;
			uint32 k = offsets[index_of(m, c)];
			detail::foreach_neighbour<MAP, TO, THROUGH>(m, c, [&](TO x) {
				if (with_lines)
					lines[k] = index_of(m, x);
				targets[k++] = x.dart;
			});
		});
		detail::state_of(m).incidence_tables.add(std::move(t));
	}

	/// Recomputes the table after topological changes (same as build). Cost of build.
	static void update(MAP& m)
	{
		build(m);
	}

	/// Frees the table; traversals walk the darts again. O(number of tables).
	static void remove(MAP& m)
	{
		detail::state_of(m).incidence_tables.remove(key);
	}

	/// True when the table is built. O(1).
	static bool is_built(const MAP& m)
	{
		return detail::state_of(m).incidence_tables.find(key) != nullptr;
	}

	/// Bytes held by the table (0 when not built). O(1).
	static std::size_t memory_bytes(const MAP& m)
	{
		const IncidenceTable* t = detail::state_of(m).incidence_tables.find(key);
		return t == nullptr ? 0 : t->memory_bytes();
	}

private:
	// Row r against the darts: the FROM cell of line r (none when the line is
	// free) must have exactly the stored neighbours, in the stored order.
	static bool row_is_valid(const CMapBase& mb, const IncidenceTable& t, uint32 r)
	{
		const MAP& m = static_cast<const MAP&>(mb);
		const AttributeContainer& from = container_of<FROM::ORBIT>(m);
		const uint32 b = t.offsets[r], e = t.offsets[r + 1];
		if (!from.is_live(r))
			return b == e;
		detail::IncidenceCacheBypass bypass;
		uint32 k = b;
		bool ok = true;
		const bool with_lines = !t.target_lines.empty();
		detail::foreach_neighbour<MAP, TO, THROUGH>(m, FROM(Dart(from.key()[r])), [&](TO x) {
			ok = k < e && t.targets[k] == x.dart && (!with_lines || t.target_lines[k] == index_of(m, x));
			++k;
			return ok;
		});
		return ok && k == e;
	}
};

} // namespace cgogn
