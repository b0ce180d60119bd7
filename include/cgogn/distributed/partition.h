// SPDX-License-Identifier: MIT
#pragma once

#include <cgogn/core/map/cmap2.h>
#include <cgogn/core/map/cmap3.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace cgogn::dist
{

/// The options of partition().
struct PartitionOptions
{
	/// The uint32 attribute of the volumes (of the faces of a CMap2) that
	/// receives each cell's part. An attribute of this name and type is
	/// overwritten; one of another type is an error.
	std::string attribute = "part";
	/// The largest part may hold up to this many times the mean number of
	/// cells (METIS's load imbalance tolerance; at least 1.001).
	double imbalance_tolerance = 1.03;
	/// METIS's random seed: the same map, parts and seed give the same
	/// partition.
	int seed = 0;
};

/// What partition() made: the size of each part, the balance, the cut, and
/// whether each part is connected through the faces between its volumes
/// (the edges between its faces in a CMap2).
struct PartitionReport
{
	uint32 nb_parts = 0;            ///< The number of parts asked for.
	std::vector<uint64> part_sizes; ///< Cells per part.
	double imbalance = 0;           ///< Cells of the largest part over the mean (1 is perfect balance).
	/// Faces between two volumes (edges between two faces in a CMap2): the
	/// edges of the dual graph.
	uint64 nb_interior_facets = 0;
	uint64 nb_cut_facets = 0; ///< Interior facets whose two sides lie in different parts.
	/// Connected pieces of each part, through its interior facets: 1 for a
	/// part in one piece. A part can only be in one piece if the map's cells
	/// are connected (nb_map_components == 1).
	std::vector<uint32> part_components;
	uint32 nb_map_components = 0; ///< Connected pieces of the whole map, through its interior facets.

	/// Cut facets over interior facets (0 without interior facet).
	double cut_ratio() const
	{
		return nb_interior_facets == 0 ? 0.0 : double(nb_cut_facets) / double(nb_interior_facets);
	}
	/// True when every part is in one piece.
	bool parts_connected() const
	{
		for (uint32 c : part_components)
			if (c != 1)
				return false;
		return true;
	}
};

/// Bad arguments of partition(): no cell, more parts than cells, zero
/// parts, or an attribute of the given name with another type.
class PartitionError : public std::invalid_argument
{
public:
	using std::invalid_argument::invalid_argument;
};

/// Splits the volumes of m into nb_parts parts with METIS (multilevel k-way
/// on the dual graph: one node per volume, one edge per pair of volumes
/// that share a face), minimising the faces between parts. Writes each
/// volume's part, in [0, nb_parts), to the uint32 volume attribute
/// `options.attribute` (added when missing; it indexes the volumes). When
/// the map's volumes are connected, METIS is asked for parts in one piece
/// each (its contiguity option); the report says whether each part is. The
/// map's relations are not changed. Throws PartitionError on bad arguments,
/// std::runtime_error when METIS fails. O(volumes log volumes) in practice.
PartitionReport partition(CMap3& m, uint32 nb_parts, const PartitionOptions& options = {});

/// The same for the faces of a surface: one node per face, one edge per
/// pair of faces that share an edge; the part goes to a uint32 face
/// attribute.
PartitionReport partition(CMap2& m, uint32 nb_parts, const PartitionOptions& options = {});

} // namespace cgogn::dist
