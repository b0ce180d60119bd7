// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attribute_container.h>
#include <cgogn/core/map/cell.h>
#include <cgogn/core/traversals/incidence_table.h>

#include <array>
#include <memory>
#include <type_traits>
#include <vector>

namespace cgogn
{

class CMapBase;
class CMap2;
class CMap3;

namespace detail
{
struct MapMembers;
}

/// What every combinatorial map holds: a dart container whose attributes are
/// the phi relations, the per-orbit index attributes and the boundary mark,
/// and one attribute container per orbit for cell data.
///
/// The members are private: programs use the free functions (phi1(m, d),
/// index_of(m, c), add_attribute<T, CELL>(m, name), container_of<O>(m), ...).
/// Core's own implementation reaches them through the accessors of
/// cgogn::detail below, which are not part of the API.
/// Maps can be moved, not copied (use merge(), from the operators, to copy one
/// map into another).
class CMapBase
{
public:
	CMapBase()
	{
		darts_ = std::make_unique<AttributeContainer>("__phi1");
		phi1_ = &darts_->key();
		relations_.push_back(phi1_);
		boundary_ = darts_->add_persistent_mark();
		for (uint32 o = 0; o < NB_ORBITS; ++o)
		{
			cells_[o] = std::make_unique<AttributeContainer>("__dart");
			cells_[o]->set_orbit(Orbit(o));
		}
		cell_index_.fill(nullptr);
	}
	/// Takes the darts, cells and attributes of another map. Attribute handles
	/// and marks stay valid (their containers do not move); the moved-from map
	/// may only be destroyed or assigned to. O(1).
	CMapBase(CMapBase&&) = default;
	/// Replaces this map by another one, as the move constructor; the
	/// attributes of the replaced map are removed (their handles stay usable
	/// but see no map). O(size of the replaced map).
	CMapBase& operator=(CMapBase&&) = default;
	CMapBase(const CMapBase&) = delete;
	CMapBase& operator=(const CMapBase&) = delete;

protected:
	/// Adds the dart attribute of the next relation (phi2, then phi3), invalid
	/// on every dart until sewn; called by the constructors of CMap2 and CMap3.
	AttributeArray<uint32>* add_relation(const std::string& name)
	{
		auto a = darts_->add_attribute<uint32>(name, INVALID_INDEX);
		relations_.push_back(a.get());
		return a.get();
	}

private:
	friend struct detail::MapMembers;

	std::unique_ptr<AttributeContainer> darts_;
	std::array<std::unique_ptr<AttributeContainer>, NB_ORBITS> cells_;
	/// Per-orbit dart attribute holding each dart's cell index (nullptr while
	/// the orbit is not indexed).
	std::array<AttributeArray<uint32>*, NB_ORBITS> cell_index_;
	/// phi1 is the key of the dart container: a dart is live when its phi1 is valid.
	AttributeArray<uint32>* phi1_ = nullptr;
	/// phi1, phi2, ... phin in this order.
	std::vector<AttributeArray<uint32>*> relations_;
	MarkAttribute* boundary_ = nullptr;
	/// Number of live darts carrying the boundary mark (kept by
	/// detail::set_boundary and remove_dart): a map without boundary answers
	/// is_incident_to_boundary in O(1). Only the friend detail::MapMembers
	/// reaches it, a use clang's -Wunused-private-field does not see.
	[[maybe_unused]] uint32 nb_boundary_darts_ = 0;
	/// Quick incidence caches (see IncidenceCache); empty unless enabled.
	IncidenceTables incidence_tables_;
};

namespace detail
{

/// Core's access to the members of the maps. Each accessor returns the member
/// itself (const when the map is), so core code reads as before. O(1).
struct MapMembers
{
	template <typename M>
	static auto& darts(M& m)
	{
		return base(m).darts_;
	}
	template <typename M>
	static auto& cells(M& m)
	{
		return base(m).cells_;
	}
	template <typename M>
	static auto& cell_index(M& m)
	{
		return base(m).cell_index_;
	}
	template <typename M>
	static auto& phi1(M& m)
	{
		return base(m).phi1_;
	}
	template <typename M>
	static auto& relations(M& m)
	{
		return base(m).relations_;
	}
	template <typename M>
	static auto& boundary(M& m)
	{
		return base(m).boundary_;
	}
	template <typename M>
	static auto& nb_boundary_darts(M& m)
	{
		return base(m).nb_boundary_darts_;
	}
	template <typename M>
	static auto& incidence_tables(M& m)
	{
		return base(m).incidence_tables_;
	}
	template <typename M>
	static auto& phi2(M& m)
	{
		return static_cast<std::conditional_t<std::is_const_v<M>, const CMap2&, CMap2&>>(m).phi2_;
	}
	template <typename M>
	static auto& phi3(M& m)
	{
		return static_cast<std::conditional_t<std::is_const_v<M>, const CMap3&, CMap3&>>(m).phi3_;
	}

private:
	template <typename M>
	static auto& base(M& m)
	{
		return static_cast<std::conditional_t<std::is_const_v<M>, const CMapBase&, CMapBase&>>(m);
	}
};

// clang-format off
template <typename M> auto& darts_of(M& m) { return MapMembers::darts(m); }
template <typename M> auto& cells_of(M& m) { return MapMembers::cells(m); }
template <typename M> auto& cell_index_of(M& m) { return MapMembers::cell_index(m); }
template <typename M> auto& phi1_of(M& m) { return MapMembers::phi1(m); }
template <typename M> auto& relations_of(M& m) { return MapMembers::relations(m); }
template <typename M> auto& boundary_of(M& m) { return MapMembers::boundary(m); }
template <typename M> auto& nb_boundary_darts_of(M& m) { return MapMembers::nb_boundary_darts(m); }
template <typename M> auto& incidence_tables_of(M& m) { return MapMembers::incidence_tables(m); }
template <typename M> auto& phi2_of(M& m) { return MapMembers::phi2(m); }
template <typename M> auto& phi3_of(M& m) { return MapMembers::phi3(m); }
// clang-format on

} // namespace detail

} // namespace cgogn
