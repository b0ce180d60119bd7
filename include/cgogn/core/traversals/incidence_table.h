// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/dart.h>
#include <cgogn/core/map/orbit.h>

#include <algorithm>
#include <cassert>
#include <memory>
#include <vector>

namespace cgogn
{

class CMapBase;

/// Storage of a quick incidence (or adjacency) cache: for each line of the
/// FROM orbit's container, the darts of its neighbour cells in the order the
/// traversal reports them, in CSR layout (row r is targets[offsets[r],
/// offsets[r + 1])). Built and used through IncidenceCache; held by the map.
struct IncidenceTable
{
	/// Identifies the relation (from, to, through): see detail::incidence_key.
	uint32 key = 0;
	Orbit from = Orbit::DART; ///< The orbit of the cells whose neighbours are stored (one row per line).
	Orbit to = Orbit::DART;   ///< The orbit of the neighbour cells stored in the rows.
	/// The orbit of the shared cell of an adjacency; NB_ORBITS for an incidence.
	uint32 through = NB_ORBITS;
	/// Number of rows: the FROM container's end index at build time
	/// (offsets holds nb_rows + 1 entries). Stored although offsets.size()
	/// tells it: the traversals test it once per cell, and reading it from the
	/// vector's bounds made the quick surface circulator 3-5% slower
	/// (8.25 -> 8.67 ms, minima of 20 alternated runs).
	uint32 nb_rows = 0;
	std::vector<uint32> offsets; ///< nb_rows + 1 entries: row r is targets[offsets[r], offsets[r + 1]).
	std::vector<Dart> targets;   ///< A dart of each neighbour cell, row after row.
	/// The line of each target cell in the TO container (same layout as
	/// targets), so that a cached traversal reports LocatedCell values whose
	/// attributes are read without a dart -> index lookup. Empty when the TO
	/// orbit was not indexed at build time.
	std::vector<uint32> target_lines;
	/// Recomputes row r from the map (without caches) and tells whether the
	/// stored row matches: used by check_integrity. Set by the builder.
	bool (*row_is_valid)(const CMapBase& m, const IncidenceTable& t, uint32 r) = nullptr;

	/// Bytes held by the table. O(1).
	std::size_t memory_bytes() const
	{
		return offsets.capacity() * sizeof(uint32) + targets.capacity() * sizeof(Dart) +
			   target_lines.capacity() * sizeof(uint32);
	}
};

/// Keys of the relations (see detail::incidence_key): from, to and through
/// orbit indices, through == NB_ORBITS for an incidence.
inline constexpr uint32 NB_INCIDENCE_KEYS = NB_ORBITS * (NB_ORBITS + 1) * (NB_ORBITS + 1);

/// The quick incidence caches a map holds. Each local traversal of a map with
/// caches asks for its relation once per cell: find() answers with one array
/// read (a table of NB_INCIDENCE_KEYS pointers, 200 KB, exists while at least
/// one cache is built), where a search of the list costs a pair of dependent
/// loads per table before it.
class IncidenceTables
{
public:
	using Tables = std::vector<std::unique_ptr<IncidenceTable>>; ///< The tables, in the order they were built.

	/// The table of relation key, nullptr when not built. O(1).
	const IncidenceTable* find(uint32 key) const
	{
		assert(key < NB_INCIDENCE_KEYS);
		return by_key_ == nullptr ? nullptr : by_key_[key];
	}
	/// Whether no cache is built: what a traversal tests first. O(1).
	bool empty() const
	{
		return by_key_ == nullptr;
	}
	/// Number of tables built. O(1).
	std::size_t size() const
	{
		return tables_.size();
	}
	/// Adds t, replacing the table of the same key if any.
	void add(std::unique_ptr<IncidenceTable> t)
	{
		assert(t->key < NB_INCIDENCE_KEYS);
		remove(t->key);
		if (by_key_ == nullptr)
			by_key_ = std::make_unique<const IncidenceTable*[]>(NB_INCIDENCE_KEYS);
		by_key_[t->key] = t.get();
		tables_.push_back(std::move(t));
	}
	/// Frees the table of key, if any.
	void remove(uint32 key)
	{
		if (find(key) == nullptr)
			return;
		by_key_[key] = nullptr;
		tables_.erase(std::remove_if(tables_.begin(), tables_.end(), [&](const auto& t) { return t->key == key; }),
					  tables_.end());
		if (tables_.empty())
			by_key_.reset();
	}
	/// Frees every table (topological changes: they would be stale).
	void clear()
	{
		tables_.clear();
		by_key_.reset();
	}
	/// The tables in the order they were built (checks, tests).
	Tables::const_iterator begin() const
	{
		return tables_.begin();
	}
	/// One past the last table.
	Tables::const_iterator end() const
	{
		return tables_.end();
	}

private:
	Tables tables_;
	std::unique_ptr<const IncidenceTable*[]> by_key_;
};

} // namespace cgogn
