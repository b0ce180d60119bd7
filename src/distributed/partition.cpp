// SPDX-License-Identifier: MIT
#include <cgogn/core/attributes/attributes.h>
#include <cgogn/core/map/indexing.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/distributed/partition.h>

#include <algorithm>
#include <cmath>
#include <metis.h>
#include <numeric>
#include <utility>

namespace cgogn::dist
{

namespace
{

// The cells a map is partitioned by, and the facets between them.
template <typename MAP>
struct DualOf;
template <>
struct DualOf<CMap3>
{
	using Cell = CMap3::Volume;
	using Facet = CMap3::Face;
	static constexpr const char* cells = "volumes";
	static Dart across(const CMap3& m, Dart d)
	{
		return phi3(m, d);
	}
};
template <>
struct DualOf<CMap2>
{
	using Cell = CMap2::Face;
	using Facet = CMap2::Edge;
	static constexpr const char* cells = "faces";
	static Dart across(const CMap2& m, Dart d)
	{
		return phi2(m, d);
	}
};

// The dual graph in compressed rows, as METIS takes it: the neighbours of
// cell i are adjacency[offsets[i], offsets[i + 1]), sorted, each once. The
// facets are kept too, one pair of cell numbers each (several between one
// pair of cells count each), for the cut count.
struct DualGraph
{
	std::vector<idx_t> offsets;
	std::vector<idx_t> adjacency;
	std::vector<std::pair<uint32, uint32>> facets;
};

// Numbers the cells 0 .. n-1 in traversal order (number[line] = k).
// Precondition: the cells are indexed.
template <typename MAP>
std::vector<uint32> number_cells(const MAP& m)
{
	using Cell = typename DualOf<MAP>::Cell;
	std::vector<uint32> number;
	uint32 k = 0;
	foreach_cell(m, [&](Cell c) {
		const uint32 line = index_of(m, c);
		if (line >= number.size())
			number.resize(std::max<std::size_t>(line + 1, 2 * number.size()), INVALID_INDEX);
		number[line] = k++;
	});
	return number;
}

// One walk of the map's facets; the rows are then built from the pairs.
template <typename MAP>
DualGraph dual_graph(const MAP& m, const std::vector<uint32>& number, uint32 n)
{
	using D = DualOf<MAP>;
	DualGraph g;
	// the two cells on either side of each interior facet; a facet with the
	// same cell on both sides adds no edge
	foreach_cell(m, [&](typename D::Facet facet) {
		const Dart d = facet.dart, e = D::across(m, d);
		if (is_boundary(m, d) || is_boundary(m, e))
			return;
		const uint32 a = number[index_of(m, typename D::Cell(d))];
		const uint32 b = number[index_of(m, typename D::Cell(e))];
		if (a != b)
			g.facets.emplace_back(a, b);
	});
	g.offsets.assign(n + 1, 0);
	for (const auto& [a, b] : g.facets)
	{
		++g.offsets[a + 1];
		++g.offsets[b + 1];
	}
	for (uint32 i = 0; i < n; ++i)
		g.offsets[i + 1] += g.offsets[i];
	std::vector<idx_t> cursor(g.offsets.begin(), g.offsets.end() - 1);
	g.adjacency.resize(std::size_t(g.offsets[n]));
	for (const auto& [a, b] : g.facets)
	{
		g.adjacency[std::size_t(cursor[a]++)] = idx_t(b);
		g.adjacency[std::size_t(cursor[b]++)] = idx_t(a);
	}
	// METIS takes each neighbour once: two cells sharing several facets
	// (possible with polyhedra) are one edge
	idx_t out = 0;
	for (uint32 i = 0; i < n; ++i)
	{
		const auto first = g.adjacency.begin() + g.offsets[i], last = g.adjacency.begin() + g.offsets[i + 1];
		std::sort(first, last);
		const auto end = std::unique(first, last);
		g.offsets[i] = out;
		out = idx_t(std::copy(first, end, g.adjacency.begin() + out) - g.adjacency.begin());
	}
	g.offsets[n] = out;
	g.adjacency.resize(std::size_t(out));
	return g;
}

// Connected pieces of the dual graph restricted to the edges whose ends have
// the same label, per label (all labels 0: the pieces of the whole graph).
std::vector<uint32> components_per_label(const DualGraph& g, const std::vector<idx_t>& label, uint32 nb_labels)
{
	const std::size_t n = label.size();
	std::vector<uint32> pieces(nb_labels, 0);
	std::vector<uint8> seen(n, 0);
	std::vector<uint32> stack;
	for (std::size_t s = 0; s < n; ++s)
	{
		if (seen[s])
			continue;
		++pieces[std::size_t(label[s])];
		seen[s] = 1;
		stack.push_back(uint32(s));
		while (!stack.empty())
		{
			const uint32 i = stack.back();
			stack.pop_back();
			for (idx_t k = g.offsets[i]; k < g.offsets[i + 1]; ++k)
			{
				const auto j = std::size_t(g.adjacency[std::size_t(k)]);
				if (!seen[j] && label[j] == label[i])
				{
					seen[j] = 1;
					stack.push_back(uint32(j));
				}
			}
		}
	}
	return pieces;
}

template <typename MAP>
PartitionReport partition_cells(MAP& m, uint32 nb_parts, const PartitionOptions& options)
{
	using Cell = typename DualOf<MAP>::Cell;
	const std::string cells = DualOf<MAP>::cells;
	// every argument is checked before the map is touched
	if (nb_parts == 0)
		throw PartitionError("partition: the number of parts must be at least 1");
	if (!(options.imbalance_tolerance >= 1.001))
		throw PartitionError("partition: the imbalance tolerance must be at least 1.001");
	const uint32 n = nb_cells<Cell>(m);
	if (n == 0)
		throw PartitionError("partition: the map has no " + cells);
	if (nb_parts > n)
		throw PartitionError("partition: " + std::to_string(nb_parts) + " parts for " + std::to_string(n) + " " +
							 cells);
	auto part_attr = get_attribute<uint32, Cell>(m, options.attribute);
	bool added = false;
	if (part_attr == nullptr)
	{
		part_attr = add_attribute<uint32, Cell>(m, options.attribute);
		if (part_attr == nullptr)
			throw PartitionError("partition: the " + cells + " have an attribute named '" + options.attribute +
								 "' that is not of type uint32, or the name is reserved");
		added = true;
	}

	const std::vector<uint32> number = number_cells(m);
	DualGraph g = dual_graph(m, number, n);

	PartitionReport report;
	report.nb_parts = nb_parts;
	report.nb_interior_facets = g.facets.size();
	report.nb_map_components = components_per_label(g, std::vector<idx_t>(n, 0), 1)[0];

	std::vector<idx_t> part(n, 0);
	if (nb_parts > 1)
	{
		idx_t metis_options[METIS_NOPTIONS];
		METIS_SetDefaultOptions(metis_options);
		metis_options[METIS_OPTION_SEED] = idx_t(options.seed);
		metis_options[METIS_OPTION_NUMBERING] = 0;
		metis_options[METIS_OPTION_UFACTOR] = idx_t(std::lround((options.imbalance_tolerance - 1.0) * 1000.0));
		// METIS refuses (and prints) a contiguity request on a disconnected graph
		metis_options[METIS_OPTION_CONTIG] = report.nb_map_components == 1 ? 1 : 0;
		idx_t nvtxs = idx_t(n), ncon = 1, nparts = idx_t(nb_parts), cut = 0;
		idx_t no_neighbour = 0; // METIS reads adjacency[0] even when there is none
		const int status = METIS_PartGraphKway(
			&nvtxs, &ncon, g.offsets.data(), g.adjacency.empty() ? &no_neighbour : g.adjacency.data(), nullptr, nullptr,
			nullptr, &nparts, nullptr, nullptr, metis_options, &cut, part.data());
		if (status != METIS_OK)
		{
			if (added)
				remove_attribute(m, part_attr);
			throw std::runtime_error(status == METIS_ERROR_MEMORY
										 ? "partition: METIS ran out of memory"
										 : "partition: METIS failed (status " + std::to_string(status) + ")");
		}
	}

	report.part_sizes.assign(nb_parts, 0);
	for (idx_t p : part)
		++report.part_sizes[std::size_t(p)];
	const uint64 largest = *std::max_element(report.part_sizes.begin(), report.part_sizes.end());
	report.imbalance = double(largest) * double(nb_parts) / double(n);
	// counted per facet: two cells may share several (polyhedra)
	for (const auto& [a, b] : g.facets)
		report.nb_cut_facets += part[a] != part[b];
	report.part_components = components_per_label(g, part, nb_parts);

	foreach_cell(m, [&](Cell c) { (*part_attr)[c] = uint32(part[number[index_of(m, c)]]); });
	return report;
}

} // namespace

PartitionReport partition(CMap3& m, uint32 nb_parts, const PartitionOptions& options)
{
	return partition_cells(m, nb_parts, options);
}

PartitionReport partition(CMap2& m, uint32 nb_parts, const PartitionOptions& options)
{
	return partition_cells(m, nb_parts, options);
}

} // namespace cgogn::dist
