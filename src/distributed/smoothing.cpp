// SPDX-License-Identifier: MIT
#include <cgogn/core/properties/properties.h>
#include <cgogn/core/traversals/global.h>
#include <cgogn/core/traversals/local_cmap2.h>
#include <cgogn/core/traversals/local_cmap3.h>
#include <cgogn/distributed/smoothing.h>

#include <algorithm>
#include <cassert>
#include <utility>

namespace cgogn::dist
{

namespace
{

// `iterations` times, one Jacobi step per factor.
template <typename MAP>
void smooth(const DistributedMap<MAP>& dm, CellAttribute<Vec3, MAP::Vertex::ORBIT>& pos, uint32 iterations,
			const std::vector<double>& factors, const SmoothingOptions& options)
{
	using Vertex = typename MAP::Vertex;
	const MAP& m = dm.map();
	// the owned vertices that move and their neighbours' lines, once
	std::vector<uint32> moving, starts{0}, neighbours;
	std::vector<std::pair<uint64, uint32>> around;
	foreach_cell(m, [&](Vertex v) {
		if (!is_owned(dm, v) || (options.fix_boundary && is_incident_to_boundary(m, v)))
			return;
		around.clear();
		foreach_adjacent_vertex_through_edge(m, v,
											 [&](Vertex w) { around.emplace_back(global_id(dm, w), index_of(m, w)); });
		if (options.deterministic)
			std::sort(around.begin(), around.end());
		moving.push_back(index_of(m, v));
		for (const auto& a : around)
			neighbours.push_back(a.second);
		starts.push_back(uint32(neighbours.size()));
	});
	std::vector<Vec3> delta(moving.size());
	for (uint32 it = 0; it < iterations; ++it)
		for (double factor : factors)
		{
			// the serial filter's arithmetic, term for term
			for (std::size_t i = 0; i < moving.size(); ++i)
			{
				Vec3 s = Vec3::Zero();
				const uint32 n = starts[i + 1] - starts[i];
				for (uint32 k = starts[i]; k < starts[i + 1]; ++k)
					s += pos[neighbours[k]];
				delta[i] = n > 0 ? Vec3(factor * (s / n - pos[moving[i]])) : Vec3::Zero();
			}
			for (std::size_t i = 0; i < moving.size(); ++i)
				pos[moving[i]] += delta[i];
			exchange(dm, pos, options.transport);
		}
}

} // namespace

void laplacian_smoothing(const DistributedCMap3& dm, CellAttribute<Vec3, CMap3::Vertex::ORBIT>& pos, uint32 iterations,
						 const SmoothingOptions& options)
{
	assert(options.lambda > 0.0 && options.lambda <= 1.0);
	smooth(dm, pos, iterations, {options.lambda}, options);
}

void laplacian_smoothing(const DistributedCMap2& dm, CellAttribute<Vec3, CMap2::Vertex::ORBIT>& pos, uint32 iterations,
						 const SmoothingOptions& options)
{
	assert(options.lambda > 0.0 && options.lambda <= 1.0);
	smooth(dm, pos, iterations, {options.lambda}, options);
}

void taubin_smoothing(const DistributedCMap3& dm, CellAttribute<Vec3, CMap3::Vertex::ORBIT>& pos, uint32 iterations,
					  double mu, const SmoothingOptions& options)
{
	assert(options.lambda > 0.0 && mu < -options.lambda);
	smooth(dm, pos, iterations, {options.lambda, mu}, options);
}

void taubin_smoothing(const DistributedCMap2& dm, CellAttribute<Vec3, CMap2::Vertex::ORBIT>& pos, uint32 iterations,
					  double mu, const SmoothingOptions& options)
{
	assert(options.lambda > 0.0 && mu < -options.lambda);
	smooth(dm, pos, iterations, {options.lambda, mu}, options);
}

} // namespace cgogn::dist
