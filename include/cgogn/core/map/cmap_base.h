// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/attributes/attribute_container.h>
#include <cgogn/core/map/cell.h>
#include <cgogn/core/traversals/incidence_table.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace cgogn
{

class CMapBase;

namespace detail
{

/// What every combinatorial map holds, gathered so that core's implementation
/// reaches it through one accessor (state_of) while programs cannot: a dart
/// container whose attributes are the phi relations, the per-orbit index
/// attributes and the boundary mark, and one attribute container per orbit
/// for cell data. Not part of the API.
struct MapState
{
	/// Number of attributes of the map whose rule is not None, kept by the
	/// containers (AttributeContainer::set_rule): operators skip the rules
	/// with one test when it is 0. On the heap so that containers keep its
	/// address when the map moves; declared first, destroyed last.
	std::unique_ptr<uint32> nb_ruled_attributes = std::make_unique<uint32>(0);
	std::unique_ptr<AttributeContainer> darts;
	std::array<std::unique_ptr<AttributeContainer>, NB_ORBITS> cells;
	/// Per-orbit dart attribute holding each dart's cell index (nullptr while
	/// the orbit is not indexed).
	std::array<AttributeArray<uint32>*, NB_ORBITS> cell_index{};
	/// The key of the dart container: a dart is live when its key is valid.
	/// phi1 in a combinatorial map, beta1 in a generalized map.
	AttributeArray<uint32>* phi1 = nullptr;
	/// phi2 and phi3, for the combinatorial maps of dimension 2 and more
	/// (nullptr below; phi4 ... of a CMapN are in `relations` only).
	AttributeArray<uint32>* phi2 = nullptr;
	AttributeArray<uint32>* phi3 = nullptr;
	/// beta1, ... betan, for the generalized maps (beta1 is the key; nullptr
	/// in a combinatorial map and above the map's dimension). beta[0] is
	/// always nullptr: beta0 is not stored, the darts of a generalized map
	/// being allocated in pairs (2k, 2k + 1) that are each other's beta0.
	std::array<AttributeArray<uint32>*, MAX_DIMENSION + 1> beta{};
	/// phi1, phi2, ... phin (or beta1, ... betan) in this order: relations[i - 1] is phi_i (beta_i).
	std::vector<AttributeArray<uint32>*> relations;
	MarkAttribute* boundary = nullptr;
	/// Number of live darts carrying the boundary mark (kept by
	/// detail::set_boundary and remove_dart): a map without boundary answers
	/// is_incident_to_boundary in O(1).
	uint32 nb_boundary_darts = 0;
	/// Quick incidence caches (see IncidenceCache); empty unless enabled.
	IncidenceTables incidence_tables;
};

MapState& state_of(CMapBase& m);
const MapState& state_of(const CMapBase& m);

} // namespace detail

/// The base of every map, combinatorial or generalized: its darts, relations, cells and
/// attributes (see detail::MapState).
///
/// The state is private: programs use the free functions (phi1(m, d),
/// index_of(m, c), add_attribute<T, CELL>(m, name), container_of<O>(m), ...);
/// core's own implementation reaches it through detail::state_of, which is
/// not part of the API.
/// Maps can be moved, not copied (use merge(), from the operators, to copy one
/// map into another).
class CMapBase
{
public:
	CMapBase() : CMapBase("__phi1")
	{
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
	/// A map whose first relation, the key of the dart container, is named
	/// `key_name` ("__phi1" for the combinatorial maps, "__beta1" for the
	/// generalized ones).
	explicit CMapBase(const std::string& key_name)
	{
		state_.darts = std::make_unique<AttributeContainer>(key_name);
		state_.darts->count_rules_in(state_.nb_ruled_attributes.get());
		state_.phi1 = &state_.darts->key();
		state_.relations.push_back(state_.phi1);
		state_.boundary = state_.darts->add_persistent_mark();
		for (uint32 o = 0; o < NB_ORBITS; ++o)
		{
			state_.cells[o] = std::make_unique<AttributeContainer>("__dart");
			state_.cells[o]->set_orbit(Orbit(o));
			state_.cells[o]->count_rules_in(state_.nb_ruled_attributes.get());
		}
	}

	/// Adds the dart attribute of the next relation (phi2, then phi3, ...),
	/// invalid on every dart until sewn; called by the constructors of CMap2,
	/// CMap3 and CMapN.
	void add_relation(const std::string& name)
	{
		AttributeArray<uint32>* a = state_.darts->add_attribute<uint32>(name, INVALID_INDEX).get();
		state_.relations.push_back(a);
		if (state_.relations.size() == 2)
			state_.phi2 = a;
		else if (state_.relations.size() == 3)
			state_.phi3 = a;
	}

	/// Makes the key beta1: called by the constructor of GMap1, whose beta0
	/// is implicit (see MapState::beta).
	void use_key_as_beta1()
	{
		state_.beta[1] = state_.phi1;
	}

	/// Adds the dart attribute of the next involution (beta2, then beta3,
	/// ...), invalid on every dart until sewn; called by the constructors of
	/// GMap2, GMap3 and GMapN.
	void add_beta_relation(const std::string& name)
	{
		AttributeArray<uint32>* a = state_.darts->add_attribute<uint32>(name, INVALID_INDEX).get();
		state_.beta[state_.relations.size() + 1] = a;
		state_.relations.push_back(a);
	}

private:
	friend detail::MapState& detail::state_of(CMapBase& m);
	friend const detail::MapState& detail::state_of(const CMapBase& m);

	detail::MapState state_;
};

namespace detail
{

/// Core's access to a map's state (the member itself, const when the map is). O(1).
inline MapState& state_of(CMapBase& m)
{
	return m.state_;
}
inline const MapState& state_of(const CMapBase& m)
{
	return m.state_;
}

} // namespace detail

} // namespace cgogn
