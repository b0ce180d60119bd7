// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/types/dart.h>
#include <cgogn/core/types/orbit.h>

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
	Orbit from = Orbit::DART;
	Orbit to = Orbit::DART;
	/// The orbit of the shared cell of an adjacency; NB_ORBITS for an incidence.
	uint32 through = NB_ORBITS;
	std::vector<uint32> offsets;
	std::vector<Dart> targets;
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

} // namespace cgogn
