// SPDX-License-Identifier: MIT
#include <cgogn/io/error.h>

#include "formats.h"

namespace cgogn::io::detail
{

void validate(const MeshData& d, const std::string& path)
{
	std::size_t total = 0;
	for (uint32 n : d.cell_sizes)
		total += n;
	if (total != d.cell_vertices.size())
		throw Error(path, "inconsistent cell sizes");
	const uint32 nv = d.nb_vertices();
	for (uint32 v : d.cell_vertices)
		if (v >= nv)
			throw Error(path, "vertex index " + std::to_string(v) + " out of range (the file has " +
								  std::to_string(nv) + " vertices)");
	for (const auto& c : d.vertex_columns)
		if (c.values.size() != std::size_t(nv) * c.dim)
			throw Error(path, "vertex data '" + c.name + "' does not have one value per vertex");
	for (const auto& c : d.cell_columns)
		if (c.values.size() != std::size_t(d.nb_cells()) * c.dim)
			throw Error(path, "cell data '" + c.name + "' does not have one value per cell");
}

} // namespace cgogn::io::detail
