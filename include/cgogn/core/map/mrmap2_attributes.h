// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/mr_lines.h>
#include <cgogn/core/map/mrmap2.h>
#include <cgogn/core/map/mrmap3.h>
#include <cgogn/core/marking/marker.h>
#include <cgogn/core/traversals/local_mrmap2.h>

#include <memory>
#include <string>
#include <type_traits>

namespace cgogn
{

// Attributes of a multiresolution 2-map. A vertex has a value at every level
// from the one where it appears: a new level starts with a copy of the level
// below (the new vertices get what the attributes' rules give: the midpoint
// of the edge they cut, the centroid of the face they centre). An edge or a
// face keeps its line and value at the levels where it exists; when it is
// refined, its children get new lines, starting with a copy of its values.
// So the value read for a cell depends on the level read; `(*attr)[c]` reads
// the finest level.

namespace detail
{

/// The container of the attributes of orbit O: the finest map's (its darts'
/// for HalfEdge). O(1).
template <Orbit O>
AttributeContainer& mr_container(const MRState2& s)
{
	if constexpr (O == Orbit::DART)
		return *state_of(s.map).darts;
	else
		return *state_of(s.map).cells[orbit_index(O)];
}

/// Gives lines to the cells of orbit o at every level (called by
/// add_attribute for the first attribute of the orbit). O(number of darts x
/// levels).
void mr_index_orbit(MRMap2& m, Orbit o);

} // namespace detail

/// Whether cells of type CELL have lines (an attribute of their orbit was
/// added). O(1).
template <typename CELL, MRMesh2 M>
bool is_indexed(const M& m)
{
	return detail::read_level(m).state().cells[detail::mr_slot(CELL::ORBIT)].index != nullptr;
}

/// The line of cell c at the level read. Precondition: the orbit is indexed.
/// O(1) at the finest level, O(levels above the one read) below.
template <MRMesh2 M, Orbit O>
CGOGN_INLINE uint32 index_of(const M& m, Cell<O> c)
{
	static_assert(O == Orbit::DART || detail::is_mr2_orbit(O), "index_of: not a cell of a multiresolution 2-map");
	if constexpr (O == Orbit::DART)
		return c.dart.index; // a dart's line is its index
	const MRLevelView2 v = detail::read_level(m);
	return detail::mr_line_of(v.state(), v.level(), detail::mr_slot(O), c.dart);
}

/// Adds an attribute of type T on cells of type CELL (half-edges, vertices,
/// edges, faces or connected components) of every level (see the rules
/// above; a half-edge has one value, read at every level). The first
/// attribute of an orbit gives lines to its cells at every level: O(number
/// of darts x levels), once. Returns nullptr when the name is taken on this
/// orbit or reserved (names starting with "__").
template <typename T, typename CELL, typename M>
requires std::same_as<M, MRMap2> std::shared_ptr<CellAttribute<T, CELL::ORBIT>> add_attribute(M& m,
																							  const std::string& name)
{
	constexpr Orbit O = CELL::ORBIT;
	static_assert(O == Orbit::DART || detail::is_mr2_orbit(O),
				  "add_attribute on a multiresolution 2-map: HalfEdge, Vertex, Edge, Face or Volume");
	AttributeContainer& container = detail::mr_container<O>(detail::mr_state_of(m));
	if (detail::is_reserved_name(name) || container.find(name) != nullptr)
		return nullptr;
	if constexpr (O != Orbit::DART)
		if (!is_indexed<CELL>(m))
			detail::mr_index_orbit(m, O);
	auto a =
		container.template add_attribute<T, CellAttribute<T, CELL::ORBIT>>(name, detail::default_attribute_value<T>());
	container.template set_default_rule<T>(*a);
	return a;
}

/// The attribute of type T on CELL named `name`; nullptr when there is none or
/// when it has another type. O(number of attributes of the orbit).
template <typename T, typename CELL, MRMesh2 M>
std::shared_ptr<CellAttribute<T, CELL::ORBIT>> get_attribute(const M& m, const std::string& name)
{
	static_assert(detail::is_mr2_orbit(CELL::ORBIT), "get_attribute: not a cell of a multiresolution 2-map");
	if (detail::is_reserved_name(name))
		return nullptr;
	const AttributeContainer& c = *detail::state_of(detail::read_level(m).state().map).cells[orbit_index(CELL::ORBIT)];
	return std::static_pointer_cast<CellAttribute<T, CELL::ORBIT>>(c.template get_attribute<T>(name));
}

/// Removes an attribute of m (the orbit keeps its lines). Returns false when
/// attr is not an attribute of m. O(number of attributes of the orbit).
template <typename... Ignored, typename A>
bool remove_attribute(MRMap2& m, const std::shared_ptr<A>& attr)
{
	static_assert(std::is_base_of_v<AttributeBase, A>);
	if (!attr || attr->container() == nullptr || detail::is_reserved_name(attr->name()))
		return false;
	const detail::MapState& flat = detail::state_of(detail::mr_state_of(m).map);
	bool mine = attr->container() == flat.darts.get();
	for (Orbit o : detail::MR2_ORBITS)
		mine = mine || attr->container() == flat.cells[orbit_index(o)].get();
	return mine && attr->container()->remove_attribute(attr.get());
}

/// The value of attribute attr for cell c at the level read: writable on a
/// (non-const) MRMap2, at its current level; read-only on a level view,
/// which never writes. O(cost of index_of).
template <typename T, typename M, Orbit O>
requires MRMesh2<std::remove_const_t<M>> CGOGN_INLINE decltype(auto) value(M& m, AttributeArray<T>& attr, Cell<O> c)
{
	if constexpr (std::is_same_v<M, MRMap2>)
		return static_cast<T&>(attr[index_of(m, c)]);
	else
		return static_cast<const T&>(attr[index_of(m, c)]);
}
/// The same, read-only. O(cost of index_of).
template <typename T, typename M, Orbit O>
requires MRMesh2<M> CGOGN_INLINE const T& value(const M& m, const AttributeArray<T>& attr, Cell<O> c)
{
	return attr[index_of(m, c)];
}

/// Marks cells of type CELL of a multiresolution map (2-D or 3-D) at the level read:
/// the darts of the cell at that level carry the mark. Cleared on
/// destruction. mark and unmark O(size of the orbit x cost of a level
/// step), is_marked O(1).
template <typename M, typename CELL>
requires(MRMesh2<M> || MRMesh3<M>) class CellMarker<M, CELL>
{
	static_assert(CellType<CELL>);
	using View = decltype(detail::read_level(std::declval<const M&>()));

public:
	using MapType = typename mesh_traits<M>::MapType; ///< The map under M.

	/// A marker of the cells of m at the level it reads (fixed for the
	/// marker's life), none marked. O(1) once the pool is warm.
	explicit CellMarker(const M& m) : view_(detail::read_level(m)), mark_(*detail::state_of(view_.state().map).darts)
	{
	}
	~CellMarker()
	{
		mark_->clear_all();
	}
	/// Marks c.
	void mark(CELL c)
	{
		foreach_dart_of_orbit(view_, c, [&](Dart d) { mark_->set(d.index); });
	}
	/// Unmarks c.
	void unmark(CELL c)
	{
		foreach_dart_of_orbit(view_, c, [&](Dart d) { mark_->reset(d.index); });
	}
	/// Whether c is marked, through any of its darts at the level.
	bool is_marked(CELL c) const
	{
		return mark_->test(c.dart.index);
	}
	/// Unmarks every cell. O(darts / 64).
	void unmark_all()
	{
		mark_->clear_all();
	}

private:
	View view_;
	ReservedMark mark_;
};

} // namespace cgogn
