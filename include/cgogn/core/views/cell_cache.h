// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/local_views.h>
#include <cgogn/core/traversals/parallel.h>
#include <cgogn/core/views/mesh_view.h>
#include <cgogn/core/views/view_queries.h>

namespace cgogn
{

/// A stored set of cells per cell type, traversed directly by foreach_cell and
/// parallel_foreach_cell: a snapshot. Cells created in the map after build()
/// are not in it, so an algorithm that creates cells while traversing a cache
/// only visits the cells that existed when it was built (e.g. cutting every
/// edge once). A cell removed from the map, or changed so that its stored dart
/// no longer represents it, makes the cache invalid: rebuild it. Local
/// traversals on a cache are those of the viewed mesh (not restricted to the
/// cache). A cell type that was never built is empty. Holds a reference to
/// the mesh, which must outlive it.
template <typename MESH>
class CellCache
{
	static_assert(MeshType<MESH>, "CellCache<MESH>: MESH must be a map or a view");

public:
	using MeshViewTag = void; ///< Marks the class as a view (see MeshView).
	using ViewedMesh = MESH;  ///< The type of the cached mesh: a map or another view.

	/// An empty cache of m (build or add cells). O(1).
	explicit CellCache(const MESH& m) : mesh_(m)
	{
	}

	/// The viewed mesh. O(1).
	const MESH& mesh() const
	{
		return mesh_;
	}

	/// Replaces the cells of type CELL by all the cells of that type of the
	/// viewed mesh. O(traversal of the mesh).
	template <typename CELL>
	void build()
	{
		auto& v = cells_of<CELL>();
		v.clear();
		cgogn::foreach_cell(mesh_, [&](CELL c) { v.push_back(c); });
	}
	/// Replaces the cells of type CELL by those of the viewed mesh for which
	/// pred(c) holds. O(traversal of the mesh + cost of pred).
	template <typename CELL, typename PRED>
	void build(const PRED& pred)
	{
		auto& v = cells_of<CELL>();
		v.clear();
		cgogn::foreach_cell(mesh_, [&](CELL c) {
			if (pred(c))
				v.push_back(c);
		});
	}
	/// Appends cell c (not checked for duplicates: a cell added twice is
	/// visited twice). Allowed during a sequential traversal of this cache
	/// (the traversal does not visit it). Amortised O(1).
	template <typename CELL>
	void add(CELL c)
	{
		cells_of<CELL>().push_back(c);
	}
	/// Empties the set of cells of type CELL. O(1) (keeps the memory).
	template <typename CELL>
	void clear()
	{
		cells_of<CELL>().clear();
	}
	/// Empties every set. O(number of cell types).
	void clear()
	{
		std::apply([](auto&... v) { (v.clear(), ...); }, cells_);
	}
	/// Number of stored cells of type CELL. O(1).
	template <typename CELL>
	uint32 size() const
	{
		return uint32(cells<CELL>().size());
	}
	/// The stored cells of type CELL, in insertion order. O(1).
	template <typename CELL>
	const std::vector<CELL>& cells() const
	{
		static_assert(has_cell_type_v<MESH, CELL>, "CellCache: CELL is not a cell type of this mesh");
		return std::get<detail::CellVector<CELL>>(cells_);
	}

	/// Every cell passes (a cache restricts global traversals only). O(1).
	template <typename CELL>
	bool accepts(CELL) const
	{
		return true;
	}

	/// Implements foreach_cell(cache, f): the stored cells as they were when f
	/// was called first (cells added meanwhile are not visited). O(stored cells).
	template <typename CELL, typename FUNC>
	void foreach_cell(const FUNC& f) const
	{
		const auto& v = cells<CELL>();
		held_callable_t<FUNC> fc = f; // see held_callable_t
		// by index: f may add cells to this cache (the vector may reallocate)
		for (std::size_t i = 0, n = v.size(); i < n; ++i)
			if (!call_and_continue(fc, CELL(v[i])))
				return;
	}

	/// Implements parallel_foreach_cell(cache, f): the stored cells split in
	/// chunks across workers. f must not add cells to the cache. O(stored cells / workers).
	template <typename CELL, typename FUNC>
	void parallel_foreach_cell(const FUNC& f) const
	{
		if (detail::run_sequentially())
		{
			foreach_cell<CELL>(f); // as parallel_foreach_cell on a map: the sequential traversal
			return;
		}
		const auto& v = cells<CELL>();
		detail::parallel_for_chunks(uint32(v.size()), detail::PARALLEL_LINE_GRAIN,
									detail::ChunkBody([&](uint32 b, uint32 e) {
										held_callable_t<FUNC> fc = f; // see held_callable_t
										for (uint32 i = b; i < e; ++i)
											fc(v[i]);
									}));
	}

private:
	template <typename CELL>
	std::vector<CELL>& cells_of()
	{
		static_assert(has_cell_type_v<MESH, CELL>, "CellCache: CELL is not a cell type of this mesh");
		return std::get<detail::CellVector<CELL>>(cells_);
	}

	const MESH& mesh_;
	typename detail::per_cell_type<typename mesh_traits<MESH>::Cells, detail::CellVector>::type cells_;
};

/// A cache has the cells, attributes and map of the mesh it caches.
template <typename MESH>
struct mesh_traits<CellCache<MESH>> : mesh_traits<MESH>
{
};

} // namespace cgogn
