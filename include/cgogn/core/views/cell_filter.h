// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/traversals/local_views.h>
#include <cgogn/core/traversals/parallel.h>
#include <cgogn/core/views/mesh_view.h>
#include <cgogn/core/views/view_queries.h>

namespace cgogn
{

/// A mesh seen through one predicate per cell type: traversals (foreach_cell,
/// parallel_foreach_cell, local traversals) only report the cells whose
/// predicate holds; a cell type without a predicate is not filtered. The
/// predicates are evaluated on the fly at each traversal, which suits sets of
/// cells that change often (see CellCache for stable ones). Holds a reference
/// to the mesh, which must outlive it. Predicates are called concurrently by
/// parallel traversals.
template <typename MESH>
class CellFilter
{
	static_assert(MeshType<MESH>, "CellFilter<MESH>: MESH must be a map or a view");

public:
	using MeshViewTag = void; ///< Marks the class as a view (see MeshView).
	using ViewedMesh = MESH;  ///< The type of the filtered mesh: a map or another view.

	/// A filter of m without any predicate (every cell passes). O(1).
	explicit CellFilter(const MESH& m) : mesh_(m)
	{
	}

	/// The filtered mesh. O(1).
	const MESH& mesh() const
	{
		return mesh_;
	}

	/// Sets the predicate `bool(CELL)` of cells of type CELL (replaces the
	/// previous one). O(1).
	template <typename CELL, typename PRED>
	void set_filter(PRED&& pred)
	{
		static_assert(has_cell_type_v<MESH, CELL>, "set_filter<CELL>: CELL is not a cell type of this mesh");
		std::get<detail::CellPredicate<CELL>>(filters_) = std::forward<PRED>(pred);
	}
	/// Removes the predicate of CELL: every cell of that type passes. O(1).
	template <typename CELL>
	void clear_filter()
	{
		std::get<detail::CellPredicate<CELL>>(filters_) = nullptr;
	}
	/// True when CELL has a predicate. O(1).
	template <typename CELL>
	bool has_filter() const
	{
		if constexpr (has_cell_type_v<MESH, CELL>)
			return bool(std::get<detail::CellPredicate<CELL>>(filters_));
		else
			return false;
	}

	/// True when c passes this filter's predicate for its type (the viewed
	/// mesh's own filters, if it is a view, are not evaluated). A LocatedCell
	/// (from a traversal that knows the line) is judged as its cell. O(cost of
	/// the predicate).
	template <CellType C>
	bool accepts(C located_or_not) const
	{
		using CELL = Cell<C::ORBIT>;
		const CELL c(located_or_not.dart);
		if constexpr (has_cell_type_v<MESH, CELL>)
		{
			const auto& p = std::get<detail::CellPredicate<CELL>>(filters_);
			return !p || p(c);
		}
		else
			return true;
	}

	/// Implements foreach_cell(filter, f): the cells of the viewed mesh that
	/// pass the predicate. O(cells of the viewed mesh).
	template <typename CELL, typename FUNC>
	void foreach_cell(const FUNC& f) const
	{
		const auto& p = std::get<detail::CellPredicate<CELL>>(filters_);
		if (!p)
			cgogn::foreach_cell(mesh_, [&](CELL c) { return call_and_continue(f, c); });
		else
			cgogn::foreach_cell(mesh_, [&](CELL c) { return !p(c) || call_and_continue(f, c); });
	}

	/// Implements parallel_foreach_cell(filter, f). O(cells / workers).
	template <typename CELL, typename FUNC>
	void parallel_foreach_cell(const FUNC& f) const
	{
		const auto& p = std::get<detail::CellPredicate<CELL>>(filters_);
		if (!p)
			cgogn::parallel_foreach_cell(mesh_, [&](CELL c) { f(c); });
		else
			cgogn::parallel_foreach_cell(mesh_, [&](CELL c) {
				if (p(c))
					f(c);
			});
	}

private:
	const MESH& mesh_;
	typename detail::per_cell_type<typename mesh_traits<MESH>::Cells, detail::CellPredicate>::type filters_;
};

/// A filter has the cells, attributes and map of the mesh it filters.
template <typename MESH>
struct mesh_traits<CellFilter<MESH>> : mesh_traits<MESH>
{
};

} // namespace cgogn
