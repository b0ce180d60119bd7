// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/container/attribute_container.h>
#include <cgogn/core/types/cell.h>
#include <cgogn/core/types/incidence_table.h>

#include <array>
#include <memory>
#include <vector>

namespace cgogn
{

/// What every combinatorial map holds: a dart container whose attributes are
/// the phi relations, the per-orbit index attributes and the boundary mark,
/// and one attribute container per orbit for cell data.
///
/// Members ending in `_` are the library's internals: use the free functions
/// (phi1(m, d), index_of(m, c), add_attribute<T, CELL>(m, name), ...).
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
	CMapBase(CMapBase&&) = default;
	CMapBase& operator=(CMapBase&&) = default;
	CMapBase(const CMapBase&) = delete;
	CMapBase& operator=(const CMapBase&) = delete;

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
	/// is_incident_to_boundary in O(1).
	uint32 nb_boundary_darts_ = 0;
	/// Quick incidence caches (see IncidenceCache); empty unless enabled.
	IncidenceTables incidence_tables_;

protected:
	AttributeArray<uint32>* add_relation(const std::string& name)
	{
		auto a = darts_->add_attribute<uint32>(name, INVALID_INDEX);
		relations_.push_back(a.get());
		return a.get();
	}
};

} // namespace cgogn
